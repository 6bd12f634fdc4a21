#pragma once
// Where a lab finds its shaders and data. Never the working directory (the classic "shader not found"
// when a program is started from elsewhere): first $GSV_ROOT, then an installed copy beside the
// executable (<exe dir>/gsv-assets), then the source tree the binary was built from.
#include "common/app/kit_layout.h"

#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

class Assets {
public:
    // `lab_dir` is relative to the kit root, e.g. "labs/lab01_gooch" or "solutions/lab01_gooch".
    Assets(std::string lab_dir, const std::filesystem::path& executable);

    const std::filesystem::path& root() const { return root_; }
    std::filesystem::path lab_dir() const { return root_ / lab_dir_; }
    KitLayout layout() const { return {root_}; }
    std::filesystem::path shaders_dir() const { return layout().shaders(); }
    std::vector<std::filesystem::path> shader_include_dirs() const { return {lab_dir(), shaders_dir()}; }
    // A file in the lab's folder (shaders) or in data/; throws naming the file and where it looked.
    std::filesystem::path lab_file(const std::string& relative) const;
    std::filesystem::path data_file(const std::string& relative) const;
    // A shader stage file: the lab's folder first, then the shared shaders/ ("gsv/fullscreen.vert").
    std::filesystem::path shader_file(const std::string& relative) const;
    // A path the user typed (a File parameter): absolute, or relative to the working directory where
    // the command was typed, or else relative to data/ ("flows/vortex_street.flow" works from anywhere).
    // Throws one line naming the path and both places looked.
    std::filesystem::path user_file(const std::string& typed) const;

    static std::vector<std::filesystem::path> candidate_roots(const std::filesystem::path& executable);
    static std::filesystem::path executable_path(const char* argv0);

private:
    std::string lab_dir_;
    std::filesystem::path root_;
};

}  // namespace gsv
