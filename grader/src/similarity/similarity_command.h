#pragma once
// `gsv-grade similarity`: a class's copied work (copied_code.h, copied_pictures.h) into similarity.html and
// similarity.csv in the batch's --out.
#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

extern const char* const kSimilarityUsage;

struct SimilarityCommand {
    std::filesystem::path kit_root;     // default: the kit gsv-grade was built from
    std::filesystem::path submissions;  // --batch: one folder per student
    std::filesystem::path out_dir;      // --out: the batch's (its pictures), where the report goes
    std::vector<std::string> labs;
    int min_run = 0;                    // 0: kMinRun
    bool help = false;
};

// The arguments after `gsv-grade similarity`. Throws gsv::Error with one line naming the option or value at fault.
SimilarityCommand read_similarity_command(const std::vector<std::string>& args, const std::filesystem::path& default_kit);

// Runs `gsv-grade similarity ARGS...`: the report written and a summary on stdout. Returns gsv-grade's exit status:
// 0 written (whatever it found), 2 a usage error, input that cannot be read, or similarity-tester missing (one line
// saying how to install it).
int run_similarity_command(const std::vector<std::string>& args, const std::filesystem::path& default_kit);

}  // namespace gsv
