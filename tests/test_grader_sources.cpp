// The grade is the sources' grade (issue 39): how, where and after what a submission is graded never changes it. Its
// files' modes, a file its C++ includes that changed since an earlier build, a header from outside its lab's folder,
// and a grading set up from another checkout than the build's: each is graded as the sources say, or stopped as the
// kit's fault.
#include "grader_fixture.h"

#include "grader/src/batch/batch.h"
#include "grader/src/grade/grade_exit.h"
#include "grader/src/run/build_reuse.h"
#include "grader/src/run/process.h"

#include <sys/stat.h>

using namespace gsv;
namespace fs = std::filesystem;

namespace {

// Every file and folder under `root` (itself included) with `file_mode` and `folder_mode`, as an archive unpacked
// under umask 077 leaves them.
void set_modes(const fs::path& root, fs::perms file_mode, fs::perms folder_mode) {
    std::vector<fs::path> folders{root};
    for (const auto& e : fs::recursive_directory_iterator(root)) {
        if (e.is_directory()) folders.push_back(e.path());
        else fs::permissions(e.path(), file_mode, fs::perm_options::replace);
    }
    // Deepest first, so a folder is closed after what is in it.
    for (auto it = folders.rbegin(); it != folders.rend(); ++it) fs::permissions(*it, folder_mode, fs::perm_options::replace);
}

std::map<std::string, unsigned> modes_of(const fs::path& root) {
    std::map<std::string, unsigned> modes;
    for (const auto& e : fs::recursive_directory_iterator(root))
        modes[e.path().lexically_relative(root).generic_string()] = static_cast<unsigned>(e.symlink_status().permissions());
    modes["."] = static_cast<unsigned>(fs::status(root).permissions());
    return modes;
}

// The self-check of `labs` of a submission, with the grader cache `cache` (what --grader-cache names).
GradeOptions self_check_of(const fs::path& submission, const fs::path& out, const std::vector<std::string>& labs, const fs::path& cache) {
    GradeOptions options = test::instructor_options(labs.front(), out);
    options.labs = labs;
    options.submission = submission;
    options.self_check = true;
    options.timing = false;
    options.build_cache = cache / "builds";  // as --grader-cache DIR names it
    options.allow_readable_kit = false;  // the walls as an instructor's run puts them up, where they can
    return options;
}

std::string lab_dir_of(const std::string& lab) { return test::mutant_spec(lab).string_at("lab_dir"); }

fs::path copy_solution(const fs::path& submission, const std::string& lab) {
    const fs::path folder = submission / "labs" / lab_dir_of(lab);
    fs::create_directories(folder.parent_path());
    fs::copy(test::source_root() / "solutions" / lab_dir_of(lab), folder, fs::copy_options::recursive);
    return folder;
}

}  // namespace

TEST_CASE("grader: a submission unpacked with files 0600 and folders 0700 is graded as its contents, its modes left alone",
          "[grader][submission]") {
    test::TempDir dir;
    // A GLSL lab (02: its C++ is the starter's, the kit's binary runs) and a C++ lab (03: built from the submission).
    const fs::path class_dir = dir.path("class"), submission = class_dir / "ada";
    copy_solution(submission, "lab02");
    copy_solution(submission, "lab03");
    set_modes(submission, fs::perms::owner_read | fs::perms::owner_write, fs::perms::owner_all);
    const auto modes = modes_of(submission);
    const GradeReport report = grade(self_check_of(submission, dir.path("one"), {"lab02", "lab03"}, dir.path("cache")));
    for (const auto& b : report.builds) INFO(b.lab << " " << b.origin << ":\n" << b.log);
    for (const auto& r : report.results) {
        INFO(r.lab << "/" << r.name << ": " << status_name(r.status) << " " << r.detail);
        CHECK(r.status == CaseStatus::Passed);
    }
    CHECK(report.max_score() > 0);
    CHECK(report.score() == report.max_score());
    CHECK(modes_of(submission) == modes);
    // The same as one of a class: a batch's run grades it alike, whatever the folder of the class allows.
    fs::permissions(class_dir, fs::perms::owner_all, fs::perm_options::replace);
    BatchOptions batch;
    batch.grader = test::bin_dir() / "gsv-grade";
    batch.submissions = class_dir;
    batch.out_dir = dir.path("batch");
    batch.workers = 1;
    batch.seed = 5;
    batch.pass_through = {"--labs", "lab02,lab03", "--self-check", "--grader-cache", dir.path("cache").string()};
    const auto entries = grade_batch(batch, nullptr);
    REQUIRE(entries.size() == 1);
    INFO(entries[0].problem);
    CHECK(entries[0].graded);
    CHECK(entries[0].score == report.score());
    CHECK(entries[0].max_score == report.max_score());
    CHECK(modes_of(submission) == modes);
}

