#pragma once
// The kit's known mistakes of a lab, as a diagnosis uses them: the classic mistakes the mutation tests prove the cases
// catch (tests/mutants/<lab>.json, "mutants"), each an edit of the reference solution with its TODO, what it says to
// a student who made it ("says": the idea missed, never the code) and the part of the lab's sheet that teaches it
// ("sheet": a heading of labs/<lab_dir>/README.md, or "TODO table"). The lists are the instructor's (their edits are
// answers): a kit without tests/ (the student edition) has none. An instructor adds a mistake with one entry there.
#include "common/app/known_mistake_pictures.h"
#include "common/io/json.h"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace gsv {

struct KnownMistake {
    std::string name;  // the kit's own name of it, for the instructor
    std::string todo, says, sheet;
    Json edit;         // the entry: {"file", "find", "replace"} or "edits"
    // Not a mistake but a TODO left as the starter has it (its blocks in `files` the starter's): a TODO whose starter
    // draws no magenta (a pass-through) is told apart from a mistake in it by its pictures, and called "not started".
    bool not_started = false;
    std::vector<std::string> files;
    StarterBlocks starter;  // not started: the starter's code in `files`
    // Made in C++: its pictures come from the lab's _mistakes build (cmake/labs.cmake) with GSV_KNOWN_MISTAKE set to
    // `switch_name` (its name, or "<TODO> left undone"), not from edited shaders.
    bool cpp = false;
    std::string switch_name = {};
};

struct KnownMistakes {
    std::string lab, lab_dir;
    // The GLSL mistakes (their pictures need no build: the solution's binary runs the edited shaders), then the C++ ones
    // ("cpp_mutants": one build holds them all, the lab's _mistakes), then each TODO not started.
    std::vector<KnownMistake> mistakes;
};

// The lab's known mistakes; none (an empty list) where the kit has no tests/mutants/<lab>.json. Throws gsv::Error
// naming the file and the entry where one is malformed or has no "says".
KnownMistakes known_mistakes(const std::filesystem::path& kit_root, const std::string& lab);

// Whether the student's copy of the lab (`student_folder`, its files by the solution's names) still holds `todo`'s
// starter code: in some file of the TODO, after the line that names it (TODO(L04-T4)), the starter's lines as the
// solution's //@starter block has them, each line's surrounding white space aside. Where a TODO's pictures are a known
// mistake's too (a pass-through starter), its source tells "not started" from the mistake.
// The lists' name of each id the kit ships for the lab's mistakes (grader/golden/<lab>/mistakes.json holds them in the
// lists' order): what a self-check names, told in the instructor's words. Empty where either is missing.
std::map<std::string, std::string> list_names_of_shipped(const std::filesystem::path& kit_root, const std::string& lab);

StarterBlocks starter_blocks(const std::filesystem::path& kit_root, const std::string& lab_dir, const std::string& todo,
                             const std::vector<std::string>& files);
bool still_starter(const std::filesystem::path& kit_root, const std::string& lab_dir, const std::filesystem::path& student_folder,
                   const std::string& todo, const std::vector<std::string>& files);

}  // namespace gsv
