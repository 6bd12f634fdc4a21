// "Needs another TODO first" (grader/src/judge/needs.h): blame lands on the TODO whose own cases fail for their own
// reason, never in a circle; only quality statuses are relabelled, integrity and process statuses stand.
#include "catch.hpp"
#include "grader/src/judge/needs.h"

#include <string>
#include <vector>

using gsv::CaseResult;
using gsv::CaseStatus;

namespace {

gsv::GradeCase grade_case(const std::string& name, const std::string& todo, std::vector<std::string> needs = {}) {
    gsv::GradeCase c;
    c.name = name;
    c.todo = todo;
    c.needs = std::move(needs);
    return c;
}

// Lab 02's cases that need each other: one-step (T1) needs T2, one-step-back (T2) needs T1.
gsv::LabCases lab02_like() {
    gsv::LabCases lab;
    lab.lab = "lab02";
    lab.cases = {grade_case("rotation", "L02-T1"), grade_case("one-step", "L02-T1", {"L02-T2"}),
                 grade_case("both-ways", "L02-T2"), grade_case("one-step-back", "L02-T2", {"L02-T1"}),
                 grade_case("border", "L02-T3", {"L02-T1", "L02-T2"})};
    return lab;
}

std::vector<CaseResult> rows(const gsv::LabCases& lab, const std::vector<std::pair<std::string, CaseStatus>>& statuses) {
    std::vector<CaseResult> results;
    for (const auto& [name, status] : statuses) {
        CaseResult r;
        r.lab = lab.lab;
        r.name = name;
        for (const auto& c : lab.cases)
            if (c.name == name) r.todo = c.todo;
        r.status = status;
        r.detail = "max diff 40";
        results.push_back(r);
    }
    return results;
}

const CaseResult& row(const std::vector<CaseResult>& results, const std::string& name) {
    for (const auto& r : results)
        if (r.name == name) return r;
    FAIL("no row " << name);
    return results.front();
}

}  // namespace

TEST_CASE("needs: two TODOs that need each other never blame each other when only one is wrong", "[unit]") {
    const gsv::LabCases lab = lab02_like();
    // Only L02-T1 is wrong: its own case rotation fails, and so does every case that needs it.
    auto results = rows(lab, {{"rotation", CaseStatus::WrongImage}, {"one-step", CaseStatus::WrongImage},
                              {"both-ways", CaseStatus::Passed}, {"one-step-back", CaseStatus::WrongImage},
                              {"border", CaseStatus::WrongImage}});
    gsv::blame_needed_todos(lab, results, 0);
    // T1's own one-step needs T2, which fails only for T1: no one else to blame, its own status stands.
    CHECK(row(results, "one-step").status == CaseStatus::WrongImage);
    CHECK(row(results, "rotation").status == CaseStatus::WrongImage);
    CHECK(row(results, "one-step-back").status == CaseStatus::NeedsFirst);
    CHECK(row(results, "one-step-back").detail.rfind("needs L02-T1 first (its case 'rotation' fails)", 0) == 0);
    // border needs T1 and T2; T2 fails only for T1, so the root is named once.
    CHECK(row(results, "border").status == CaseStatus::NeedsFirst);
    CHECK(row(results, "border").detail.rfind("needs L02-T1 first", 0) == 0);
}

TEST_CASE("needs: a need that fails only for its own needs is blamed on the root it comes down to", "[unit]") {
    gsv::LabCases lab;
    lab.lab = "lab05";
    lab.cases = {grade_case("fountain", "L05-T1"), grade_case("abc", "L05-T3"), grade_case("fountain-euler", "L05-T3", {"L05-T1"}),
                 grade_case("spare", "L05-T2", {"L05-T3"})};
    auto results = rows(lab, {{"fountain", CaseStatus::WrongImage}, {"abc", CaseStatus::Passed},
                              {"fountain-euler", CaseStatus::WrongImage}, {"spare", CaseStatus::WrongData}});
    gsv::blame_needed_todos(lab, results, 0);
    const CaseResult& spare = row(results, "spare");
    CHECK(spare.status == CaseStatus::NeedsFirst);
    INFO(spare.detail);
    CHECK(spare.detail.rfind("needs L05-T1 first (its case 'fountain' fails; L05-T3, which this case needs, waits on it)", 0) == 0);
    CHECK(spare.detail.find("needs L05-T3 first") == std::string::npos);
}

