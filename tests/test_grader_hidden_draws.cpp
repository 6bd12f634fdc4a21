// Every draw tests its TODO (issue 39): whatever the seed, a hidden case's drawn settings tell each classic mistake
// it must fail (tests/mutants/<lab>.json, a mutant's "must_fail_hidden") from the reference. Over 50 seeds (1..49 and
// 4711), each hidden case is drawn as grading draws it, the reference renders it and every mistake listed for it renders
// it, each by one process that serves all the seeds' cases; each mistake must fail under the case's live tolerance
// (its image, its arrays, the whole picture's place), as instructor grading judges a hidden case.
#include "grader_fixture.h"
#include "per_lab.h"

#include "common/app/kit_layout.h"
#include "grader/src/cases/case_row.h"
#include "grader/src/judge/data_check.h"
#include "grader/src/judge/image_verdict.h"
#include "grader/src/run/lab_serve.h"

#include <map>
#include <set>

using namespace gsv;

namespace {

std::vector<std::uint64_t> seeds() {
    std::vector<std::uint64_t> list;
    for (std::uint64_t s = 1; s <= 49; ++s) list.push_back(s);
    list.push_back(4711);  // the seed whose hidden L05-T4 cases drew no RK4 (issue 39)
    return list;
}

// A hidden case's name without the instance number a "count" adds ("hidden-phong-2" -> "hidden-phong").
std::string base_name(const std::string& name, const std::set<std::string>& bases) {
    if (bases.count(name)) return name;
    const auto dash = name.rfind('-');
    return dash == std::string::npos ? name : name.substr(0, dash);
}

ProcessLimits limits_of(const LabCases& lab) {
    ProcessLimits limits;
    limits.timeout = std::chrono::milliseconds(static_cast<long>(lab.timeout_s * 1000));
    return limits;
}

void every_draw_tests_its_todo(const std::string& lab_id) {
    const Json spec = test::mutant_spec(lab_id);
    const std::string lab_dir = spec.string_at("lab_dir");
    const KitLayout kit{test::source_root()};
    const LabCases public_cases = load_lab_cases(kit.case_file(lab_id));
    std::set<std::string> bases;
    const Json hidden = read_json_file(kit.hidden_case_file(lab_id));
    for (const Json& c : hidden.array_at("cases").as_array()) bases.insert(c.string_at("name"));

    // Every hidden case drawn with every seed: one list of cases, each named by its seed.
    LabCases drawn = public_cases;
    drawn.cases.clear();
    std::map<std::string, std::string> base_of;  // drawn case -> hidden case
    for (const std::uint64_t seed : seeds()) {
        LabCases one = public_cases;
        one.cases.clear();
        add_hidden_cases(one, kit.hidden_case_file(lab_id), seed);
        for (GradeCase c : one.cases) {
            const std::string base = base_name(c.name, bases);
            c.name = "seed-" + std::to_string(seed) + "/" + c.name;
            base_of[c.name] = base;
            drawn.cases.push_back(c);
        }
    }

    // Which GLSL mistakes each hidden case must fail; every hidden case is there to catch some.
    struct Mistake {
        std::string name;
        Json edit;
        std::set<std::string> hidden;
    };
    std::vector<Mistake> mistakes;
    std::map<std::string, int> caught_by;
    for (const Json& m : spec.array_at("mutants").as_array()) {
        const Json* list = m.find("must_fail_hidden");
        INFO(lab_id << ": mutant '" << m.string_at("name") << "' says which hidden cases it must fail (\"must_fail_hidden\", [] for none, "
                    "with \"hidden_why\")");
        REQUIRE(list);
        if (list->size() == 0) CHECK(m.contains("hidden_why"));
        Mistake mistake{m.string_at("name"), m, {}};
        for (const Json& h : list->as_array()) {
            INFO(lab_id << ": mutant '" << mistake.name << "' names hidden case '" << h.as_string() << "'");
            REQUIRE(bases.count(h.as_string()));
            mistake.hidden.insert(h.as_string());
            ++caught_by[h.as_string()];
        }
        if (!mistake.hidden.empty()) mistakes.push_back(std::move(mistake));
    }
    // A hidden case of a TODO whose mistakes are all C++ (lab 05's L05-T1) is the C++ mutation test's: those need a build.
    std::set<std::string> glsl_todos;
    for (const Json& m : spec.array_at("mutants").as_array()) glsl_todos.insert(m.string_at("todo"));
    for (const Json& c : hidden.array_at("cases").as_array()) {
        if (!glsl_todos.count(c.string_at("todo"))) continue;
        INFO(lab_id << ": hidden case '" << c.string_at("name") << "' is listed by no mistake it must fail");
        CHECK(caught_by[c.string_at("name")] > 0);
    }

    // The reference, one process for every drawn case.
    const ProcessLimits limits = limits_of(public_cases);
    std::map<std::string, LabRun> reference;
    {
        LabRunner runner{test::bin_dir(), "", false, Profile::Core};
        ServedLab served(lab_id + "_solution");
        runner.served = &served;
        for (const GradeCase& c : drawn.cases) {
            // Only the draws some mistake is held to (a C++ TODO's hidden case is the C++ mutation test's).
            if (!caught_by.count(base_of[c.name])) continue;
            LabRun run = runner.render(lab_id + "_solution", drawn, c, limits);
            INFO(lab_id << ": the reference on " << c.name << ": " << run.detail);
            REQUIRE(run.status == CaseStatus::Passed);
            reference.emplace(c.name, std::move(run));
        }
    }
    std::string passed;  // the draws that let a mistake by
    int judged = 0;
    for (const Mistake& m : mistakes) {
        test::TempDir dir;
        make_edited_kit(dir.path(), test::source_root(), test::bin_dir(), lab_id, lab_dir, m.edit);
        LabRunner runner{dir.path("bin"), dir.path("kit"), true, Profile::Core};
        ServedLab served(lab_id);
        runner.served = &served;
        for (const GradeCase& c : drawn.cases) {
            if (!m.hidden.count(base_of[c.name])) continue;
            const LabRun run = runner.render(lab_id, drawn, c, limits);
            const LabRun& expected = reference.at(c.name);
            CaseResult r = case_row(drawn, c);
            r.status = run.status;
            r.detail = run.detail;
            if (run.status == CaseStatus::Passed) judge_image(*run.image, *expected.image, drawn.tolerance(c, true), c, r);
            check_case_data(drawn, c, run, expected, r);
            ++judged;
            if (r.status == CaseStatus::Passed) {
                std::string settings;
                for (const auto& s : c.settings) settings += " " + s;
                passed += "  '" + m.name + "' passes " + c.name + " (" + r.detail + "):" + settings + "\n";
            }
        }
    }
    INFO(lab_id << ": " << judged << " renders of " << mistakes.size() << " mistakes over " << seeds().size()
                << " seeds; draws that let a mistake pass a hidden case it must fail:\n" << passed);
    CHECK(passed.empty());
}

}  // namespace

GSV_PER_LAB_TEST("every seed's hidden cases fail each mistake they must fail", "[grader][mutants]", every_draw_tests_its_todo)
