#pragma once
// A lab's named cases are declared once, in its public case file grader/cases/<lab>.json: the grader grades
// its "cases" (each tagged with the TODO it checks), and "demos" are named views for lectures and slides that
// nothing grades. `<lab> list` prints both, `render --case NAME`, `--case` in a window and the window's C key
// apply them. The file sits outside labs/ because the grader takes only a submission's labs/: a student
// cannot change what a case sets.
#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

class Json;
class Params;

struct RenderCase {
    std::string name;
    std::string description;
    std::vector<std::string> settings;  // "name=value", applied over the defaults
    std::string todo;                   // "L02-T4" for a graded case; empty for a demo
    std::string where;                  // "grader/cases/lab02.json:17", for messages
};

// The name, description and settings of one case object: what the grader's cases share with the lab's.
// Throws gsv::Error naming the file and line when the name is not lower-case letters, digits and '-'.
RenderCase named_case_from(const Json& object);

// Every case of `file`, graded ones first, then the demos. Throws gsv::Error naming the file (and line) when it
// cannot be read, belongs to another lab, or names a case twice.
std::vector<RenderCase> read_case_file(const std::filesystem::path& file, const std::string& lab_id);
// The same, with each setting applied to a copy of the lab's `defaults`, so that a misspelt parameter or an
// out-of-range value is reported where it is written ("lab02.json:17:19: case 'long': unknown parameter 'lenght'").
std::vector<RenderCase> read_case_file(const std::filesystem::path& file, const std::string& lab_id,
                                       const Params& defaults);

}  // namespace gsv
