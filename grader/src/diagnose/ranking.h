#pragma once
// Which known mistakes are named for a lab's failing cases, from which cases each explains (grader/src/diagnose/):
// without GL or processes, so the browser page's self-check names them as gsv-grade does.
#include "grader/src/diagnose/known_mistakes.h"
#include "grader/src/judge/grade_result.h"

#include <filesystem>
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

// A TODO not started (its pictures the starter's) is said so, not named as a mistake. Where a mistake or another TODO's
// starter draws the same on these cases (a pass-through starter leaves out what the mistake leaves out), the student's
// source (`student_folder`, the lab's files) decides: the TODO whose starter code is still there is not started, else
// the mistake. Mistakes found keep their first real mistake's text; each case of a TODO not started is returned with
// its TODO, which is added to d.not_started.
std::map<std::string, std::string> tell_not_started(LabDiagnosis& d, const KnownMistakes& known,
                                                    const std::filesystem::path& student_folder);

}  // namespace gsv
