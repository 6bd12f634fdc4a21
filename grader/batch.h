#pragma once
// Grades a folder of submissions (one sub-folder each) with N workers: each submission is graded by a
// gsv-grade process of its own into <out>/<name>/, all with the same seed, then one class table.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

// How a batch hands each submission's gsv-grade its seed: an environment variable (not a GSV_ one, which student
// processes inherit), never the command line.
inline constexpr const char* kSeedVariable = "GSVGRADE_SEED";

struct BatchOptions {
    std::filesystem::path grader;       // the gsv-grade executable
    std::filesystem::path submissions;  // one folder per student
    std::filesystem::path out_dir;
    int workers = 2;
    std::uint64_t seed = 0;
    std::vector<std::string> pass_through;  // options given to every submission's run (--kit, --labs, ...)
};

struct BatchEntry {
    std::string name;
    bool graded = false;   // the run ended with a results.json
    double score = 0, max_score = 0;
    double seconds = 0;
    std::string problem;   // why it was not graded
};

std::vector<BatchEntry> grade_batch(const BatchOptions& options, void (*progress)(const BatchEntry&, int done, int total));
std::string class_csv(const std::vector<BatchEntry>& entries);
std::string class_table(const std::vector<BatchEntry>& entries);

}  // namespace gsv
