#include "common/app/lab_sources.h"

#include "common/core/error.h"
#include "common/core/fnv1a.h"
#include "common/io/json.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <fstream>
#include <iterator>

namespace fs = std::filesystem;

namespace gsv {

bool is_build_input(const fs::path& file) {
    static const std::array<const char*, 16> kReadAtRunTime = {
        ".glsl", ".vert", ".frag", ".comp", ".geom", ".tesc", ".tese", ".network",
        ".json", ".md", ".txt", ".png", ".jpg", ".obj", ".csv", ".pdf"};
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    return std::find_if(kReadAtRunTime.begin(), kReadAtRunTime.end(),
                        [&](const char* e) { return extension == e; }) == kReadAtRunTime.end();
}

std::map<std::string, std::string> build_input_fingerprints(const fs::path& lab_folder) {
    std::map<std::string, std::string> fingerprints;
    if (!fs::is_directory(lab_folder)) return fingerprints;
    for (auto it = fs::recursive_directory_iterator(lab_folder); it != fs::recursive_directory_iterator(); ++it) {
        if (!it->is_regular_file() || !is_build_input(it->path())) continue;
        std::ifstream in(it->path(), std::ios::binary);
        if (!in) throw Error("cannot read '" + it->path().string() + "'");
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        Fnv1a hash;
        hash.add(bytes.data(), bytes.size());
        fingerprints[it->path().lexically_relative(lab_folder).generic_string()] = hash.hex();
    }
    return fingerprints;
}

fs::path starter_manifest(const fs::path& kit_root) { return kit_root / "grader" / "starters.json"; }

bool is_starter_cpp(const fs::path& kit_root, const std::string& lab_dir, const fs::path& lab_folder) {
    try {
        const Json manifest = read_json_file(starter_manifest(kit_root));
        const Json* labs = manifest.find("labs");
        const Json* recorded = labs ? labs->find(lab_dir) : nullptr;
        if (!recorded || !recorded->is_object()) return false;
        std::map<std::string, std::string> expected;
        for (const auto& [name, fingerprint] : recorded->as_object()) expected[name] = fingerprint.as_string();
        return !expected.empty() && build_input_fingerprints(lab_folder) == expected;
    } catch (const Error&) {
        return false;
    }
}

}  // namespace gsv
