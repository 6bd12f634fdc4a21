// The kit's command-line conventions: sizes refused with their limit, output folders checked before long
// work starts (and never called an internal error), scores as people write them, a progress line with the
// time left.
#include "common/app/cli.h"
#include "common/core/error.h"
#include "common/core/progress.h"
#include "common/io/output_folder.h"
#include "grader/src/batch/batch.h"
#include "grader/src/cases/cases.h"
#include "lab_runner.h"
#include "test_support.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <string>
#include <vector>

using namespace gsv;

namespace {

std::string cli_error(std::vector<const char*> argv) {
    argv.insert(argv.begin(), "lab01");
    return test::gsv_error_message([&] { parse_cli(static_cast<int>(argv.size()), argv.data()); });
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Where no folder can be made, whoever runs the test (root ignores permission bits): under a regular file.
std::filesystem::path folder_under_a_file(const test::TempDir& dir) {
    return dir.write("a-file", "not a folder\n") / "out";
}

}  // namespace

TEST_CASE("cli: a size too large names the limit, a zero side and a malformed size each their own line", "[unit]") {
    const std::string large = cli_error({"render", "--size", "100000x100000"});
    CHECK(contains(large, "100000x100000"));
    CHECK(contains(large, "too large"));
    CHECK(contains(large, std::to_string(kMaxImageSide)));
    CHECK(!contains(large, "WIDTHxHEIGHT"));
    CHECK(contains(cli_error({"render", "--size", "99999999999999999999999x4"}), "too large"));
    CHECK(contains(cli_error({"render", "--size", "8193x16"}), "too large"));
    CHECK(contains(cli_error({"render", "--size", "0x16"}), "--size = 0 is out of range [1, " + std::to_string(kMaxImageSide) + "]"));
    CHECK(contains(cli_error({"render", "--size", "16 x 16"}), "needs WIDTHxHEIGHT"));
    const char* fits[] = {"lab01", "render", "--size", "8192x0016"};
    const CliOptions o = parse_cli(4, fits);
    CHECK(o.width == kMaxImageSide);
    CHECK(o.height == 16);
}

TEST_CASE("cli: --version is taken by every mode's command line, beside --help", "[unit]") {
    const char* argv[] = {"lab01", "sweep", "--version"};
    CHECK(parse_cli(3, argv).version);
}

TEST_CASE("progress: the time left is the mean step's time times the steps left, and the last step says done", "[unit]") {
    CHECK(duration_text(0.4) == "0 s");
    CHECK(duration_text(59.4) == "59 s");
    CHECK(duration_text(200) == "3 min 20 s");
    CHECK(duration_text(7500) == "2 h 05 min");
    CHECK(progress_text(0, 12, "a", 5) == "[0/12] a");
    CHECK(progress_text(3, 12, "b", 30) == "[3/12] b, about 1 min 30 s left");
    CHECK(progress_text(11, 12, "c", 110) == "[11/12] c, about 10 s left");
    CHECK(progress_text(12, 12, "d", 121) == "[12/12] d, done in 2 min 1 s");
}

TEST_CASE("progress: where the stream is not a terminal, each step is one line and nothing else is printed", "[unit]") {
    std::FILE* stream = std::tmpfile();
    REQUIRE(stream);
    {
        Progress progress("sweep lab01", 3, stream);
        progress.step("one");
        progress.step("two");
        progress.step("three");
        progress.finish();
    }
    std::rewind(stream);
    std::vector<std::string> lines;
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, stream)) lines.push_back(buffer);
    std::fclose(stream);
    REQUIRE(lines.size() == 3);
    CHECK(lines[0].rfind("sweep lab01 [1/3] one, about ", 0) == 0);
    CHECK(lines[2].rfind("sweep lab01 [3/3] three, done in ", 0) == 0);
    for (const auto& line : lines) CHECK(!contains(line, "\r"));
}

TEST_CASE("output folder: a missing one is made, and one that cannot be is a line naming the option and the folder", "[unit]") {
    test::TempDir dir;
    prepare_output_folder(dir.path("new/deeper"), "--out-dir");
    CHECK(std::filesystem::is_directory(dir.path("new/deeper")));
    CHECK(std::filesystem::is_empty(dir.path("new/deeper")));  // the write check leaves nothing behind
    prepare_output_file(dir.path("images/a.png"), "--out");
    CHECK(std::filesystem::is_directory(dir.path("images")));

    const std::filesystem::path blocked = folder_under_a_file(dir);
    const std::string under_file = test::gsv_error_message([&] { prepare_output_folder(blocked, "--out-dir"); });
    CHECK(contains(under_file, "--out-dir: cannot write into folder '" + blocked.string() + "'"));
    CHECK(!contains(under_file, "\n"));
    const std::string is_file = test::gsv_error_message([&] { prepare_output_folder(dir.path("a-file"), "--out"); });
    CHECK(contains(is_file, "it is a file, not a folder"));
    CHECK(contains(test::gsv_error_message([&] { prepare_output_file(blocked / "x.png", "--out"); }), blocked.string()));
    CHECK(contains(test::gsv_error_message([&] { prepare_output_file(dir.path("images"), "--out"); }),
                   "--out: '" + dir.path("images").string() + "' is a folder"));
}

