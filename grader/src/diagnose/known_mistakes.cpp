#include "grader/src/diagnose/known_mistakes.h"

#include "common/app/kit_layout.h"
#include "common/core/error.h"
#include "grader/src/margins/mutant_kit.h"
#include "tools/starter.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

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
    for (const Json& m : spec.array_at("mutants").as_array()) {
        const std::string name = m.string_or("name", "");
        if (name.empty()) throw Error(file.string() + ": a mistake without a \"name\"");
        if (is_cpp_file(m.string_or("file", ""))) continue;
        const std::string says = m.string_or("says", "");
        if (says.empty()) throw Error(file.string() + ": mistake '" + name + "' has no \"says\" (what it tells a student who made it)");
        known.mistakes.push_back({name, m.string_at("todo"), says, m.string_or("sheet", "TODO table"), m, false, {}});
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
        std::ifstream in(source, std::ios::binary);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        for (const auto& id : make_starter(text, name).todo_ids) {
            if (is_cpp_file(name)) in_cpp.insert(id);
            if (std::find(files_of[id].begin(), files_of[id].end(), name) == files_of[id].end()) files_of[id].push_back(name);
        }
    }
    for (const auto& [todo, files] : files_of) {
        if (in_cpp.count(todo)) continue;
        known.mistakes.push_back({todo + " not started", todo, "not started: its part is still the starter's", "TODO table",
                                  Json::object(), true, files});
    }
    return known;
}

}  // namespace gsv
