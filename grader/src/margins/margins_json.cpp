// The margin measurement as JSON and back, and measurements made apart (on other machines, or an implementation at a
// time) joined into one, so that one table holds them all.
#include "grader/src/margins/margins.h"

#include "grader/src/core/safe_text.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <set>

namespace gsv {
namespace {

Json number_or_null(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

}  // namespace

Json margins_json(const MarginMeasurement& m) {
    // An object with these members, in this order.
    const auto object = [](std::initializer_list<std::pair<const char*, Json>> members) {
        Json j = Json::object();
        for (const auto& [key, value] : members) j[key] = value;
        return j;
    };
    Json implementations = Json::array(), cases = Json::array(), renders = Json::array(), notes = Json::array();
    for (const auto& run : m.implementations)
        implementations.push_back(object({{"name", run.implementation.name}, {"how", run.implementation.how},
                                          {"renderer", valid_utf8(run.renderer)}, {"available", run.available},
                                          {"why_not", valid_utf8(run.why_not)}, {"seconds", number_or_null(run.seconds)}}));
    for (const auto& c : m.cases) cases.push_back(object({{"lab", c.lab}, {"case", c.name}, {"todo", c.todo}, {"budget", c.budget}}));
    // A share of null: the render could not be compared (its status says why).
    for (const auto& r : m.renders)
        renders.push_back(object({{"implementation", r.implementation}, {"lab", r.lab}, {"case", r.case_name}, {"kind", r.kind},
                                  {"source", r.source}, {"share", number_or_null(r.share)}, {"status", r.status},
                                  {"detail", valid_utf8(r.detail)}, {"offset", number_or_null(r.offset)}}));
    for (const auto& n : m.notes) notes.push_back(n);
    Json diagnoses = Json::array();
    for (const auto& d : m.diagnoses)
        diagnoses.push_back(object({{"implementation", d.implementation}, {"lab", d.lab}, {"mutant", d.mutant}, {"named", d.named},
                                    {"right", d.right}}));
    return object({{"implementations", implementations}, {"cases", cases}, {"renders", renders}, {"diagnoses", diagnoses},
                   {"labs_with_mutants", m.labs_with_mutants}, {"notes", notes}});
}

MarginMeasurement margins_from_json(const Json& root) {
    MarginMeasurement m;
    for (const Json& j : root.array_at("implementations").as_array()) {
        MarginImplementationRun run;
        run.implementation.name = j.string_at("name");
        run.implementation.how = j.string_at("how");
        run.renderer = j.string_at("renderer");
        run.available = j.bool_at("available");
        run.why_not = j.string_at("why_not");
        run.seconds = j.number_or("seconds", 0);
        m.implementations.push_back(run);
    }
    for (const Json& j : root.array_at("cases").as_array())
        m.cases.push_back({j.string_at("lab"), j.string_at("case"), j.string_at("todo"), j.string_at("budget")});
    for (const Json& j : root.array_at("renders").as_array())
        m.renders.push_back({j.string_at("implementation"), j.string_at("lab"), j.string_at("case"), j.string_at("kind"),
                             j.string_at("source"), j.number_or("share", kInfiniteShare), j.string_at("status"),
                             j.string_at("detail"), j.number_or("offset", 0)});
    for (const Json& n : root.array_at("notes").as_array()) m.notes.push_back(n.as_string());
    m.labs_with_mutants = static_cast<std::size_t>(root.number_or("labs_with_mutants", 0));
    if (const Json* list = root.find("diagnoses"))
        for (const Json& j : list->as_array())
            m.diagnoses.push_back({j.string_at("implementation"), j.string_at("lab"), j.string_at("mutant"), j.string_at("named"),
                                   j.bool_at("right")});
    return m;
}

MarginMeasurement merge_margins(const std::vector<MarginMeasurement>& parts) {
    MarginMeasurement all;
    std::set<std::string> seen_cases, seen_notes;
    for (const auto& part : parts) {
        all.implementations.insert(all.implementations.end(), part.implementations.begin(), part.implementations.end());
        for (const auto& c : part.cases)
            if (seen_cases.insert(c.lab + "/" + c.name).second) all.cases.push_back(c);
        all.renders.insert(all.renders.end(), part.renders.begin(), part.renders.end());
        all.diagnoses.insert(all.diagnoses.end(), part.diagnoses.begin(), part.diagnoses.end());
        all.labs_with_mutants = std::max(all.labs_with_mutants, part.labs_with_mutants);
        for (const auto& n : part.notes)
            if (seen_notes.insert(n).second) all.notes.push_back(n);
    }
    return all;
}

}  // namespace gsv
