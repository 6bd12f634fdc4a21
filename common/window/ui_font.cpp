#include "common/window/ui_font.h"

#include <cstdlib>

namespace gsv {

std::vector<std::filesystem::path> ui_font_candidates() {
    std::vector<std::filesystem::path> paths;
    if (const char* chosen = std::getenv("GSV_UI_FONT"); chosen && *chosen) paths.emplace_back(chosen);
    for (const char* path : {
             "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",  // Debian, Ubuntu
             "/usr/share/fonts/dejavu-sans-fonts/DejaVuSans.ttf",  // Fedora
             "/usr/share/fonts/TTF/DejaVuSans.ttf",                // Arch
             "/Library/Fonts/Arial Unicode.ttf",                   // macOS
             "/System/Library/Fonts/Supplemental/Arial.ttf",
             "C:/Windows/Fonts/segoeui.ttf",                       // Windows
             "C:/Windows/Fonts/arial.ttf",
         })
        paths.emplace_back(path);
    return paths;
}

std::optional<std::filesystem::path> find_ui_font() {
    std::error_code ec;
    for (const auto& path : ui_font_candidates())
        if (std::filesystem::is_regular_file(path, ec)) return path;
    return std::nullopt;
}

}  // namespace gsv
