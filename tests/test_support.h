#pragma once
// Small helpers the test files share.
#include "common/core/error.h"

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

namespace gsv::test {

// A fresh folder per test, removed with everything in it afterwards; unique even when ctest runs test
// cases in parallel processes.
class TempDir {
public:
    TempDir() {
        static std::atomic<int> counter{0};
        const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
        root_ = std::filesystem::temp_directory_path() /
                ("gsv_test_" + std::to_string(stamp) + "_" + std::to_string(counter++));
        std::filesystem::create_directories(root_);
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(root_, ignored);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    std::filesystem::path path(const std::filesystem::path& relative = {}) const {
        return (root_ / relative).lexically_normal();
    }
    // Writes `content` to a file in the folder (creating subfolders) and returns its path.
    std::filesystem::path write(const std::filesystem::path& relative, const std::string& content) const {
        const std::filesystem::path file = root_ / relative;
        std::filesystem::create_directories(file.parent_path());
        std::ofstream(file, std::ios::binary) << content;
        return file;
    }

private:
    std::filesystem::path root_;
};

inline std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The message of the gsv::Error that `action` throws.
template <typename Action>
std::string gsv_error_message(Action&& action) {
    try {
        action();
    } catch (const gsv::Error& e) {
        return e.what();
    }
    return "<no gsv::Error thrown>";
}

// How many times `needle` occurs in `haystack`, overlaps included.
inline std::size_t count_of(const std::string& haystack, const std::string& needle) {
    std::size_t count = 0;
    for (auto at = haystack.find(needle); at != std::string::npos; at = haystack.find(needle, at + 1)) ++count;
    return count;
}

// The cell of `row` under the column `name` of `header` (a sweep's CSV), as a number; throws gsv::Error
// naming the column when the header has none of that name.
inline double csv_value(const std::string& header, const std::string& row, const std::string& name) {
    std::stringstream h(header), r(row);
    std::string key, cell;
    while (std::getline(h, key, ',') && std::getline(r, cell, ','))
        if (key == name) return std::stod(cell);
    throw Error("no column " + name + " in " + header);
}

// Replaces the first `from` in `file` with `to` (breaking a copied shader on purpose); throws gsv::Error
// when `from` is not there, so a test cannot pass by editing nothing.
inline void replace_in_file(const std::filesystem::path& file, const std::string& from, const std::string& to) {
    std::string text = read_text(file);
    const auto at = text.find(from);
    if (at == std::string::npos) throw Error("'" + from + "' is not in " + file.string());
    text.replace(at, from.size(), to);
    std::ofstream(file, std::ios::binary) << text;
}

// The shared shaders/ and one reference lab (solutions/<lab_dir>) of the kit at `source` copied under
// `root`, with an empty data/ for the caller to fill with what the lab reads: a kit to break files in, for
// a lab binary run with GSV_ROOT=root.
inline void copy_lab_kit(const std::filesystem::path& source, const std::filesystem::path& root, const std::string& lab_dir) {
    namespace fs = std::filesystem;
    fs::create_directories(root);
    fs::copy(source / "shaders", root / "shaders", fs::copy_options::recursive);
    fs::create_directories(root / "solutions");
    fs::copy(source / "solutions" / lab_dir, root / "solutions" / lab_dir, fs::copy_options::recursive);
    fs::create_directories(root / "data");
}

}  // namespace gsv::test
