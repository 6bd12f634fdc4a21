// Which labs and cases a run grades, and the instructor's case files checked before any student code runs.
#include "grader/src/grade/session.h"

#include "common/app/exit_status.h"
#include "common/app/kit_layout.h"
#include "common/core/error.h"
#include "grader/src/cases/draw.h"

#include <algorithm>
#include <fstream>
#include <regex>
#include <set>

namespace fs = std::filesystem;

namespace gsv {

void GradingSession::check_cases() const {
    // The TODO ids the kit's labs have: the reference's blocks, or in a student edition the starters' TODO comments.
    std::set<std::string> todos;
    static const std::regex id(R"((?://@solution |TODO\()(L[0-9]{2}-T[0-9]+))");
    const KitLayout layout{kit};
    for (const fs::path& folder : {layout.solutions(), layout.labs()}) {
        std::error_code ec;
        for (auto it = fs::recursive_directory_iterator(folder, fs::directory_options::follow_directory_symlink, ec);
             !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
            if (!it->is_regular_file(ec) || it->file_size(ec) > (1u << 20)) continue;
            std::ifstream in(it->path());
            for (std::string line; std::getline(in, line);)
                for (std::sregex_iterator m(line.begin(), line.end(), id), end; m != end; ++m) todos.insert((*m)[1]);
        }
    }
    for (std::size_t i = 0; i < labs.size(); ++i) {
        const LabCases& lab = labs[i];
        const fs::path file = KitLayout{kit}.case_file(lab.lab);
        for (const auto& c : lab.cases) {
            const std::string where = (c.visibility == "public" ? file : hidden_case_file(kit, lab.lab)).string() + ": case '" + c.name + "'";
            if (!todos.empty() && !todos.count(c.todo)) throw Error(where + ": no lab has a TODO '" + c.todo + "'");
            for (const auto& n : c.needs)
                if (!todos.empty() && !todos.count(n)) throw Error(where + " needs '" + n + "', which no lab has");
        }
        // The settings, through the reference's own parameters (where it is built): `list` reads the public case file
        // and refuses an unknown name or a value out of range at its file:line:column; with a hidden case's settings
        // given, it applies those.
        const fs::path solution = bin / (lab.lab + "_solution");
        if (!fs::exists(solution)) continue;
        const auto refused = [&](const std::vector<std::string>& settings) {
            std::vector<std::string> argv{solution.string(), "list"};
            for (const auto& s : settings) argv.insert(argv.end(), {"--set", s});
            ProcessLimits l;
            l.timeout = std::chrono::seconds(20);
            const ProcessResult checked = run_process(argv, kit, l, {"GSV_ROOT=" + kit.string()});
            if (checked.exit_code == kExitOk) return std::string();
            std::string why = checked.output;
            if (const auto at = why.find(lab.lab + ": "); at != std::string::npos) why = why.substr(at + lab.lab.size() + 2);
            return why.substr(0, why.find('\n'));
        };
        if (const std::string why = refused({}); !why.empty()) throw Error(why);
        for (const auto& c : lab.cases)
            if (c.visibility != "public")
                if (const std::string why = refused(c.settings); !why.empty())
                    throw Error(hidden_case_file(kit, lab.lab).string() + ": case '" + c.name + "' (as drawn): " + why);
        // A timed case's "vary", drawn once as the timed frames will be: a setting the lab refuses stops grading here.
        for (const auto& c : lab.cases)
            if (c.timing.vary) {
                SeededDraw trial(report.seed, lab.lab + "/" + c.name + "/check");
                std::vector<std::string> settings = c.settings;
                for (auto& s : draw_settings(*c.timing.vary, trial, c.settings)) settings.push_back(std::move(s));
                if (const std::string why = refused(settings); !why.empty())
                    throw Error(file.string() + ": case '" + c.name + "': timing \"vary\" (as drawn): " + why);
            }
    }
}

void GradingSession::load_labs() {
    std::vector<std::string> known;
    for (const auto& file : case_files(kit)) {
        LabCases lab = load_lab_cases(file);
        known.push_back(lab.lab);
        if (!options.labs.empty() && std::find(options.labs.begin(), options.labs.end(), lab.lab) == options.labs.end())
            continue;
        // --todo L02-T3: lab02's cases of that TODO.
        if (!options.todo.empty() && lab.lab != "lab" + options.todo.substr(1, 2)) continue;
        const bool against_live = !options.self_check && purpose_ != RunPurpose::UpdateGoldens &&
                                  fs::exists(bin / (lab.lab + "_solution"));
        const fs::path hidden = hidden_case_file(kit, lab.lab);
        if (against_live && options.hidden && fs::exists(hidden)) {
            add_hidden_cases(lab, hidden, report.seed);
            report.hidden_included = true;
        }
        if (options.es_at_least)
            for (GradeCase& c : lab.cases)
                if (!c.es_version || *c.es_version < *options.es_at_least) c.es_version = options.es_at_least;
        if (!options.cases.empty())
            lab.cases.erase(std::remove_if(lab.cases.begin(), lab.cases.end(),
                                           [&](const GradeCase& c) {
                                               return std::find(options.cases.begin(), options.cases.end(), c.name) ==
                                                      options.cases.end();
                                           }),
                            lab.cases.end());
        if (!options.todo.empty())
            lab.cases.erase(std::remove_if(lab.cases.begin(), lab.cases.end(), [&](const GradeCase& c) { return c.todo != options.todo; }),
                            lab.cases.end());
        if (against_live && options.timing)
            for (const auto& c : lab.cases) report.timing_included = report.timing_included || c.timing.points > 0;
        labs.push_back(std::move(lab));
        live.push_back(against_live);
    }
    for (const auto& wanted : options.labs)
        if (std::find(known.begin(), known.end(), wanted) == known.end()) {
            std::string list;
            for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
            throw Error("no grading cases for lab '" + wanted + "' (grader/cases/" + wanted + ".json); labs with cases: " + list);
        }
    for (const auto& wanted : options.cases) {
        bool found = false;
        for (const auto& lab : labs)
            for (const auto& c : lab.cases) found = found || c.name == wanted;
        if (!found) throw Error("no case named '" + wanted + "' in the labs being graded (`<lab> list` and grader/cases/<lab>.json name them)");
    }
    check_cases();
    if (!options.todo.empty()) {
        std::size_t cases = 0;
        for (const auto& lab : labs) cases += lab.cases.size();
        if (cases == 0) throw Error("no case checks TODO '" + options.todo + "' (each case's \"todo\" in grader/cases/<lab>.json)");
    }
    for (std::size_t i = 0; i < labs.size(); ++i)
        for (const auto& c : labs[i].cases) total_ += 1 + (live[i] && options.timing && c.timing.points > 0 ? 1 : 0);
}

}  // namespace gsv
