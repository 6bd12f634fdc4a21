#include "grader/src/diagnose/mutant_kit.h"

#include "common/app/kit_layout.h"
#include "common/core/error.h"

#include <algorithm>
#include <fstream>
#include <iterator>

namespace fs = std::filesystem;

namespace gsv {

std::string read_text_file(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error("cannot read " + file.string());
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

Json read_mutant_spec(const fs::path& kit_root, const std::string& lab) {
    return read_json_file(KitLayout{kit_root}.tests() / "mutants" / (lab + ".json"));
}

std::vector<std::string> labs_with_mutants(const fs::path& kit_root) {
    std::vector<std::string> labs;
    const fs::path dir = KitLayout{kit_root}.tests() / "mutants";
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) return labs;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == ".json") labs.push_back(e.path().stem().string());
    std::sort(labs.begin(), labs.end());
    return labs;
}

void apply_mutant_edits(const fs::path& lab_folder, const Json& edit, const fs::path& kit_root) {
    const fs::path file = lab_folder / edit.string_at("file");
    std::string text = read_text_file(file);
    auto one = [&](const Json& e) {
        const std::string find = e.string_at("find");
        const auto at = text.find(find);
        if (at == std::string::npos)
            throw Error("'" + edit.string_or("name", "an edit") + "': '" + find + "' is not in " + file.string());
        std::string replace = e.string_at("replace");
        for (auto kit = replace.find("@KIT@"); kit != std::string::npos; kit = replace.find("@KIT@"))
            replace.replace(kit, 5, kit_root.string());
        text.replace(at, find.size(), replace);
    };
    if (const Json* edits = edit.find("edits")) {
        for (const Json& e : edits->as_array()) one(e);
    } else {
        one(edit);
    }
    std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
}

void make_edited_kit(const fs::path& dir, const fs::path& kit_root, const fs::path& bin_dir, const std::string& lab,
                     const std::string& lab_dir, const std::function<void(const fs::path&)>& edit, const std::string& binary) {
    const KitLayout kit{kit_root};
    const fs::path root = dir / "kit";
    fs::create_directories(root / "solutions");
    // The public files are the kit's own, linked (the sandbox binds what they lead to).
    fs::create_directory_symlink(kit.shaders(), root / "shaders");
    fs::create_directory_symlink(kit.data(), root / "data");
    fs::copy(kit.solutions() / lab_dir, root / "solutions" / lab_dir, fs::copy_options::recursive);
    edit(root / "solutions" / lab_dir);
    fs::create_directories(dir / "bin");
    fs::copy_file(bin_dir / (binary.empty() ? lab + "_solution" : binary), dir / "bin" / lab);
}

void make_edited_kit(const fs::path& dir, const fs::path& kit_root, const fs::path& bin_dir, const std::string& lab,
                     const std::string& lab_dir, const Json& edit) {
    // Only shader edits: the solution's binary is copied, not rebuilt, so a C++ edit would change nothing and its
    // mutant would "pass". C++ faults go through a submission, which the grader builds.
    const std::string file = edit.string_or("file", "");
    if (is_cpp_file(file))
        throw Error("'" + edit.string_at("name") + "' edits " + file + ": C++ is not rebuilt for mutants; plant C++ faults in a submission");
    make_edited_kit(dir, kit_root, bin_dir, lab, lab_dir, [&](const fs::path& folder) { apply_mutant_edits(folder, edit, kit_root); });
}

}  // namespace gsv
