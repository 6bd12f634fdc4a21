// A hostile student's submission against the grader's walls (grader/src/run/sandbox.h), inward and outward. One
// submission plants an attack in each case of lab 01 (tests/attacks/attacks.cpp.in), attacks on the grader's clock
// in labs 03 and 05 (tests/attacks/timing_attacks.cpp.in) and odd files in its labs/, and is graded the way an
// instructor grades in a terminal: gsv-grade as its own process on a pseudo terminal, the seed on its command line.
// The attacks must learn nothing, earn no mark they did not earn, reach nothing of the grader's (descriptors,
// terminal, disk), leave nothing outside their case and no process behind.
#include "grader_fixture.h"

#include "grader/src/run/process.h"
#include "grader/src/run/sandbox.h"
#include "grader/src/run/submission.h"

#include <dirent.h>
#include <fcntl.h>
#include <grp.h>
#include <pty.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <termios.h>
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

// A submission whose lab 01 plants tests/attacks/attacks.cpp.in and whose labs 03 and 05 (student code in C++) plant
// tests/attacks/timing_attacks.cpp.in around their render.
class HostileSubmission {
public:
    explicit HostileSubmission(const fs::path& folder, const fs::path& out, const std::vector<std::string>& labs) : folder_(folder) {
        for (const auto& lab : labs) {
            const std::string lab_dir = test::mutant_spec(lab).string_at("lab_dir");
            const fs::path dir = folder / "labs" / lab_dir;
            fs::create_directories(dir.parent_path());
            fs::copy(test::source_root() / "solutions" / lab_dir, dir, fs::copy_options::recursive);
            if (lab == "lab01") plant_lab01(dir, out);
            else plant_timing(dir);
        }
    }
    const fs::path& path() const { return folder_; }

private:
    static void plant_lab01(const fs::path& lab, const fs::path& out) {
        std::string attacks = test::read_text(test::source_root() / "tests" / "attacks" / "attacks.cpp.in");
        attacks = substitute(substitute(substitute(attacks, "@KIT@", test::source_root().string()), "@SEED@", kSeed), "@OUT@", out.string());
        std::ofstream(lab / "attacks.cpp") << attacks;
        std::ofstream(lab / "leak.frag") << "#include \"" << (test::source_root() / "solutions" / "lab01_gooch" / "gooch.glsl").string()
                                         << "\"\nout vec4 fColor;\nvoid main() { fColor = vec4(1.0); }\n";
        std::string lab_cpp = test::read_text(lab / "lab.cpp");
        const std::string draw = "        draw(kit, frame, *shade_, kBackground);\n    }\n";
        REQUIRE(lab_cpp.find(draw) != std::string::npos);
        lab_cpp = substitute(lab_cpp, draw, "        attack(kit, frame);\n" + draw);
        lab_cpp = substitute(lab_cpp, "namespace {\n", "void attack(gsv::LabKit& kit, const gsv::Frame& frame);\n\nnamespace {\n");
        std::ofstream(lab / "lab.cpp") << lab_cpp;
    }
    static void plant_timing(const fs::path& lab) {
        fs::copy_file(test::source_root() / "tests" / "attacks" / "timing_attacks.cpp.in", lab / "timing_attacks.cpp");
        std::string lab_cpp = test::read_text(lab / "lab.cpp");
        const std::string render = "    void render(gsv::LabKit& kit, const gsv::Frame& frame) override {\n";
        REQUIRE(lab_cpp.find(render) != std::string::npos);
        lab_cpp = substitute(lab_cpp, render,
                             "    void render(gsv::LabKit& kit, const gsv::Frame& frame) override {\n"
                             "        if (timing_attack_before(frame)) return;\n"
                             "        render_honest(kit, frame);\n"
                             "        timing_attack_after(frame);\n"
                             "    }\n"
                             "    void render_honest(gsv::LabKit& kit, const gsv::Frame& frame) {\n");
        lab_cpp = substitute(lab_cpp, "namespace {\n",
                             "bool timing_attack_before(const gsv::Frame& frame);\nvoid timing_attack_after(const gsv::Frame& frame);\n\nnamespace {\n");
        std::ofstream(lab / "lab.cpp") << lab_cpp;
    }
    fs::path folder_;
};

