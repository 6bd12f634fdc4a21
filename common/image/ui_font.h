#pragma once
// The one font the kit writes with: legends and comparison labels on CPU images (common/image/text.h) and the
// window panel. DejaVu Sans where it is installed (Debian: fonts-dejavu-core), else a system sans-serif.
#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

// Where the font is looked for, in order: $GSV_FONT when set, DejaVu Sans in the usual Linux, Homebrew and
// user folders, then macOS's and Windows' own sans-serif fonts.
std::vector<std::filesystem::path> ui_font_candidates();

// The first candidate that is a file. Throws gsv::Error naming every path tried.
std::filesystem::path find_ui_font();

}  // namespace gsv
