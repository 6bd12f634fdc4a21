#pragma once
// gsv-grade's command line (grader/README.md lists every option), read into what each way of running it needs: one
// submission (or the kit's own labs/), a batch of them, or the goldens rewritten.
#include "grader/src/grade/grade.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

extern const char* const kGradeUsage;

struct GradeCommand {
    GradeOptions options;
    bool update_mistakes = false;  // rewrite the shipped mistake pictures (grader/src/update/mistake_update.h)
    bool update_goldens = false;  // rewrite the committed goldens instead of grading (grader/src/update/golden_update.h)
    double fail_under = -1;       // exit kGradeFailed under this share of the maximum score; < 0: no gate
    bool quiet = false;           // no progress and no table
    // --regrade-only changed: grade only the labs whose inputs changed since the last run in --out, keep the others'
    // rows (grader/src/grade/regrade.h).
    bool regrade_only_changed = false;
    std::filesystem::path batch;  // a folder of submissions; empty: one
    int workers = 2;
    std::string shard;            // K/N of a batch
    std::filesystem::path roster;
    std::vector<std::string> pass_through;  // the options each submission's run in a batch gets too
    // Whether --passed-pictures and --keep-build were given: a batch's runs default to thumbnails and no build kept.
    bool passed_pictures_given = false, keep_build_given = false;
};

enum class GradeAction { Grade, Help, Version };

// Reads argv into `command`, which holds the defaults, and checks the options against one another (and reads the seed
// from GSVGRADE_SEED where none is given). --help and --version end the reading where they stand. Throws gsv::Error
// naming the option; what was read before it stays in `command`.
GradeAction read_grade_command(int argc, char** argv, GradeCommand& command);

// A --seed: a whole number, or gsv::Error naming the text.
std::uint64_t parse_seed(const std::string& text);

}  // namespace gsv
