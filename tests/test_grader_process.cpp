// The walls around student processes, tested with small shell programs (no GL).
#include "catch.hpp"
#include "test_support.h"

#include "grader/src/run/lab_run.h"
#include "grader/src/run/process.h"
#include "grader/src/run/uid_lease.h"

#include "common/io/folder_tree.h"

#include <csignal>
#include <sstream>
#include <cstdlib>
#include <optional>
#include <fcntl.h>
#include <pty.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using namespace gsv;

namespace {

ProcessResult sh(const std::string& script, const std::filesystem::path& dir, ProcessLimits limits = {},
                 const std::vector<std::string>& env = {}) {
    return run_process({"/bin/sh", "-c", script}, dir, limits, env);
}

// A root test's sandboxed processes run as a uid leased as a grader run leases one (grader/src/run/uid_lease.h).
// Without namespaces the sandbox ends every process of its uid after each run; the policy's default uid, unleased, is
// the one the first grader run on the machine leases, whose labs that would kill (seen: another test's lab processes
// killed by signal 9 while this one ran beside them).
std::optional<UidLease> lease_uid(SandboxPolicy& policy) {
    if (geteuid() != 0) return std::nullopt;
    UidLease lease = UidLease::any();
    policy.uid = lease.uid();
    return lease;
}

}  // namespace

TEST_CASE("process: a program that never ends is killed at the wall-clock limit", "[grader][process]") {
    test::TempDir dir;
    ProcessLimits limits;
    limits.timeout = std::chrono::milliseconds(300);
    const auto r = sh("sleep 30", dir.path(), limits);
    CHECK(r.timed_out);
    CHECK(r.seconds < 5);
    std::string detail;
    CHECK(classify(r, detail) == CaseStatus::Timeout);
}

TEST_CASE("process: output is capped, and a flood is killed", "[grader][process]") {
    test::TempDir dir;
    ProcessLimits limits;
    limits.max_output_bytes = 1000;
    limits.flood_bytes = 1 << 20;
    const auto some = sh("i=0; while [ $i -lt 200 ]; do echo line $i; i=$((i+1)); done", dir.path(), limits);
    CHECK(some.exit_code == 0);
    CHECK_FALSE(some.flooded);
    CHECK(some.output_bytes > 1000);
    CHECK(some.output.find("[output cut:") != std::string::npos);
    const auto flood = sh("yes flood", dir.path(), limits);
    CHECK(flood.flooded);
    std::string detail;
    CHECK(classify(flood, detail) == CaseStatus::OutputFlood);
}

TEST_CASE("process: exit status, signals and failures to start are told apart", "[grader][process]") {
    test::TempDir dir;
    std::string detail;
    CHECK(classify(sh("exit 0", dir.path()), detail) == CaseStatus::Passed);
    CHECK(classify(sh("kill -SEGV $$", dir.path()), detail) == CaseStatus::Crash);
    CHECK(detail.find("signal 11") != std::string::npos);
    CHECK(classify(sh("echo 'lab01: needs OpenGL 4.3 for compute shaders' >&2; exit 3", dir.path()), detail) == CaseStatus::Unsupported);
    CHECK(detail == "lab01: needs OpenGL 4.3 for compute shaders");
    CHECK(classify(sh("exit 4", dir.path()), detail) == CaseStatus::NonFinite);
    CHECK(classify(sh("echo 'lab01: shader compile error in a.frag:' >&2; exit 1", dir.path()), detail) == CaseStatus::ShaderCompileError);
    CHECK(classify(sh("echo 'lab01: shader link error in program x' >&2; exit 1", dir.path()), detail) == CaseStatus::ShaderLinkError);
    CHECK(classify(sh("echo 'lab01: internal error during render: std::bad_alloc' >&2; exit 1", dir.path()), detail) == CaseStatus::MemoryLimit);
    CHECK(classify(run_process({(dir.path() / "no-such-binary").string()}, dir.path(), {}), detail) == CaseStatus::MissingBinary);
}

