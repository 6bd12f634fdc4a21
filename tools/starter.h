#pragma once
// Starter code is generated from the annotated solution, so the two cannot drift apart.
//
// In a solution file (C++ or GLSL, both use // comments):
//     // TODO(L01-T4): what to do and why            <- kept in both
//     //@solution L01-T4
//         ...the reference code...                   <- solution only
//     //@starter
//     //    return kNotDone;                         <- starter only: the leading // is removed
//     //@end
#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace gsv {

struct StarterText {
    std::string text;
    std::vector<std::string> todo_ids;  // in order of appearance, e.g. L01-T1, L01-T2
};

// Throws gsv::Error "file:line: ..." on a malformed block (unterminated, nested, missing id, a starter
// line that is not a comment, an id that does not match L<lab>-T<n>). With `only_todo`, only that TODO's blocks
// become the starter's and the others keep the solution: the reference with one TODO left undone.
StarterText make_starter(const std::string& solution_text, const std::string& file_name, const std::string& only_todo = "");

// The reference with every TODO but those in `done` left as the starter has it: a student part way through the lab.
StarterText make_partial_starter(const std::string& solution_text, const std::string& file_name, const std::set<std::string>& done);

struct StarterFileResult {
    std::filesystem::path solution, starter;
    bool up_to_date = false;
};

// For every file under solutions/<lab>/ the matching file under labs/<lab>/: generated (write) or
// compared (check). Returns one entry per file.
std::vector<StarterFileResult> sync_starters(const std::filesystem::path& kit_root, bool write);

}  // namespace gsv
