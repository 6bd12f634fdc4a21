#include "common/params/case_file.h"

#include "common/params/params.h"
#include "common/core/error.h"
#include "common/io/json.h"

#include <regex>
#include <set>

namespace gsv {

RenderCase named_case_from(const Json& object) {
    static const std::regex name_pattern(R"(^[a-z0-9][a-z0-9-]{0,40}$)");
    RenderCase c;
    c.where = object.source_name() + ":" + std::to_string(object.line());
    c.name = object.string_at("name");
    if (!std::regex_match(c.name, name_pattern))
        throw Error(c.where + ": case name '" + c.name + "' must be lower-case letters, digits and '-' (it names a folder)");
    c.description = object.string_or("description", "");
    for (const Json& s : object.array_at("settings").as_array()) c.settings.push_back(s.as_string());
    return c;
}

namespace {

void check_settings(const Json& entry, const RenderCase& c, const Params& defaults) {
    Params probe = defaults;
    auto where = [&](const Json& s) {
        return s.source_name() + ":" + std::to_string(s.line()) + ":" + std::to_string(s.column()) + ": case '" + c.name + "': ";
    };
    for (const Json& s : entry.array_at("settings").as_array()) {
        try {
            probe.set_assignment(s.as_string());
        } catch (const Error& e) {
            throw Error(where(s) + e.what());
        }
    }
    for (const Json& s : entry.array_at("settings").as_array()) {
        const std::string name = s.as_string().substr(0, s.as_string().find('='));
        probe.check_applies({name}, where(s));
    }
}

std::vector<RenderCase> read_cases(const std::filesystem::path& file, const std::string& lab_id, const Params* defaults) {
    if (!std::filesystem::exists(file))
        throw Error("cannot find the case file '" + file.string() + "' of " + lab_id + ", which declares its named cases");
    const Json root = read_json_file(file);
    if (root.string_at("lab") != lab_id)
        throw Error(file.string() + ": 'lab' is '" + root.string_at("lab") + "', expected '" + lab_id + "'");
    std::vector<RenderCase> cases;
    std::set<std::string> names;
    for (const char* list : {"cases", "demos"}) {
        const Json* entries = root.find(list);
        if (!entries || entries->is_null()) continue;
        for (const Json& entry : entries->as_array()) {
            RenderCase c = named_case_from(entry);
            if (std::string(list) == "cases") c.todo = entry.string_at("todo");
            if (defaults) check_settings(entry, c, *defaults);
            if (!names.insert(c.name).second) throw Error(c.where + ": a second case named '" + c.name + "'");
            cases.push_back(std::move(c));
        }
    }
    return cases;
}

}  // namespace

std::vector<RenderCase> read_case_file(const std::filesystem::path& file, const std::string& lab_id) {
    return read_cases(file, lab_id, nullptr);
}

std::vector<RenderCase> read_case_file(const std::filesystem::path& file, const std::string& lab_id,
                                       const Params& defaults) {
    return read_cases(file, lab_id, &defaults);
}

}  // namespace gsv
