#include "common/window/scripted_keys.h"

#include "common/core/error.h"
#include "common/core/number_text.h"

#include <GLFW/glfw3.h>

#include <cctype>
#include <cmath>
#include <utility>

namespace gsv {
namespace {

int key_code(const std::string& name) {
    if (name.size() == 1) {
        const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
        if (c >= 'A' && c <= 'Z') return GLFW_KEY_A + (c - 'A');
        if (c >= '0' && c <= '9') return GLFW_KEY_0 + (c - '0');
    }
    static const std::pair<const char*, int> named[] = {
        {"Tab", GLFW_KEY_TAB},     {"Space", GLFW_KEY_SPACE}, {"Esc", GLFW_KEY_ESCAPE}, {"Left", GLFW_KEY_LEFT},
        {"Right", GLFW_KEY_RIGHT}, {"Up", GLFW_KEY_UP},       {"Down", GLFW_KEY_DOWN},
    };
    for (const auto& [text, code] : named)
        if (name == text) return code;
    if (name.size() >= 2 && name[0] == 'F') {
        const std::optional<double> n = parse_finite_number(name.substr(1));
        if (n && *n >= 1 && *n <= 12 && *n == std::floor(*n)) return GLFW_KEY_F1 + static_cast<int>(*n) - 1;
    }
    return -1;
}

}  // namespace

std::vector<ScriptedKey> parse_scripted_keys(const std::vector<std::string>& entries) {
    std::vector<ScriptedKey> keys;
    for (const auto& entry : entries) {
        const auto at = entry.rfind('@');
        const int code = at == std::string::npos ? -1 : key_code(entry.substr(0, at));
        const std::optional<double> frame = at == std::string::npos ? std::nullopt : parse_finite_number(entry.substr(at + 1));
        if (code < 0 || !frame || *frame < 1 || *frame > 1e6 || *frame != std::floor(*frame))
            throw Error("option --press '" + entry + "' needs KEY@FRAME, a key (a letter or digit, Tab, Space, Esc, Left, "
                        "Right, Up, Down, F1-F12) and a frame from 1");
        keys.push_back({code, static_cast<int>(*frame)});
    }
    return keys;
}

}  // namespace gsv