TEST_CASE("sandbox: an allow-list file system, private /tmp, no network, limits and a clean environment", "[grader][process]") {
    test::TempDir dir;
    const auto allowed = dir.path("allowed");
    std::filesystem::create_directories(allowed);
    dir.write("allowed/public.txt", "the kit's public data\n");
    const auto secret_file = dir.write("secret.txt", "the reference\n");
    dir.write("secret/answer.png", "pixels");
    const auto work = dir.path("work");
    std::filesystem::create_directories(work);
    SandboxPolicy policy;
    policy.read_only = {allowed};
    policy.file_size_bytes = 1 << 20;
    policy.tmp_bytes = 4 << 20;
    const std::optional<UidLease> lease = lease_uid(policy);
    const SandboxSupport support = probe_sandbox(policy);
    hand_over(work, policy, support);
    INFO(support.describe(policy));
    ProcessLimits limits;
    limits.sandbox = &policy;
    limits.support = &support;
    setenv("GSV_TEST_TOKEN_SECRET", "token", 1);
    setenv("MESA_TEST_PASSES", "1", 1);

    const auto env = sh("env", work, limits);
    CHECK(env.exit_code == 0);
    CHECK(env.output.find("GSV_TEST_TOKEN_SECRET") != std::string::npos);  // GSV_ names pass: the labs' own
    unsetenv("GSV_TEST_TOKEN_SECRET");
    setenv("GITHUB_TOKEN_FOR_TEST", "token", 1);
    const auto env2 = sh("env", work, limits);
    unsetenv("GITHUB_TOKEN_FOR_TEST");
    CHECK(env2.output.find("GITHUB_TOKEN_FOR_TEST") == std::string::npos);
    CHECK(env2.output.find("MESA_TEST_PASSES=1") != std::string::npos);
    CHECK(env2.output.find("HOME=" + std::filesystem::weakly_canonical(work).string()) != std::string::npos);

    // A file over the size limit ends the writer.
    const auto big = sh("exec head -c 4000000 /dev/zero > big", work, limits);
    std::string detail;
    CHECK(classify(big, detail) == CaseStatus::OutputFlood);

    if (!support.allow_list()) {
        WARN("no namespaces here (" << support.refused << "): the allow-list walls are not tested");
        return;
    }
    // Only what the policy allows: the secret beside the allowed folder is not there at all.
    const auto peek = sh("cat " + (allowed / "public.txt").string() + "; cat " + secret_file.string() + "; ls " +
                             dir.path().string(), work, limits);
    CHECK(peek.output.find("the kit's public data") != std::string::npos);
    CHECK(peek.output.find("the reference") == std::string::npos);
    const auto listing = sh("ls " + dir.path().string(), work, limits).output;
    CHECK(listing.find("allowed") != std::string::npos);
    CHECK(listing.find("secret") == std::string::npos);
    // The allowed folder is read-only; the working folder is not.
    CHECK(sh("echo x > " + (allowed / "new.txt").string(), work, limits).exit_code != 0);
    CHECK(sh("echo x > mine.txt", work, limits).exit_code == 0);
    CHECK(std::filesystem::exists(work / "mine.txt"));
    // Only loopback in a fresh network namespace; a /tmp of its own, empty, with a quota.
    const auto net = sh("cat /proc/net/dev", work, limits);
    CHECK(net.output.find("eth") == std::string::npos);
    const auto host_tmp = dir.write("../gsv-sandbox-host-tmp-probe.txt", "grader's /tmp\n");
    CHECK(sh("ls /tmp", work, limits).output.find("gsv-sandbox-host-tmp-probe") == std::string::npos);
    std::filesystem::remove(host_tmp);
    CHECK(sh("head -c 6000000 /dev/zero > /tmp/fill", work, limits).exit_code != 0);
    // No other process is visible: the shell is alone with what it starts.
    const auto ps = sh("ls /proc | grep -c '^[0-9]'", work, limits);
    CHECK(std::atoi(ps.output.c_str()) <= 4);  // the namespace's init, the shell, ls and grep
    if (geteuid() == 0 && support.namespaces == SandboxSupport::Namespaces::AsRoot)
        CHECK(sh("id -u", work, limits).output == std::to_string(policy.uid) + "\n");
    // The grader itself still sees everything.
    CHECK(test::read_text(secret_file) == "the reference\n");
}

namespace {

// The descriptors a program started by run_process holds, as "0:/dev/null 1:pipe 2:pipe": `ls` itself, exec'd
// directly (a shell would hold pipes and saved descriptors of its own), less the folder it opens to list them.
std::string descriptors_of_a_child(const std::filesystem::path& dir, const ProcessLimits& limits) {
    const ProcessResult r = run_process({"/bin/ls", "-l", "/proc/self/fd"}, dir, limits);
    std::string found;
    std::istringstream lines(r.output);
    for (std::string line; std::getline(lines, line);) {
        const auto arrow = line.find(" -> ");
        if (arrow == std::string::npos) continue;
        const std::string target = line.substr(arrow + 4);
        if (target.rfind("/proc/", 0) == 0) continue;
        const std::string fd = line.substr(line.rfind(' ', arrow - 1) + 1, arrow - line.rfind(' ', arrow - 1) - 1);
        found += (found.empty() ? "" : " ") + fd + ":" + target.substr(0, target.find(':'));
    }
    return found;
}

// The shell's controlling terminal (field 7 of /proc/PID/stat): 0 for none.
const char* const kTerminal = "cut -d' ' -f7 /proc/$$/stat";

ProcessLimits sandboxed(const SandboxPolicy& policy, const SandboxSupport& support) {
    ProcessLimits limits;
    limits.sandbox = &policy;
    limits.support = &support;
    return limits;
}

}  // namespace

