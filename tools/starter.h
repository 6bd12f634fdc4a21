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

// True for a C++ file (.cpp, .h): what a lab's build compiles, so an edit of it needs a build to be seen.
bool is_cpp_file(const std::string& file);

// A known mistake in C++ (tests/mutants/<lab>.json, "cpp_mutants"): `find` replaced in its TODO's solution block.
struct CppMistake {
    std::string name, todo, file, find, replace;
};

// The environment variable that picks, in a build of switch_cpp_blocks' sources, the mistake its C++ makes: a
// CppMistake's name, or "<TODO> left undone"; unset or anything else, the solution.
inline constexpr const char* kKnownMistakeVariable = "GSV_KNOWN_MISTAKE";

// A solution file with each TODO's C++ block made a choice at run time (the solution, the starter's, and each of
// `mistakes` in that block), so one build holds them all; they call known_mistake_is(), which
// known_mistake_switch_source() defines. Throws gsv::Error naming a mistake whose find is not in its block.
std::string switch_cpp_blocks(const std::string& solution_text, const std::string& file, const std::vector<CppMistake>& mistakes);
std::string known_mistake_switch_source();

// The lab's C++ mistakes in tests/mutants/<lab>.json (its "cpp_mutants", and with `stateful` its "cpp_stateful"
// variants); none where the kit has no such file (the student edition).
std::vector<CppMistake> cpp_mistakes(const std::filesystem::path& kit_root, const std::string& lab, bool stateful = false);

// solutions/<lab_dir> with every C++ TODO block switched between the solution, the starter's and `mistakes`
// (switch_cpp_blocks), into `to`, with the switch's own source (known_mistake_switch.cpp): what a lab's "_mistakes"
// build compiles (cmake/labs.cmake), and the tests' switched submissions. Returns the files written.
int write_switched_lab(const std::filesystem::path& kit_root, const std::string& lab_dir, const std::vector<CppMistake>& mistakes,
                       const std::filesystem::path& to);

struct StarterFileResult {
    std::filesystem::path solution, starter;
    bool up_to_date = false;
};

// For every file under solutions/<lab>/ the matching file under labs/<lab>/: generated (write) or
// compared (check). Returns one entry per file.
std::vector<StarterFileResult> sync_starters(const std::filesystem::path& kit_root, bool write);

}  // namespace gsv
