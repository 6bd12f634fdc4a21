// A hostile student's submission against the grader's walls (grader/sandbox.h). One submission plants an attack in
// each case of lab 01 (tests/attacks/attacks.cpp.in) and odd files in its labs/, and is graded the way a batch
// grades it: gsv-grade as its own process, the seed on its command line. The attacks must learn nothing, earn no
// mark they did not earn, leave nothing outside their case and no process behind.
#include "grader_fixture.h"

#include "grader/process.h"
#include "grader/sandbox.h"
#include "grader/submission.h"

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

using namespace gsv;
namespace fs = std::filesystem;

namespace {

constexpr const char* kSeed = "918273645";

std::string substitute(std::string text, const std::string& from, const std::string& to) {
    for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) text.replace(at, from.size(), to);
    return text;
}

std::string probe(const std::string& output, const std::string& key) {
    const auto at = output.find("probe " + key + "=");
    if (at == std::string::npos) return "<not printed>";
    const auto from = at + 7 + key.size();
    return output.substr(from, output.find('\n', from) - from);
}

// Processes whose name is `comm`, on the whole machine.
int processes_named(const std::string& comm) {
    int count = 0;
    if (DIR* d = opendir("/proc")) {
        while (const dirent* e = readdir(d))
            if (e->d_name[0] >= '0' && e->d_name[0] <= '9' &&
                test::read_text(std::string("/proc/") + e->d_name + "/comm") == comm + "\n")
                ++count;
        closedir(d);
    }
    return count;
}

}  // namespace

