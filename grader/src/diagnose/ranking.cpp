#include "grader/src/diagnose/ranking.h"

#include "common/app/known_mistake_pictures.h"

#include <algorithm>
#include <map>
#include <optional>

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

std::vector<MistakePair> consistent_pairs(const std::vector<std::string>& left, const std::vector<std::string>& failing,
                                          const std::vector<KnownMistake>& mistakes,
                                          const std::vector<std::set<std::string>>& explains,
                                          const std::vector<std::set<std::string>>& fails, const std::vector<std::size_t>& named,
                                          const TogetherCheck& check) {
    const std::set<std::string> is_left(left.begin(), left.end()), failed(failing.begin(), failing.end());
    // A second: its picture explains a case left, or (where pictures drawn together can be told) it fails a case left
    // and fails no case the student passed.
    const auto may_second = [&](std::size_t m) {
        if (std::any_of(left.begin(), left.end(), [&](const std::string& c) { return explains[m].count(c) > 0; })) return true;
        return check && std::any_of(fails[m].begin(), fails[m].end(), [&](const std::string& c) { return is_left.count(c) > 0; }) &&
               std::all_of(fails[m].begin(), fails[m].end(), [&](const std::string& c) { return failed.count(c) > 0; });
    };
    const auto is_named = [&](std::size_t m) { return std::find(named.begin(), named.end(), m) != named.end(); };
    std::vector<std::size_t> firsts, seconds;
    for (std::size_t m = 0; m < mistakes.size(); ++m) {
        if (is_named(m)) firsts.push_back(m);
        else if (mistakes[m].not_started) continue;  // a TODO not started is told by its source (tell_not_started), not paired
        else if (may_second(m)) seconds.push_back(m);
    }
    if (named.empty()) firsts = seconds;
    std::vector<MistakePair> pairs;
    for (const std::size_t a : firsts)
        for (const std::size_t b : seconds) {
            if (a == b || mistakes[a].todo == mistakes[b].todo || (named.empty() && b < a)) continue;
            MistakePair p{a, b, {}, {}, {}, 0};
            bool consistent = true, shows_first = !named.empty(), shows_second = false;
            for (const std::string& c : left) {
                if (named.empty() && explains[a].count(c)) p.by_first.push_back(c);
                else if (explains[b].count(c)) p.by_second.push_back(c);
                else if (fails[a].count(c) && fails[b].count(c)) p.together.push_back(c);
                else consistent = false;
            }
            if (!consistent) continue;
            for (const std::string& c : p.together) {
                if (!check) break;
                const TogetherEvidence e = check(a, b, c);
                p.together_matched += e.matches;
                shows_first = shows_first || (e.matches && e.shows_first);
                shows_second = shows_second || (e.matches && e.shows_second);
            }
            // As for one mistake (name_mistakes): pictures must explain at least half the failures left, not a case or two.
            const std::size_t by_pictures = p.by_first.size() + p.by_second.size() + p.together_matched;
            if ((shows_first || !p.by_first.empty()) && (shows_second || !p.by_second.empty()) && by_pictures * 2 >= left.size())
                pairs.push_back(std::move(p));
        }
    std::stable_sort(pairs.begin(), pairs.end(), [](const MistakePair& x, const MistakePair& y) {
        const std::size_t px = x.by_first.size() + x.by_second.size() + x.together_matched,
                          py = y.by_first.size() + y.by_second.size() + y.together_matched;
        return px != py ? px > py : x.together.size() < y.together.size();
    });
    return pairs;
}

