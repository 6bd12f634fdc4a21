#pragma once
// Key presses given on the command line (--press U@5): a lecturer's scripted demo, and the way the window tests
// press keys without an X input tool.
#include <string>
#include <vector>

namespace gsv {

struct ScriptedKey {
    int key = 0;    // a GLFW key code
    int frame = 0;  // pressed just before this frame (1 = the first)
};

// "U@5", "F1@10", "Tab@3", "Right@7": throws gsv::Error naming the bad entry and the key names known.
std::vector<ScriptedKey> parse_scripted_keys(const std::vector<std::string>& entries);

}  // namespace gsv
