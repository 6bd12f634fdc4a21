#include "grader/cases.h"

#include "common/error.h"
#include "common/json.h"

#include <algorithm>
#include <regex>

namespace gsv {
namespace {

ImageTolerance tolerance_from(const Json& j) {
    ImageTolerance t;
    t.max_channel_diff = static_cast<int>(j.number_at("max_channel_diff"));
    t.max_differing_fraction = j.number_at("max_differing_fraction");
    if (t.max_channel_diff < 0 || t.max_channel_diff > 255 || t.max_differing_fraction < 0 || t.max_differing_fraction > 1)
        throw Error(j.source_name() + ": tolerance out of range (max_channel_diff 0..255, max_differing_fraction 0..1)");
    return t;
}

}  // namespace

LabCases load_lab_cases(const std::filesystem::path& file) {
    const Json root = read_json_file(file);
    LabCases lab;
    lab.lab = root.string_at("lab");
    const std::string size = root.string_at("size");
    static const std::regex size_pattern(R"(^([0-9]{1,4})x([0-9]{1,4})$)");
    std::smatch m;
    if (!std::regex_match(size, m, size_pattern)) throw Error(file.string() + ": 'size' must be WIDTHxHEIGHT, got '" + size + "'");
    lab.width = std::stoi(m[1]);
    lab.height = std::stoi(m[2]);
    const Json& tolerance = root.object_at("tolerance");
    lab.live_tolerance = tolerance_from(tolerance.object_at("live"));
    lab.golden_tolerance = tolerance_from(tolerance.object_at("golden"));
    lab.timeout_s = root.number_or("timeout_s", 60);
    static const std::regex todo_pattern(R"(^L[0-9]{2}-T[0-9]+$)");
    for (const Json& c : root.array_at("cases").as_array()) {
        GradeCase gc;
        gc.name = c.string_at("name");
        gc.todo = c.string_at("todo");
        if (!std::regex_match(gc.todo, todo_pattern))
            throw Error(file.string() + ": case '" + gc.name + "' has todo '" + gc.todo + "', expected an id like L01-T2");
        gc.description = c.string_or("description", "");
        gc.visibility = c.string_or("visibility", "public");
        gc.points = c.number_or("points", 1);
        for (const Json& s : c.array_at("settings").as_array()) gc.settings.push_back(s.as_string());
        lab.cases.push_back(gc);
    }
    if (lab.cases.empty()) throw Error(file.string() + ": no cases");
    return lab;
}

std::vector<std::filesystem::path> case_files(const std::filesystem::path& kit_root) {
    std::vector<std::filesystem::path> files;
    const auto dir = kit_root / "grader" / "cases";
    if (!std::filesystem::is_directory(dir)) throw Error("no grader/cases folder in '" + kit_root.string() + "'");
    for (const auto& e : std::filesystem::directory_iterator(dir))
        if (e.path().extension() == ".json") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace gsv
