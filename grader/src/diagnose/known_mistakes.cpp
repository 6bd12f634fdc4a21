#include "grader/src/diagnose/known_mistakes.h"

#include "common/app/kit_layout.h"
#include "common/core/error.h"
#include "grader/src/diagnose/mutant_kit.h"
#include "tools/starter.h"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace gsv {

KnownMistakes known_mistakes(const fs::path& kit_root, const std::string& lab) {
    KnownMistakes known;
    known.lab = lab;
    const fs::path file = KitLayout{kit_root}.tests() / "mutants" / (lab + ".json");
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) return known;
    const Json spec = read_mutant_spec(kit_root, lab);
    known.lab_dir = spec.string_at("lab_dir");
    for (const char* list : {"mutants", "cpp_mutants"}) {
        const Json* entries = spec.find(list);
        if (!entries) continue;
        for (const Json& m : entries->as_array()) {
            const std::string name = m.string_or("name", "");
            if (name.empty()) throw Error(file.string() + ": a mistake without a \"name\"");
            const bool cpp = is_cpp_file(m.string_or("file", ""));
            if (cpp != (std::string(list) == "cpp_mutants"))
                throw Error(file.string() + ": mistake '" + name + "' edits " + m.string_or("file", "no file") + ": a C++ mistake belongs in "
                            "\"cpp_mutants\", a shader's in \"mutants\"");
            const std::string says = m.string_or("says", "");
            if (says.empty()) throw Error(file.string() + ": mistake '" + name + "' has no \"says\" (what it tells a student who made it)");
            known.mistakes.push_back({name, m.string_at("todo"), says, m.string_or("sheet", "TODO table"), m, false, {}, {}, cpp, cpp ? name : ""});
        }
    }
    // Each TODO of the solution whose blocks are all in shaders, left as the starter has it.
    std::map<std::string, std::vector<std::string>> files_of;
    std::set<std::string> in_cpp;
    const fs::path folder = KitLayout{kit_root}.solutions() / known.lab_dir;
    std::vector<fs::path> sources;
    for (const auto& e : fs::directory_iterator(folder, ec))
        if (e.is_regular_file()) sources.push_back(e.path());
    std::sort(sources.begin(), sources.end());
    for (const fs::path& source : sources) {
        const std::string name = source.filename().string();
        for (const auto& id : make_starter(read_text_file(source), name).todo_ids) {
            if (is_cpp_file(name)) in_cpp.insert(id);
            if (std::find(files_of[id].begin(), files_of[id].end(), name) == files_of[id].end()) files_of[id].push_back(name);
        }
    }
    for (const auto& [todo, files] : files_of) {
        const bool cpp = in_cpp.count(todo) > 0;
        known.mistakes.push_back({todo + " not started", todo, "not started: its part is still the starter's", "TODO table",
                                  Json::object(), true, files, starter_blocks(kit_root, known.lab_dir, todo, files), cpp,
                                  cpp ? todo + " left undone" : ""});
    }
    return known;
}

std::map<std::string, std::string> list_names_of_shipped(const fs::path& kit_root, const std::string& lab) {
    const KnownMistakes known = known_mistakes(kit_root, lab);
    const KnownMistakePictures shipped = read_known_mistake_pictures(kit_root, lab);
    std::map<std::string, std::string> names;
    for (std::size_t m = 0; m < shipped.mistakes.size() && m < known.mistakes.size(); ++m) names[shipped.mistakes[m].id] = known.mistakes[m].name;
    return names;
}

namespace {

std::string trimmed(const std::string& line) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) return "";
    return line.substr(first, line.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(trimmed(line));
    return lines;
}

}  // namespace

StarterBlocks starter_blocks(const fs::path& kit_root, const std::string& lab_dir, const std::string& todo,
                             const std::vector<std::string>& files) {
    StarterBlocks out;
    for (const std::string& file : files) {
        // This TODO's starter blocks in the file, as make_starter writes them (the leading // removed), each after the
        // code between the comment that names the TODO and the block (a function's first line), and before the line
        // that follows the block.
        std::vector<std::vector<std::string>> blocks;
        bool ours = false, in_solution = false, in_starter = false, after_marker = false;
        std::vector<std::string>* follow = nullptr;
        std::vector<std::string> prefix;
        const std::string marker = "TODO(" + todo + ")";
        for (const std::string& line : lines_of(read_text_file(KitLayout{kit_root}.solutions() / lab_dir / file))) {
            if (line.rfind("//@solution", 0) == 0) {
                ours = trimmed(line.substr(11)) == todo;
                in_solution = true;
            } else if (line.rfind("//@starter", 0) == 0) {
                in_solution = false;
                in_starter = true;
                if (ours) blocks.push_back(after_marker ? prefix : std::vector<std::string>{});
            } else if (line.rfind("//@end", 0) == 0) {
                in_starter = false;
                if (ours) follow = &blocks.back();
                ours = after_marker = false;
                prefix.clear();
            } else if (in_solution) {
                continue;
            } else if (in_starter) {
                if (ours) blocks.back().push_back(trimmed(line.size() >= 2 && line.compare(0, 2, "//") == 0 ? line.substr(2) : line));
            } else if (line.find(marker) != std::string::npos) {
                after_marker = true;
                prefix.clear();
            } else if (follow && !line.empty()) {
                // The first line after the block closes it: an empty starter (a line left out) is told by what follows.
                follow->push_back(line);
                follow = nullptr;
            } else if (after_marker && !line.empty() && line.rfind("//", 0) != 0) {
                prefix.push_back(line);
            }
        }
        if (!blocks.empty()) out[file] = std::move(blocks);
    }
    return out;
}

bool still_starter(const fs::path& kit_root, const std::string& lab_dir, const fs::path& student_folder, const std::string& todo,
                   const std::vector<std::string>& files) {
    return holds_starter(student_folder, todo, starter_blocks(kit_root, lab_dir, todo, files));
}

}  // namespace gsv
