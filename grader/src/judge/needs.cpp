#include "grader/src/judge/needs.h"

#include <algorithm>
#include <functional>
#include <map>
#include <set>
#include <string>

namespace gsv {
namespace {

const GradeCase* case_named(const LabCases& lab, const std::string& name) {
    const auto c = std::find_if(lab.cases.begin(), lab.cases.end(), [&](const GradeCase& x) { return x.name == name; });
    return c == lab.cases.end() ? nullptr : &*c;
}

}  // namespace

bool is_quality_status(CaseStatus status) {
    switch (status) {
    case CaseStatus::WrongImage:
    case CaseStatus::BlankImage:
    case CaseStatus::NotDone:
    case CaseStatus::WrongData:
    case CaseStatus::GpuMargin:
        return true;
    default:
        return false;
    }
}

void blame_needed_todos(const LabCases& lab, std::vector<CaseResult>& results, std::size_t first) {
    // Each TODO's failing cases (image rows), with the statuses they came out with, before any is relabelled.
    std::map<std::string, std::vector<const GradeCase*>> failing;
    std::map<std::string, std::string> first_failing;  // TODO -> the name of its first failing case
    std::set<std::string> diagnosed;  // TODOs a known mistake's picture puts a failure on: failing for their own reason
    for (std::size_t i = first; i < results.size(); ++i) {
        const CaseResult& r = results[i];
        if (r.kind != "image" || r.status == CaseStatus::Passed || is_kit_fault(r.status)) continue;
        if (!r.mistake_todo.empty()) {
            diagnosed.insert(r.mistake_todo);
            if (!first_failing.count(r.mistake_todo)) first_failing[r.mistake_todo] = r.name;
            if (r.mistake_todo != r.todo) continue;
        }
        if (!first_failing.count(r.todo)) first_failing[r.todo] = r.name;
        if (const GradeCase* c = case_named(lab, r.name)) failing[r.todo].push_back(c);
    }
    const auto fails = [&](const std::string& todo) { return first_failing.count(todo) > 0; };
    // A failing case's needs that fail too (its own TODO aside).
    const auto failing_needs = [&](const GradeCase& c) {
        std::vector<std::string> needed;
        for (const auto& n : c.needs)
            if (n != c.todo && fails(n)) needed.push_back(n);
        return needed;
    };
    // Roots: TODOs with a failing case that no failing need explains (a failing TODO whose cases are not all in the
    // case file, such as a build error's rows, is a root too: nothing explains it).
    std::set<std::string> roots = diagnosed;
    for (const auto& [todo, name] : first_failing) {
        const auto it = failing.find(todo);
        if (it == failing.end() || std::any_of(it->second.begin(), it->second.end(), [&](const GradeCase* c) { return failing_needs(*c).empty(); }))
            roots.insert(todo);
    }
    // The roots a failing TODO comes down to, following the needs of its failing cases; a TODO already on the way is
    // not followed again, so a circle ends.
    std::function<void(const std::string&, std::set<std::string>&, std::set<std::string>&)> roots_of =
        [&](const std::string& todo, std::set<std::string>& seen, std::set<std::string>& found) {
            if (!seen.insert(todo).second) return;
            if (roots.count(todo)) {
                found.insert(todo);
                return;
            }
            for (const GradeCase* c : failing[todo])
                for (const auto& n : failing_needs(*c)) roots_of(n, seen, found);
        };
    for (std::size_t i = first; i < results.size(); ++i) {
        CaseResult& r = results[i];
        if (r.status == CaseStatus::Passed || r.status == CaseStatus::BuildError || is_kit_fault(r.status)) continue;
        // A failure a known mistake explains is that mistake's TODO's, whatever TODO the case carries.
        if (!r.mistake_todo.empty()) {
            r.detail = (r.mistake.empty() ? r.mistake_todo + " is not started (its part is the starter's), which explains it"
                                          : "a known mistake in " + r.mistake_todo + " explains it: " + r.mistake) +
                       "; here: " + r.detail;
            continue;
        }
        const GradeCase* c = case_named(lab, r.name);
        if (!c) continue;
        for (const auto& needed : failing_needs(*c)) {
            std::set<std::string> seen{r.todo}, found;
            roots_of(needed, seen, found);
            if (found.empty()) continue;  // only a circle back to this case's own TODO: no one else to blame
            // The root once: the first (by id) of those the need comes down to.
            const std::string& root = *found.begin();
            std::string need = "needs " + root + " first (its case '" + first_failing[root] + "' fails";
            if (root != needed) need += "; " + needed + ", which this case needs, waits on it";
            need += ")";
            if (is_quality_status(r.status)) {
                r.status = CaseStatus::NeedsFirst;
                r.detail = need + "; here: " + r.detail;
            } else {
                r.detail += "; it also " + need;
            }
            break;
        }
    }
}

std::string way_in(const LabCases& lab, const std::vector<CaseResult>& results, std::size_t first) {
    std::set<std::string> unfinished;
    for (std::size_t i = first; i < results.size(); ++i)
        if (results[i].status != CaseStatus::Passed && !results[i].todo.empty()) unfinished.insert(results[i].todo);
    for (const GradeCase& c : lab.cases)
        if (c.visibility == "public" && c.needs.empty() && unfinished.count(c.todo))
            return c.todo + " (its case '" + c.name + "' needs no other TODO)";
    return "";
}

}  // namespace gsv
