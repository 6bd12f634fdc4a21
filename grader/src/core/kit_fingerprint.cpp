#include "grader/src/core/kit_fingerprint.h"

#include "common/core/error.h"
#include "common/core/fnv1a.h"

#include <algorithm>
#include <fstream>
#include <vector>

namespace fs = std::filesystem;

namespace gsv {

std::string kit_fingerprint(const fs::path& kit_root) {
    static const char* kWhatGrades[] = {"grader/cases", "grader/hidden", "grader/golden", "solutions", "shaders", "common", "support", "data"};
    std::vector<fs::path> files;
    for (const char* part : kWhatGrades) {
        const fs::path folder = kit_root / part;
        if (!fs::is_directory(folder)) continue;
        for (const auto& e : fs::recursive_directory_iterator(folder))
            if (e.is_regular_file()) files.push_back(e.path().lexically_relative(kit_root));
    }
    if (files.empty()) throw Error("'" + kit_root.string() + "' is not a kit (no grader/cases, solutions, ...)");
    std::sort(files.begin(), files.end());
    Fnv1a hash;
    std::vector<char> buffer(1 << 16);
    for (const fs::path& file : files) {
        hash.add(file.generic_string());
        std::ifstream in(kit_root / file, std::ios::binary);
        if (!in) throw Error("cannot read '" + (kit_root / file).string() + "' to fingerprint the kit");
        while (in.read(buffer.data(), static_cast<std::streamsize>(buffer.size())) || in.gcount() > 0)
            hash.add(buffer.data(), static_cast<std::size_t>(in.gcount()));
    }
    return hash.hex();
}

}  // namespace gsv
