// The numbers a lab hands in besides its image: compared element by element, sampled into goldens, read back
// strictly from a lab that may be student code, and folded into a case's result after its image.
#include "catch.hpp"
#include "test_support.h"

#include "common/image/image.h"
#include "common/io/data_array.h"
#include "common/io/handin.h"
#include "common/io/json.h"
#include "common/io/little_endian.h"
#include "grader/src/golden/array_golden.h"
#include "grader/src/update/golden_update.h"
#include "grader/src/grade/grade.h"
#include "grader/src/judge/array_compare.h"
#include "grader/src/judge/data_check.h"
#include "grader/src/report/report.h"
#include "common/io/handin.h"
#include "common/io/little_endian.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>

using namespace gsv;
namespace fs = std::filesystem;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// count elements of 4 components: (i, i/2, -i, 1) / 10.
DataArray ramp(const std::string& name, std::size_t count, int components = 4) {
    DataArray a{name, components, {}};
    for (std::size_t i = 0; i < count; ++i)
        for (int c = 0; c < components; ++c)
            a.values.push_back(c == 3 ? 1.0f : float(i) * (c == 0 ? 0.1f : c == 1 ? 0.05f : -0.1f));
    return a;
}

ArrayDiff diff(const DataArray& actual, const DataArray& expected, double max_abs = 1e-4, double fraction = 0) {
    return compare_array(&actual, expected_from(expected), {max_abs, fraction});
}

std::string le_u32(std::uint32_t v) {
    unsigned char b[4];
    u32_to_le_bytes(v, b);
    return std::string(reinterpret_cast<char*>(b), 4);
}

std::string le_f32s(const std::vector<float>& values) {
    std::string bytes;
    for (const float v : values) {
        unsigned char b[4];
        float_to_le_bytes(v, b);
        bytes.append(reinterpret_cast<char*>(b), 4);
    }
    return bytes;
}

std::string golden_bytes(std::uint32_t count, std::uint32_t components, std::uint32_t samples,
                         const std::vector<std::uint32_t>& indices, const std::vector<float>& values) {
    std::string bytes("GSVARR1\0", 8);
    bytes += le_u32(count) + le_u32(components) + le_u32(samples);
    for (const auto i : indices) bytes += le_u32(i);
    return bytes + le_f32s(values);
}

// A lab's JSON report listing one array.
LabCases lab_checking_arrays() {
    LabCases lab;
    lab.lab = "lab99";
    lab.live_array_tolerance = ArrayTolerance{1e-4, 0};
    lab.golden_array_tolerance = ArrayTolerance{1e-3, 0};
    return lab;
}

LabRun run_with(std::vector<DataArray> arrays) {
    LabRun run;
    run.status = CaseStatus::Passed;
    run.arrays = std::move(arrays);
    return run;
}

CaseResult image_passed() {
    CaseResult r;
    r.status = CaseStatus::Passed;
    r.points = r.max_points = 2;
    r.detail = "identical";
    return r;
}

}  // namespace

TEST_CASE("arrays: an element differs past max_abs in any component, and the differing fraction decides", "[grader][arrays]") {
    const DataArray reference = ramp("positions", 1000);
    CHECK(diff(reference, reference).within());
    CHECK(diff(reference, reference).differing == 0);

    DataArray near = reference;
    near.values[4 * 10 + 1] += 0.5e-4f;  // within max_abs
    CHECK(diff(near, reference).differing == 0);
    CHECK(diff(near, reference).max_abs_diff > 0);

    DataArray off = reference;
    off.values[4 * 17 + 1] += 0.01f;  // element 17, its second component only
    off.values[4 * 500 + 3] = 2.0f;   // element 500
    const ArrayDiff d = diff(off, reference);
    CHECK(d.differing == 2);
    CHECK(d.compared == 1000);
    CHECK(d.first == 17);
    CHECK_FALSE(d.within());
    CHECK(diff(off, reference, 0.02).differing == 1);  // a looser max_abs: only element 500
    // Two of 1000 may differ at a fraction of 0.002, not at 0.0019.
    CHECK(diff(off, reference, 1e-4, 0.002).within());
    CHECK_FALSE(diff(off, reference, 1e-4, 0.0019).within());
    // 0.003 * 1000 is 2.9999999999999996 in binary: exactly the written fraction still passes.
    off.values[4 * 900] += 1.0f;
    CHECK(diff(off, reference, 1e-4, 0.003).within());
}

TEST_CASE("arrays: NaN and Inf equal only the same on the reference's side", "[grader][arrays]") {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    DataArray reference{"v", 1, {1, nan, inf, -inf, 5, 6}};
    CHECK(diff(reference, reference).differing == 0);  // NaN where the reference has NaN counts as equal

    DataArray student{"v", 1, {nan, nan, inf, inf, 5, inf}};
    const ArrayDiff d = diff(student, reference, 1e9, 0);
    CHECK(d.differing == 3);    // NaN for 1, +Inf for -Inf, Inf for 6
    CHECK(d.non_finite == 2);   // where the reference is finite
    CHECK(d.first == 0);
    CHECK(contains(d.summary(), "first at element 0: (NaN) where the reference has (1)"));
    CHECK(contains(d.summary(), "; 2 of them NaN or Inf where the reference is finite"));

    DataArray finite_for_nan{"v", 1, {1, 2, inf, -inf, 5, 6}};  // a number where the reference has NaN
    CHECK(diff(finite_for_nan, reference, 1e9).differing == 1);
    CHECK(diff(finite_for_nan, reference, 1e9).non_finite == 0);
}