void add_pair(LabDiagnosis& d, const MistakePair& pair, bool first_is_new, const std::vector<KnownMistake>& mistakes,
              const std::vector<std::set<std::string>>& explains, const std::vector<std::set<std::string>>& fails) {
    std::set<std::string> already;
    for (const MistakeFound& f : d.found) already.insert(f.names.begin(), f.names.end());
    const auto found = [&](std::size_t m, std::vector<std::string> cases, bool with_earlier) {
        MistakeFound f{mistakes[m].todo, mistakes[m].says, mistakes[m].sheet, {mistakes[m].name}, std::move(cases), with_earlier};
        already.insert(mistakes[m].name);  // m itself first: its picture is the one shown; then its twins
        for (std::size_t i = 0; i < mistakes.size(); ++i)
            if (explains[i] == explains[m] && fails[i] == fails[m] && already.insert(mistakes[i].name).second)
                f.names.push_back(mistakes[i].name);
        return f;
    };
    if (first_is_new) d.found.push_back(found(pair.first, pair.by_first, false));
    std::vector<std::string> second = pair.by_second;
    second.insert(second.end(), pair.together.begin(), pair.together.end());
    d.found.push_back(found(pair.second, second, true));
    std::set<std::string> explained(pair.by_first.begin(), pair.by_first.end());
    explained.insert(second.begin(), second.end());
    d.unexplained.erase(std::remove_if(d.unexplained.begin(), d.unexplained.end(), [&](const std::string& c) { return explained.count(c) > 0; }),
                        d.unexplained.end());
}

namespace {

// A second for the mistakes `named`: outside their TODOs, no TODO not started, and its picture fails something and
// nothing the student passed (`failed`: the cases the student failed).
bool may_be_second(std::size_t m, const std::vector<KnownMistake>& mistakes, const std::vector<std::set<std::string>>& fails,
                   const std::vector<std::size_t>& named, const std::set<std::string>& failed) {
    if (fails[m].empty() || mistakes[m].not_started) return false;
    if (std::any_of(named.begin(), named.end(), [&](std::size_t n) { return mistakes[n].todo == mistakes[m].todo; })) return false;
    return std::all_of(fails[m].begin(), fails[m].end(), [&](const std::string& c) { return failed.count(c) > 0; });
}

// The one candidate that scores highest; none where two in different TODOs score alike (which to name is a guess).
class OneBest {
public:
    void offer(std::size_t m, long score, const std::vector<KnownMistake>& mistakes) {
        if (!best_ || score > score_) {
            best_ = m;
            score_ = score;
            ambiguous_ = false;
        } else if (score == score_ && mistakes[m].todo != mistakes[*best_].todo) {
            ambiguous_ = true;
        }
    }
    std::optional<std::size_t> get() const { return ambiguous_ ? std::nullopt : best_; }

private:
    std::optional<std::size_t> best_;
    long score_ = 0;
    bool ambiguous_ = false;
};

// A second mistake whose own picture shows nowhere: where every failure left is a case a mistake named also fails, the
// second's picture there is drawn over by the first's. It is named only where it alone fits: the mistakes (not in a
// TODO named) whose pictures fail every case left and no case the student did not fail, the one failing fewest;
// none where two in different TODOs fit as well.
std::optional<std::size_t> hidden_second(const std::vector<std::string>& left, const std::vector<std::string>& failing,
                                         const std::vector<KnownMistake>& mistakes, const std::vector<std::set<std::string>>& fails,
                                         const std::vector<std::size_t>& named) {
    const std::set<std::string> failed(failing.begin(), failing.end());
    for (const std::string& c : left)
        if (std::none_of(named.begin(), named.end(), [&](std::size_t n) { return fails[n].count(c) > 0; })) return std::nullopt;
    OneBest best;
    for (std::size_t m = 0; m < mistakes.size(); ++m) {
        if (!may_be_second(m, mistakes, fails, named, failed)) continue;
        if (!std::all_of(left.begin(), left.end(), [&](const std::string& c) { return fails[m].count(c) > 0; })) continue;
        best.offer(m, -static_cast<long>(fails[m].size()), mistakes);  // the one failing fewest
    }
    return best.get();
}

// A second mistake beneath the one named, where every failure is explained: on the cases both fail the student's
// picture is the two's together (`check`) and, on one at least, shows the second beyond the first alone; the cases
// only it fails its own picture explains. Named only where one TODO's mistakes fit best; the cases it shows on move to it.
void second_beneath(LabDiagnosis& d, const std::vector<std::string>& failing, const std::vector<KnownMistake>& mistakes,
                    const std::vector<std::set<std::string>>& explains, const std::vector<std::set<std::string>>& fails,
                    const std::vector<std::size_t>& named, const TogetherCheck& check) {
    const std::set<std::string> failed(failing.begin(), failing.end());
    const std::size_t first = named.front();
    std::map<std::size_t, std::vector<std::string>> shows;  // a candidate -> the cases it shows on
    OneBest best;
    for (std::size_t m = 0; m < mistakes.size(); ++m) {
        if (!may_be_second(m, mistakes, fails, named, failed)) continue;
        std::vector<std::string> on;
        bool fits = true;
        for (const std::string& c : fails[m]) {
            if (!fails[first].count(c)) fits = explains[m].count(c) > 0;
            else if (const TogetherEvidence e = check(first, m, c); !e.matches) fits = false;
            else if (e.shows_second) on.push_back(c);
            if (!fits) break;
        }
        if (!fits || on.empty()) continue;
        best.offer(m, static_cast<long>(on.size()), mistakes);
        shows[m] = std::move(on);
    }
    const std::optional<std::size_t> second = best.get();
    if (!second) return;
    const std::vector<std::string>& best_shows = shows.at(*second);
    const std::set<std::string> moved(best_shows.begin(), best_shows.end());
    for (MistakeFound& f : d.found)
        f.cases.erase(std::remove_if(f.cases.begin(), f.cases.end(), [&](const std::string& c) { return moved.count(c) > 0; }), f.cases.end());
    add_pair(d, MistakePair{first, *second, {}, {}, best_shows, best_shows.size()}, false, mistakes, explains, fails);
}

}  // namespace

