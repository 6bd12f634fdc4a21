// Proof that the grader works on shader edits: known-wrong variants of the reference (mutants) each fail
// the case that names their bug, and planted faults each get their own status while the rest is graded.
#include "grader_fixture.h"
#include "per_lab.h"
#include "serve_compare.h"

#include "grader/src/diagnose/known_mistakes.h"
#include "tools/starter.h"

#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <memory>

using namespace gsv;
namespace fs = std::filesystem;

namespace {

struct Outcome {
    bool lost = false;    // some case of the TODO lost points
    std::string details;  // a line per case
    std::string log;      // the output of the first case that lost points
    std::vector<std::string> first_named;  // the diagnosis's first mistake and its twins (grader/src/diagnose/)
    std::vector<std::string> not_started;
};

// Grades the cases of `todo` (public ones, untimed), against the live reference or the goldens, by one process per lab
// (the default); against the goldens also by one process per case, every check held alike (issue 30: serving grades as
// restarting does; `racy`: serve_compare.h).
Outcome grade_todo(GradeOptions options, const std::string& todo, bool self_check, const std::shared_ptr<ReferenceCache>& cache,
                   const std::string& what, bool racy = false) {
    options.todo = todo;
    options.self_check = self_check;
    options.hidden = false;
    options.timing = false;
    options.reference_cache = cache;
    // The diagnosis is checked where students see it, the self-check: in instructor grading it names mistakes the same
    // way (only what the failing picture is judged against differs), and twice would double the test's time.
    options.diagnose = self_check ? DiagnoseCases::Public : DiagnoseCases::Off;
    const GradeReport report = grade(options);
    if (self_check) {
        options.lab_processes = LabProcesses::PerCase;
        test::check_graded_alike(grade(options), report, what, racy);
    }
    Outcome o;
    // The self-check names mistakes by the ids the kit ships (grader/golden/<lab>/mistakes.json): the lists' names here.
    std::map<std::string, std::string> name_of;
    for (const std::string& lab : options.labs) name_of.merge(list_names_of_shipped(test::source_root(), lab));
    for (const auto& d : report.diagnoses) {
        if (!d.found.empty() && o.first_named.empty())
            for (const std::string& n : d.found.front().names) o.first_named.push_back(name_of.count(n) ? name_of[n] : n);
        o.not_started.insert(o.not_started.end(), d.not_started.begin(), d.not_started.end());
    }
    for (const auto& r : report.results) {
        if (r.points < r.max_points && !o.lost) o.log = r.output.substr(0, 3000);
        o.lost = o.lost || r.points < r.max_points;
        o.details += r.name + ": " + status_name(r.status) + " " + r.detail + "\n";
    }
    return o;
}

// The mutation test of the grading cases: for each TODO the reference with that TODO left as the starter has it, and
// the classic bugs in tests/mutants/<lab>.json, must each lose points on a case of that TODO, against the live
// reference AND against the golden images (what students run); the correct variants beside them must not. A test
// case a lab, so that ctest spreads them over the cores.
void mutation_test(const std::string& lab) {
    const auto cache = std::make_shared<ReferenceCache>();
    std::string summary = "lab    mode        killed / mutants, variants kept, classic mistakes the diagnosis names first\n";
    {
        const Json spec = test::mutant_spec(lab);
        const std::string lab_dir = spec.string_at("lab_dir");
        const auto todos = test::todo_files(lab_dir);
        struct Mutant {
            std::string todo, name;
            std::function<void(const std::filesystem::path&)> edit;
            bool racy = false;
        };
        std::vector<Mutant> mutants;
        for (const auto& [todo, files] : todos) {
            if (std::any_of(files.begin(), files.end(), is_cpp_file)) continue;  // C++ TODOs: the test below builds them
            const Json* racy_undone = spec.find("racy_undone");
            mutants.push_back({todo, todo + " left undone", [todo = todo, files = files](const std::filesystem::path& folder) {
                                   // Read before the stream truncates the file: `a << b` runs a first.
                                   for (const auto& file : files) {
                                       const std::string undone = make_starter(test::read_text(folder / file), file, todo).text;
                                       std::ofstream(folder / file, std::ios::binary) << undone;
                                   }
                               },
                               racy_undone && racy_undone->contains(todo)});
        }
        std::map<std::string, int> classic;
        for (const Json& m : spec.array_at("mutants").as_array()) {
            mutants.push_back({m.string_at("todo"), m.string_at("name"), [m](const std::filesystem::path& folder) { test::apply_edits(folder, m); },
                               m.contains("racy")});
            ++classic[m.string_at("todo")];
        }
        for (const auto& [todo, files] : todos) {
            INFO(lab << ": classic bugs of " << todo << " in tests/mutants/" << lab << ".json");
            if (!std::any_of(files.begin(), files.end(), is_cpp_file)) CHECK(classic[todo] >= test::lab_rule("mistakes_per_todo"));
        }
        for (const bool self_check : {true, false}) {
            int killed = 0, classic_diagnosed = 0, classic_named = 0;
            std::string misnamed;
            for (const auto& m : mutants) {
                test::EditedKit kit(lab, lab_dir, m.edit);
                const Outcome o = grade_todo(kit.options(), m.todo, self_check, cache, lab + " mutant '" + m.name + "'", m.racy);
                INFO(lab << " (" << (self_check ? "self-check" : "live") << ") mutant '" << m.name << "' of " << m.todo << ":\n" << o.details);
                CHECK(o.lost);
                killed += o.lost;
                // The diagnosis (issue 40): a classic mistake graded as a student's is named first (or a twin, whose
                // pictures are the same); a TODO left undone is "not started" and named as no mistake.
                if (!self_check) continue;
                if (m.name == m.todo + " left undone") {
                    CHECK(o.first_named.empty());
                    CHECK(o.not_started == std::vector<std::string>{m.todo});
                    continue;
                }
                if (o.first_named.empty() && o.not_started.empty()) {
                    // Only failures no picture can explain (NaN, a crash): nothing to name.
                    if (o.details.find("wrong image") == std::string::npos && o.details.find("wrong data") == std::string::npos &&
                        o.details.find("blank image") == std::string::npos)
                        continue;
                }
                ++classic_diagnosed;
                // A mistake whose edit is the starter's own code (lab 04's grid left flat: the line left out) is "not
                // started", its twin: the source is the starter's.
                if (std::find(o.first_named.begin(), o.first_named.end(), m.name) != o.first_named.end() ||
                    (o.first_named.empty() && o.not_started == std::vector<std::string>{m.todo}))
                    ++classic_named;
                else
                    misnamed += "  '" + m.name + "' named as '" + (o.first_named.empty() ? std::string("(none)") : o.first_named.front()) + "'\n";
            }
            INFO(lab << " (" << (self_check ? "self-check" : "live") << "): " << classic_named << " of " << classic_diagnosed
                     << " classic mistakes named first:\n" << misnamed);
            if (self_check) CHECK(classic_named * 100 >= classic_diagnosed * 95);
            int kept = 0, variants = 0;
            if (const Json* list = spec.find("variants"))
                for (const Json& v : list->as_array()) {
                    test::EditedKit kit(lab, lab_dir, v);
                    const Outcome o = grade_todo(kit.options(), v.string_at("todo"), self_check, cache,
                                                 lab + " correct variant '" + v.string_at("name") + "'");
                    INFO(lab << " (" << (self_check ? "self-check" : "live") << ") correct variant '" << v.string_at("name") << "':\n" << o.details);
                    CHECK_FALSE(o.lost);
                    kept += !o.lost;
                    ++variants;
                }
            char line[160];
            std::snprintf(line, sizeof line, "%-6s %-11s %3d / %-3zu  %d / %d  named first %d / %d\n", lab.c_str(),
                          self_check ? "self-check" : "live", killed, mutants.size(), kept, variants, classic_named, classic_diagnosed);
            summary += line + misnamed;
        }
    }
    WARN(summary);
}

}  // namespace

