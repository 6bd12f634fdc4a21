#pragma once
// The known mistakes' renders of a grading run's cases (grader/src/diagnose/): the reference solution with one mistake
// made to its shaders (the mutant kit of grader/src/diagnose/mutant_kit.h), rendering the cases on this machine as the
// student's lab did. Each is made once per kit, case and mistake: kept in the run's reference cache and in the
// reference store under the reference's key with the mistake's edit added, so a batch or a rerun renders none again.
// The edited solutions hold answers: they live in a folder of the grader's own (0700) for the run, made only where the
// allow-list walls keep student code out of it, and removed at the end.
#include "grader/src/diagnose/known_mistakes.h"
#include "grader/src/grade/session.h"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace gsv {

class MistakePictures {
public:
    explicit MistakePictures(GradingSession& session) : s_(session) {}
    ~MistakePictures();
    MistakePictures(const MistakePictures&) = delete;
    MistakePictures& operator=(const MistakePictures&) = delete;

    // The mistakes `made` of `known` (one, or several made together) on each of `cases`, in order: from the cache or
    // the store, else rendered (one process serving the cases it has not got). Throws gsv::Error where the mistakes
    // cannot be made together (one's edit undoes the text another's needs).
    std::vector<LabRun> render(const LabCases& lab, const KnownMistakes& known, const std::vector<std::size_t>& made,
                               const std::vector<const GradeCase*>& cases);
    int rendered() const { return rendered_; }
    int looked_up() const { return looked_up_; }  // pictures asked for, rendered or kept

private:
    // An edited kit: its folder, and the C++ mistake its build makes ("" for none: the solution's binary).
    struct Kit {
        std::filesystem::path folder;
        std::string cpp_mistake;
    };
    const Kit& kit_of(const KnownMistakes& known, const std::vector<std::size_t>& made);
    std::string key(const LabCases& lab, const KnownMistakes& known, const std::vector<std::size_t>& made, const GradeCase& c);

    GradingSession& s_;
    std::filesystem::path dir_;                   // the run's edited kits, one folder each
    std::map<std::string, Kit> kits_;  // lab + mistake names -> its kit
    int folders_ = 0;
    int rendered_ = 0, looked_up_ = 0;
};

}  // namespace gsv
