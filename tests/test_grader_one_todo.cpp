// Progress TODO by TODO (issue 40): a student works one TODO at a time. For every case of every lab, the reference with
// every TODO left as the starter has it but the case's own and those it declares as "needs" must pass the case: a
// public case in the self-check, as a student's lab would; a hidden case (drawn from the fixture's seed) in instructor
// grading, whose blame ("needs L01-T1 first") reads the same declarations. Each lab's cases are grouped by the TODOs
// done, one grading per group and kind. A C++ TODO left undone is the starter's binary (each lab has
// at most one C++ TODO: its build is the kit's own starter build).
#include "grader_fixture.h"
#include "per_lab.h"

#include "common/app/kit_layout.h"
#include "tools/starter.h"

#include <map>
#include <set>

using namespace gsv;
namespace fs = std::filesystem;

namespace {

std::string joined(const std::set<std::string>& items) {
    std::string out;
    for (const auto& i : items) out += (out.empty() ? "" : ", ") + i;
    return out;
}

void one_todo_at_a_time(const std::string& lab) {
    const KitLayout kit{test::source_root()};
    const std::string lab_dir = test::mutant_spec(lab).string_at("lab_dir");
    const fs::path solution = kit.solutions() / lab_dir;
    const auto todos = test::todo_files(lab_dir);
    std::set<std::string> cpp_todos;
    for (const auto& [todo, files] : todos)
        for (const auto& f : files)
            if (is_cpp_file(f)) cpp_todos.insert(todo);
    REQUIRE(cpp_todos.size() <= 1);
    LabCases cases = load_lab_cases(kit.case_file(lab));
    add_hidden_cases(cases, kit.hidden_case_file(lab), *test::instructor_options(lab, {}).seed);
    // The TODOs done, and whether the cases are hidden -> the cases they must pass.
    std::map<std::pair<std::set<std::string>, bool>, std::vector<std::string>> groups;
    int need_nothing = 0, needs = 0, public_cases = 0, hidden_cases = 0, hidden_need_nothing = 0, hidden_needs = 0;
    for (const GradeCase& c : cases.cases) {
        if (c.visibility != "public" && c.visibility != "hidden") continue;
        const bool hidden = c.visibility == "hidden";
        std::set<std::string> done{c.todo};
        done.insert(c.needs.begin(), c.needs.end());
        groups[{done, hidden}].push_back(c.name);
        (hidden ? hidden_cases : public_cases) += 1;
        (hidden ? hidden_need_nothing : need_nothing) += c.needs.empty();
        (hidden ? hidden_needs : needs) += static_cast<int>(c.needs.size());
    }
    std::string failures;
    for (const auto& [group, names] : groups) {
        const auto& [done, hidden] = group;
        test::TempDir dir;
        const fs::path root = dir.path("kit");
        fs::create_directories(root / "solutions");
        fs::create_directory_symlink(kit.shaders(), root / "shaders");
        fs::create_directory_symlink(kit.data(), root / "data");
        fs::copy(solution, root / "solutions" / lab_dir, fs::copy_options::recursive);
        for (const auto& e : fs::directory_iterator(root / "solutions" / lab_dir)) {
            const std::string text = make_partial_starter(test::read_text(e.path()), e.path().filename().string(), done).text;
            std::ofstream(e.path(), std::ios::binary | std::ios::trunc) << text;
        }
        // The C++ TODO left undone: the kit's starter build, which reads its lab folder from labs/.
        const bool cpp_undone = !cpp_todos.empty() && !done.count(*cpp_todos.begin());
        fs::create_directories(root / "labs");
        fs::copy(root / "solutions" / lab_dir, root / "labs" / lab_dir, fs::copy_options::recursive);
        fs::create_directories(dir.path("bin"));
        fs::copy_file(test::bin_dir() / (cpp_undone ? lab : lab + "_solution"), dir.path("bin") / lab);
        GradeOptions options = test::instructor_options(lab, dir.path("out"));
        options.student_bin_dir = dir.path("bin");
        options.student_root = root;
        options.self_check = !hidden;
        options.hidden = hidden;
        options.timing = false;
        options.cases = names;
        const GradeReport report = grade(options);
        for (const auto& r : report.results)
            if (r.status != CaseStatus::Passed)
                failures += "  " + r.name + " (" + r.todo + ") with only " + joined(done) + " done: " + status_name(r.status) + ", " +
                            r.detail.substr(0, 160) + "\n";
    }
    INFO(lab << ": cases that need a TODO they do not declare (grader/cases/" << lab << ".json or grader/hidden/" << lab
              << ".json, \"needs\"):\n" << failures);
    CHECK(failures.empty());
    char line[300];
    std::snprintf(line, sizeof line,
                  "%s: %d public cases, %d need no other TODO, %.2f other TODOs needed on average; %d hidden cases drawn, "
                  "%d need no other TODO, %.2f needed on average; %zu gradings",
                  lab.c_str(), public_cases, need_nothing, double(needs) / public_cases, hidden_cases, hidden_need_nothing,
                  double(hidden_needs) / std::max(1, hidden_cases), groups.size());
    WARN(line);
}

}  // namespace

GSV_PER_LAB_TEST("each case passes with its TODO and the TODOs it declares done, the rest the starter's", "[grader][mutants]",
                 one_todo_at_a_time)
