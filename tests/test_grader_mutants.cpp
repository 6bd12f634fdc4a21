// Proof that the grader works: known-wrong variants of the reference (mutants) each fail the case that
// names their bug, and planted faults each get their own status while the rest is still graded.
// tests/mutants/<lab>.json lists them as text edits of the solution's files.
#include "catch.hpp"
#include "gl_fixture.h"
#include "lab_runner.h"
#include "test_support.h"

#include "common/json.h"
#include "grader/grade.h"

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

using namespace gsv;
namespace fs = std::filesystem;

namespace {


// A kit whose labs/<lab_dir> is the solution with one edit; GSV_ROOT points both binaries at it, so the
// "student" lab reads the edited shaders and the reference reads the untouched solution.
class EditedKit {
public:
    EditedKit(const std::string& lab_dir, const Json& edit) {
        const fs::path root = dir_.path();
        fs::copy(test::source_root() / "shaders", root / "shaders", fs::copy_options::recursive);
        fs::copy(test::source_root() / "data", root / "data", fs::copy_options::recursive);
        fs::create_directories(root / "solutions");
        fs::create_directories(root / "labs");
        fs::copy(test::source_root() / "solutions" / lab_dir, root / "solutions" / lab_dir, fs::copy_options::recursive);
        fs::copy(test::source_root() / "solutions" / lab_dir, root / "labs" / lab_dir, fs::copy_options::recursive);
        const fs::path file = root / "labs" / lab_dir / edit.string_at("file");
        std::string text = test::read_text(file);
        const std::string find = edit.string_at("find");
        const auto at = text.find(find);
        if (at == std::string::npos) FAIL("mutant '" << edit.string_at("name") << "': '" << find << "' not found in " << file);
        text.replace(at, find.size(), edit.string_at("replace"));
        std::ofstream(file, std::ios::binary) << text;
        setenv("GSV_ROOT", root.c_str(), 1);
    }
    ~EditedKit() { unsetenv("GSV_ROOT"); }
    fs::path out() const { return dir_.path("out"); }

private:
    test::TempDir dir_;
};

std::map<std::string, CaseResult> grade_edited(const std::string& lab, const std::string& lab_dir, const Json& edit,
                                               double timeout_s) {
    EditedKit kit(lab_dir, edit);
    GradeOptions options;
    options.kit_root = test::source_root();
    options.bin_dir = test::bin_dir();
    options.out_dir = kit.out();
    options.labs = {lab};
    options.timeout_s = timeout_s;
    std::map<std::string, CaseResult> by_case;
    for (const auto& r : grade(options)) by_case[r.name] = r;
    return by_case;
}

}  // namespace

TEST_CASE("grader: every mutant of lab01 fails the case that names its bug", "[grader]") {
    const Json spec = read_json_file(test::source_root() / "tests" / "mutants" / "lab01.json");
    for (const Json& mutant : spec.array_at("mutants").as_array()) {
        const auto results = grade_edited(spec.string_at("lab"), spec.string_at("lab_dir"), mutant, 60);
        for (const Json& name : mutant.array_at("must_fail").as_array()) {
            INFO("mutant '" << mutant.string_at("name") << "', case " << name.as_string());
            REQUIRE(results.count(name.as_string()) == 1);
            const CaseResult& r = results.at(name.as_string());
            CHECK(r.status == CaseStatus::WrongImage);
            CHECK(r.points == 0);
            CHECK(r.reference == "live");
        }
    }
}

TEST_CASE("grader: planted faults each get their own status, and every case is still graded", "[grader]") {
    const Json spec = read_json_file(test::source_root() / "tests" / "mutants" / "lab01.json");
    for (const Json& fault : spec.array_at("faults").as_array()) {
        // The slow shader gets a short limit and dies by SIGKILL.
        const auto results = grade_edited(spec.string_at("lab"), spec.string_at("lab_dir"), fault, fault.number_or("timeout_s", 60));
        REQUIRE(results.size() >= 8);
        for (const auto& [name, r] : results) {
            INFO("fault '" << fault.string_at("name") << "', case " << name << ": " << r.detail);
            CHECK(std::string(status_name(r.status)) == fault.string_at("status"));
            CHECK(r.points == 0);
        }
        if (fault.string_at("status") == "shader error") {
            const CaseResult& r = results.begin()->second;
            CHECK(r.detail.find("shader compile error") != std::string::npos);
            CHECK(r.output.find("phong.glsl:") != std::string::npos);
            CHECK(r.output.find("vec3 r = reflect(-l, n) +;") != std::string::npos);
        }
    }
}
