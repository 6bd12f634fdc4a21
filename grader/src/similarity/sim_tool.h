#pragma once
// Debian's similarity-tester (Dick Grune's SIM 3.0.2, `apt-get install similarity-tester`), the token matcher the
// copied-work report is built on: it is made for finding copied code among students' programs, compares each file
// with each (-e), keeps a group of "old" files that are only compared with (-S: the template), and reads every
// identifier as one token, so renamed variables still match. GLSL is read by sim_c: GLSL's lexical grammar is C's
// (its comments, preprocessor lines, numbers and operators), and SIM has no lexer of its own for it; C++ by sim_c++.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace gsv {

// What an instructor without the tool is told, in one line.
inline constexpr const char* kSimInstall =
    "needs Debian's similarity-tester (sim_c, sim_c++): sudo apt-get install similarity-tester (scripts/setup.sh installs it)";

enum class SimLanguage { C, Cpp };

// A run of tokens SIM found in two files: the lines of the first and of the second that hold it (1-based,
// inclusive) and its length in tokens.
struct SimRun {
    std::string file_a, file_b;
    int a_first = 0, a_last = 0, b_first = 0, b_last = 0;
    int tokens = 0;
};

struct SimOutput {
    std::map<std::string, int> tokens_of;  // each input file's number of tokens, as SIM counted them
    std::vector<SimRun> runs;
};

// sim_c or sim_c++ on PATH; throws gsv::Error with kSimInstall where it is not.
std::filesystem::path find_sim(SimLanguage language);

// SIM's -n output ("File NAME: N tokens, ..." lines, then "A: line 2-9 |B: line 4-11 [37]" per run) read back;
// throws gsv::Error naming a file SIM could not open.
SimOutput read_sim_output(const std::string& text);

// Runs SIM in `working_dir` on files named relative to it (no spaces: SIM's output is split at them, so callers
// stage their files under plain names), each ending in a newline (SIM numbers an unterminated last line 0).
// `options` come before the files; `old_files` follow a "/" (SIM's old group). Throws gsv::Error with SIM's output
// where it fails.
SimOutput run_sim(SimLanguage language, const std::vector<std::string>& options, const std::vector<std::string>& new_files,
                  const std::vector<std::string>& old_files, const std::filesystem::path& working_dir);

}  // namespace gsv