TEST_CASE("arrays: a missing array, or another count or number of components, fails naming both", "[grader][arrays]") {
    const DataArray reference = ramp("positions", 65536);
    const ArrayDiff missing = compare_array(nullptr, expected_from(reference), {1e-4, 0.001});
    CHECK_FALSE(missing.within());
    CHECK(missing.summary() == "the lab handed in no 'positions' array");

    const ArrayDiff fewer = diff(ramp("positions", 1000), reference);
    CHECK_FALSE(fewer.within());
    CHECK(fewer.summary() == "positions: 1,000 elements of 4 components where the reference has 65,536 of 4");
    const ArrayDiff narrower = diff(ramp("positions", 65536 * 4 / 2, 2), reference);
    CHECK(narrower.summary() == "positions: 131,072 elements of 2 components where the reference has 65,536 of 4");
}

TEST_CASE("arrays: the summary counts, gives the share, the first difference and the tolerance", "[grader][arrays]") {
    const DataArray reference = ramp("positions", 65536);
    DataArray student = reference;
    for (std::size_t i = 17; i < 17 + 1234; ++i) student.values[4 * i + 1] += 0.05f;
    const ArrayDiff d = diff(student, reference, 1e-4, 0.001);
    CHECK_FALSE(d.within());
    CHECK(d.summary().rfind("positions: 1,234 of 65,536 elements (1.9%) differ by more than 0.0001; first at element 17: "
                            "(1.7, 0.9, -1.7, 1) where the reference has (1.7, 0.85, -1.7, 1)",
                            0) == 0);
    CHECK(diff(reference, reference, 1e-4).summary() == "positions: all 65,536 elements within 0.0001 (max diff 0)");
    // Values that differ past the 7th digit are shown with 9, so the two never read the same.
    DataArray tiny{"t", 1, {1.0f}}, other{"t", 1, {std::nextafter(1.0f, 2.0f)}};
    CHECK(contains(diff(other, tiny, 0).summary(), "(1.00000012) where the reference has (1)"));
    CHECK(with_commas(0) == "0");
    CHECK(with_commas(999) == "999");
    CHECK(with_commas(1000) == "1,000");
    CHECK(with_commas(1234567) == "1,234,567");
}

TEST_CASE("arrays: a golden sample round trip keeps every element up to 4096, else a stride and the last 64", "[grader][arrays]") {
    test::TempDir dir;
    CHECK(golden_sample_indices(0).empty());
    CHECK(golden_sample_indices(4096).size() == 4096);
    CHECK(golden_sample_indices(4096).back() == 4095);

    const std::size_t count = 65536 + 1000;
    const std::vector<std::uint32_t> indices = golden_sample_indices(count);
    REQUIRE(indices.size() == 4096 + 64);
    CHECK(indices.front() == 0);
    bool ascending = true;
    for (std::size_t i = 1; i < indices.size(); ++i) ascending = ascending && indices[i] > indices[i - 1];
    CHECK(ascending);
    for (std::size_t i = 0; i < 64; ++i)  // the sentinels at the end are all kept
        CHECK(indices[4096 + i] == count - 64 + i);
    CHECK(indices[1] - indices[0] == (count - 64) / 4096);
    CHECK(indices[4095] < count - 64);
    CHECK(golden_sample_indices(4100).size() == 4100);  // 4036 before the tail: all of them
    CHECK(golden_sample_indices(4161).size() == 4160);

    const DataArray array = ramp("positions", count);
    const ExpectedArray sample = sample_array(array);
    const fs::path file = dir.path("golden/lab99/a.positions.f32s");
    write_array_golden(file, sample);
    CHECK(fs::file_size(file) == 20 + indices.size() * 4 * 5);
    const ExpectedArray back = read_array_golden(file, "positions");
    CHECK(back.name == "positions");
    CHECK(back.count == count);
    CHECK(back.components == 4);
    CHECK(back.indices == indices);
    CHECK(back.values == sample.values);
    CHECK(back.values[4 * (back.indices.size() - 1)] == array.values[4 * (count - 1)]);

    // Against the golden only the sampled elements count: a change between two samples goes unseen, one in
    // the tail does not.
    DataArray between = array, tail = array;
    between.values[4 * 5] += 1.0f;
    tail.values[4 * (count - 3)] += 1.0f;
    const ArrayTolerance tolerance{1e-4, 0};
    CHECK(compare_array(&array, back, tolerance).within());
    CHECK(compare_array(&array, back, tolerance).compared == indices.size());
    CHECK(compare_array(&between, back, tolerance).within());
    const ArrayDiff d = compare_array(&tail, back, tolerance);
    CHECK_FALSE(d.within());
    CHECK(d.first == count - 3);
    CHECK(contains(d.summary(), "1 of 4,160 sampled elements"));

    // A small array is kept whole.
    write_array_golden(dir.path("small.f32s"), sample_array(ramp("v", 10, 3)));
    const ExpectedArray small = read_array_golden(dir.path("small.f32s"), "v");
    CHECK(small.indices.size() == 10);
    CHECK(small.values == ramp("v", 10, 3).values);

    // The goldens a case has, by name; another case's and other files are not its.
    write_array_golden(dir.path("golden/lab99/a.velocities.f32s"), sample);
    write_array_golden(dir.path("golden/lab99/ab.positions.f32s"), sample);
    dir.write("golden/lab99/a.png", "x");
    CHECK(golden_array_names(dir.path(), "lab99", "a").empty());  // not under grader/golden
    fs::rename(dir.path("golden"), dir.path("grader-golden"));
    fs::create_directories(dir.path("grader"));
    fs::rename(dir.path("grader-golden"), dir.path("grader/golden"));
    CHECK(golden_array_names(dir.path(), "lab99", "a") == std::vector<std::string>{"positions", "velocities"});
    CHECK(array_golden_path(dir.path(), "lab99", "a", "positions") == dir.path("grader/golden/lab99/a.positions.f32s"));
}

