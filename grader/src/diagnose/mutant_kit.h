#pragma once
// Known-wrong and known-right edits of a lab's reference (tests/mutants/<lab>.json: "mutants", each with the cases
// it "must_fail", "variants" that must pass, "faults" with their own status), made into a kit the grader grades as a
// student's: the edited solutions/<lab_dir> beside the kit's own shaders/ and data/, and a copy of the built
// <lab>_solution run as the student's <lab> (shader edits need no build). The mutation tests (tests/) and the margin
// table (gsv-margins) grade them the same way.
#include "common/io/json.h"
#include "tools/starter.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace gsv {

// tests/mutants/<lab>.json of the kit; throws gsv::Error naming the file when it is missing or malformed.
Json read_mutant_spec(const std::filesystem::path& kit_root, const std::string& lab);
// The labs with a tests/mutants/<lab>.json, in order; none in a kit without tests/ (the student edition).
std::vector<std::string> labs_with_mutants(const std::filesystem::path& kit_root);

// Applies one {"find", "replace"} edit (or each of "edits") to the file `edit` names ("file") in `lab_folder`;
// "@KIT@" in a replacement becomes `kit_root`. Throws gsv::Error when a find is not in the file.
void apply_mutant_edits(const std::filesystem::path& lab_folder, const Json& edit, const std::filesystem::path& kit_root);

// A file of the kit (or of a copy of a lab) as text; throws gsv::Error naming it when it cannot be read.
std::string read_text_file(const std::filesystem::path& file);

// is_cpp_file (tools/starter.h): a C++ edit, which the copied binary would not see, needs a build.

// In `dir` (created): kit/ with shaders/ and data/ linked to `kit_root`'s and solutions/<lab_dir> copied and
// changed by `edit`, and bin/<lab>, a copy of `bin_dir`/<binary> (default <lab>_solution; <lab>_mistakes for a C++
// mistake). Grade it with GradeOptions::student_bin_dir = dir/bin and student_root = dir/kit.
void make_edited_kit(const std::filesystem::path& dir, const std::filesystem::path& kit_root, const std::filesystem::path& bin_dir,
                     const std::string& lab, const std::string& lab_dir,
                     const std::function<void(const std::filesystem::path&)>& edit, const std::string& binary = "");
// The same with one edit of the spec (a mutant, variant or fault); refuses a C++ edit, naming it.
void make_edited_kit(const std::filesystem::path& dir, const std::filesystem::path& kit_root, const std::filesystem::path& bin_dir,
                     const std::string& lab, const std::string& lab_dir, const Json& edit);

}  // namespace gsv
