#include "grader/src/judge/needs.h"

#include <algorithm>
#include <map>
#include <string>

namespace gsv {

void blame_needed_todos(const LabCases& lab, std::vector<CaseResult>& results, std::size_t first) {
    std::map<std::string, std::string> failing;  // TODO -> its first failing case
    for (std::size_t i = first; i < results.size(); ++i) {
        const CaseResult& r = results[i];
        if (r.kind == "image" && r.status != CaseStatus::Passed && !failing.count(r.todo)) failing[r.todo] = r.name;
    }
    for (std::size_t i = first; i < results.size(); ++i) {
        CaseResult& r = results[i];
        if (r.status == CaseStatus::Passed || r.status == CaseStatus::BuildError || is_kit_fault(r.status)) continue;
        const auto c = std::find_if(lab.cases.begin(), lab.cases.end(), [&](const GradeCase& x) { return x.name == r.name; });
        if (c == lab.cases.end()) continue;
        for (const auto& needed : c->needs) {
            const auto f = failing.find(needed);
            if (f == failing.end() || needed == r.todo) continue;
            r.status = CaseStatus::NeedsFirst;
            r.detail = "needs " + needed + " first (its case '" + f->second + "' fails); here: " + r.detail;
            break;
        }
    }
}

}  // namespace gsv