TEST_CASE("grader: a build is reused only where every file the compiler read is as it was", "[grader][submission]") {
    test::TempDir dir;
    const fs::path submission = dir.path("submission");
    const fs::path lab = copy_solution(submission, "lab01");
    // lab.cpp includes a text file: 42 in it, the lab runs; anything else, it stops at its start.
    std::string text = test::read_text(lab / "lab.cpp");
    const auto namespace_at = text.find("namespace {");
    REQUIRE(namespace_at != std::string::npos);
    text.insert(namespace_at, "static const int kAnswer =\n#include \"answer.txt\"\n    ;\n"
                              "static const bool kChecked = [] { if (kAnswer != 42) std::abort(); return true; }();\n\n");
    if (text.find("#include <cstdlib>") == std::string::npos) text.insert(0, "#include <cstdlib>\n");
    std::ofstream(lab / "lab.cpp", std::ios::binary) << text;
    std::ofstream(lab / "answer.txt") << "42\n";
    const fs::path cache = dir.path("cache");
    // The first run as an instructor's command runs it, so that a rerun in its folder has its record.
    const fs::path grader = test::bin_dir() / "gsv-grade";
    ProcessLimits limits;
    limits.timeout = std::chrono::minutes(10);
    const auto run_grader = [&](std::vector<std::string> extra) {
        std::vector<std::string> argv{grader.string(), "--submission", submission.string(), "--out", dir.path("first").string(),
                                      "--labs", "lab01", "--self-check", "--grader-cache", cache.string(), "--quiet", "--allow-readable-kit"};
        argv.insert(argv.end(), extra.begin(), extra.end());
        return run_process(argv, dir.path(), limits);
    };
    const ProcessResult first = run_grader({});
    INFO(first.output);
    REQUIRE(first.exit_code == kGradeOk);
    const Json first_results = read_json_file(dir.path("first/results.json"));
    CHECK(first_results.number_at("score") > 0);
    CHECK(test::read_text(dir.path("first/report.json")).find("\"origin\": \"built\"") != std::string::npos);
    // The text changes; its C++ does not. An earlier build of the same C++ read the old text: built again.
    std::ofstream(lab / "answer.txt") << "41\n";
    const GradeReport second = grade(self_check_of(submission, dir.path("second"), {"lab01"}, cache));
    INFO(second.builds.at(0).log);
    CHECK(second.builds.at(0).origin == "built");
    CHECK(second.builds.at(0).log.find("answer.txt, which has changed since") != std::string::npos);
    CHECK(second.score() == 0);
    for (const auto& r : second.results) CHECK(r.status == CaseStatus::Crash);
    // A rerun after the change in the first run's folder: the lab is graded again, with the build of what it has now.
    const ProcessResult regraded = run_grader({"--regrade-only", "changed"});
    INFO(regraded.output);
    CHECK(regraded.exit_code == kGradeOk);
    CHECK(read_json_file(dir.path("first/results.json")).number_at("score") == 0);
    const Json report = read_json_file(dir.path("first/report.json"));
    CHECK(report.array_at("regraded").size() == 1);
    CHECK(test::read_text(dir.path("first/report.json")).find("unchanged C++: an earlier build") != std::string::npos);
    // Unchanged since: the build the second run kept is this text's.
    const GradeReport third = grade(self_check_of(submission, dir.path("third"), {"lab01"}, cache));
    CHECK(third.builds.at(0).origin == "unchanged C++: an earlier build");
    CHECK(third.score() == 0);
}

TEST_CASE("grader: a header from outside the lab's folder fails to compile, with a line that says why", "[grader][submission]") {
    test::TempDir dir;
    const fs::path submission = dir.path("submission");
    const fs::path lab = copy_solution(submission, "lab01");
    fs::create_directories(submission / "labs" / "shared");
    std::ofstream(submission / "labs" / "shared" / "helper.h") << "#pragma once\nstatic const int kHelper = 1;\n";
    std::string text = test::read_text(lab / "lab.cpp");
    text.insert(0, "#include \"../shared/helper.h\"\n");
    std::ofstream(lab / "lab.cpp", std::ios::binary) << text;
    for (const char* round : {"first", "second"}) {
        const GradeReport report = grade(self_check_of(submission, dir.path(round), {"lab01"}, dir.path("cache")));
        INFO(round << ": " << report.builds.at(0).log);
        CHECK_FALSE(report.builds.at(0).ok);
        CHECK(report.score() == 0);
        REQUIRE_FALSE(report.results.empty());
        CHECK(report.results.front().status == CaseStatus::BuildError);
        CHECK(report.results.front().detail.find("is labs/shared/helper.h, outside this lab's folder") != std::string::npos);
        // Changed between the two: still the sources' verdict, never an earlier build.
        std::ofstream(submission / "labs" / "shared" / "helper.h") << "#pragma once\nstatic const int kHelper = 2;\n";
    }
}