constexpr const char* kMutationTest =
    "every TODO left undone or with a classic bug loses points, live and in the self-check, variants do not";
GSV_PER_LAB_TEST(kMutationTest, "[grader][mutants]", mutation_test)

TEST_CASE("every lab has a mutation test above", "[grader][mutants]") {
    // Every lab of the list has its list of mistakes (tests/lab_rules.json, mistakes_per_todo) and its test.
    CHECK(test::labs_with_mutants() == test::all_labs());
    CHECK(test::labs_missing_test(kMutationTest, test::PerLab::Every).empty());
}

TEST_CASE("grader: planted shader faults each get their own status, and every case is still graded", "[grader]") {
    const Json spec = test::mutant_spec("lab01");
    for (const Json& fault : spec.array_at("faults").as_array()) {
        test::EditedKit kit("lab01", spec.string_at("lab_dir"), fault);
        GradeOptions options = kit.options();
        options.hidden = false;
        if (fault.bool_or("timed_only", false)) continue;  // below
        options.timing = false;
        options.timeout_s = fault.number_or("timeout_s", 0);
        const GradeReport report = grade(options);
        const auto images = test::by_name(report);
        REQUIRE(images.size() >= 9);
        for (const auto& [name, r] : images) {
            INFO("fault '" << fault.string_at("name") << "', case " << name << ": " << r.detail);
            CHECK(std::string(status_name(r.status)) == fault.string_at("status"));
            CHECK(r.points == 0);
        }
        if (fault.string_at("status") == "shader compile error") {
            const CaseResult& r = images.begin()->second;
            // The located message, in the file the student edits, as the student names it.
            CHECK(r.detail.find("solutions/lab01_gooch/phong.glsl:") == 0);
            CHECK(r.output.find("phong.glsl:") != std::string::npos);
            CHECK(r.output.find("vec3 r = reflect(-l, n) +;") != std::string::npos);
        }
    }
}

