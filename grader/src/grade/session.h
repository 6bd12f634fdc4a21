#pragma once
// One run of the grader, set up before any case runs; grading (grade.cpp) and rewriting the goldens
// (grader/src/update/golden_update.cpp) share it. Setting up chooses the labs and their cases and checks them
// (case_selection.cpp), puts up the walls (walls.cpp), builds a submission's labs and makes the two runners; then
// each check is one row, recorded here.
#include "grader/src/grade/grade.h"
#include "grader/src/run/lab_serve.h"
#include "grader/src/run/process.h"
#include "grader/src/run/reference_store.h"
#include "grader/src/run/sandbox.h"
#include "grader/src/run/uid_lease.h"

#include <chrono>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gsv {

enum class RunPurpose { Grade, UpdateGoldens };

class GradingSession {
public:
    GradingSession(const GradeOptions& options, const std::function<void(const GradeProgress&)>& progress, RunPurpose purpose);

    // The seed, the labs and their cases (chosen and checked), the output folder, the walls, a submission's build and
    // the runners. Throws gsv::Error on what stops the run as a whole.
    void set_up();
    // The report, with the run's wall time.
    GradeReport finish();

    // A result row for a case, before anything ran.
    CaseResult result_for(const LabCases& lab, const GradeCase& c) const;
    void record(CaseResult r);
    ProcessLimits limits(const LabCases& lab, bool student) const;
    // The reference's image of a case: from the in-process cache where the options share one, else from the store on
    // disk where the walls allow one, else rendered (and stored).
    LabRun reference_render(const LabCases& lab, const GradeCase& c);
    // The student's copy of the kit (its labs/), or the kit itself when its own labs are graded.
    std::filesystem::path student_kit() const;
    // The build of a lab of the submission; none when the kit's own labs are graded.
    const LabBuild* build_of(const std::string& lab) const;
    // Whether the student's binary of the lab is built from C++ that is the kit's own: its starter's, by the fingerprints
    // grader/starters.json records (common/app/lab_sources.h), or the solution's binary byte for byte. The kit's tests
    // prove such a lab's cases come out alike whatever ran before them in its process.
    bool cpp_is_the_kits(const std::string& lab) const;
    // From serve(lab) to end_serving(), the runners render the lab's cases through one process each (lab_serve.h),
    // where the options choose it and, for the student, the allow-list walls are up; ended by end_serving.
    void serve(const LabCases& lab);
    void end_serving();
    // Where the allow-list walls are up: student code cannot read what the grader keeps outside its own folder (the
    // reference store, the known mistakes' edited solutions).
    bool walls_up() const { return options.sandbox && support_.allow_list(); }
    // The store of live references, where this run keeps one; null otherwise.
    ReferenceStore* reference_store() { return reference_store_ ? &*reference_store_ : nullptr; }
    // What a reference render of the case depends on: its key in the store.
    std::string reference_key(const LabCases& lab, const GradeCase& c);

    const GradeOptions& options;
    const std::filesystem::path out, kit, bin;
    GradeReport report;
    std::vector<LabCases> labs;
    std::vector<bool> live;  // per lab: against its reference rendered in this run, else the committed goldens
    LabRunner student, reference;
    DiagnoseCases diagnose = DiagnoseCases::Off;  // the options' choice, its default resolved for this run
    int mistake_store_hits = 0;  // of the store's hits, the known mistakes' pictures (grade/mistake_pictures.h)

private:
    // Which labs and cases the options choose, the hidden ones drawn (case_selection.cpp).
    void load_labs();
    // An instructor's mistake in a case file stops grading with one line, before any student code runs: a TODO id
    // no lab has, a parameter the lab does not have or a value out of its range (hidden cases as drawn included).
    void check_cases() const;
    // The allow-lists of a lab run and of a build, the uid, and which walls this machine allows (walls.cpp).
    void set_up_sandbox(const std::filesystem::path& student_bin, const std::filesystem::path& student_root,
                        const std::filesystem::path& build_dir);

    const std::function<void(const GradeProgress&)>& progress_;
    const RunPurpose purpose_;
    const std::chrono::steady_clock::time_point start_;
    SandboxPolicy policy_;        // running a student's lab: what every lab may read
    std::map<std::string, SandboxPolicy> lab_policies_;  // and each lab's own: policy_ with its binary and folder
    SandboxPolicy build_policy_;  // building a submission's labs
    SandboxSupport support_;
    std::optional<UidLease> uid_lease_;  // a root grader's uid for student code, held until the run ends
    // Live references on disk, where the walls keep student code from them; its key's context (kit, driver, environment)
    // and each reference binary's fingerprint, computed once.
    std::optional<ReferenceStore> reference_store_;
    std::string reference_context_;
    std::map<std::string, std::string> solution_fingerprints_;
    int references_rendered_ = 0;
    int total_ = 0;
    std::map<std::string, bool> kit_cpp_;  // cpp_is_the_kits, worked out once per lab at set-up
    // Last: their processes end before the walls (policy_, support_) and the uid lease they run under go.
    std::unique_ptr<ServedLab> served_student_, served_reference_;
};

}  // namespace gsv
