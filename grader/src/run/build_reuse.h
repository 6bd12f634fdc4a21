#pragma once
// A lab compiled only where its C++ differs from one already built (grader/submission.h says the rules): its build
// inputs read and compared byte for byte, the kit's own binary, and a cache of earlier builds that keeps the inputs
// it was built from beside each binary, so a hit is proved by comparing them, never by a hash alone.
#include <filesystem>
#include <map>
#include <string>

namespace gsv {

// A lab folder's build inputs: each file's path relative to the folder, and its bytes.
using BuildInputs = std::map<std::string, std::string>;

// Whether the compiler may read this file: anything but what labs read at run time (shaders, network and case files,
// pictures, text). An unknown kind of file counts as an input, so that it can only cause a build, never skip one.
bool is_build_input(const std::filesystem::path& file);
// Throws gsv::Error naming a file it cannot read. Plain files only (the submission's copy holds nothing else).
BuildInputs read_build_inputs(const std::filesystem::path& lab_folder);
// Whether `binary` was built after the newest of `lab_folder`'s build inputs was last written.
bool binary_is_newer(const std::filesystem::path& binary, const std::filesystem::path& lab_folder);

// Earlier builds by their inputs and the kit build they linked against. Every fault (a folder that cannot be made or
// written, a full disk, a damaged entry) is one line in `note` and a miss; a damaged entry is removed.
class BuildCache {
public:
    BuildCache(std::filesystem::path folder, const std::filesystem::path& kit_build);
    // Copies the binary built from exactly these inputs to `to`; false when there is none.
    bool fetch(const std::string& lab, const BuildInputs& inputs, const std::filesystem::path& to, std::string& note) const;
    // Keeps `binary` as built from `inputs` (atomically: a half-written entry is never seen).
    void store(const std::string& lab, const BuildInputs& inputs, const std::filesystem::path& binary, std::string& note) const;

private:
    std::filesystem::path entry(const std::string& lab, const BuildInputs& inputs) const;
    std::filesystem::path folder_;
    std::string kit_stamp_;  // the kit build's libraries (path, size, time) and its build settings
};

}  // namespace gsv
