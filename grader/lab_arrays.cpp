#include "grader/lab_arrays.h"

#include "common/core/error.h"
#include "common/io/json.h"

#include <set>

namespace fs = std::filesystem;

namespace gsv {

std::vector<DataArray> read_lab_arrays(const Json& report, const fs::path& report_file, const fs::path& png) {
    std::vector<DataArray> arrays;
    const Json* listed = report.find("arrays");
    if (!listed || listed->is_null()) return arrays;
    const std::string where = report_file.filename().string();
    if (listed->as_array().size() > kMaxArrays)
        throw Error(where + ": lists " + std::to_string(listed->size()) + " arrays, more than the " +
                    std::to_string(kMaxArrays) + " the grader reads");
    std::set<std::string> seen;
    std::uint64_t floats = 0;
    for (std::size_t i = 0; i < listed->size(); ++i) {
        const Json& entry = listed->at(i);
        DataArray a;
        a.name = entry.string_at("name");
        const std::string what = where + ": arrays[" + std::to_string(i) + "]";
        if (!valid_array_name(a.name)) throw Error(what + " has no valid name (1.." + std::to_string(kMaxArrayNameBytes) + " of a-z, 0-9, '_')");
        const std::string array = where + ": array '" + a.name + "'";
        if (!seen.insert(a.name).second) throw Error(array + " is listed twice");
        a.components = entry.int_at("components");
        if (a.components < 1 || a.components > kMaxArrayComponents)
            throw Error(array + " has " + std::to_string(a.components) + " components, not 1.." +
                        std::to_string(kMaxArrayComponents));
        const int count = entry.int_at("count");
        if (count < 0) throw Error(array + " has a negative count " + std::to_string(count));
        const std::uint64_t values = std::uint64_t(count) * std::uint64_t(a.components);
        floats += values;
        if (floats > kMaxArrayFloats)
            throw Error(array + ": " + std::to_string(count) + " x " + std::to_string(a.components) +
                        " floats, more than the " + std::to_string(kMaxArrayFloats) + " in all the grader reads");
        // Only the file render mode writes for this name counts: a path elsewhere could make the grader read
        // (or compare) anything it can read itself.
        const fs::path expected = data_array_path(png, a.name);
        const fs::path file = entry.string_at("file");
        if ((file.is_absolute() ? file : png.parent_path() / file).lexically_normal() != expected.lexically_normal())
            throw Error(array + " names file '" + file.string() + "', not " + expected.filename().string() +
                        " beside the image in the lab's working folder");
        try {
            a.values = read_f32_file(expected, values);
        } catch (const Error& e) {
            throw Error(array + ": " + e.what());
        }
        arrays.push_back(std::move(a));
    }
    return arrays;
}

}  // namespace gsv