TEST_CASE("arrays: a corrupt, truncated or lying golden is one line naming the file", "[grader][arrays]") {
    test::TempDir dir;
    auto message = [&](const std::string& bytes) {
        const fs::path file = dir.write("g.f32s", bytes);
        return test::gsv_error_message([&] { read_array_golden(file, "positions"); });
    };
    const std::string good = golden_bytes(3, 2, 2, {0, 2}, {1, 2, 3, 4});
    CHECK(message(good) == "<no gsv::Error thrown>");
    for (const auto& [bytes, why] : std::vector<std::pair<std::string, std::string>>{
             {"", "shorter than the 20-byte header"},
             {"GSVARR1", "shorter than the 20-byte header"},
             {"PNG\0\0\0\0\0" + good.substr(8), "not a golden array"},
             {good.substr(0, good.size() - 1), "not the 44 its header promises"},
             {good + "x", "45 bytes, not the 44"},
             {golden_bytes(3, 0, 2, {0, 2}, {1, 2}), "0 components"},
             {golden_bytes(3, 17, 0, {}, {}), "17 components"},
             {golden_bytes(3, 2, 4000000000u, {0, 2}, {1, 2, 3, 4}), "4000000000 samples of an array of 3"},
             {golden_bytes(4000000000u, 16, 2, {0, 2}, {1, 2, 3, 4}), "more than the 67108864"},
             {golden_bytes(3, 2, 2, {2, 0}, {1, 2, 3, 4}), "indices must ascend"},
             {golden_bytes(3, 2, 2, {0, 3}, {1, 2, 3, 4}), "names element 3"},
         }) {
        const std::string m = message(bytes);
        INFO(m);
        CHECK(contains(m, "golden array '" + dir.path("g.f32s").string() + "': "));
        CHECK(contains(m, why));
        CHECK_FALSE(contains(m, "\n"));
    }
    CHECK(contains(test::gsv_error_message([&] { read_array_golden(dir.path("none.f32s"), "p"); }), "no such file"));
}

