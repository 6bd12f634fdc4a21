// Each grader run's student code under a uid of its own (grader/src/run/uid_lease.h): leases never shared, and what one
// student's processes do to their uid's limits reaches no other run.
#include "catch.hpp"
#include "test_support.h"

#include "grader/src/run/lab_run.h"
#include "grader/src/run/process.h"
#include "grader/src/run/uid_lease.h"

#include <csignal>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using namespace gsv;
namespace fs = std::filesystem;

TEST_CASE("uids: leases are held by one run at a time, skip a uid that runs processes, and need a folder of the grader's alone",
          "[grader][process]") {
    if (geteuid() != 0) {
        WARN("not root: a grader that is not root maps its own uid in a user namespace and leases none");
        return;
    }
    test::TempDir dir;
    const fs::path locks = dir.path("locks");
    const UidLease first = UidLease::any(locks), second = UidLease::any(locks);
    CHECK(first.uid() >= kSandboxUidBase);
    CHECK(second.uid() != first.uid());
    CHECK(test::gsv_error_message([&] { UidLease::exactly(first.uid(), locks); }).find("another grader run on this machine holds") !=
          std::string::npos);
    const uid_t freed = second.uid();
    { UidLease moved = UidLease::exactly(first.uid() + 100, locks); }  // released when it goes
    CHECK_NOTHROW(UidLease::exactly(first.uid() + 100, locks));
    // A process left running as a uid (a run that could not kill it) makes that uid unclean: skipped.
    const pid_t left = fork();
    if (left == 0) {
        if (setgid(freed + 1) == 0 && setuid(freed + 1) == 0) pause();
        _exit(1);
    }
    usleep(100000);
    {
        const UidLease third = UidLease::any(locks);
        CHECK(third.uid() != freed + 1);
    }
    kill(left, SIGKILL);
    waitpid(left, nullptr, 0);
    // A lock folder others could write in is refused, in one line.
    const fs::path open_folder = dir.path("open-locks");
    fs::create_directories(open_folder);
    fs::permissions(open_folder, fs::perms::all);
    const std::string refused = test::gsv_error_message([&] { UidLease::any(open_folder); });
    CHECK(refused.find("is not the grader's alone") != std::string::npos);
    CHECK(refused.find('\n') == std::string::npos);
}

TEST_CASE("uids: one student's fork bomb does not stop another grader run's processes", "[grader][process]") {
    SandboxPolicy bomb_policy, build_policy;
    bomb_policy.processes = build_policy.processes = 64;
    const SandboxSupport support = probe_sandbox(bomb_policy);
    if (geteuid() != 0 || support.namespaces != SandboxSupport::Namespaces::AsRoot) {
        WARN("needs a root grader with namespaces: " << support.describe(bomb_policy));
        return;
    }
    // Leased from the machine's own locks, as gsv-grade leases them: no grader running meanwhile uses these uids.
    // Two grader runs: A's student forks until its limit, B's build then needs 40 processes at once.
    auto contest = [&](uid_t bomb_uid, uid_t build_uid) {
        bomb_policy.uid = bomb_uid;
        build_policy.uid = build_uid;
        ProcessLimits bomb_limits, build_limits;
        bomb_limits.sandbox = &bomb_policy;
        bomb_limits.support = build_limits.support = &support;
        build_limits.sandbox = &build_policy;
        bomb_limits.timeout = std::chrono::seconds(4);
        bomb_limits.private_folder = build_limits.private_folder = true;
        // The bomb takes every process its limit allows (63 and itself) and holds them until it is killed.
        std::thread bomb([&] {
            run_process({"/bin/sh", "-c", "i=0; while [ $i -lt 63 ]; do sleep 30 & i=$((i+1)); done; echo at the limit; wait"}, {}, bomb_limits);
        });
        for (int i = 0; i < 100 && tasks_of_user(bomb_uid) < 64; ++i) usleep(20000);
        CHECK(tasks_of_user(bomb_uid) == 64);
        const ProcessResult build =
            run_process({"/bin/sh", "-c", "i=0; while [ $i -lt 40 ]; do sleep 1 & i=$((i+1)); done; wait; echo built"}, {}, build_limits);
        bomb.join();
        return build;
    };
    // The same uid (as every run had before leases): the bomb's processes count against the build's limit.
    const UidLease one = UidLease::any();
    const ProcessResult shared = contest(one.uid(), one.uid());
    INFO("same uid: " << shared.output);
    CHECK(shared.output.find("fork") != std::string::npos);
    // Leased uids: the build runs as if the bomb were not there.
    const UidLease a = UidLease::any(), b = UidLease::any();
    const ProcessResult apart = contest(a.uid(), b.uid());
    INFO("leased uids: " << apart.output);
    CHECK(apart.output == "built\n");  // no "Cannot fork"
    std::string detail;
    CHECK(classify(apart, detail) == CaseStatus::Passed);
}
