#pragma once
// Numbers a lab hands the grader besides its image (lab 05's particle buffers), and the file render mode
// stores each in beside the PNG: `<png stem>.<name>.f32`, count x components little-endian float32 and
// nothing else (the count and components are in the lab's JSON report, which lists the files).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

// Read back after the last frame: `count` elements of `components` floats each, element-major.
struct DataArray {
    std::string name;  // "positions": names the file and the grader's message
    int components = 4;
    std::vector<float> values;
    std::size_t count() const { return components > 0 ? values.size() / static_cast<std::size_t>(components) : 0; }
};

inline constexpr int kMaxArrayComponents = 16;
inline constexpr std::size_t kMaxArrayNameBytes = 40;
inline constexpr std::size_t kMaxArrays = 16;
// All the arrays of one render together (256 MiB): the most the grader reads back from one run.
inline constexpr std::uint64_t kMaxArrayFloats = std::uint64_t(64) << 20;

// [a-z0-9_]+, at most kMaxArrayNameBytes: the name becomes part of a file name and of messages.
bool valid_array_name(const std::string& name);

// At most kMaxArrays arrays of kMaxArrayFloats values in all, names valid and distinct, 1..kMaxArrayComponents
// components, a whole number of elements. Throws gsv::Error
// naming the array: what a lab hands in is the lab's own bug when malformed (run_lab prefixes the lab's id).
void check_data_arrays(const std::vector<DataArray>& arrays);

// Where render mode stores array `name` beside image `png`: out/phong.png -> out/phong.positions.f32.
std::filesystem::path data_array_path(const std::filesystem::path& png, const std::string& name);

// Throws gsv::Error "cannot write array file '<path>': <why>".
void write_f32_file(const std::filesystem::path& path, const std::vector<float>& values);
// Exactly `floats` values. The file's size is checked before anything is allocated, so a count that lies
// costs nothing. Throws gsv::Error "array file '<path>': <why>".
std::vector<float> read_f32_file(const std::filesystem::path& path, std::uint64_t floats);

}  // namespace gsv