TEST_CASE("arrays: a lab's array files, and its array messages to the grader, are read back strictly", "[grader][arrays]") {
    // Render mode outside the grader: a file beside the PNG.
    test::TempDir dir;
    const fs::path png = dir.path("out.png");
    const fs::path file = data_array_path(png, "positions");
    CHECK(file == dir.path("out.positions.f32"));
    const DataArray positions = ramp("positions", 5);
    write_f32_file(file, positions.values);
    CHECK(fs::file_size(file) == 5 * 4 * 4);
    CHECK(read_f32_file(file, 20) == positions.values);

    // Under the grader: a message on the hand-in socket, read whole or refused in one line.
    const std::vector<std::uint8_t> good = array_payload("positions", 4, positions.values);
    const HandinArray read = read_array_payload(good);
    CHECK(read.name == "positions");
    CHECK(read.components == 4);
    CHECK(read.count == 5);
    CHECK(read.values == positions.values);
    auto message = [&](std::vector<std::uint8_t> bytes) { return test::gsv_error_message([&] { read_array_payload(bytes); }); };
    auto with_u32 = [&](std::size_t at, std::uint32_t value) {
        std::vector<std::uint8_t> bytes = good;
        u32_to_le_bytes(value, bytes.data() + at);
        return bytes;
    };
    const std::size_t name_end = 4 + std::string("positions").size();
    const std::vector<std::pair<std::vector<std::uint8_t>, std::string>> lies{
        {with_u32(name_end + 4, 6), "6 x 4 floats declared, 80 bytes sent"},
        {with_u32(name_end + 4, 2000000000), "more than the 67108864"},  // refused before anything is allocated
        {with_u32(name_end, 0), "array 'positions' has 0 components, not 1..16"},
        {with_u32(name_end, 17), "17 components"},
        {with_u32(0, 41), "an array of 41 bytes"},
        {with_u32(0, 400), "an array of 400 bytes"},
        {array_payload("Positions", 4, positions.values), "not 1..40 of a-z, 0-9, '_'"},
        {array_payload("../x", 4, positions.values), "not 1..40 of a-z, 0-9, '_'"},
        {std::vector<std::uint8_t>(good.begin(), good.begin() + 6), "ends before its content does"},
        {std::vector<std::uint8_t>(good.begin(), good.end() - 1), "floats declared"},
    };
    for (const auto& [bytes, why] : lies) {
        const std::string m = message(bytes);
        INFO(m);
        CHECK(contains(m, why));
        CHECK_FALSE(contains(m, "\n"));
    }
    // The header's size is checked before the payload is read: an array larger than all the grader takes never
    // arrives, and neither does a message no lab sends.
    CHECK(contains(test::gsv_error_message([&] { checked_payload_size(kTagArray, 0xffffffffu, 64, kMaxArrayFloats / 4); }),
                   "over the"));
    CHECK(contains(test::gsv_error_message([&] { checked_payload_size(HandinTag{'/', 'e', 't', 'c'}, 4, 64, 64); }),
                   "which is no message of the hand-in"));
}

TEST_CASE("arrays: render mode's files, and a malformed readback is the lab's own error", "[grader][arrays]") {
    test::TempDir dir;
    CHECK(data_array_path("phong.png", "positions") == fs::path("phong.positions.f32"));
    CHECK(valid_array_name("positions_2"));
    CHECK_FALSE(valid_array_name(""));
    CHECK_FALSE(valid_array_name("Positions"));
    CHECK_FALSE(valid_array_name("a.b"));
    CHECK_FALSE(valid_array_name(std::string(41, 'a')));

    const std::vector<float> values{1.5f, -0.0f, std::numeric_limits<float>::quiet_NaN(), 3e38f};
    write_f32_file(dir.path("v.f32"), values);
    CHECK(test::read_text(dir.path("v.f32")) == le_f32s(values));  // raw little-endian, nothing else
    const std::vector<float> back = read_f32_file(dir.path("v.f32"), 4);
    CHECK(back[0] == 1.5f);
    CHECK(std::signbit(back[1]));
    CHECK(std::isnan(back[2]));
    CHECK(contains(test::gsv_error_message([&] { read_f32_file(dir.path("v.f32"), 5); }), "16 bytes, not the 5 float32 values"));
    const std::string blocked = test::gsv_error_message([&] { write_f32_file(dir.path(), values); });
    CHECK(blocked.rfind("cannot write array file '" + dir.path().string() + "'", 0) == 0);

    CHECK_NOTHROW(check_data_arrays({ramp("positions", 3), ramp("velocities", 3)}));
    CHECK(test::gsv_error_message([] { check_data_arrays({ramp("Bad Name", 1)}); }).rfind("readback array 'Bad Name': a name must be", 0) == 0);
    CHECK(contains(test::gsv_error_message([] { check_data_arrays({ramp("p", 1), ramp("p", 2)}); }), "'p' is handed in twice"));
    CHECK(contains(test::gsv_error_message([] { check_data_arrays({DataArray{"p", 4, {1, 2, 3}}}); }),
                   "3 values, not a whole number of 4-component elements"));
    CHECK(contains(test::gsv_error_message([] { check_data_arrays({DataArray{"p", 0, {}}}); }), "0 components"));
}

