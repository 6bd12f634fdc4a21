// The walls around student processes, tested with small shell programs (no GL).
#include "catch.hpp"
#include "test_support.h"

#include "grader/process.h"
#include "grader/run_lab.h"

#include <csignal>
#include <cstdlib>
#include <unistd.h>

using namespace gsv;

namespace {

ProcessResult sh(const std::string& script, const std::filesystem::path& dir, ProcessLimits limits = {},
                 const std::vector<std::string>& env = {}) {
    return run_process({"/bin/sh", "-c", script}, dir, limits, env);
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
