#include "common/image/ui_font.h"

#include "common/core/error.h"

#include <cstdlib>
#include <system_error>

namespace fs = std::filesystem;

namespace gsv {

std::vector<fs::path> ui_font_candidates() {
    std::vector<fs::path> paths;
    if (const char* chosen = std::getenv("GSV_FONT"); chosen && *chosen) paths.emplace_back(chosen);
    // Debian and Ubuntu, Fedora, Arch, then Homebrew's and a user's own install of the same font.
    for (const char* dir : {"/usr/share/fonts/truetype/dejavu", "/usr/share/fonts/dejavu-sans-fonts",
                            "/usr/share/fonts/dejavu", "/usr/share/fonts/TTF", "/usr/local/share/fonts",
                            "/opt/homebrew/share/fonts"})
        paths.push_back(fs::path(dir) / "DejaVuSans.ttf");
    if (const char* home = std::getenv("HOME"); home && *home) {
        paths.push_back(fs::path(home) / ".local/share/fonts/DejaVuSans.ttf");
        paths.push_back(fs::path(home) / "Library/Fonts/DejaVuSans.ttf");
    }
    // macOS has no DejaVu unless installed; its own sans-serif faces are TrueType (a .ttc holds several).
    paths.emplace_back("/System/Library/Fonts/Supplemental/Arial.ttf");
    paths.emplace_back("/Library/Fonts/Arial.ttf");
    paths.emplace_back("/System/Library/Fonts/Helvetica.ttc");
    const char* windows = std::getenv("WINDIR");
    const fs::path fonts = fs::path(windows && *windows ? windows : "C:\\Windows") / "Fonts";
    paths.push_back(fonts / "segoeui.ttf");
    paths.push_back(fonts / "arial.ttf");
    return paths;
}

fs::path find_ui_font() {
    std::string tried;
    for (const fs::path& path : ui_font_candidates()) {
        std::error_code ec;
        if (fs::is_regular_file(path, ec)) return path;
        tried += (tried.empty() ? "" : ", ") + path.string();
    }
    throw Error("no font to write text with (tried " + tried +
                "); install DejaVu Sans (Debian: apt-get install fonts-dejavu-core) or set GSV_FONT to a .ttf file");
}

}  // namespace gsv