TEST_CASE("arrays: the data check after the image, live: wrong data, the image's status kept, the reference's fault", "[grader][arrays]") {
    const LabCases lab = lab_checking_arrays();
    GradeCase c;
    c.name = "a";
    const LabRun reference = run_with({ramp("positions", 100), ramp("velocities", 100)});

    CaseResult same = image_passed();
    check_case_data(lab, c, run_with(reference.arrays), reference, same);
    CHECK(same.status == CaseStatus::Passed);
    CHECK(same.points == 2);
    CHECK(same.detail == "identical; arrays match: positions, velocities");
    CHECK(same.data.done);
    CHECK(same.data.reference == "live");
    CHECK(same.data.arrays.size() == 2);

    DataArray moved = ramp("velocities", 100);
    moved.values[4 * 99] = 7;
    CaseResult wrong = image_passed();
    check_case_data(lab, c, run_with({ramp("positions", 100), moved}), reference, wrong);
    CHECK(wrong.status == CaseStatus::WrongData);
    CHECK(wrong.points == 0);
    CHECK(wrong.detail.rfind("velocities: 1 of 100 elements (1%) differ by more than 0.0001; first at element 99: (7, ", 0) == 0);
    CHECK(std::string(status_name(wrong.status)) == "wrong data");

    CaseResult missing = image_passed();
    check_case_data(lab, c, run_with({ramp("positions", 100)}), reference, missing);
    CHECK(missing.status == CaseStatus::WrongData);
    CHECK(missing.detail == "the lab handed in no 'velocities' array");

    // The image failed first: its status stands, the numbers are appended.
    CaseResult both = image_passed();
    both.status = CaseStatus::WrongImage;
    both.points = 0;
    both.detail = "max diff 200";
    check_case_data(lab, c, run_with({ramp("positions", 100), moved}), reference, both);
    CHECK(both.status == CaseStatus::WrongImage);
    CHECK(both.detail.rfind("max diff 200; arrays: velocities: 1 of 100", 0) == 0);

    // Only the picture failed: the detail says first that the numbers are right, in the lab's own word for them.
    CaseResult picture = image_passed();
    picture.status = CaseStatus::WrongImage;
    picture.points = 0;
    picture.detail = "max diff 200, 12 of 65536 px differ";
    check_case_data(lab, c, run_with(reference.arrays), reference, picture);
    CHECK(picture.status == CaseStatus::WrongImage);
    CHECK(picture.detail == "the arrays match the reference (positions, velocities); the picture differs: max diff 200, 12 of 65536 px differ");
    LabCases particles = lab;
    particles.arrays_are = "particles";
    CaseResult named = image_passed();
    named.status = CaseStatus::WrongImage;
    named.detail = "max diff 200";
    check_case_data(particles, c, run_with(reference.arrays), reference, named);
    CHECK(named.detail == "particles match the reference (positions, velocities); the picture differs: max diff 200");

    // The case checks only what it lists.
    c.arrays = std::vector<std::string>{"positions"};
    CaseResult listed = image_passed();
    check_case_data(lab, c, run_with({ramp("positions", 100), moved}), reference, listed);
    CHECK(listed.status == CaseStatus::Passed);
    CHECK(listed.data.arrays.size() == 1);
    c.arrays = std::vector<std::string>{"colors"};
    CaseResult lacking = image_passed();
    check_case_data(lab, c, run_with(reference.arrays), reference, lacking);
    CHECK(lacking.status == CaseStatus::ReferenceFailed);
    CHECK(lacking.points == 0);
    CHECK(contains(lacking.detail, "handed in no 'colors' array"));

    // A student run that failed keeps its own status; a lab that checks no arrays is left alone.
    c.arrays.reset();
    CaseResult crashed;
    crashed.status = CaseStatus::Crash;
    LabRun crash = run_with({});
    crash.status = CaseStatus::Crash;
    check_case_data(lab, c, crash, reference, crashed);
    CHECK(crashed.status == CaseStatus::Crash);
    CHECK_FALSE(crashed.data.done);
    CaseResult images_only = image_passed();
    check_case_data(LabCases{}, c, run_with({}), reference, images_only);
    CHECK(images_only.status == CaseStatus::Passed);
    CHECK_FALSE(images_only.data.done);
}

TEST_CASE("arrays: the data check against goldens: the golden tolerance, a sample, a missing golden is the kit's fault", "[grader][arrays]") {
    test::TempDir kit;
    const LabCases lab = lab_checking_arrays();
    GradeCase c;
    c.name = "a";
    const DataArray positions = ramp("positions", 10000);
    write_array_golden(array_golden_path(kit.path(), "lab99", "a", "positions"), sample_array(positions));

    CaseResult same = image_passed();
    check_case_data(lab, c, run_with({positions}), kit.path(), same);
    CHECK(same.status == CaseStatus::Passed);
    CHECK(same.data.reference == "golden");
    CHECK(same.data.tolerance.max_abs == 1e-3);  // the golden's own tolerance
    CHECK(same.data.arrays.at(0).compared == golden_sample_indices(10000).size());

    DataArray near = positions, sentinel = positions;
    near.values[4 * 9999] += 5e-4f;  // within the golden's 1e-3, not the live 1e-4
    sentinel.values[4 * 9999] += 1.0f;
    CaseResult near_result = image_passed();
    check_case_data(lab, c, run_with({near}), kit.path(), near_result);
    CHECK(near_result.status == CaseStatus::Passed);
    CaseResult moved = image_passed();
    check_case_data(lab, c, run_with({sentinel}), kit.path(), moved);
    CHECK(moved.status == CaseStatus::WrongData);
    CHECK(contains(moved.detail, "first at element 9999"));

    // A case whose goldens are gone, though its lab hands in arrays; a listed golden that is missing or broken.
    GradeCase other;
    other.name = "b";
    CaseResult lost = image_passed();
    check_case_data(lab, other, run_with({positions}), kit.path(), lost);
    CHECK(lost.status == CaseStatus::ReferenceFailed);
    CHECK(contains(lost.detail, "no golden array " + array_golden_path(kit.path(), "lab99", "b", "positions").string()));
    CHECK(contains(lost.detail, "--update-goldens"));
    CaseResult nothing = image_passed();
    check_case_data(lab, other, run_with({}), kit.path(), nothing);
    CHECK(nothing.status == CaseStatus::Passed);  // nothing handed in, nothing to check against

    c.arrays = std::vector<std::string>{"positions", "velocities"};
    CaseResult listed = image_passed();
    check_case_data(lab, c, run_with({positions}), kit.path(), listed);
    CHECK(listed.status == CaseStatus::ReferenceFailed);
    CHECK(contains(listed.detail, "a.velocities.f32s"));
    kit.write("grader/golden/lab99/a.velocities.f32s", "GSVARR1");
    CaseResult broken = image_passed();
    check_case_data(lab, c, run_with({positions}), kit.path(), broken);
    CHECK(broken.status == CaseStatus::ReferenceFailed);
    CHECK(contains(broken.detail, "the golden array is unreadable: golden array '"));
}

