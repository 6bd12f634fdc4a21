#pragma once
// Reruns after a fix (--regrade-only changed): each lab of a run is graded again only where something its grade
// depends on changed since the last run in the same --out, and the other labs keep that run's rows. What a lab's grade
// depends on, as one fingerprint per lab (recorded in <out>/inputs.json after every run):
// - the student's work: the submission's labs/<lab folder> (names, kinds and bytes), or the kit's own labs/;
// - the kit: the lab's case file, hidden cases, goldens and solution, and what every lab shares (shaders/, common/,
//   support/, data/, reference/, cmake/, grader/submission/);
// - the build: the kit's <lab> and <lab>_solution binaries and gsv-grade itself, by their bytes;
// - the run: the seed and every option that changes a grade (mode, timing, hidden cases, profile, cases, TODO, limits).
// A fix to one lab's case file regrades that lab for every student; a fix to the grader or the framework, every lab.
#include "grader/src/grade/grade.h"

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gsv {

using LabInputs = std::map<std::string, std::string>;  // lab -> fingerprint of what its grade depends on

// The labs a run grades: options.labs, or every lab with a case file in the kit.
std::vector<std::string> labs_of_run(const GradeOptions& options);
// Each lab's fingerprint; `seed` is the run's (options.seed, or the one it will draw); `grader` is gsv-grade's path.
LabInputs lab_inputs(const GradeOptions& options, const std::vector<std::string>& labs, std::uint64_t seed,
                     const std::filesystem::path& grader);
// <out>/inputs.json, written after a run with the fingerprints of the labs it graded or kept.
void write_lab_inputs(const std::filesystem::path& out, const LabInputs& inputs);

struct RegradePlan {
    std::vector<std::string> regrade, keep;  // labs to grade now; labs whose last rows stand
    std::optional<GradeReport> earlier;      // the last run's report, when there is one to keep rows from
    std::string note;                        // why every lab is graded, when that is so ("no earlier run in ...")
};
// What --regrade-only changed does in `out`: labs whose fingerprint is the one recorded there, and whose rows the last
// report holds, are kept; the others graded. No record, an unreadable one, or a report that does not read back: every
// lab graded, and the note says why.
RegradePlan plan_regrade(const std::filesystem::path& out, const LabInputs& now);
// The options of the run that grades `plan.regrade` only: those labs, and of --cases the names they have (a kept lab's
// case would be refused as unknown). None when none of the asked cases is in those labs: nothing to grade.
std::optional<GradeOptions> options_for_regrade(const GradeOptions& options, const RegradePlan& plan);
// The last run's rows of the kept labs and this run's of the regraded ones, in lab order, with the run's set-up from
// `fresh`; `regraded`/`kept` recorded in the report.
GradeReport merge_regraded(const GradeReport& earlier, const GradeReport& fresh, const RegradePlan& plan,
                           const std::vector<std::string>& labs);

}  // namespace gsv