LabDiagnosis name_mistakes_and_pairs(const std::string& lab, const std::vector<std::string>& failing,
                                     const std::vector<KnownMistake>& mistakes, const std::vector<std::set<std::string>>& explains,
                                     const std::vector<std::set<std::string>>& fails, const TogetherCheck& check) {
    LabDiagnosis d = name_mistakes(lab, failing, mistakes, explains);
    std::vector<std::size_t> named;
    for (const MistakeFound& f : d.found)
        for (const std::string& n : f.names)
            for (std::size_t m = 0; m < mistakes.size(); ++m)
                if (mistakes[m].name == n) named.push_back(m);
    if (d.unexplained.empty()) {
        if (check && !named.empty()) second_beneath(d, failing, mistakes, explains, fails, named, check);
        return d;
    }
    const std::vector<MistakePair> pairs = consistent_pairs(d.unexplained, failing, mistakes, explains, fails, named, check);
    if (!pairs.empty()) {
        add_pair(d, pairs.front(), named.empty(), mistakes, explains, fails);
    } else if (const auto hidden = hidden_second(d.unexplained, failing, mistakes, fails, named)) {
        add_pair(d, MistakePair{named.front(), *hidden, {}, {}, d.unexplained}, false, mistakes, explains, fails);
    }
    return d;
}

void prefer_confirmed_not_started(std::vector<std::set<std::string>>& explains, const KnownMistakes& known,
                                  const std::filesystem::path& student_folder) {
    for (std::size_t m = 0; m < known.mistakes.size() && m < explains.size(); ++m) {
        const KnownMistake& k = known.mistakes[m];
        if (!k.not_started || explains[m].empty() || !holds_starter(student_folder, k.todo, k.starter)) continue;
        for (std::size_t other = 0; other < explains.size(); ++other)
            if (other != m && !(known.mistakes[other].not_started && known.mistakes[other].todo == k.todo))
                for (const std::string& c : explains[m]) explains[other].erase(c);
    }
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