// A "lab" that is a small Python program: hands a fixed image and the arrays of its fixture folder in over the
// hand-in socket, as render mode does under the grader (common/io/handin.h), and answers timed frames with the same
// image. Grades end to end without GL: the runner, the hand-in, the check, the goldens.
namespace {

struct FakeLab {
    Image image;
    std::map<std::string, DataArray> arrays;
    std::map<std::string, std::uint32_t> listed_counts;  // name -> the count its message claims, where it lies
    std::string renderer;                                // GL_RENDERER its report names; "": none
};

void write_bytes(const fs::path& file, const std::vector<std::uint8_t>& bytes) {
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

void write_fake_lab(const fs::path& bin, const std::string& binary, const fs::path& fixture, const FakeLab& lab) {
    fs::remove_all(fixture);
    fs::create_directories(fixture);
    write_bytes(fixture / "image.msg", image_payload(std::uint32_t(lab.image.width), std::uint32_t(lab.image.height), lab.image.rgba));
    for (const auto& [name, a] : lab.arrays) {
        std::vector<std::uint8_t> payload = array_payload(name, std::uint32_t(a.components), a.values);
        if (const auto lie = lab.listed_counts.find(name); lie != lab.listed_counts.end())
            u32_to_le_bytes(lie->second, payload.data() + 4 + name.size() + 4);
        write_bytes(fixture / (name + ".arr"), payload);
    }
    const fs::path script = bin / binary;
    fs::create_directories(bin);
    std::ofstream(script) << "#!/usr/bin/env python3\n"
                             "import os, struct, sys\n"
                             "if sys.argv[1:2] == ['list']: sys.exit(0)\n"
                             "fixture = '" << fixture.string() << "'\n"
                             "fd = int(os.environ['GSV_HANDIN_FD'])\n"
                             "def send(tag, payload=b''):\n"
                             "    data = tag + struct.pack('<I', len(payload)) + payload\n"
                             "    while data: data = data[os.write(fd, data):]\n"
                             "def read(n):\n"
                             "    data = b''\n"
                             "    while len(data) < n:\n"
                             "        more = os.read(fd, n - len(data))\n"
                             "        if not more: sys.exit(0)\n"
                             "        data += more\n"
                             "    return data\n"
                             "def message():\n"
                             "    tag, size = read(4), struct.unpack('<I', read(4))[0]\n"
                             "    return tag, read(size)\n"
                             "image = open(os.path.join(fixture, 'image.msg'), 'rb').read()\n"
                             "def render_case():\n"
                             "    for name in sorted(f for f in os.listdir(fixture) if f.endswith('.arr')):\n"
                             "        send(b'ARR1', open(os.path.join(fixture, name), 'rb').read())\n"
                             "    send(b'IMG1', image)\n"
                             "    send(b'RPT1', b'{\"timing\": {\"median_ms\": 1}"
                          << (lab.renderer.empty() ? "" : ", \"gl\": {\"renderer\": \"" + lab.renderer + "\"}") << "}')\n"
                             "    send(b'RDY1')\n"
                             "    while True:\n"
                             "        tag, payload = message()\n"
                             "        if tag == b'END1': return\n"
                             "        send(b'FRM1', payload[:4] + image)\n"
                             // render --serve: a case per request, until the grader's END.
                             "if '--serve' in sys.argv: send(b'DNE1')\n"
                             "while '--serve' in sys.argv and message()[0] == b'CAS1':\n"
                             "    render_case()\n"
                             "    send(b'DNE1')\n"
                             "if '--serve' not in sys.argv: render_case()\n";
    fs::permissions(script, fs::perms::owner_all);
}

Image flat(std::uint8_t red) {
    Image image(4, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            std::uint8_t* p = image.at(x, y);
            p[0] = red, p[1] = static_cast<std::uint8_t>(x * 60), p[2] = static_cast<std::uint8_t>(y * 60), p[3] = 255;
        }
    return image;
}

// Grading the fake labs of `dir`'s kit/ and bin/ into `dir`/`out`.
GradeOptions fake_kit_options(const test::TempDir& dir, const std::string& out) {
    GradeOptions options;
    options.diagnose = DiagnoseCases::Off;  // the diagnosis has tests of its own (test_grader_diagnosis*.cpp)
    options.kit_root = dir.path("kit");
    options.bin_dir = dir.path("bin");
    options.out_dir = dir.path(out);
    options.sandbox = false;  // the scripts live in the test's own temporary folder
    options.seed = 1;
    return options;
}

CaseResult grade_one(const test::TempDir& dir, bool self_check) {
    GradeOptions options = fake_kit_options(dir, "out");
    options.self_check = self_check;
    const GradeReport report = grade(options);
    REQUIRE(report.results.size() == 1);
    return report.results[0];
}

}  // namespace

TEST_CASE("arrays: graded end to end through lab processes, live and against goldens", "[grader][arrays]") {
    test::TempDir dir;
    dir.write("kit/grader/cases/lab99.json", R"({"lab": "lab99", "size": "4x4", "timeout_s": 20,
        "tolerance": {"live": {"max_channel_diff": 0, "max_differing_fraction": 0},
                      "golden": {"max_channel_diff": 0, "max_differing_fraction": 0},
                      "arrays": {"max_abs": 1e-4, "max_differing_fraction": 0}},
        "cases": [{"name": "cloud", "todo": "L99-T1", "points": 3, "settings": []}]})");
    const FakeLab reference{flat(100), {{"positions", ramp("positions", 5000)}, {"velocities", ramp("velocities", 5000)}}, {}, ""};
    write_fake_lab(dir.path("bin"), "lab99_solution", dir.path("fixture/reference"), reference);