// Runs `argv` with a pseudo terminal as its controlling terminal and stdin/stdout/stderr (an instructor's shell), an
// extra descriptor of the invoker's left open (not close-on-exec), and returns what reached the terminal; `typed`
// gets what was injected into the terminal's input queue, which the instructor's shell would run next.
struct TerminalRun {
    int exit_code = -1;
    std::string screen, typed;
};
TerminalRun run_on_terminal(const std::vector<std::string>& argv, const fs::path& secret, int timeout_s) {
    int master = -1, slave = -1;
    REQUIRE(openpty(&master, &slave, nullptr, nullptr, nullptr) == 0);
    const int open_secret = open(secret.c_str(), O_RDONLY);  // deliberately inheritable, as an invoker's file may be
    REQUIRE(open_secret >= 0);
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    const pid_t pid = fork();
    if (pid == 0) {
        setsid();
        ioctl(slave, TIOCSCTTY, 0);
        dup2(slave, 0);
        dup2(slave, 1);
        dup2(slave, 2);
        close(master);
        alarm(static_cast<unsigned>(timeout_s));
        execv(args[0], args.data());
        _exit(127);
    }
    close(open_secret);
    TerminalRun run;
    fcntl(master, F_SETFL, O_NONBLOCK);
    int status = 0;
    char buffer[4096];
    while (true) {
        const ssize_t n = read(master, buffer, sizeof buffer);
        if (n > 0) {
            run.screen.append(buffer, static_cast<std::size_t>(n));
            continue;
        }
        if (waitpid(pid, &status, WNOHANG) == pid) break;
        usleep(20000);
    }
    for (ssize_t n; (n = read(master, buffer, sizeof buffer)) > 0;) run.screen.append(buffer, static_cast<std::size_t>(n));
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    // Whatever was pushed into the terminal's input: read from the terminal's side, without waiting.
    fcntl(slave, F_SETFL, O_NONBLOCK);
    termios raw{};
    tcgetattr(slave, &raw);
    cfmakeraw(&raw);
    tcsetattr(slave, TCSANOW, &raw);
    for (ssize_t n; (n = read(slave, buffer, sizeof buffer)) > 0;) run.typed.append(buffer, static_cast<std::size_t>(n));
    close(slave);
    close(master);
    return run;
}

std::map<std::string, Json> results_of(const Json& report, const std::string& kind) {
    std::map<std::string, Json> found;
    for (const Json& r : report.array_at("results").as_array())
        if (r.string_at("kind") == kind) found[r.string_at("name")] = r;
    return found;
}

