#pragma once
// Which files of a lab's folder its C++ build reads, and the fingerprint of those files: what the grader compares to
// reuse a build (grader/src/run/build_reuse.h) and what grader/starters.json records of each starter, written with the
// starters by gsv-make-starters.
#include <filesystem>
#include <map>
#include <string>

namespace gsv {

// Whether the compiler may read this file without anyone saying so: anything but what labs read at run time
// (shaders, network and case files, pictures, text). An unknown kind of file counts as an input, so that it can only
// cause a build, never skip one.
bool is_build_input(const std::filesystem::path& file);

// Each build input of the folder (its path relative to the folder) with the FNV-1a fingerprint of its bytes. Throws
// gsv::Error naming a file it cannot read.
std::map<std::string, std::string> build_input_fingerprints(const std::filesystem::path& lab_folder);

// grader/starters.json: each lab folder's starter C++ as build_input_fingerprints gives it, from the starters
// generated from solutions/ (gsv-make-starters --write). Where a lab's C++ is its starter's, the kit's own tests prove
// that its cases come out alike whatever ran before them in the same process (grader/src/grade/grade.cpp).
std::filesystem::path starter_manifest(const std::filesystem::path& kit_root);
// Whether the folder's C++ is byte for byte (by fingerprint) the starter's the manifest records for `lab_dir`; false
// without a manifest or a record.
bool is_starter_cpp(const std::filesystem::path& kit_root, const std::string& lab_dir, const std::filesystem::path& lab_folder);

}  // namespace gsv
