#pragma once
// Which known mistakes are named for a lab's failing cases, from which cases each explains (grader/src/diagnose/):
// without GL or processes, so the browser page's self-check names them as gsv-grade does.
#include "grader/src/diagnose/known_mistakes.h"
#include "grader/src/core/grade_result.h"

#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace gsv {

// The ranking: `explains[m]` holds the failing cases mistake m explains. Greedily the mistake that explains the most
// failing cases not yet explained (ties: the one that explains fewer cases in all, then the list's order); mistakes that
// explain exactly the same cases as it are its twins (named together, one text). Stops where none explains another.
LabDiagnosis rank_mistakes(const std::string& lab, const std::vector<std::string>& failing,
                           const std::vector<KnownMistake>& mistakes, const std::vector<std::set<std::string>>& explains);

// The ranking as it is reported: a mistake is named only where it explains at least half the failures still left when
// its turn comes (one that matches a case or two of many is a coincidence of pictures, not evidence); the failures
// none named explains are unexplained.
LabDiagnosis name_mistakes(const std::string& lab, const std::vector<std::string>& failing, const std::vector<KnownMistake>& mistakes,
                           const std::vector<std::set<std::string>>& explains);

// Two mistakes in two TODOs where none alone explains half the failures (where both touch a case, neither's picture
// alone is what the student drew). A pair is consistent with the failures `left` where each of them is a case one of
// the two explains by its picture, or a case both fail alone (`fails[m]`: the cases m's own picture fails); each of the
// two explains one case by its picture at least, and they sit in different TODOs. Where `named` is not empty, the
// pair's first is one of those (already reported) and only its second is new. Best first: the most cases explained by
// pictures, then the fewest drawn together, then the lists' order.
// Where a case both fail is drawn together, what can be told of it without drawing them (`check`, where given: the
// self-check guesses the picture from the two shipped ones): whether the student's picture is the two's together, and
// whether it shows each of them beyond the other alone. That is evidence of a mistake whose own picture explains no
// case by itself (its cases all touched by the other too).
struct TogetherEvidence {
    bool matches = false, shows_first = false, shows_second = false;
};
using TogetherCheck = std::function<TogetherEvidence(std::size_t first, std::size_t second, const std::string& case_name)>;
struct MistakePair {
    std::size_t first = 0, second = 0;
    std::vector<std::string> by_first, by_second, together;  // the cases of `left` each explains; those both fail
    std::size_t together_matched = 0;                        // cases drawn together that `check` says are the two's
};
// `failing`: every case the student failed (a second found through `check` fails no other).
std::vector<MistakePair> consistent_pairs(const std::vector<std::string>& left, const std::vector<std::string>& failing,
                                          const std::vector<KnownMistake>& mistakes,
                                          const std::vector<std::set<std::string>>& explains,
                                          const std::vector<std::set<std::string>>& fails, const std::vector<std::size_t>& named,
                                          const TogetherCheck& check = {});

// The pair as reported: its first (where new) with its twins (same pictures, same failing cases), then its second and
// its twins with the cases drawn together, marked as made together with the mistakes above.
void add_pair(LabDiagnosis& d, const MistakePair& pair, bool first_is_new, const std::vector<KnownMistake>& mistakes,
              const std::vector<std::set<std::string>>& explains, const std::vector<std::set<std::string>>& fails);

// name_mistakes, then, where failures are left, the best consistent pair (completing the mistakes named, or two new).
LabDiagnosis name_mistakes_and_pairs(const std::string& lab, const std::vector<std::string>& failing,
                                     const std::vector<KnownMistake>& mistakes, const std::vector<std::set<std::string>>& explains,
                                     const std::vector<std::set<std::string>>& fails, const TogetherCheck& check = {});

// Before ranking: a TODO whose starter code the student's source still holds (`student_folder`) and whose not-started
// pictures explain some failures takes those failures from every other mistake that explains them too: what the source
// shows is known, a look-alike picture is a guess (lab 05's fountain with L05-T1 not started looks like an L05-T3 slip).
void prefer_confirmed_not_started(std::vector<std::set<std::string>>& explains, const KnownMistakes& known,
                                  const std::filesystem::path& student_folder);

// A TODO not started (its pictures the starter's) is said so, not named as a mistake. Where a mistake or another TODO's
// starter draws the same on these cases (a pass-through starter leaves out what the mistake leaves out), the student's
// source (`student_folder`, the lab's files) decides: the TODO whose starter code is still there is not started, else
// the mistake. Mistakes found keep their first real mistake's text; each case of a TODO not started is returned with
// its TODO, which is added to d.not_started.
std::map<std::string, std::string> tell_not_started(LabDiagnosis& d, const KnownMistakes& known,
                                                    const std::filesystem::path& student_folder);

}  // namespace gsv