const char* const kLab01Cases = "gooch,diffuse,diffuse-white,phong,backlit,stretched,gooch-torus,renormalize,back-faces,per-vertex,silhouette";

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
    const fs::path out = dir.path("out");
    const HostileSubmission submission(dir.path("submission"), out, {"lab01", "lab03", "lab05"});
    const fs::path lab = submission.path() / "labs" / "lab01_gooch";
    // Odd files: a hard link to something outside, a link into the reference, a FIFO, a file over the size limit.
    const fs::path outside = dir.write("outside.txt", "outside the submission\n");
    fs::create_hard_link(outside, lab / "hardlink.txt");
    fs::create_symlink(test::source_root() / "solutions" / "lab01_gooch" / "shade.frag", lab / "symlink.txt");
    REQUIRE(mkfifo((lab / "fifo").c_str(), 0644) == 0);
    std::ofstream(lab / "big.bin") << std::string(kMaxSubmissionFileBytes + 1, 'x');
    const fs::path secret = dir.write("invoker-secret.txt", "the invoker's open file\n");

    // As an instructor grades in a terminal: the grader's stdin, stdout and stderr are the terminal.
    const TerminalRun graded = run_on_terminal({(test::bin_dir() / "gsv-grade").string(), "--submission", submission.path().string(),
                                                "--labs", "lab01,lab03,lab05", "--cases", std::string(kLab01Cases) + ",gyre,abc",
                                                "--seed", kSeed, "--out", out.string(), "--quiet"},
                                               secret, 900);
    INFO(graded.screen.substr(0, 4000));
    REQUIRE(graded.exit_code == 0);
    // Nothing reached the instructor's terminal, or its input queue, from student code.
    CHECK(graded.screen.find("FAKE SCORE") == std::string::npos);
    CHECK(graded.typed.find("INJECTED") == std::string::npos);
    CHECK(graded.typed.empty());
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

    const std::map<std::string, Json> image = results_of(report, "image"), timing = results_of(report, "timing");
    const auto seen = [&](const std::string& name) { return image.at(name).string_at("output"); };

    // Reading: nothing of the kit but its public files, nothing of other processes or earlier results.
    const std::string read = seen("gooch");
    INFO("gooch saw:\n" << read);
    for (const char* secret_probe : {"solutions", "golden", "hidden-cases", "git", "kit-build", "kit-tests", "reference-binary",
                                     "compile-time-include", "hard-link", "symlink", "fifo", "big-file", "glsl-include", "seed"})
        CHECK(probe(read, secret_probe) == "hidden");
    CHECK(probe(read, "grader-out") == "submission-build");  // the path to its own build; no report, no other lab
    CHECK(std::stoi(probe(read, "processes")) <= 2);  // the namespace's init and the lab
    CHECK(probe(read, "tmp").find("gsv-attack") == std::string::npos);

    // Writing: private /tmp, /var/tmp and /dev/shm with a quota; the kit and the lab's own files read-only.
    const std::string wrote = seen("diffuse");
    INFO("diffuse saw:\n" << wrote);
    for (const char* where : {"tmp-fill-mib", "shm-fill-mib", "var-tmp-fill-mib"}) CHECK(std::stol(probe(wrote, where)) <= 64);
    for (const char* where : {"own-lab-dir", "kit-shaders", "root"}) CHECK(probe(wrote, where) == "read-only");

    // Descriptors: stdin /dev/null, stdout and stderr the grader's pipe, fd 3 its hand-in socket; nothing else, no
    // terminal (a session of its own), and /sys read-only to the last mount.
    const std::string held = seen("diffuse-white");
    INFO("diffuse-white saw:\n" << held);
    CHECK(probe(held, "fds") == "0:/dev/null,1:pipe,2:pipe,3:socket");
    CHECK(probe(held, "ttys") == "none");
    CHECK(probe(held, "inherited-read") == "nothing");
    CHECK(probe(held, "tiocsti") == "refused");
    CHECK(probe(held, "dev-tty") == "none");
    CHECK(probe(held, "controlling-terminal") == "none");
    CHECK(probe(held, "sys-rw") == "none");
    CHECK(probe(held, "sys-mkdir") == "refused");

    // No network.
    CHECK(probe(seen("stretched"), "loopback") == "unreachable");
    CHECK(probe(seen("stretched"), "internet") == "unreachable");

    // The working folder: 100,000 files and 2.4 GB asked for, its limits given, and its own status; a deep tree gone
    // with the case.
    INFO("backlit: " << image.at("backlit").string_at("detail") << "\n" << seen("backlit"));
    CHECK(image.at("backlit").string_at("status") == "wrote too much");
    CHECK(image.at("backlit").string_at("detail").find("the working folder holds 128 MiB") != std::string::npos);
    CHECK(std::stol(probe(seen("backlit"), "folder-fill-mib")) <= 128);
    CHECK(std::stol(probe(seen("backlit"), "folder-files")) < 4096);  // of the 100,000 asked for
    CHECK(probe(seen("gooch-torus"), "deep-tree") == "3000");
    // Links planted where files used to be read, then no hand-in: no output, quickly, nothing followed.
    INFO("renormalize: " << image.at("renormalize").string_at("detail"));
    CHECK(image.at("renormalize").string_at("status") == "no output");
    CHECK(image.at("renormalize").number_at("seconds") < 20);

    // Every attack that changed nothing in the picture still drew it right: the walls cost the honest part nothing.
    for (const char* name : {"gooch", "diffuse", "diffuse-white", "stretched", "gooch-torus", "back-faces", "per-vertex", "phong",
                             "silhouette", "gyre", "abc"}) {
        INFO(name << ": " << image.at(name).string_at("status") << " " << image.at(name).string_at("detail"));
        CHECK(image.at(name).string_at("status") == "passed");
    }
    // Frame times are the grader's: slow frames that claim speed in their report are too slow; frames handed in
    // before they were asked for are refused. Honest labs 03 and 05 keep their timing grades.
    INFO("phong timing: " << timing.at("phong").string_at("detail"));
    CHECK(timing.at("phong").string_at("status") == "too slow");
    CHECK(timing.at("phong").number_at("points") == 0);
    INFO("silhouette timing: " << timing.at("silhouette").string_at("detail"));
    CHECK(timing.at("silhouette").string_at("status") == "refused");
    CHECK(timing.at("silhouette").string_at("detail").find("before the grader asked for it") != std::string::npos);
    CHECK(timing.at("silhouette").number_at("points") == 0);
    for (const char* name : {"gyre", "abc"}) {
        INFO(name << " timing: " << timing.at(name).string_at("detail"));
        CHECK(timing.at(name).string_at("status") == "passed");
    }

    // Nothing outlives its case: the setsid daemon died with it, and left nothing in the grader's /tmp.
    CHECK(probe(seen("back-faces"), "daemon") == "started");
    CHECK(processes_named("gsvdaemon") == 0);
    CHECK_FALSE(fs::exists("/tmp/gsv-attack-daemon-alive"));
    CHECK_FALSE(fs::exists("/tmp/fill"));
    // The grader and its report survived a kill(-1, SIGKILL); the rest of the cases were graded.
    CHECK(probe(seen("per-vertex"), "kill-all") != "<not printed>");
    CHECK(image.size() == 13);

    // Labs 03 and 05, whose student code is C++, against the grader's clock: the same build graded again with each
    // attack; the honest sleeping control is too slow, every forgery is refused, and no attack passes.
    const fs::path built = out / "submission-build";
    for (const auto& [lab_id, case_name] : std::vector<std::pair<std::string, std::string>>{{"lab03", "gyre"}, {"lab05", "abc"}}) {
        for (const auto& [attack, expected] : std::vector<std::pair<std::string, std::string>>{
                 {"sleep", "too slow"}, {"forge", "refused"}, {"replay", "refused"}, {"skip", "refused"}}) {
            GradeOptions options = test::instructor_options(lab_id, dir.path("out-" + lab_id + "-" + attack));
            options.allow_readable_kit = false;
            options.student_bin_dir = built / "build" / "bin";
            options.student_root = built / "kit";
            options.cases = {case_name};
            options.hidden = false;
            setenv("GSV_ATTACK", attack.c_str(), 1);
            const GradeReport attacked = grade(options);
            unsetenv("GSV_ATTACK");
            const auto images = test::by_name(attacked), times = test::by_name(attacked, "timing");
            INFO(lab_id << " " << attack << ": image " << status_name(images.at(case_name).status) << " " << images.at(case_name).detail);
            INFO(lab_id << " " << attack << ": timing " << status_name(times.at(case_name).status) << " " << times.at(case_name).detail);
            CHECK(images.at(case_name).status == CaseStatus::Passed);  // the frame handed in is honest in every attack
            CHECK(status_name(times.at(case_name).status) == expected);
            CHECK(times.at(case_name).points == 0);
        }
    }
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

