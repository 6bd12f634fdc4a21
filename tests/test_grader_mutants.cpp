// Proof that the grader works on shader edits: known-wrong variants of the reference (mutants) each fail
// the case that names their bug, and planted faults each get their own status while the rest is graded.
#include "grader_fixture.h"

using namespace gsv;

TEST_CASE("grader: every mutant of every lab fails the case that names its bug", "[grader]") {
    for (const auto& lab : test::labs_with_mutants()) {
        const Json spec = test::mutant_spec(lab);
        for (const Json& mutant : spec.array_at("mutants").as_array()) {
            test::EditedKit kit(lab, spec.string_at("lab_dir"), mutant);
            GradeOptions options = kit.options();
            options.hidden = false;
            options.timing = false;
            for (const Json& name : mutant.array_at("must_fail").as_array()) options.cases.push_back(name.as_string());
            const auto results = test::by_name(grade(options));
            for (const Json& name : mutant.array_at("must_fail").as_array()) {
                INFO(lab << " mutant '" << mutant.string_at("name") << "', case " << name.as_string());
                REQUIRE(results.count(name.as_string()) == 1);
                const CaseResult& r = results.at(name.as_string());
                INFO(r.detail);
                CHECK(std::string(status_name(r.status)) == mutant.string_or("status", "wrong image"));
                CHECK(r.points == 0);
                CHECK(r.reference == "live");
                if (r.status == CaseStatus::WrongImage) CHECK(std::filesystem::exists(kit.out() / r.diff_png));
            }
        }
    }
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
            CHECK(r.detail.find("shader compile error") != std::string::npos);
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