TEST_CASE("process: a child starts with stdin from /dev/null, its own session, and no descriptor of the grader's", "[grader][process]") {
    test::TempDir dir;
    // An invoker's file and a pipe, both inheritable (no close-on-exec), as a careless caller or library leaves them.
    const int file = open(dir.write("secret.txt", "secret\n").c_str(), O_RDONLY);
    int leaky[2];
    REQUIRE(pipe(leaky) == 0);
    CHECK(descriptors_of_a_child(dir.path(), {}) == "0:/dev/null 1:pipe 2:pipe");
    CHECK(sh(std::string("echo tty: $(") + kTerminal + ")", dir.path()).output == "tty: 0\n");
    // With a hand-in socket: fd 3, and nothing else.
    struct Silent : HandinConversation {
        std::uint64_t max_image_pixels() const override { return 1; }
        void received(HandinMessage, double, const Reply&) override {}
    } silent;
    ProcessLimits with_socket;
    with_socket.handin = &silent;
    CHECK(descriptors_of_a_child(dir.path(), with_socket) == "0:/dev/null 1:pipe 2:pipe 3:socket");
    CHECK(sh("echo $GSV_HANDIN_FD", dir.path(), with_socket).output == "3\n");
    close(file);
    close(leaky[0]);
    close(leaky[1]);

    // Threads starting processes at once, as a batch's workers do: no child holds another's pipes.
    std::vector<std::string> seen(4);
    std::vector<std::thread> threads;
    for (std::size_t i = 0; i < seen.size(); ++i)
        threads.emplace_back([&, i] {
            seen[i] = descriptors_of_a_child(dir.path(), with_socket);
        });
    for (auto& t : threads) t.join();
    for (const auto& s : seen) CHECK(s == "0:/dev/null 1:pipe 2:pipe 3:socket");
}

TEST_CASE("process: a child of a grader on a terminal has no controlling terminal to type into", "[grader][process]") {
    int master = -1, slave = -1;
    REQUIRE(openpty(&master, &slave, nullptr, nullptr, nullptr) == 0);
    int report[2];
    REQUIRE(pipe(report) == 0);
    const pid_t pid = fork();
    if (pid == 0) {
        // The grader, in an instructor's terminal.
        setsid();
        ioctl(slave, TIOCSCTTY, 0);
        dup2(slave, 0);
        dup2(slave, 1);
        dup2(slave, 2);
        const auto r = sh(std::string("echo tty: $(") + kTerminal + "); echo stdin: $(readlink /proc/$$/fd/0); echo FAKE SCORE > /dev/tty; echo after: $?",
                          std::filesystem::temp_directory_path());
        (void)!write(report[1], r.output.data(), r.output.size());
        _exit(0);
    }
    close(report[1]);
    std::string seen;
    char buffer[1024];
    for (ssize_t n; (n = read(report[0], buffer, sizeof buffer)) > 0;) seen.append(buffer, static_cast<std::size_t>(n));
    int status = 0;
    waitpid(pid, &status, 0);
    close(report[0]);
    INFO(seen);
    CHECK(seen.find("tty: 0\n") != std::string::npos);
    CHECK(seen.find("stdin: /dev/null") != std::string::npos);
    CHECK(seen.find("after: 0") == std::string::npos);  // /dev/tty cannot be opened
    fcntl(master, F_SETFL, O_NONBLOCK);
    std::string screen;
    for (ssize_t n; (n = read(master, buffer, sizeof buffer)) > 0;) screen.append(buffer, static_cast<std::size_t>(n));
    CHECK(screen.find("FAKE SCORE") == std::string::npos);
    close(master);
    close(slave);
}