    FakeLab student = reference;
    write_fake_lab(dir.path("bin"), "lab99", dir.path("fixture/student"), student);
    CaseResult r = grade_one(dir, false);
    CHECK(r.status == CaseStatus::Passed);
    CHECK(r.points == 3);
    CHECK(r.data.arrays.size() == 2);

    student.arrays["velocities"].values[4 * 4999] = -1;  // the last particle moved
    write_fake_lab(dir.path("bin"), "lab99", dir.path("fixture/student"), student);
    r = grade_one(dir, false);
    CHECK(r.status == CaseStatus::WrongData);
    CHECK(r.points == 0);
    CHECK(r.detail.rfind("velocities: 1 of 5,000 elements (0.02%) differ by more than 0.0001; first at element 4999", 0) == 0);

    student.image = flat(0);
    write_fake_lab(dir.path("bin"), "lab99", dir.path("fixture/student"), student);
    r = grade_one(dir, false);
    CHECK(r.status == CaseStatus::WrongImage);
    CHECK(contains(r.detail, "; arrays: velocities: 1 of 5,000"));

    FakeLab liar = reference;
    liar.listed_counts["positions"] = 1000000;
    write_fake_lab(dir.path("bin"), "lab99", dir.path("fixture/student"), liar);
    r = grade_one(dir, false);
    CHECK(r.status == CaseStatus::Refused);
    CHECK(contains(r.detail, "array 'positions': 1000000 x 4 floats declared, 80000 bytes sent"));

    // The goldens: a compact sample beside the image, then the self-check uses them.
    GradeOptions update = fake_kit_options(dir, "out-update");
    const GradeReport updated = update_goldens(update);
    REQUIRE(updated.results.size() == 1);
    CHECK(updated.results[0].status == CaseStatus::Passed);
    CHECK(contains(updated.results[0].detail, "and 2 arrays"));
    const fs::path golden = dir.path("kit/grader/golden/lab99/cloud.positions.f32s");
    CHECK(fs::exists(dir.path("kit/grader/golden/lab99/cloud.png")));
    CHECK(fs::file_size(golden) == 20 + 4160 * 4 * 5);
    CHECK(fs::exists(dir.path("kit/grader/golden/lab99/cloud.velocities.f32s")));

    write_fake_lab(dir.path("bin"), "lab99", dir.path("fixture/student"), reference);
    r = grade_one(dir, true);
    CHECK(r.reference == "golden");
    CHECK(r.status == CaseStatus::Passed);
    CHECK(r.data.reference == "golden");

    student.image = flat(100);
    write_fake_lab(dir.path("bin"), "lab99", dir.path("fixture/student"), student);
    r = grade_one(dir, true);
    CHECK(r.status == CaseStatus::WrongData);  // the last element is always in the sample
    CHECK(contains(r.detail, "1 of 4,160 sampled elements"));

    // Without a list in the case, the goldens it has are what it checks.
    write_fake_lab(dir.path("bin"), "lab99", dir.path("fixture/student"), reference);
    fs::remove(golden);
    r = grade_one(dir, true);
    CHECK(r.status == CaseStatus::Passed);
    CHECK(r.data.arrays.size() == 1);
    fs::remove(dir.path("kit/grader/golden/lab99/cloud.velocities.f32s"));
    r = grade_one(dir, true);
    CHECK(r.status == CaseStatus::ReferenceFailed);
    CHECK(contains(r.detail, "no golden array"));
}

