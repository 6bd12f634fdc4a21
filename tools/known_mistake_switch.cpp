// One build of a lab that makes any of its known C++ mistakes, picked at run time (tools/starter.h): a C++ mistake's
// picture needs a build, and one build for all of them is what the kit can afford.
#include "tools/starter.h"

#include "common/app/kit_layout.h"
#include "common/core/error.h"
#include "common/io/json.h"

#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace gsv {
namespace {

std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

}  // namespace

bool is_cpp_file(const std::string& file) {
    const auto ends = [&](const std::string& tail) {
        return file.size() >= tail.size() && file.compare(file.size() - tail.size(), tail.size(), tail) == 0;
    };
    return ends(".cpp") || ends(".h");
}

std::string switch_cpp_blocks(const std::string& text, const std::string& file, const std::vector<CppMistake>& mistakes) {
    std::istringstream in(text);
    std::string out = "bool known_mistake_is(const char* name);\n", line, todo, solution, starter;
    enum { Both, Solution, Starter } state = Both;
    while (std::getline(in, line)) {
        const auto marker = line.find_first_not_of(" \t");
        const std::string t = marker == std::string::npos ? "" : line.substr(marker);
        if (t.rfind("//@solution", 0) == 0) {
            todo = t.substr(12);
            solution.clear();
            starter.clear();
            state = Solution;
        } else if (t == "//@starter") {
            state = Starter;
        } else if (t == "//@end") {
            out += "if (known_mistake_is(" + quoted(todo + " left undone") + ")) {\n" + starter + "}";
            for (const CppMistake& m : mistakes) {
                if (m.file != file || m.todo != todo) continue;
                std::string made = solution;
                const auto at = made.find(m.find);
                if (at == std::string::npos)
                    throw Error(file + ": the C++ mistake '" + m.name + "': its find is not in " + todo + "'s block");
                made.replace(at, m.find.size(), m.replace);
                out += " else if (known_mistake_is(" + quoted(m.name) + ")) {\n" + made + "}";
            }
            out += " else {\n" + solution + "}\n";
            state = Both;
        } else if (state == Solution) {
            solution += line + "\n";
        } else if (state == Starter) {
            starter += line.substr(line.find("//") + 2) + "\n";
        } else {
            out += line + "\n";
        }
    }
    return out;
}

std::string known_mistake_switch_source() {
    return std::string("// Which known mistake this build makes (tools/known_mistake_switch.cpp): none unless ") + kKnownMistakeVariable +
           " names one.\n#include <cstdlib>\n#include <cstring>\nbool known_mistake_is(const char* name) {\n"
           "    const char* chosen = std::getenv(\"" + kKnownMistakeVariable + "\");\n"
           "    return chosen && std::strcmp(chosen, name) == 0;\n}\n";
}

std::vector<CppMistake> cpp_mistakes(const fs::path& kit_root, const std::string& lab, bool stateful) {
    const fs::path file = KitLayout{kit_root}.tests() / "mutants" / (lab + ".json");
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) return {};
    const Json spec = read_json_file(file);
    std::vector<CppMistake> out;
    for (const char* list : {"cpp_mutants", "cpp_stateful"}) {
        if (std::string(list) == "cpp_stateful" && !stateful) continue;
        if (const Json* entries = spec.find(list))
            for (const Json& m : entries->as_array())
                out.push_back({m.string_at("name"), m.string_at("todo"), m.string_at("file"), m.string_at("find"), m.string_at("replace")});
    }
    return out;
}

int write_switched_lab(const fs::path& kit_root, const std::string& lab_dir, const std::vector<CppMistake>& mistakes,
                       const fs::path& to) {
    const fs::path from = KitLayout{kit_root}.solutions() / lab_dir;
    fs::create_directories(to);
    int written = 0;
    const auto write = [&](const fs::path& path, const std::string& text) {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        if (!out || !(out << text)) throw Error("cannot write '" + path.string() + "'");
        ++written;
    };
    for (const auto& e : fs::directory_iterator(from)) {
        if (!e.is_regular_file()) continue;
        std::ifstream in(e.path(), std::ios::binary);
        std::stringstream text;
        text << in.rdbuf();
        const std::string name = e.path().filename().string();
        write(to / name, is_cpp_file(name) ? switch_cpp_blocks(text.str(), name, mistakes) : text.str());
    }
    write(to / "known_mistake_switch.cpp", known_mistake_switch_source());
    return written;
}

}  // namespace gsv
