// What a margin measurement says: per case the worst correct render and the nearest must-fail mutant against the bars,
// the cases that miss them, and what CI holds each implementation to.
#include "grader/src/margins/margins.h"

#include "common/image/image_offset.h"
#include "grader/src/report/report_format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

namespace gsv {
namespace {

std::string percent_text(double share) {
    if (std::isinf(share)) return "fails";
    if (share >= 9.995) return ">999%";
    char text[16];
    std::snprintf(text, sizeof text, "%.0f%%", 100.0 * share);
    return text;
}

// What one case's renders say against the bar.
struct CaseVerdict {
    std::map<std::string, double> correct_by_implementation;  // the worst correct render on each
    double worst_correct = -1;
    double nearest_wrong = kInfiniteShare;
    std::string nearest_wrong_what;
    int wrong_renders = 0;
    std::vector<std::string> misses;
};

std::string why_correct(const MarginRender& r) {
    return std::string(r.kind == "variant" ? "correct variant '" + r.source + "'" : "the solution") + " uses " +
           percent_text(r.share) + " of the budget on " + r.implementation + " (" + r.status + (r.detail.empty() ? "" : ": " + r.detail) + ")";
}

// The same verdict whatever order the renders were measured or joined in.
CaseVerdict verdict_of(const MarginMeasurement& m, const MarginCase& c) {
    CaseVerdict v;
    std::map<std::pair<std::string, std::string>, std::vector<std::string>> wrong_where;  // (before, after) -> where
    for (const auto& r : m.renders) {
        if (r.lab != c.lab || r.case_name != c.name) continue;
        if (r.kind == "mutant") {
            ++v.wrong_renders;
            const std::string what = "'" + r.source + "' on " + r.implementation;
            if (v.nearest_wrong_what.empty() || r.share < v.nearest_wrong || (r.share == v.nearest_wrong && what < v.nearest_wrong_what)) {
                v.nearest_wrong = r.share;
                v.nearest_wrong_what = what;
            }
            if (r.share <= kWrongBar) {
                // One line for a mutant as far away on several implementations.
                const std::string key = "must-fail mutant '" + r.source + "' is " + percent_text(r.share) + " of the budget on ";
                const std::string why = r.share <= 1 ? " (it passes: " + r.detail + ")"
                                                     : " (it fails, but by under 150% of the budget)";
                wrong_where[{key, why}].push_back(r.implementation);
            }
            continue;
        }
        auto& worst = v.correct_by_implementation.emplace(r.implementation, -1.0).first->second;
        worst = std::max(worst, r.share);
        v.worst_correct = std::max(v.worst_correct, r.share);
        if (r.share >= kCorrectBar) v.misses.push_back(why_correct(r));
    }
    std::sort(v.misses.begin(), v.misses.end());
    for (auto [line, where] : wrong_where) {
        std::sort(where.begin(), where.end());
        std::string joined;
        for (const auto& name : where) joined += (joined.empty() ? "" : ", ") + name;
        v.misses.push_back(line.first + joined + line.second);
    }
    return v;
}

std::string pad(const std::string& text, std::size_t width) { return text.size() >= width ? text : text + std::string(width - text.size(), ' '); }
std::string pad_left(const std::string& text, std::size_t width) {
    return text.size() >= width ? text : std::string(width - text.size(), ' ') + text;
}

std::string renderer_of(const MarginMeasurement& m, const std::string& implementation) {
    for (const auto& run : m.implementations)
        if (run.implementation.name == implementation) return run.renderer;
    return "";
}

}  // namespace

std::vector<std::string> cases_missing_the_bar(const MarginMeasurement& m) {
    std::vector<std::string> lines;
    for (const auto& c : m.cases) {
        const CaseVerdict v = verdict_of(m, c);
        for (const auto& why : v.misses) lines.push_back(c.lab + "/" + c.name + " (" + c.todo + "): " + why);
    }
    return lines;
}

std::vector<std::string> grading_failures(const MarginMeasurement& m) {
    std::vector<std::string> lines;
    const auto on = [&](const std::string& implementation) {
        return implementation + " (GL_RENDERER '" + renderer_of(m, implementation) + "')";
    };
    // A mutant holds when it lost points on one of the cases it must fail, as the mutation test asks on llvmpipe.
    std::map<std::string, bool> mutant_failed;  // implementation|lab|mutant
    for (const auto& r : m.renders) {
        if (r.kind == "mutant") {
            mutant_failed[r.implementation + "|" + r.lab + "|" + r.source] |= r.status != "passed";
        } else if (r.status != "passed") {
            lines.push_back("on " + on(r.implementation) + ": " + r.lab + "/" + r.case_name + ": " +
                            (r.kind == "variant" ? "the correct variant '" + r.source + "'" : std::string("the solution")) +
                            " is graded " + r.status + (r.detail.empty() ? "" : ": " + r.detail));
        }
    }
    for (const auto& [key, failed] : mutant_failed) {
        if (failed) continue;
        const auto bar = key.find('|'), bar2 = key.find('|', bar + 1);
        lines.push_back("on " + on(key.substr(0, bar)) + ": " + key.substr(bar + 1, bar2 - bar - 1) + ": mutant '" + key.substr(bar2 + 1) +
                        "' passes every case it must fail");
    }
    // The diagnosis: never another mistake's name for a mutant, on any implementation (none at all is honest: "no
    // known mistake matches"); and, where the measurement holds every lab with mutants, the mutant itself named first
    // for kDiagnosisBar of them on each implementation (the bar is over the kit's mistakes, not a lab's few).
    std::map<std::string, std::pair<int, int>> named;  // implementation -> right, all
    std::map<std::string, std::string> missed;
    std::set<std::string> labs;
    for (const auto& d : m.diagnoses) {
        labs.insert(d.lab);
        auto& [right, all] = named[d.implementation];
        ++all;
        right += d.right;
        if (!d.right) missed[d.implementation] += (missed[d.implementation].empty() ? "" : "; ") + d.lab + " '" + d.mutant + "'";
        if (!d.right && !d.named.empty())
            lines.push_back("on " + on(d.implementation) + ": " + d.lab + ": mutant '" + d.mutant + "' is named as '" + d.named + "'");
    }
    if (labs.size() >= m.labs_with_mutants)
        for (const auto& [implementation, count] : named)
            if (count.first < kDiagnosisBar * count.second)
                lines.push_back("on " + on(implementation) + ": the self-check names " + std::to_string(count.first) + " of " +
                                std::to_string(count.second) + " mutants first, under " + percent_text(kDiagnosisBar) + ": not " +
                                missed[implementation]);
    for (const auto& run : m.implementations)
        if (!run.available) lines.push_back(run.implementation.name + " was not measured: " + run.why_not);
    return lines;
}

std::string margins_table(const MarginMeasurement& m) {
    std::ostringstream out;
    out << "implementations\n";
    std::vector<std::string> measured;
    for (const auto& run : m.implementations) {
        out << "  " << pad(run.implementation.name, 17) << " ";
        if (run.available) {
            measured.push_back(run.implementation.name);
            out << run.renderer << "; " << run.implementation.how << " (" << fixed(run.seconds / 60.0, 1) << " min)\n";
        } else {
            out << "not measured: " << run.why_not << "\n";
        }
    }
    out << "\nper case: the worst correct render (the solution and the correct variants of tests/mutants/) on each "
           "implementation, and the nearest\nmutant that must fail the case (over all implementations), as shares of the "
           "case's golden budget. The bar: correct under "
        << percent_text(kCorrectBar) << ", must-fail\nmutants over " << percent_text(kWrongBar)
        << " (a failing self-check within that, on another renderer, is told it differs by a margin seen between GPUs).\n";
    std::size_t w_case = 4;
    for (const auto& c : m.cases) w_case = std::max(w_case, c.name.size());
    int missing = 0, cases = 0, without_mutants = 0;
    for (std::size_t i = 0; i < m.cases.size(); ++i) {
        const MarginCase& c = m.cases[i];
        if (i == 0 || m.cases[i - 1].lab != c.lab) {
            // The budget once for a lab whose cases share it.
            bool one_budget = true;
            for (const auto& other : m.cases)
                if (other.lab == c.lab && other.budget != c.budget) one_budget = false;
            out << "\n" << c.lab << (one_budget ? "  (budget: " + c.budget + ")" : "") << "\n  " << pad("case", w_case) << "  "
                << pad("todo", 6);
            for (const auto& name : measured) out << "  " << pad_left(name.size() > 12 ? name.substr(0, 12) : name, 12);
            out << "  " << pad_left("mutant", 7) << "  verdict\n";
        }
        const CaseVerdict v = verdict_of(m, c);
        ++cases;
        out << "  " << pad(c.name, w_case) << "  " << pad(c.todo, 6);
        for (const auto& name : measured) {
            const auto it = v.correct_by_implementation.find(name);
            out << "  " << pad_left(it == v.correct_by_implementation.end() ? "-" : percent_text(it->second), 12);
        }
        out << "  " << pad_left(v.wrong_renders ? percent_text(v.nearest_wrong) : "-", 7) << "  ";
        if (!v.misses.empty()) {
            ++missing;
            out << "MISSES THE BAR";
        } else {
            out << "ok";
        }
        if (v.wrong_renders) {
            out << " (nearest: " << v.nearest_wrong_what << ")";
        } else {
            ++without_mutants;
            out << " (no mutant must fail it)";
        }
        out << "\n";
        bool one_budget = true;
        for (const auto& other : m.cases)
            if (other.lab == c.lab && other.budget != c.budget) one_budget = false;
        if (!one_budget) out << "    budget: " << c.budget << "\n";
    }
    // The whole picture's place: correct renders within half of what the grader refuses as a shifted picture.
    // The same words whatever order the renders were measured or joined in: the largest, and of equals the first by name.
    double worst_offset = 0;
    std::string worst_offset_what = "no correct render moved";
    for (const auto& r : m.renders) {
        const std::string what = r.lab + "/" + r.case_name + " on " + r.implementation;
        if (r.kind != "mutant" && r.offset > 0 && (r.offset > worst_offset || (r.offset == worst_offset && what < worst_offset_what))) {
            worst_offset = r.offset;
            worst_offset_what = what;
        }
    }
    out << "\nthe whole picture's offset: the largest of a correct render " << fixed(worst_offset, 2) << " px (" << worst_offset_what
        << "); a share of the budget above is also the offset over the " << fixed(kMaxGlobalOffset, 2)
        << " px the grader refuses, so correct renders stay under " << fixed(kCorrectBar * kMaxGlobalOffset, 2) << " px\n";
    // The diagnosis: per implementation, how many mutants the self-check named first, from the shipped pictures.
    if (!m.diagnoses.empty()) {
        out << "\nthe diagnosis (the self-check's first name, from the pictures the kit ships) of the mutants graded; at least "
            << percent_text(kDiagnosisBar) << " right on each:\n";
        for (const auto& name : measured) {
            int right = 0, all = 0;
            std::string wrong;
            for (const auto& d : m.diagnoses) {
                if (d.implementation != name) continue;
                ++all;
                right += d.right;
                if (!d.right) wrong += (wrong.empty() ? "" : "; ") + d.lab + " '" + d.mutant + "' as " + (d.named.empty() ? "none" : "'" + d.named + "'");
            }
            if (all == 0) continue;
            out << "  " << pad(name, 17) << " " << right << " of " << all << " named first" << (wrong.empty() ? "" : ": not " + wrong) << "\n";
        }
    }
    out << "\n" << cases - missing << " of " << cases << " cases meet the bar";
    if (without_mutants) out << " (" << without_mutants << " with no mutant that must fail them: correct renders only)";
    out << "\n";
    const auto lines = cases_missing_the_bar(m);
    if (!lines.empty()) {
        out << "\nwhy cases miss the bar\n";
        for (const auto& line : lines) out << "  " << line << "\n";
    }
    if (!m.notes.empty()) {
        out << "\nnotes\n";
        for (const auto& n : m.notes) out << "  " << n << "\n";
    }
    return out.str();
}

}  // namespace gsv
