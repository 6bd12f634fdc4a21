#include "grader/src/diagnose/ranking.h"

#include "common/app/known_mistake_pictures.h"

#include <algorithm>

namespace gsv {

LabDiagnosis rank_mistakes(const std::string& lab, const std::vector<std::string>& failing,
                           const std::vector<KnownMistake>& mistakes, const std::vector<std::set<std::string>>& explains) {
    LabDiagnosis d;
    d.lab = lab;
    d.failing = failing;
    std::set<std::string> left(failing.begin(), failing.end());
    std::vector<bool> named(mistakes.size(), false);
    const auto still_explained = [&](std::size_t m) {
        std::vector<std::string> cases;
        for (const auto& f : failing)
            if (left.count(f) && explains[m].count(f)) cases.push_back(f);
        return cases;
    };
    while (!left.empty()) {
        std::size_t best = mistakes.size();
        std::size_t best_count = 0;
        for (std::size_t m = 0; m < mistakes.size(); ++m) {
            if (named[m]) continue;
            const std::size_t count = still_explained(m).size();
            if (count == 0) continue;
            if (best == mistakes.size() || count > best_count ||
                (count == best_count && explains[m].size() < explains[best].size())) {
                best = m;
                best_count = count;
            }
        }
        if (best == mistakes.size()) break;
        MistakeFound found{mistakes[best].todo, mistakes[best].says, mistakes[best].sheet, {}, still_explained(best)};
        for (std::size_t m = 0; m < mistakes.size(); ++m) {
            if (named[m] || explains[m] != explains[best]) continue;
            named[m] = true;
            found.names.push_back(mistakes[m].name);
        }
        for (const auto& c : found.cases) left.erase(c);
        d.found.push_back(std::move(found));
    }
    for (const auto& f : failing)
        if (left.count(f)) d.unexplained.push_back(f);
    return d;
}

LabDiagnosis name_mistakes(const std::string& lab, const std::vector<std::string>& failing, const std::vector<KnownMistake>& mistakes,
                           const std::vector<std::set<std::string>>& explains) {
    const LabDiagnosis ranked = rank_mistakes(lab, failing, mistakes, explains);
    LabDiagnosis d;
    d.lab = lab;
    d.failing = failing;
    std::set<std::string> explained;
    std::size_t remaining = failing.size();
    for (const MistakeFound& f : ranked.found) {
        if (f.cases.size() * 2 < remaining) break;
        remaining -= f.cases.size();
        explained.insert(f.cases.begin(), f.cases.end());
        d.found.push_back(f);
    }
    for (const std::string& name : failing)
        if (!explained.count(name)) d.unexplained.push_back(name);
    return d;
}

std::map<std::string, std::string> tell_not_started(LabDiagnosis& d, const KnownMistakes& known, const std::filesystem::path& student_folder) {
    const auto mistake = [&](const std::string& name) -> const KnownMistake& {
        return *std::find_if(known.mistakes.begin(), known.mistakes.end(), [&](const KnownMistake& k) { return k.name == name; });
    };
    std::map<std::string, std::string> not_started_cases;
    std::vector<MistakeFound> mistakes_found;
    for (MistakeFound& found : d.found) {
        std::vector<std::string> starters, confirmed;
        for (const std::string& n : found.names) {
            const KnownMistake& k = mistake(n);
            if (!k.not_started) continue;
            starters.push_back(k.todo);
            if (holds_starter(student_folder, k.todo, k.starter)) confirmed.push_back(k.todo);
        }
        const bool any_mistake = starters.size() < found.names.size();
        if (starters.empty() || (confirmed.empty() && any_mistake)) {
            found.names.erase(std::remove_if(found.names.begin(), found.names.end(),
                                             [&](const std::string& n) { return mistake(n).not_started; }),
                              found.names.end());
            const KnownMistake& first = mistake(found.names.front());
            found.todo = first.todo;
            found.says = first.says;
            found.sheet = first.sheet;
            mistakes_found.push_back(std::move(found));
            continue;
        }
        const std::string todo = confirmed.empty() ? starters.front() : confirmed.front();
        if (std::find(d.not_started.begin(), d.not_started.end(), todo) == d.not_started.end()) d.not_started.push_back(todo);
        for (const std::string& name : found.cases) not_started_cases[name] = todo;
    }
    d.found = std::move(mistakes_found);
    return not_started_cases;
}

}  // namespace gsv
