#include "grader/src/judge/data_check.h"

#include "common/core/error.h"
#include "common/core/find_named.h"
#include "grader/src/golden/array_golden.h"
#include "grader/src/judge/array_compare.h"

namespace gsv {
namespace {

void reference_failed(CaseResult& r, const std::string& why) {
    r.status = CaseStatus::ReferenceFailed;
    r.points = 0;
    r.detail = why;
}

std::string names_of(const DataCheck& data) {
    std::string names;
    for (const auto& a : data.arrays) names += (names.empty() ? "" : ", ") + a.name;
    return names;
}

}  // namespace

DataCheck compare_data(const std::vector<DataArray>& student, const std::vector<ExpectedArray>& expected,
                       const ArrayTolerance& tolerance, const std::string& reference) {
    DataCheck data;
    data.done = true;
    data.reference = reference;
    data.tolerance = tolerance;
    for (const auto& e : expected) data.arrays.push_back(compare_array(find_named(student, e.name), e, tolerance));
    return data;
}

void apply_data_check(CaseResult& r, const DataCheck& data) {
    r.data = data;
    if (data.passed()) {
        if (r.status == CaseStatus::Passed && !data.arrays.empty()) r.detail += "; arrays match: " + names_of(data);
        // The numbers are right and only the picture is not: say so first, since it changes where to look (how they
        // are drawn, or where this GPU places a point), not what was computed.
        if (r.status == CaseStatus::WrongImage && !data.arrays.empty())
            r.detail = data.describes + " match the reference (" + names_of(data) + "); the picture differs: " + r.detail;
        if (r.status == CaseStatus::GpuMargin && !data.arrays.empty())
            r.detail = data.describes + " match the reference (" + names_of(data) + "); the picture " + r.detail;
        return;
    }
    std::string wrong;
    for (const auto& a : data.arrays)
        if (!a.within()) wrong += (wrong.empty() ? "" : "; ") + a.summary();
    if (r.status == CaseStatus::Passed) {
        r.status = CaseStatus::WrongData;
        r.points = 0;
        r.detail = wrong;
    } else if (r.status == CaseStatus::GpuMargin) {
        // Wrong numbers are no GPU's margin: the picture being near the golden is beside the point.
        r.status = CaseStatus::WrongData;
        r.detail = wrong + "; the picture is off too, by a margin seen between GPUs";
    } else {
        r.detail += (r.detail.empty() ? "" : "; ") + std::string("arrays: ") + wrong;
    }
}

void check_case_data(const LabCases& lab, const GradeCase& c, const LabRun& student, const LabRun& reference,
                     CaseResult& r) {
    if (!lab.checks_arrays()) return;
    std::vector<ExpectedArray> expected;
    if (c.arrays) {
        for (const auto& name : *c.arrays) {
            const DataArray* a = find_named(reference.arrays, name);
            if (!a) return reference_failed(r, "the reference solution handed in no '" + name + "' array, which the case checks");
            expected.push_back(expected_from(*a));
        }
    } else {
        for (const auto& a : reference.arrays) expected.push_back(expected_from(a));
    }
    if (student.status != CaseStatus::Passed) return;
    DataCheck data = compare_data(student.arrays, expected, *lab.live_array_tolerance, "live");
    data.describes = lab.arrays_are;
    apply_data_check(r, data);
}

void check_case_data(const LabCases& lab, const GradeCase& c, const LabRun& student, const std::filesystem::path& kit,
                     CaseResult& r) {
    if (!lab.checks_arrays()) return;
    std::vector<std::string> names = c.arrays ? *c.arrays : golden_array_names(kit, lab.lab, c.name);
    if (!c.arrays && names.empty() && student.status == CaseStatus::Passed && !student.arrays.empty())
        return reference_failed(r, "no golden array " + array_golden_path(kit, lab.lab, c.name, student.arrays.front().name).string() +
                                       " (run gsv-grade --update-goldens)");
    std::vector<ExpectedArray> expected;
    for (const auto& name : names) {
        const auto path = array_golden_path(kit, lab.lab, c.name, name);
        if (!std::filesystem::exists(path))
            return reference_failed(r, "no golden array " + path.string() + " (run gsv-grade --update-goldens)");
        try {
            expected.push_back(read_array_golden(path, name));
        } catch (const Error& e) {
            return reference_failed(r, std::string("the golden array is unreadable: ") + e.what());
        }
    }
    if (student.status != CaseStatus::Passed) return;
    DataCheck data = compare_data(student.arrays, expected, *lab.golden_array_tolerance, "golden");
    data.describes = lab.arrays_are;
    apply_data_check(r, data);
}

}  // namespace gsv
