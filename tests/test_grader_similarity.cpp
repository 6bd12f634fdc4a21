// Copied work found, the template subtracted (issue 42 item 3): a made-up class of lab 01 and lab 05 built from the
// reference and the kit's correct variants (tests/mutants/<lab>.json), with planted copies (byte for byte, identifiers
// renamed, functions reordered) that must all be found, and students who must not be paired: one with other correct
// variants of the same TODOs, two who each did one TODO with the reference's answer, one who handed in the starter.
// And a batch folder with planted pictures: one wrong picture two students alone drew is a pair; one three drew, one a
// known mistake explains and one only one student drew are not.
#include "catch.hpp"
#include "gl_fixture.h"
#include "lab_runner.h"
#include "test_support.h"

#include "common/image/image.h"
#include "grader/src/batch/batch_record.h"
#include "grader/src/diagnose/mutant_kit.h"
#include "grader/src/report/report.h"
#include "grader/src/run/process.h"
#include "grader/src/similarity/copied_code.h"
#include "grader/src/similarity/copied_pictures.h"
#include "grader/src/similarity/sim_tool.h"
#include "grader/src/similarity/similarity_report.h"
#include "tools/starter.h"

#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>

namespace fs = std::filesystem;
using namespace gsv;

namespace {

// similarity-tester is in scripts/setup.sh's packages, so CI (.ci/run, GSV_REQUIRE_SIMILARITY=1) has it: there a
// missing one fails; elsewhere the test says how to install it and passes without running.
bool sim_missing() {
    try {
        find_sim(SimLanguage::C);
        find_sim(SimLanguage::Cpp);
        return false;
    } catch (const Error& e) {
        if (std::getenv("GSV_REQUIRE_SIMILARITY")) FAIL(e.what());
        WARN(std::string("skipped: ") + e.what());
        return true;
    }
}

std::string lab_dir_of(const std::string& lab) { return read_mutant_spec(test::source_root(), lab).string_at("lab_dir"); }

// The lab's reference with `edits` (entries of its mutants file) applied, as a student hands it in: every TODO done,
// or only those in `done` (the others as the starter has them); the solution's //@ markers gone.
void write_student_lab(const fs::path& submission, const std::string& lab, const std::vector<Json>& edits,
                       const std::set<std::string>* done = nullptr) {
    const std::string lab_dir = lab_dir_of(lab);
    test::TempDir scratch;
    const fs::path edited = scratch.path(lab_dir);
    fs::copy(test::source_root() / "solutions" / lab_dir, edited, fs::copy_options::recursive);
    for (const Json& edit : edits) apply_mutant_edits(edited, edit, test::source_root());
    for (const auto& e : fs::directory_iterator(edited)) {
        const std::string name = e.path().filename().string(), text = test::read_text(e.path());
        const std::vector<std::string> ids = make_starter(text, name).todo_ids;
        const std::set<std::string> all(ids.begin(), ids.end());
        const std::string answer = make_partial_starter(text, name, done ? *done : all).text;
        std::ofstream(submission / "labs" / lab_dir / name, std::ios::binary) << answer;
    }
}

void make_lab_folder(const fs::path& submission, const std::string& lab) { fs::create_directories(submission / "labs" / lab_dir_of(lab)); }

// The lab's variants, the first (or second) of each TODO that has one.
std::vector<Json> variants(const std::string& lab, std::size_t which) {
    std::map<std::string, std::vector<Json>> by_todo;
    const Json spec = read_mutant_spec(test::source_root(), lab);
    for (const Json& v : spec.array_at("variants").as_array()) by_todo[v.string_at("todo")].push_back(v);
    std::vector<Json> chosen;
    for (const auto& [todo, list] : by_todo)
        if (which < list.size()) chosen.push_back(list[which]);
    return chosen;
}

void rename_identifiers(const fs::path& lab_folder, const std::vector<std::pair<std::string, std::string>>& renames) {
    for (const auto& e : fs::directory_iterator(lab_folder)) {
        std::string text = test::read_text(e.path());
        for (const auto& [from, to] : renames) text = std::regex_replace(text, std::regex("\\b" + from + "\\b"), to);
        std::ofstream(e.path(), std::ios::binary) << text;
    }
}

// Swaps the first two functions (a line ending in ") {" at the left margin, to its "}") of each GLSL file that has two.
void reorder_functions(const fs::path& lab_folder) {
    static const std::regex opening(R"(^[A-Za-z_].*\)\s*\{\s*$)");
    for (const auto& e : fs::directory_iterator(lab_folder)) {
        if (!is_glsl_file(e.path().filename().string())) continue;
        std::vector<std::string> lines;
        std::istringstream in(test::read_text(e.path()));
        for (std::string line; std::getline(in, line);) lines.push_back(line);
        std::vector<std::pair<std::size_t, std::size_t>> functions;  // first line, one past the last
        for (std::size_t i = 0; i < lines.size() && functions.size() < 2; ++i)
            if (std::regex_match(lines[i], opening))
                for (std::size_t j = i + 1; j < lines.size(); ++j)
                    if (lines[j] == "}") {
                        functions.push_back({i, j + 1});
                        i = j;
                        break;
                    }
        if (functions.size() < 2) continue;
        const auto [a0, a1] = functions[0];
        const auto [b0, b1] = functions[1];
        std::vector<std::string> out(lines.begin(), lines.begin() + static_cast<long>(a0));
        out.insert(out.end(), lines.begin() + static_cast<long>(b0), lines.begin() + static_cast<long>(b1));
        out.insert(out.end(), lines.begin() + static_cast<long>(a1), lines.begin() + static_cast<long>(b0));
        out.insert(out.end(), lines.begin() + static_cast<long>(a0), lines.begin() + static_cast<long>(a1));
        out.insert(out.end(), lines.begin() + static_cast<long>(b1), lines.end());
        std::string text;
        for (const auto& line : out) text += line + "\n";
        std::ofstream(e.path(), std::ios::binary) << text;
    }
}

// Alice's own way to lab 05's L05-T2 in advect.comp, for a compute shader's extension to be in a shared run: the kit's
// variant there has the reference's shape, token for token but two lines, so the template takes most of it.
void hand_written_invocation_index(const fs::path& lab_folder) {
    const fs::path file = lab_folder / "advect.comp";
    std::string text = test::read_text(file);
    const auto from = text.find("    uint group = gl_WorkGroupID.y"), to = text.find("    vec3 p = positions[index].xyz;");
    REQUIRE(from != std::string::npos);
    REQUIRE(to != std::string::npos);
    text.replace(from, to - from,
                 "    // rows of groups first, then the groups in this row, then this invocation in its group\n"
                 "    uint groups_before = gl_WorkGroupID.y * gl_NumWorkGroups.x;\n"
                 "    groups_before += gl_WorkGroupID.x;\n"
                 "    uint index = gl_LocalInvocationID.x;\n"
                 "    index += groups_before * gl_WorkGroupSize.x;\n"
                 "    if (index >= uint(uCount)) {\n"
                 "        return;\n"
                 "    }\n");
    std::ofstream(file, std::ios::binary) << text;
}

// The planted class, lab 01 and lab 05 (advect.comp: a compute shader's extension too).
void plant_class(const fs::path& class_dir) {
    for (const std::string lab : {"lab01", "lab05"}) {
        const std::string lab_dir = lab_dir_of(lab);
        for (const char* name : {"alice", "erin", "frank", "grace", "heidi"}) make_lab_folder(class_dir / name, lab);
        write_student_lab(class_dir / "alice", lab, variants(lab, 0));
        if (lab == "lab05") hand_written_invocation_index(class_dir / "alice" / "labs" / lab_dir);
        // Copies of alice: byte for byte, her identifiers renamed, her functions in another order.
        for (const char* copy : {"bob", "carol", "dave"}) {
            fs::create_directories(class_dir / copy / "labs");
            fs::copy(class_dir / "alice" / "labs" / lab_dir, class_dir / copy / "labs" / lab_dir, fs::copy_options::recursive);
        }
        rename_identifiers(class_dir / "carol" / "labs" / lab_dir,
                           {{"n_dot_l", "cos_theta"}, {"highlight", "glint"}, {"len", "normal_length"}, {"kd", "diffuse_color"},
                            {"group", "block_number"}, {"w", "blend"}, {"x", "position_on_ramp"}});
        reorder_functions(class_dir / "dave" / "labs" / lab_dir);
        // On her own: the same TODOs, other correct ways (the second variant where a TODO has two).
        write_student_lab(class_dir / "erin", lab, variants(lab, 1));
        // Each did one TODO, with the reference's answer; heidi handed in the starter.
        const std::set<std::string> one_todo{lab == "lab01" ? "L01-T2" : "L05-T5"};
        write_student_lab(class_dir / "frank", lab, {}, &one_todo);
        write_student_lab(class_dir / "grace", lab, {}, &one_todo);
        fs::copy(test::source_root() / "labs" / lab_dir, class_dir / "heidi" / "labs" / lab_dir,
                 fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    }
}

std::set<std::pair<std::string, std::string>> pairs_of(const LabCode& lab) {
    std::set<std::pair<std::string, std::string>> pairs;
    for (const CodePair& p : lab.pairs) pairs.insert({p.a, p.b});
    return pairs;
}

const std::set<std::pair<std::string, std::string>> kPlanted{{"alice", "bob"}, {"alice", "carol"}, {"alice", "dave"},
                                                              {"bob", "carol"},  {"bob", "dave"},   {"carol", "dave"}};

}  // namespace

TEST_CASE("similarity: the template is the lab's starter and reference, every lab's starter and the shared shaders", "[grader][similarity]") {
    const std::vector<fs::path> files = template_files(test::source_root(), "lab02_lic");
    const auto has = [&](const fs::path& relative) { return std::find(files.begin(), files.end(), test::source_root() / relative) != files.end(); };
    CHECK(has("labs/lab02_lic/lic.frag"));
    CHECK(has("solutions/lab02_lic/lic.frag"));
    // Lab 03's starter holds lab 02's answer.
    CHECK(has("labs/lab03_texture_arrays/lic_time.frag"));
    CHECK(has("labs/lab01_gooch/phong.glsl"));
    CHECK(has("shaders/gsv/math.glsl"));
    CHECK_FALSE(has("solutions/lab03_texture_arrays/lic_time.frag"));
    CHECK_FALSE(has("labs/lab02_lic/README.md"));
    for (const char* name : {"a.glsl", "a.vert", "a.frag", "a.geom", "a.comp", "a.tesc", "a.tese"}) CHECK(is_glsl_file(name));
    CHECK(is_compared_file("lab.cpp"));
    CHECK_FALSE(is_compared_file("raycast.network"));
}

TEST_CASE("similarity: SIM's runs and token counts are read back, and a file it cannot open is an error", "[grader][similarity]") {
    const SimOutput out = read_sim_output("File s0/f1: 129 tokens, 24 lines\nFile s1/f1: 1 token, 1 line (not NL-terminated)\n"
                                          "Total input: 2 files (2 new, 0 old), 130 tokens\n\n"
                                          "s0/f1: line 2-24            |s1/f1: line 3-25         [129]\n");
    CHECK(out.tokens_of.at("s0/f1") == 129);
    CHECK(out.tokens_of.at("s1/f1") == 1);
    REQUIRE(out.runs.size() == 1);
    CHECK(out.runs[0].file_b == "s1/f1");
    CHECK(out.runs[0].b_first == 3);
    CHECK(out.runs[0].tokens == 129);
    CHECK(test::gsv_error_message([] { read_sim_output("File gone.c: >>>> cannot open <<<<\n"); }) ==
          "similarity-tester could not open 'gone.c'");
}

TEST_CASE("similarity: every planted copy is found, and no pair of independent or template-only work", "[grader][similarity]") {
    if (sim_missing()) return;
    test::TempDir dir;
    plant_class(dir.path("class"));
    CopiedCodeOptions options;
    options.kit_root = test::source_root();
    options.submissions = dir.path("class");
    options.labs = {"lab01", "lab05"};
    const std::vector<LabCode> labs = find_copied_code(options);
    REQUIRE(labs.size() == 2);
    for (const LabCode& lab : labs) {
        INFO(lab.lab);
        CHECK(lab.students == 8);
        CHECK(pairs_of(lab) == kPlanted);
        for (const CodePair& p : lab.pairs) {
            INFO(p.a << " " << p.b << " " << p.shared_tokens << " of " << p.own_a << ", " << p.own_b);
            CHECK(p.likely_copied());
        }
        // The reference's answer and the starter leave no own code that could make a run (what is left: pieces of the
        // template around the TODO done, each shorter than a run).
        CHECK(lab.own_tokens.at("frank") < kMinRun);
        CHECK(lab.own_tokens.at("grace") < kMinRun);
        CHECK(lab.own_tokens.at("heidi") == 0);
        CHECK(lab.own_tokens.at("alice") > 40);
    }
    // The compute shader is compared too: alice's L05-T2 variant in advect.comp is in a shared run.
    const LabCode& lab05 = labs[1];
    const auto alice_bob = std::find_if(lab05.pairs.begin(), lab05.pairs.end(), [](const CodePair& p) { return p.a == "alice" && p.b == "bob"; });
    REQUIRE(alice_bob != lab05.pairs.end());
    CHECK(std::any_of(alice_bob->runs.begin(), alice_bob->runs.end(), [](const SharedRun& r) { return r.file == "advect.comp"; }));
}

namespace {

// A graded student of a made-up batch: report.json with one wrong picture per case given, and the picture.
struct PlantedPicture {
    std::string case_name;
    int shade;                // the picture: one grey level, so equal shades are equal pictures
    std::string mistake;      // what a known mistake says, where one explains it
};

void plant_report(const fs::path& out, const std::string& student, const std::vector<PlantedPicture>& pictures,
                  bool not_started = false) {
    GradeReport report;
    report.submission = student;
    report.mode = "instructor";
    report.diagnose = "all";
    if (not_started) {  // L01-T2 left as the starter has it: the diagnosis says so
        LabDiagnosis d;
        d.lab = "lab01";
        d.not_started = {"L01-T2"};
        report.diagnoses.push_back(d);
    }
    for (const PlantedPicture& p : pictures) {
        CaseResult r;
        r.lab = "lab01";
        r.name = p.case_name;
        r.todo = "L01-T2";
        r.status = CaseStatus::WrongImage;
        r.max_points = 1;
        r.actual_png = "lab01/" + p.case_name + "/actual.png";
        r.mistake = p.mistake;
        if (!p.mistake.empty()) r.mistake_todo = "L01-T2";
        Image image(8, 8);
        for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = static_cast<std::uint8_t>(i % 4 == 3 ? 255 : p.shade);
        fs::create_directories(out / student / "lab01" / p.case_name);
        write_png(out / student / r.actual_png, image);
        report.results.push_back(r);
    }
    fs::create_directories(out / student);
    std::ofstream(out / student / "report.json") << report_json(report);
}

}  // namespace

TEST_CASE("similarity: a wrong picture two students alone drew is a pair, not one three drew, a known mistake's or a unique one",
          "[grader][similarity]") {
    test::TempDir dir;
    const fs::path out = dir.path("out");
    BatchRecord record;
    for (const char* name : {"p1", "p2", "p3", "p4", "p5", "p6", "p7"}) {
        BatchEntry e;
        e.name = name;
        e.graded = true;
        record.roster.push_back(name);
        record.entries.push_back(e);
    }
    const std::string mistake = "the ambient term forgotten";
    plant_report(out, "p1", {{"diffuse", 40, ""}, {"gooch", 90, mistake}});
    plant_report(out, "p2", {{"diffuse", 40, ""}, {"gooch", 90, mistake}, {"stretched", 7, ""}});
    plant_report(out, "p3", {{"diffuse", 120, ""}, {"gooch", 90, mistake}});
    plant_report(out, "p4", {{"diffuse", 120, ""}, {"stretched", 8, ""}});
    plant_report(out, "p5", {{"diffuse", 120, ""}});
    // Two who left L01-T2 undone draw the starter's picture alike: no pair.
    plant_report(out, "p6", {{"phong", 60, ""}}, true);
    plant_report(out, "p7", {{"phong", 60, ""}}, true);
    write_batch_record(record, out);
    const CopiedPictures found = find_copied_pictures(out);
    CHECK(found.batch_found);
    CHECK(found.students == 7);
    CHECK(found.notes.empty());
    REQUIRE(found.pairs.size() == 1);
    CHECK(found.pairs[0].a == "p1");
    CHECK(found.pairs[0].b == "p2");
    CHECK(found.pairs[0].case_name == "diffuse");
    CHECK(found.pairs[0].picture == "p1/lab01/diffuse/actual.png");
    CHECK(found.pairs[0].mistakes_looked_for);
    // A folder without a batch: no pictures compared, said so.
    CHECK_FALSE(find_copied_pictures(dir.path("class")).batch_found);
}

TEST_CASE("similarity: gsv-grade similarity writes a report that loads nothing from anywhere, and a CSV of the pairs ranked",
          "[grader][similarity]") {
    if (sim_missing()) return;
    test::TempDir dir;
    plant_class(dir.path("class"));
    const fs::path out = dir.path("out");
    // The batch's pictures: bob drew alice's wrong picture.
    BatchRecord record;
    for (const char* name : {"alice", "bob"}) {
        BatchEntry e;
        e.name = name;
        e.graded = true;
        record.roster.push_back(name);
        record.entries.push_back(e);
        plant_report(out, name, {{"diffuse", 33, ""}});
    }
    write_batch_record(record, out);
    const fs::path grader = test::bin_dir() / "gsv-grade";
    ProcessLimits limits;
    limits.timeout = std::chrono::minutes(2);
    const ProcessResult run = run_process({grader.string(), "similarity", "--batch", dir.path("class").string(), "--out", out.string(),
                                           "--labs", "lab01"},
                                          dir.path(), limits);
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    CHECK(run.output.find("pairs sharing own code: 6 (6 likely copied); pairs with the same rare wrong picture: 1") != std::string::npos);
    const std::string csv = test::read_text(out / "similarity.csv");
    INFO(csv);
    CHECK(csv.rfind("rank,kind,lab,student_a,student_b,similarity_percent,shared_tokens,", 0) == 0);
    CHECK(test::count_of(csv, ",code,lab01,") == 6);
    CHECK(csv.find("1,code,lab01,") != std::string::npos);
    CHECK(csv.find(",picture,lab01,alice,bob,,,,,yes,,,,diffuse,alice/lab01/diffuse/actual.png,") != std::string::npos);
    const std::string page = test::read_text(out / "similarity.html");
    // Offline: a policy that lets nothing load but data: pictures and the page's own style, no script, no address.
    CHECK(page.find("default-src 'none'; img-src data:; style-src 'unsafe-inline'") != std::string::npos);
    CHECK(page.find("<script") == std::string::npos);
    CHECK(page.find("http://") == std::string::npos);
    CHECK(page.find("https://") == std::string::npos);
    CHECK(page.find("src=\"data:image/png;base64,") != std::string::npos);
    CHECK(page.find("class=\"sides\"") != std::string::npos);
    // Bad input: one line, exit 2.
    const ProcessResult bad = run_process({grader.string(), "similarity", "--batch", dir.path("nowhere").string(), "--out", out.string()},
                                          dir.path(), limits);
    CHECK(bad.exit_code == 2);
    CHECK(bad.output == "gsv-grade similarity: no folder of submissions '" + dir.path("nowhere").string() + "'\n");
    const ProcessResult unknown = run_process({grader.string(), "similarity", "--batch", dir.path("class").string(), "--out", out.string(),
                                               "--labs", "lab99"},
                                              dir.path(), limits);
    CHECK(unknown.exit_code == 2);
    CHECK(unknown.output == "gsv-grade similarity: --labs: the kit has no lab 'lab99' (no labs/lab99_* folder)\n");
}

TEST_CASE("similarity: a reference-like submission with one slip, handed in twice, is a pair, the same slip made apart is not",
          "[grader][similarity]") {
    if (sim_missing()) return;
    test::TempDir dir;
    const Json mutants = read_mutant_spec(test::source_root(), "lab01").array_at("mutants");
    // kai and lee hand in the same file: the reference with one classic mistake, too short an edit for a run of SIM's.
    // mia makes the same mistake in a file of her own (a comment line of hers); noa makes another one.
    for (const char* name : {"kai", "lee", "mia", "noa"}) make_lab_folder(dir.path(name), "lab01");
    write_student_lab(dir.path("kai"), "lab01", {mutants.at(0)});
    write_student_lab(dir.path("lee"), "lab01", {mutants.at(0)});
    write_student_lab(dir.path("mia"), "lab01", {mutants.at(0)});
    write_student_lab(dir.path("noa"), "lab01", {mutants.at(1)});
    const fs::path mia_file = dir.path("mia") / "labs" / lab_dir_of("lab01") / mutants.at(0).string_at("file");
    std::ofstream(mia_file, std::ios::app) << "\n// checked against the sheet's figure\n";
    CopiedCodeOptions options;
    options.kit_root = test::source_root();
    options.submissions = dir.path();
    options.labs = {"lab01"};
    const std::vector<LabCode> labs = find_copied_code(options);
    REQUIRE(labs.size() == 1);
    CHECK(pairs_of(labs[0]) == std::set<std::pair<std::string, std::string>>{{"kai", "lee"}});
    REQUIRE(labs[0].pairs.size() == 1);
    CHECK(labs[0].pairs[0].identical_edits);
    CHECK(labs[0].pairs[0].likely_copied());
}