namespace {

// A 10x10 picture, `changed` of its pixels (from the top left, row by row) far off.
Image picture(int changed) {
    Image image(10, 10);
    for (int i = 0; i < 100; ++i) {
        std::uint8_t* p = image.at(i % 10, i / 10);
        p[0] = static_cast<std::uint8_t>(i * 2), p[1] = 90, p[2] = i < changed ? 250 : 30, p[3] = 255;
    }
    return image;
}

}  // namespace

// The goldens name the renderer they were made on (grader/golden/renderer.json); against goldens from another
// renderer, a picture off by more than its budget but within one and a half budgets is told it differs by a margin
// seen between GPUs (no points), with the command that shows it; anything else stays a wrong image.
TEST_CASE("grader: against another renderer's goldens, a picture within one and a half budgets is a GPU margin, said so", "[grader][arrays]") {
    test::TempDir dir;
    dir.write("kit/grader/cases/lab99.json", R"({"lab": "lab99", "size": "10x10", "timeout_s": 20, "arrays_are": "particles",
        "tolerance": {"live": {"max_channel_diff": 0, "max_differing_fraction": 0},
                      "golden": {"max_channel_diff": 2, "max_differing_fraction": 0.1},
                      "arrays": {"max_abs": 1e-4, "max_differing_fraction": 0}},
        "cases": [{"name": "cloud", "todo": "L99-T1", "points": 3, "settings": []}]})");
    const std::string gpu = "TestGPU 9000 (driver 1.0)", llvmpipe = "llvmpipe (LLVM 15.0.6, 256 bits)";
    FakeLab reference{picture(0), {{"positions", ramp("positions", 50)}}, {}, gpu};
    write_fake_lab(dir.path("bin"), "lab99_solution", dir.path("fixture/reference"), reference);
    GradeOptions update = fake_kit_options(dir, "out-update");
    REQUIRE(update_goldens(update).results.at(0).status == CaseStatus::Passed);
    const Json record = read_json_file(dir.path("kit/grader/golden/renderer.json"));
    CHECK(record.object_at("labs").string_at("lab99") == gpu);

    const auto self_check = [&](int changed, const std::string& renderer, bool right_arrays = true) {
        FakeLab student = reference;
        student.image = picture(changed);
        student.renderer = renderer;
        if (!right_arrays) student.arrays["positions"].values[0] = 9;
        write_fake_lab(dir.path("bin"), "lab99", dir.path("fixture/student"), student);
        GradeOptions options = fake_kit_options(dir, "out");
        options.self_check = true;
        return grade(options);
    };
    // 12 pixels of a budget of 10, on another renderer: a GPU's margin, no points, and what to run.
    const GradeReport margin = self_check(12, llvmpipe);
    CHECK(margin.renderer == llvmpipe);
    CHECK(margin.golden_renderers.at("lab99") == gpu);
    const CaseResult& r = margin.results.at(0);
    CHECK(r.status == CaseStatus::GpuMargin);
    CHECK(std::string(status_name(r.status)) == "GPU margin");
    CHECK(r.points == 0);
    CHECK(r.detail.rfind("particles match the reference (positions); the picture differs from the TestGPU 9000 golden by a margin seen "
                         "between GPUs: check with `build/bin/lab99 compare --case cloud` (max diff 220, 12 of 100 px differ (12.00%)", 0) == 0);
    CHECK(contains(r.detail, "; within 1.5 times the case's budget)"));
    const std::string table = score_table(margin);
    CHECK(contains(table, "renderer " + llvmpipe + " (the labs ran on it)"));
    CHECK(contains(table, "goldens  rendered on " + gpu));
    const Json json = parse_json(report_json(margin), "report.json");
    CHECK(json.string_at("renderer") == llvmpipe);
    CHECK(json.object_at("golden_renderers").string_at("lab99") == gpu);
    CHECK(contains(html_report(margin, dir.path("out")), "<tr><th>goldens rendered on</th><td>rendered on TestGPU 9000 (driver 1.0)</td></tr>"));

    // Past one and a half budgets, on the goldens' own renderer, or with no renderer named: a wrong image.
    const CaseResult far = self_check(16, llvmpipe).results.at(0);
    CHECK(far.status == CaseStatus::WrongImage);
    CHECK(far.detail.rfind("particles match the reference (positions); the picture differs: max diff 220, 16 of 100 px", 0) == 0);
    CHECK(self_check(12, gpu).results.at(0).status == CaseStatus::WrongImage);
    CHECK(self_check(12, "").results.at(0).status == CaseStatus::WrongImage);
    // Wrong numbers are no GPU's margin.
    const CaseResult wrong = self_check(12, llvmpipe, false).results.at(0);
    CHECK(wrong.status == CaseStatus::WrongData);
    CHECK(contains(wrong.detail, "; the picture is off too, by a margin seen between GPUs"));
    // Within the budget it passes wherever it ran.
    CHECK(self_check(10, llvmpipe).results.at(0).status == CaseStatus::Passed);
}