TEST_CASE("cases: a case file's size too large names the limit, like the lab's --size", "[grader]") {
    test::TempDir dir;
    const std::string tolerance = R"("tolerance": {"live": {"max_channel_diff": 2, "max_differing_fraction": 0},
        "golden": {"max_channel_diff": 2, "max_differing_fraction": 0}},
        "cases": [{"name": "a", "todo": "L01-T1", "settings": []}])";
    const auto large = dir.write("a.json", R"({"lab": "lab01", "size": "100000x100000", )" + tolerance + "}");
    const std::string message = test::gsv_error_message([&] { load_lab_cases(large); });
    CHECK(contains(message, "a.json: a size of 100000x100000 is too large: each side is at most " + std::to_string(kMaxImageSide)));
    const auto fits = dir.write("b.json", R"({"lab": "lab01", "size": "8192x64", )" + tolerance + "}");
    CHECK(load_lab_cases(fits).width == kMaxImageSide);
    const auto zero = dir.write("c.json", R"({"lab": "lab01", "size": "0x64", )" + tolerance + "}");
    CHECK(contains(test::gsv_error_message([&] { load_lab_cases(zero); }), "WIDTHxHEIGHT"));
}

TEST_CASE("class table: scores print as people write them", "[grader]") {
    std::vector<BatchEntry> entries(3);
    entries[0].name = "ada", entries[0].graded = true, entries[0].score = 0, entries[0].max_score = 14;
    entries[1].name = "bo", entries[1].graded = true, entries[1].score = 12.5, entries[1].max_score = 14;
    entries[2].name = "cy", entries[2].problem = "no labs/ folder";
    const std::string table = class_table(entries);
    CHECK(contains(table, " 0 / 14 "));
    CHECK(contains(table, " 12.5 / 14 "));
    CHECK(contains(table, "no labs/ folder"));
    CHECK(!contains(table, "0.000000"));
    CHECK(!contains(table, "14.0"));
}

// Each command is given far more work than the test's two-minute limit allows (100000 frames, 9999 animation
// frames): only a check made before the first frame ends it in time.
TEST_CASE("an output folder that cannot be written stops sweep, animate, render and compare before the first frame", "[lab]") {
    test::TempDir dir;
    const std::filesystem::path blocked = folder_under_a_file(dir);
    struct Command {
        std::string lab;  // lab 03 has an animated parameter (time), lab 01 none
        std::vector<std::string> args;
        std::string option;
    };
    const std::vector<Command> commands = {
        {"lab01", {"sweep", "--frames", "100000", "--out-dir", blocked.string()}, "--out-dir"},
        {"lab03", {"animate", "--count", "9999", "--out-dir", blocked.string()}, "--out-dir"},
        {"lab01", {"render", "--frames", "100000", "--out", (blocked / "a.png").string()}, "--out"},
        {"lab01", {"render", "--frames", "100000", "--out", dir.path("fine.png").string(), "--json", (blocked / "a.json").string()}, "--json"},
        {"lab01", {"compare", "--out", (blocked / "c.png").string()}, "--out"},
    };
    for (const auto& command : commands) {
        INFO(command.args[0] << " " << command.option);
        const test::LabRun run = test::run_lab(command.lab + "_solution", command.args, dir.path());
        CHECK(!run.process.timed_out);
        CHECK(run.exit_code() == 1);
        CHECK(contains(run.process.output, command.lab + ": " + command.option + ": cannot write into folder '" + blocked.string() + "'"));
        CHECK(!contains(run.process.output, "internal error"));
        CHECK(!contains(run.process.output, "wrote"));
    }
    CHECK(!std::filesystem::exists(dir.path("fine.png")));
}

TEST_CASE("gsv-grade: an --out that cannot be written is one line naming it before any build, not an internal error", "[grader]") {
    test::TempDir dir;
    const std::filesystem::path blocked = folder_under_a_file(dir);
    ProcessLimits limits;
    limits.timeout = std::chrono::seconds(60);
    const ProcessResult single = run_process({(test::bin_dir() / "gsv-grade").string(), "--labs", "lab01", "--public-only",
                                              "--no-timing", "--out", blocked.string()}, dir.path(), limits);
    CHECK(single.exit_code == 2);
    CHECK(single.output.rfind("gsv-grade: --out: cannot write into folder '" + blocked.string() + "': ", 0) == 0);
    CHECK(test::count_of(single.output, "\n") == 1);

    dir.write("class/ada/README", "a submission\n");
    const ProcessResult batch = run_process({(test::bin_dir() / "gsv-grade").string(), "--batch", dir.path("class").string(),
                                             "--out", blocked.string()}, dir.path(), limits);
    CHECK(batch.exit_code == 2);
    CHECK(contains(batch.output, "--out: cannot write into folder '" + blocked.string() + "'"));
    CHECK(!contains(batch.output, "internal error"));
    CHECK(!contains(batch.output, "[1/1]"));
}

TEST_CASE("gsv-grade: a bad --profile, or goldens asked for on ES, is one line and status 2 before anything runs", "[grader]") {
    test::TempDir dir;
    ProcessLimits limits;
    limits.timeout = std::chrono::seconds(60);
    const auto grade = [&](const std::vector<std::string>& args) {
        std::vector<std::string> argv{(test::bin_dir() / "gsv-grade").string()};
        argv.insert(argv.end(), args.begin(), args.end());
        argv.insert(argv.end(), {"--out", dir.path("out").string()});
        return run_process(argv, dir.path(), limits);
    };
    const ProcessResult metal = grade({"--profile", "metal"});
    CHECK(metal.exit_code == 2);
    CHECK(contains(metal.output, "unknown profile 'metal'"));
    CHECK(test::count_of(metal.output, "\n") == 1);
    const ProcessResult goldens = grade({"--profile", "es", "--update-goldens"});
    CHECK(goldens.exit_code == 2);
    CHECK(contains(goldens.output, "--update-goldens renders the goldens on the core profile; drop --profile es"));
    CHECK(test::count_of(goldens.output, "\n") == 1);
    CHECK(!std::filesystem::exists(dir.path("out")));
}