TEST_CASE("grader: a hostile submission learns nothing, earns nothing it did not earn, and leaves nothing behind", "[grader][submission][attacks]") {
    SandboxPolicy policy;
    policy.read_only = {test::source_root() / "shaders"};
    const SandboxSupport support = probe_sandbox(policy);
    if (!support.allow_list()) {
        // Without the walls these attacks would reach the machine itself (one kills every process it may).
        WARN("no namespaces here (" << support.refused << "): the attacks are not run");
        return;
    }
    test::TempDir dir;
    const std::string lab_dir = "lab01_gooch";
    const fs::path lab = dir.path("submission/labs") / lab_dir;
    fs::create_directories(lab.parent_path());
    fs::copy(test::source_root() / "solutions" / lab_dir, lab, fs::copy_options::recursive);
    const fs::path out = dir.path("out");
    std::string attacks = test::read_text(test::source_root() / "tests" / "attacks" / "attacks.cpp.in");
    attacks = substitute(substitute(substitute(attacks, "@KIT@", test::source_root().string()), "@SEED@", kSeed), "@OUT@",
                         out.string());
    std::ofstream(lab / "attacks.cpp") << attacks;
    std::ofstream(lab / "leak.frag") << "#include \"" << (test::source_root() / "solutions" / lab_dir / "gooch.glsl").string()
                                     << "\"\nout vec4 fColor;\nvoid main() { fColor = vec4(1.0); }\n";
    std::string lab_cpp = test::read_text(lab / "lab.cpp");
    const std::string draw = "        draw(kit, frame, *shade_, kBackground);\n    }\n";
    REQUIRE(lab_cpp.find(draw) != std::string::npos);
    lab_cpp = substitute(lab_cpp, draw, "        attack(kit, frame);\n" + draw);
    lab_cpp = substitute(lab_cpp, "namespace {\n", "void attack(gsv::LabKit& kit, const gsv::Frame& frame);\n\nnamespace {\n");
    std::ofstream(lab / "lab.cpp") << lab_cpp;
    // Odd files: a hard link to something outside, a link into the reference, a FIFO, a file over the size limit.
    const fs::path outside = dir.write("outside.txt", "outside the submission\n");
    fs::create_hard_link(outside, lab / "hardlink.txt");
    fs::create_symlink(test::source_root() / "solutions" / lab_dir / "shade.frag", lab / "symlink.txt");
    REQUIRE(mkfifo((lab / "fifo").c_str(), 0644) == 0);
    std::ofstream(lab / "big.bin") << std::string(kMaxSubmissionFileBytes + 1, 'x');

    ProcessLimits limits;
    limits.timeout = std::chrono::minutes(10);
    limits.max_output_bytes = 1 << 20;
    const ProcessResult graded = run_process({(test::bin_dir() / "gsv-grade").string(), "--submission", dir.path("submission").string(),
                                              "--labs", "lab01", "--seed", kSeed, "--out", out.string(), "--quiet"},
                                             dir.path(), limits);
    INFO(graded.output.substr(0, 4000));
    REQUIRE(graded.exit_code == 0);
    const Json report = read_json_file(out / "report.json");
    INFO("sandbox: " << report.string_at("sandbox"));
    REQUIRE(report.string_at("sandbox").find("allow-list") != std::string::npos);

    // The odd files were refused, each named.
    const std::string log = report.array_at("builds").at(0).string_at("log");
    INFO("build log: " << log.substr(log.size() > 1500 ? log.size() - 1500 : 0));
    CHECK(log.find("hardlink.txt: a hard link") != std::string::npos);
    CHECK(log.find("symlink.txt: a symbolic link") != std::string::npos);
    CHECK(log.find("fifo: not a plain file") != std::string::npos);
    CHECK(log.find("big.bin: ") != std::string::npos);

    std::map<std::string, Json> image, timing;
    for (const Json& r : report.array_at("results").as_array()) (r.string_at("kind") == "image" ? image : timing)[r.string_at("name")] = r;
    const auto seen = [&](const std::string& name) { return image.at(name).string_at("output"); };

    // Reading: nothing of the kit but its public files, nothing of other processes or earlier results.
    const std::string read = seen("gooch");
    INFO("gooch saw:\n" << read);
    for (const char* secret : {"solutions", "golden", "hidden-cases", "git", "kit-build", "kit-tests", "reference-binary",
                               "compile-time-include", "hard-link", "symlink", "fifo", "big-file", "glsl-include", "seed"})
        CHECK(probe(read, secret) == "hidden");
    CHECK(probe(read, "grader-out") == "submission-build");  // the path to its own build; no report, no other lab
    CHECK(std::stoi(probe(read, "processes")) <= 2);  // the namespace's init and the lab
    CHECK(probe(read, "tmp").find("gsv-attack") == std::string::npos);

    // Writing: private /tmp, /var/tmp and /dev/shm with a quota; the kit and the lab's own files read-only.
    const std::string wrote = seen("diffuse");
    INFO("diffuse saw:\n" << wrote);
    for (const char* where : {"tmp-fill-mib", "shm-fill-mib", "var-tmp-fill-mib"}) CHECK(std::stol(probe(wrote, where)) <= 64);
    for (const char* where : {"own-lab-dir", "kit-shaders", "root"}) CHECK(probe(wrote, where) == "read-only");

    // No network.
    CHECK(probe(seen("stretched"), "loopback") == "unreachable");
    CHECK(probe(seen("stretched"), "internet") == "unreachable");

    // Every attack that changed nothing in the picture still drew it right: the walls cost the honest part nothing.
    for (const char* name : {"gooch", "diffuse", "stretched", "back-faces", "per-vertex", "phong", "silhouette"}) {
        INFO(name << ": " << image.at(name).string_at("status") << " " << image.at(name).string_at("detail"));
        CHECK(image.at(name).string_at("status") == "passed");
    }
    // Frame times are the grader's: slow frames that claim speed in their report are too slow, forged marks fail.
    INFO("phong timing: " << timing.at("phong").string_at("detail"));
    CHECK(timing.at("phong").string_at("status") == "too slow");
    CHECK(timing.at("phong").number_at("points") == 0);
    INFO("silhouette timing: " << timing.at("silhouette").string_at("detail"));
    CHECK(timing.at("silhouette").string_at("status") != "passed");
    CHECK(timing.at("silhouette").number_at("points") == 0);

    // Nothing outlives its case: the setsid daemon died with it, and left nothing in the grader's /tmp.
    CHECK(probe(seen("back-faces"), "daemon") == "started");
    CHECK(processes_named("gsvdaemon") == 0);
    CHECK_FALSE(fs::exists("/tmp/gsv-attack-daemon-alive"));
    CHECK_FALSE(fs::exists("/tmp/fill"));
    // The grader and its report survived a kill(-1, SIGKILL); the rest of the cases were graded.
    CHECK(probe(seen("per-vertex"), "kill-all") != "<not printed>");
    CHECK(image.size() >= 9);
}

TEST_CASE("grader: where the walls cannot go up, hidden cases and live references are refused in one line", "[grader][submission]") {
    const Json unchanged = parse_json(R"({"name": "unchanged", "file": "shade.frag", "find": "void main", "replace": "void main"})", "test");
    const test::EditedKit kit("lab01", test::mutant_spec("lab01").string_at("lab_dir"), unchanged);
    GradeOptions options = kit.options();
    options.allow_readable_kit = false;
    options.namespaces = false;
    options.timing = false;
    const std::string refused = test::gsv_error_message([&] { grade(options); });
    CHECK(refused.find("cannot hide the kit here (--no-namespaces)") != std::string::npos);
    CHECK(refused.find("--allow-readable-kit") != std::string::npos);
    CHECK(refused.find('\n') == std::string::npos);
    // Asked for, it grades, and the report says the kit was readable.
    options.allow_readable_kit = true;
    options.cases = {"gooch"};
    const GradeReport graded = grade(options);
    CHECK(graded.sandbox.find("the kit and the network are reachable") != std::string::npos);
    CHECK(graded.sandbox.find("(--allow-readable-kit)") != std::string::npos);
    // The self-check has nothing to hide: it runs, and says so.
    options.allow_readable_kit = false;
    options.self_check = true;
    CHECK(grade(options).sandbox.find("no namespaces here") != std::string::npos);
}