TEST_CASE("build cache: an entry is proved on the bytes of what its build read in the lab's folder and elsewhere", "[unit]") {
    test::TempDir dir;
    const fs::path kit_build = dir.path("kit-build"), lab = dir.path("lab"), elsewhere = dir.path("elsewhere.h");
    fs::create_directories(kit_build);
    fs::create_directories(lab);
    std::ofstream(kit_build / "gsv-targets.cmake") << "# no libraries\n";
    std::ofstream(kit_build / "gsv-build-settings.cmake") << "# settings\n";
    std::ofstream(lab / "lab.cpp") << "int main() {}\n";
    std::ofstream(lab / "table.txt") << "1, 2, 3\n";
    std::ofstream(elsewhere) << "#pragma once\n";
    std::ofstream(dir.path("binary")) << "a binary";
    const BuildCache cache(dir.path("cache"), kit_build);
    BuildReads reads;
    reads.complete = true;
    reads.files = {lab / "lab.cpp", lab / "table.txt", elsewhere};
    std::string note;
    cache.store("lab01", lab, read_files(reads, lab, dir.path("build")), dir.path("binary"), note);
    CHECK(note.empty());
    CHECK(cache.fetch("lab01", lab, dir.path("out/a"), note));
    CHECK(test::read_text(dir.path("out/a")) == "a binary");
    // A read text of the lab's own folder changes: no hit, and the note names it.
    std::ofstream(lab / "table.txt") << "1, 2, 4\n";
    CHECK_FALSE(cache.fetch("lab01", lab, dir.path("out/b"), note));
    CHECK(note.find("table.txt") != std::string::npos);
    std::ofstream(lab / "table.txt") << "1, 2, 3\n";
    CHECK(cache.fetch("lab01", lab, dir.path("out/c"), note));
    // A header elsewhere changes: no hit.
    std::ofstream(elsewhere) << "#pragma once\n#define X 1\n";
    CHECK_FALSE(cache.fetch("lab01", lab, dir.path("out/d"), note));
    // A new file in the folder (what __has_include could ask about): another entry.
    std::ofstream(elsewhere) << "#pragma once\n";
    std::ofstream(lab / "extra.md") << "notes\n";
    CHECK_FALSE(cache.fetch("lab01", lab, dir.path("out/e"), note));
    // Stored again with what it read now, the entry replaces the one whose reads changed.
    fs::remove(lab / "extra.md");
    std::ofstream(lab / "table.txt") << "1, 2, 5\n";
    cache.store("lab01", lab, read_files(reads, lab, dir.path("build")), dir.path("binary"), note);
    CHECK(cache.fetch("lab01", lab, dir.path("out/f"), note));
}

TEST_CASE("grader: a class graded with --kit another checkout than the build's stops as the kit's fault, after a few",
          "[grader][submission]") {
    test::TempDir dir;
    // Another checkout: the kit's files, through links, in a folder of its own.
    const fs::path other = dir.path("other-kit");
    fs::create_directories(other);
    for (const char* part : {"grader", "shaders", "data", "common", "support", "cmake", "labs", "solutions", "third_party"})
        fs::create_directory_symlink(test::source_root() / part, other / part);
    for (const char* name : {"ada", "bob", "cy", "dee", "eve"}) copy_solution(dir.path("class") / name, "lab01");
    const fs::path grader = test::bin_dir() / "gsv-grade";
    ProcessLimits limits;
    limits.timeout = std::chrono::minutes(10);
    const ProcessResult one = run_process({grader.string(), "--submission", (dir.path("class") / "ada").string(), "--out",
                                           dir.path("one").string(), "--kit", other.string(), "--labs", "lab01", "--self-check",
                                           "--allow-readable-kit"},
                                          dir.path(), limits);
    INFO(one.output);
    CHECK(one.exit_code == kGradeKitFault);
    CHECK(one.output.find("is not the checkout the build in") != std::string::npos);
    CHECK(read_json_file(dir.path("one/results.json")).string_at("output").find("the kit's fault, not yours") != std::string::npos);
    const ProcessResult batch = run_process({grader.string(), "--batch", dir.path("class").string(), "--workers", "1", "--out",
                                             dir.path("batch").string(), "--kit", other.string(), "--labs", "lab01", "--self-check",
                                             "--seed", "5", "--allow-readable-kit"},
                                            dir.path(), limits);
    INFO(batch.output);
    CHECK(batch.exit_code == kGradeKitFault);
    CHECK(batch.output.find("were not graded for the kit's reason") != std::string::npos);
    const std::string csv = test::read_text(dir.path("batch/class.csv"));
    INFO(csv);
    // Nobody got a grade, and the last two were never started.
    CHECK(csv.find(",yes,") == std::string::npos);
    CHECK(test::count_of(csv, "not graded: the batch stopped") == 2);
}