TEST_CASE("needs: integrity and process statuses stand under a failing needed TODO, the need added to their detail", "[unit]") {
    const gsv::LabCases lab = lab02_like();
    for (const CaseStatus status : {CaseStatus::CopiedImage, CaseStatus::Refused, CaseStatus::Crash, CaseStatus::Timeout,
                                    CaseStatus::MemoryLimit, CaseStatus::WroteTooMuch, CaseStatus::NonFinite,
                                    CaseStatus::OutputFlood, CaseStatus::ShaderCompileError, CaseStatus::Error}) {
        auto results = rows(lab, {{"rotation", CaseStatus::WrongImage}, {"both-ways", CaseStatus::Passed},
                                  {"one-step-back", status}});
        gsv::blame_needed_todos(lab, results, 0);
        INFO(gsv::status_name(status));
        CHECK(row(results, "one-step-back").status == status);
        CHECK(row(results, "one-step-back").detail.find("needs L02-T1 first") != std::string::npos);
    }
    // Quality statuses are the ones a needed TODO explains.
    for (const CaseStatus status : {CaseStatus::WrongImage, CaseStatus::BlankImage, CaseStatus::NotDone, CaseStatus::WrongData,
                                    CaseStatus::GpuMargin}) {
        auto results = rows(lab, {{"rotation", CaseStatus::WrongImage}, {"one-step-back", status}});
        gsv::blame_needed_todos(lab, results, 0);
        INFO(gsv::status_name(status));
        CHECK(row(results, "one-step-back").status == CaseStatus::NeedsFirst);
    }
}

TEST_CASE("needs: a copied image in a needed TODO's case makes it a root, and the copy is not hidden by it", "[unit]") {
    const gsv::LabCases lab = lab02_like();
    // The copy is in T2's own case; T1 fails too. Before, the copy became "needs L02-T1 first".
    auto results = rows(lab, {{"rotation", CaseStatus::WrongImage}, {"both-ways", CaseStatus::Passed},
                              {"one-step-back", CaseStatus::CopiedImage}});
    gsv::blame_needed_todos(lab, results, 0);
    CHECK(row(results, "one-step-back").status == CaseStatus::CopiedImage);
}

TEST_CASE("needs: where both TODOs are wrong on their own, each case names the other as what it needs", "[unit]") {
    const gsv::LabCases lab = lab02_like();
    auto results = rows(lab, {{"rotation", CaseStatus::WrongImage}, {"one-step", CaseStatus::WrongImage},
                              {"both-ways", CaseStatus::WrongImage}, {"one-step-back", CaseStatus::WrongImage}});
    gsv::blame_needed_todos(lab, results, 0);
    CHECK(row(results, "rotation").status == CaseStatus::WrongImage);
    CHECK(row(results, "both-ways").status == CaseStatus::WrongImage);
    CHECK(row(results, "one-step").detail.rfind("needs L02-T2 first (its case 'both-ways' fails)", 0) == 0);
    CHECK(row(results, "one-step-back").detail.rfind("needs L02-T1 first (its case 'rotation' fails)", 0) == 0);
}

TEST_CASE("needs: passes, build errors and the kit's faults are never relabelled", "[unit]") {
    const gsv::LabCases lab = lab02_like();
    auto results = rows(lab, {{"rotation", CaseStatus::WrongImage}, {"one-step-back", CaseStatus::ReferenceFailed},
                              {"border", CaseStatus::Passed}});
    gsv::blame_needed_todos(lab, results, 0);
    CHECK(row(results, "one-step-back").status == CaseStatus::ReferenceFailed);
    CHECK(row(results, "one-step-back").detail == "max diff 40");
    CHECK(row(results, "border").status == CaseStatus::Passed);
}