// Seen on a GPU machine whose kit sat behind a symbolic link: the sandbox binds each allowed path where it really is,
// so a lab started by its linked path was not there, and every case ended in "the lab binary could not be started".
TEST_CASE("grader: a kit, a build and a student's labs reached through symbolic links are graded where they really are",
          "[grader][submission]") {
    const Json unchanged = parse_json(R"({"name": "unchanged", "file": "shade.frag", "find": "void main", "replace": "void main"})", "test");
    const test::EditedKit kit("lab01", test::mutant_spec("lab01").string_at("lab_dir"), unchanged);
    test::TempDir links;
    fs::create_directory_symlink(test::source_root(), links.path("kit"));
    fs::create_directory_symlink(test::bin_dir(), links.path("bin"));
    GradeOptions options = kit.options();
    fs::create_directory_symlink(options.student_bin_dir, links.path("student-bin"));
    fs::create_directory_symlink(options.student_root, links.path("student-kit"));
    fs::create_directories(links.path("real-out"));
    fs::create_directory_symlink(links.path("real-out"), links.path("out"));
    options.kit_root = links.path("kit");
    options.bin_dir = links.path("bin");
    options.student_bin_dir = links.path("student-bin");
    options.student_root = links.path("student-kit");
    options.out_dir = links.path("out") / "report";
    options.cases = {"gooch"};
    options.timing = false;
    options.hidden = false;
    const GradeReport report = grade(options);
    const auto results = test::by_name(report);
    REQUIRE(results.count("gooch"));
    INFO(results.at("gooch").detail);
    CHECK(results.at("gooch").status == CaseStatus::Passed);  // the solution, run by its linked path
    CHECK(fs::exists(links.path("real-out") / "report" / "lab01" / "gooch" / "expected.png"));
}

