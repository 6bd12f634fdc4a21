#pragma once
// The panel's font: a scalable one (DejaVu Sans, Debian's fonts-dejavu-core) looked up where each platform keeps its
// fonts, so the panel stays sharp at any size a projector needs.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gsv {

// The first of the candidates that exists; GSV_UI_FONT (a .ttf path) goes first when set.
std::optional<std::filesystem::path> find_ui_font();
// The paths find_ui_font tries, in order: for a message that names them.
std::vector<std::filesystem::path> ui_font_candidates();

}  // namespace gsv