TEST_CASE("process: a private working folder has a size and a file-count limit, its own status, and is gone after", "[grader][process]") {
    SandboxPolicy policy;
    policy.folder_bytes = 8 << 20;
    policy.folder_files = 500;
    const std::optional<UidLease> lease = lease_uid(policy);
    SandboxSupport probed = probe_sandbox(policy);
    SandboxSupport none;
    none.refused = "a test of the fallback";
    std::vector<const SandboxSupport*> kinds{&none};
    if (probed.allow_list()) kinds.push_back(&probed);
    else WARN("no namespaces here (" << probed.refused << "): only the fallback's folder is tested");
    const std::filesystem::path outside = test::TempDir().path();  // a name only
    test::TempDir keep;
    const auto kept = keep.write("kept.txt", "the grader's own file\n");
    for (const SandboxSupport* support : kinds) {
        INFO(support->describe(policy));
        ProcessLimits limits = sandboxed(policy, *support);
        limits.private_folder = true;
        std::string detail;

        // Bytes: 40 files of 1 MiB into a folder of 8 MiB.
        const auto bytes = sh("for i in $(seq 40); do head -c 1048576 /dev/zero > f$i || break; done; exit 0", {}, limits);
        CHECK(bytes.folder_full);
        CHECK(classify(bytes, detail) == CaseStatus::WroteTooMuch);
        CHECK(detail.find("wrote too much: ") != std::string::npos);
        CHECK(detail.find("the working folder holds 8 MiB in 500") != std::string::npos);
        // Entries: 1000 empty files into a folder of 500.
        const auto files = sh("i=0; while [ $i -lt 1000 ]; do : > f$i 2>/dev/null || break; i=$((i+1)); done; exit 0", {}, limits);
        CHECK(files.folder_full);
        CHECK(classify(files, detail) == CaseStatus::WroteTooMuch);
        // A deep tree (longer than any path), a folder without permissions, a link out and a FIFO: all gone, and
        // the link's target untouched.
        // (The tree grows from the top, so no path the shell names is long: 300 levels of 20 characters.)
        const auto tree = sh("ln -s " + kept.string() + " link; mkfifo fifo; mkdir locked; chmod 0 locked; mkdir t; "
                             "i=0; while [ $i -lt 300 ]; do mkdir n && mv t n/dddddddddddddddddddd && mv n t || break; i=$((i+1)); done; "
                             "chmod 0 t; echo depth $i; echo in $(pwd)",
                             {}, limits);
        INFO(tree.output << tree.cleanup_error);
        CHECK(tree.output.find("depth 300") != std::string::npos);
        CHECK(tree.cleanup_error.empty());
        CHECK_FALSE(tree.folder_full);
        CHECK(classify(tree, detail) == CaseStatus::Passed);
        CHECK(test::read_text(kept) == "the grader's own file\n");
        // Nothing is left on the grader's disk; with namespaces nothing was ever there (HOME is the folder inside).
        const std::string folder = tree.output.substr(tree.output.find("in ") + 3, tree.output.find('\n', tree.output.find("in ")) - tree.output.find("in ") - 3);
        if (support->allow_list()) {
            CHECK(folder == kCaseFolder);
            CHECK(sh("echo $HOME", {}, limits).output == std::string(kCaseFolder) + "\n");
        } else {
            CHECK(folder.find("gsv-case-") != std::string::npos);
            CHECK_FALSE(std::filesystem::exists(folder));
        }
    }
}

TEST_CASE("folders: a tree removed whatever it holds, deeper than any path, and what it held counted", "[grader][process]") {
    test::TempDir dir;
    const auto kept = dir.write("kept.txt", "kept\n");
    const std::filesystem::path top = dir.path("tree");
    std::filesystem::create_directories(top);
    // 400 levels of 20 characters: 8 KiB of path, twice PATH_MAX.
    std::string relative;
    {
        const int root = open(top.c_str(), O_RDONLY | O_DIRECTORY);
        int at = root;
        for (int i = 0; i < 400; ++i) {
            REQUIRE(mkdirat(at, "dddddddddddddddddddd", 0755) == 0);
            const int next = openat(at, "dddddddddddddddddddd", O_RDONLY | O_DIRECTORY);
            if (at != root) close(at);
            at = next;
        }
        const int leaf = openat(at, "leaf", O_WRONLY | O_CREAT, 0644);
        (void)!write(leaf, "x", 1);
        close(leaf);
        REQUIRE(symlinkat(kept.c_str(), at, "link") == 0);
        REQUIRE(mkfifoat(at, "fifo", 0644) == 0);
        REQUIRE(fchmod(at, 0) == 0);
        close(at);
        close(root);
    }
    std::filesystem::create_directories(top / "locked" / "inner");
    std::filesystem::permissions(top / "locked", std::filesystem::perms::none);
    const FolderUse measured = measure_folder(top);
    CHECK(measured.files >= 200);
    CHECK(measured.too_deep);  // past kMeasuredDepth levels it stops looking, and says so
    const FolderUse removed = remove_folder(top);
    CHECK(removed.files == 400 + 3 + 2 + 1);  // the levels, leaf, link and FIFO, locked and inner, the folder itself
    CHECK_FALSE(std::filesystem::exists(top));
    CHECK(test::read_text(kept) == "kept\n");
    CHECK(remove_folder(top).files == 0);  // already gone: nothing to do
}