TEST_CASE("grader: a batch of hostile submissions, graded by a grader that is not root, reaches no sibling and earns nothing",
          "[grader][submission][attacks]") {
    // Root tests this as nobody (uid 65534), as an instructor's own account would run it; a grader that is not root
    // puts its walls up in a user namespace of its own.
    const uid_t grader_uid = geteuid() == 0 ? 65534 : geteuid();
    test::TempDir dir;
    const fs::path out = dir.path("out"), submissions = dir.path("submissions");
    const std::vector<std::string> names{"ada", "bob", "cyd"};
    for (std::size_t i = 0; i < names.size(); ++i)
        // Each plants a link to the next classmate's reference images, and its other attacks.
        HostileSubmission(submissions / names[i], out / names[(i + 1) % names.size()], {"lab01"});
    fs::create_directories(out);
    for (const fs::path& folder : {dir.path(), out})
        if (geteuid() == 0) REQUIRE(chown(folder.c_str(), grader_uid, grader_uid) == 0);
    int output[2];
    REQUIRE(pipe(output) == 0);
    const pid_t pid = fork();
    if (pid == 0) {
        dup2(output[1], 1);
        dup2(output[1], 2);
        if (geteuid() == 0 && (setgroups(0, nullptr) != 0 || setgid(grader_uid) != 0 || setuid(grader_uid) != 0)) _exit(126);
        setenv("HOME", dir.path().c_str(), 1);
        alarm(900);
        const std::string grader = (test::bin_dir() / "gsv-grade").string();
        execl(grader.c_str(), grader.c_str(), "--batch", submissions.c_str(), "--out", out.c_str(), "--workers", "3", "--seed", kSeed,
              "--labs", "lab01", "--cases", "gooch,diffuse-white,backlit,renormalize,silhouette", "--quiet", nullptr);
        _exit(127);
    }
    close(output[1]);
    std::string printed;
    char buffer[4096];
    for (ssize_t n; (n = read(output[0], buffer, sizeof buffer)) > 0;) printed.append(buffer, static_cast<std::size_t>(n));
    close(output[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    INFO(printed.substr(0, 3000));
    REQUIRE(WIFEXITED(status));
    const int exited = WEXITSTATUS(status);
    if (exited == 2 && printed.find("cannot hide the kit") != std::string::npos) {
        WARN("no user namespaces for a grader that is not root here: the batch is refused, as it should be");
        return;
    }
    REQUIRE(exited == 0);
    for (const auto& name : names) {
        const Json report = read_json_file(out / name / "report.json");
        INFO(name << ": sandbox " << report.string_at("sandbox"));
        if (grader_uid != 0) CHECK(report.string_at("sandbox").find("in a user namespace") != std::string::npos);
        const std::map<std::string, Json> image = results_of(report, "image"), timing = results_of(report, "timing");
        const std::string held = image.at("diffuse-white").string_at("output");
        INFO(name << " diffuse-white saw:\n" << held);
        // Three workers started their processes side by side: none holds another's pipe, or anything of the grader's.
        CHECK(probe(held, "fds") == "0:/dev/null,1:pipe,2:pipe,3:socket");
        CHECK(probe(held, "tiocsti") == "refused");
        CHECK(probe(held, "sys-rw") == "none");
        const std::string read = image.at("gooch").string_at("output");
        for (const char* secret_probe : {"solutions", "golden", "hidden-cases", "kit-build", "seed"}) CHECK(probe(read, secret_probe) == "hidden");
        CHECK(image.at("backlit").string_at("status") == "wrote too much");
        // A link to a classmate's expected.png where the image used to be read: nothing followed, no output.
        CHECK(image.at("renormalize").string_at("status") == "no output");
        CHECK(timing.at("silhouette").string_at("status") == "refused");
        CHECK(image.at("silhouette").string_at("status") == "passed");
        CHECK(image.at("gooch").string_at("status") == "passed");
    }
}