// Tagged [timing]: ctest runs it alone, so no other test's load is measured.
TEST_CASE("grader: a shader doing sixteen times the work is too slow, though its images are right", "[grader][timing]") {
    const Json spec = test::mutant_spec("lab01");
    int timed_faults = 0;
    for (const Json& fault : spec.array_at("faults").as_array()) {
        if (!fault.bool_or("timed_only", false)) continue;
        ++timed_faults;
        test::EditedKit kit("lab01", spec.string_at("lab_dir"), fault);
        GradeOptions options = kit.options();
        options.hidden = false;
        const GradeReport report = grade(options);
        for (const auto& [name, r] : test::by_name(report)) CHECK(r.status == CaseStatus::Passed);
        const auto timings = test::by_name(report, "timing");
        REQUIRE(timings.size() >= 1);
        for (const auto& [name, r] : timings) {
            INFO("fault '" << fault.string_at("name") << "', " << name << ": " << r.detail);
            CHECK(std::string(status_name(r.status)) == fault.string_at("status"));
            CHECK(r.timing.ratio > r.timing.max_ratio);
            CHECK(r.timing.rounds >= 2);
            CHECK(r.points == 0);
        }
    }
    CHECK(timed_faults == 1);
}

TEST_CASE("every C++ TODO: left undone or with a classic bug it loses points, live and in the self-check", "[grader][mutants]") {
    const auto cache = std::make_shared<ReferenceCache>();
    for (const auto& lab : test::labs_with_mutants()) {
        const Json spec = test::mutant_spec(lab);
        const std::string lab_dir = spec.string_at("lab_dir");
        std::vector<std::string> cpp_todos;
        for (const auto& [todo, files] : test::todo_files(lab_dir))
            if (std::any_of(files.begin(), files.end(), is_cpp_file)) cpp_todos.push_back(todo);
        if (cpp_todos.empty()) continue;
        const Json none = Json::array();
        const Json& cpp_mutants = spec.contains("cpp_mutants") ? spec.array_at("cpp_mutants") : none;
        const Json& cpp_stateful = spec.contains("cpp_stateful") ? spec.array_at("cpp_stateful") : none;
        // One submission: the reference with every C++ TODO block switched at run time (the stateful variants too).
        test::TempDir dir;
        test::write_switched_cpp_submission(dir.path("submission"), lab, lab_dir);
        GradeOptions built = test::instructor_options(lab, dir.path("built"));
        built.submission = dir.path("submission");
        for (const auto& todo : cpp_todos) {
            // The build, graded as it is: the solution, full marks.
            const Outcome unchanged = grade_todo(built, todo, false, cache, lab + ": the switched build");
            INFO(lab << ": the switched build as the solution:\n" << unchanged.details << unchanged.log);
            REQUIRE_FALSE(unchanged.lost);
        }
        GradeOptions options = test::instructor_options(lab, dir.path("out"));
        options.student_bin_dir = dir.path("built/submission-build/build/bin");
        options.student_root = dir.path("built/submission-build/kit");
        std::vector<std::pair<std::string, std::string>> mutants;  // todo, name
        for (const auto& todo : cpp_todos) mutants.push_back({todo, todo + " left undone"});
        for (const Json& m : cpp_mutants.as_array()) mutants.push_back({m.string_at("todo"), m.string_at("name")});
        for (const auto& todo : cpp_todos) {
            const auto n = std::count_if(mutants.begin(), mutants.end(), [&](const auto& m) { return m.first == todo; });
            INFO(lab << ": classic bugs of " << todo << " in cpp_mutants");
            CHECK(n - 1 >= test::lab_rule("mistakes_per_todo"));
        }
        for (const bool self_check : {true, false})
            for (const auto& [todo, name] : mutants) {
                setenv(kKnownMistakeVariable, name.c_str(), 1);
                const Outcome o = grade_todo(options, todo, self_check, cache, lab + " C++ mutant '" + name + "'");
                unsetenv(kKnownMistakeVariable);
                INFO(lab << " (" << (self_check ? "self-check" : "live") << ") C++ mutant '" << name << "' of " << todo << ":\n" << o.details);
                CHECK(o.lost);
                // Named where students see it, the self-check, from the pictures the kit ships (its _mistakes build made
                // them): the mistake first, or its TODO not started.
                if (!self_check) continue;
                const std::string first = o.first_named.empty() ? "nothing" : o.first_named.front();
                INFO("named first: " << first);
                // Left undone here is not "not started": the switched source is not the starter's (checked below).
                if (name != todo + " left undone")
                    CHECK(std::find(o.first_named.begin(), o.first_named.end(), name) != o.first_named.end());
            }
        // The C++ TODO as a student leaves it before starting (its starter code, in the kit's starter build) and every
        // other TODO done: "not started" for that TODO, and no known mistake named in its place.
        for (const auto& todo : cpp_todos) {
            test::TempDir undone;
            const fs::path root = undone.path("kit");
            fs::create_directories(root / "labs");
            fs::create_directory_symlink(test::source_root() / "shaders", root / "shaders");
            fs::create_directory_symlink(test::source_root() / "data", root / "data");
            fs::copy(test::source_root() / "solutions" / lab_dir, root / "labs" / lab_dir, fs::copy_options::recursive);
            for (const auto& e : fs::directory_iterator(root / "labs" / lab_dir)) {
                const std::string text = make_starter(test::read_text(e.path()), e.path().filename().string(), todo).text;
                std::ofstream(e.path(), std::ios::binary | std::ios::trunc) << text;
            }
            fs::create_directories(undone.path("bin"));
            fs::copy_file(test::bin_dir() / lab, undone.path("bin") / lab);  // its one C++ TODO is the starter's
            GradeOptions left = test::instructor_options(lab, undone.path("out"));
            left.student_bin_dir = undone.path("bin");
            left.student_root = root;
            const Outcome o = grade_todo(left, todo, true, cache, lab + " " + todo + " not started");
            INFO(lab << ": " << todo << " not started, named first: " << (o.first_named.empty() ? "nothing" : o.first_named.front())
                     << "\n" << o.details);
            CHECK(o.lost);
            CHECK(std::find(o.not_started.begin(), o.not_started.end(), todo) != o.not_started.end());
            CHECK(o.first_named.empty());
        }
        // Served equals alone (issue 39): a lab that keeps state in a `static` from one case to the next is graded on
        // every case as one process per case grades it, each of its public cases in the lab's order, live and in the
        // self-check; the served rows that passed only alone say so, and there must be some (else the variant proves
        // nothing).
        for (const Json& v : cpp_stateful.as_array()) {
            setenv(kKnownMistakeVariable, v.string_at("name").c_str(), 1);
            for (const bool self_check : {true, false}) {
                GradeOptions served = options;
                served.self_check = self_check;
                served.hidden = false;
                served.timing = false;
                served.reference_cache = cache;
                GradeOptions alone = served;
                alone.lab_processes = LabProcesses::PerCase;
                const GradeReport per_lab = grade(served), per_case = grade(alone);
                // Status and score: a picture that passes after other cases may differ within the tolerance from the one alone.
                const int noted = test::check_graded_alike(per_case, per_lab, lab + " stateful variant '" + v.string_at("name") + "'",
                                                           false, false);
                INFO(lab << " (" << (self_check ? "self-check" : "live") << ") stateful variant '" << v.string_at("name") << "'");
                CHECK(noted >= 1);
                CHECK(per_lab.score() == per_lab.max_score());
                CHECK(per_case.score() == per_case.max_score());
            }
            unsetenv(kKnownMistakeVariable);
        }
    }
}
