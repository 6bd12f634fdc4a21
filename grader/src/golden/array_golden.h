#pragma once
// Golden arrays, so the self-check (no reference binary) checks a lab's numbers too: a compact sample of the
// reference's array, grader/golden/<lab>/<case>.<name>.f32s, written by gsv-grade --update-goldens.
//
// The file, little-endian: the magic "GSVARR1\0" (8 bytes); uint32 count (elements of the whole array),
// components and samples; the samples' element indices (uint32, strictly ascending, each < count); then their
// values (samples x components float32, element-major).
//
// The sample: every element when count <= 4096; else the last 64, where lab 05 keeps sentinel particles that a
// missing bounds check would move, plus 4096 evenly strided among the elements before them (all of them when
// there are no more than 4096).
#include "grader/src/core/array_diff.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

inline constexpr std::size_t kGoldenStrided = 4096;
inline constexpr std::size_t kGoldenTail = 64;

// The element indices a golden keeps of an array of `count` elements, ascending.
std::vector<std::uint32_t> golden_sample_indices(std::size_t count);
// The sampled elements of `array`. Throws gsv::Error for an array too large for the format.
ExpectedArray sample_array(const DataArray& array);

// Throws gsv::Error "cannot write golden array '<path>': <why>".
void write_array_golden(const std::filesystem::path& path, const ExpectedArray& sample);
// Strict, as for any file: sizes are checked against the file before anything is allocated. Throws gsv::Error
// "golden array '<path>': <why>".
ExpectedArray read_array_golden(const std::filesystem::path& path, const std::string& name);

// grader/golden/<lab>/<case>.<name>.f32s under the kit.
std::filesystem::path array_golden_path(const std::filesystem::path& kit, const std::string& lab,
                                        const std::string& case_name, const std::string& name);
// The names of the arrays a case has goldens for, sorted (case names hold no '.', so the prefix is the case's).
std::vector<std::string> golden_array_names(const std::filesystem::path& kit, const std::string& lab,
                                            const std::string& case_name);

}  // namespace gsv
