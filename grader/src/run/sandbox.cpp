#include "grader/src/run/sandbox.h"

#include "grader/src/run/sandbox_steps.h"
#include "grader/src/run/uid_lease.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <grp.h>
#include <sched.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/utsname.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;

namespace gsv {

bool sandbox_fail(std::string& why, const std::string& what) {
    why = what + ": " + std::strerror(errno);
    return false;
}

namespace {

const char* const kDeviceNodes[] = {"null", "zero", "full", "random", "urandom", "tty"};

bool write_file(const char* path, const char* text) {
    const int fd = open(path, O_WRONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const auto length = static_cast<ssize_t>(std::strlen(text));
    const bool ok = write(fd, text, static_cast<size_t>(length)) == length;
    close(fd);
    return ok;
}

bool set_limit(int resource, rlim_t value) {
    const rlimit limit{value, value};
    return setrlimit(resource, &limit) == 0;
}

bool become_student(const SandboxPlan& plan, std::string& why) {
    if (plan.as_root && (setgroups(0, nullptr) != 0 || setgid(plan.uid) != 0 || setuid(plan.uid) != 0 || getuid() != plan.uid))
        return sandbox_fail(why, "cannot run as uid " + std::to_string(plan.uid));
    bool ok = set_limit(RLIMIT_CPU, plan.cpu_seconds) && set_limit(RLIMIT_FSIZE, plan.file_size_bytes) &&
              set_limit(RLIMIT_CORE, 0) && set_limit(RLIMIT_NOFILE, 1024);
    if (plan.address_space_bytes > 0) ok = ok && set_limit(RLIMIT_AS, plan.address_space_bytes);
    // Counted per real uid: the sandbox's own under root; under a user namespace the grader's, so the count adds
    // what the grader's uid runs already (plan.processes was worked out that way).
    ok = ok && set_limit(RLIMIT_NPROC, plan.processes);
    if (!ok) return sandbox_fail(why, "cannot set the resource limits");
    if (chdir(plan.working_dir.c_str()) != 0) return sandbox_fail(why, "cannot enter the working folder " + plan.working_dir);
    return true;
}

// Absolute, with every folder on the way resolved; the last component is kept as it is, so a link stays a link
// (a submission's view of the kit links to its shaders/ and data/, which are bound too).
std::string host_path(const fs::path& p) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(p, ec).lexically_normal();
    const fs::path parent = fs::weakly_canonical(absolute.parent_path(), ec);
    return ec ? absolute.string() : (parent / absolute.filename()).string();
}

}  // namespace

// Linux counts RLIMIT_NPROC per user namespace from 5.14 on; before, per real uid across every namespace.
static bool processes_counted_per_namespace() {
    utsname name {};
    if (uname(&name) != 0) return false;
    int major = 0, minor = 0;
    if (std::sscanf(name.release, "%d.%d", &major, &minor) != 2) return false;
    return major > 5 || (major == 5 && minor >= 14);
}

SandboxPlan plan_sandbox(const SandboxPolicy& policy, const SandboxSupport& support, const fs::path& working_dir,
                         double timeout_s, bool private_folder) {
    SandboxPlan plan;
    plan.namespaces = support.namespaces;
    // A user namespace maps only the grader's own uid; elsewhere a root grader runs student code as policy.uid.
    plan.as_root = geteuid() == 0 && support.namespaces != SandboxSupport::Namespaces::AsUser;
    plan.uid = plan.as_root ? policy.uid : geteuid();
    plan.host_uid = geteuid();
    plan.host_gid = getegid();
    std::error_code ec;
    const auto add = [&](const fs::path& p, bool read_only) {
        const std::string path = host_path(p);
        plan.binds.push_back({path, read_only, fs::exists(fs::symlink_status(path, ec))});
    };
    for (const auto& p : policy.read_only) add(p, true);
    for (const auto& p : policy.read_write) add(p, false);
    if (private_folder && support.allow_list()) {
        plan.working_dir = kCaseFolder;
        plan.folder_options = "size=" + std::to_string(policy.folder_bytes) + ",nr_inodes=" + std::to_string(policy.folder_files) +
                              ",mode=0700" + (plan.as_root ? ",uid=" + std::to_string(plan.uid) + ",gid=" + std::to_string(plan.uid) : "");
    } else if (!working_dir.empty()) {
        plan.working_dir = fs::weakly_canonical(working_dir).string();
        add(plan.working_dir, false);
    }
    for (const char* node : kDeviceNodes) plan.devices.emplace_back(node);
    // A GPU where there is one: the render nodes and NVIDIA's device files.
    if (fs::is_directory("/dev/dri", ec)) plan.devices.emplace_back("dri");
    for (auto it = fs::directory_iterator("/dev", ec); !ec && it != fs::directory_iterator(); it.increment(ec))
        if (it->path().filename().string().rfind("nvidia", 0) == 0) plan.devices.push_back(it->path().filename().string());
    plan.tmp_options = "size=" + std::to_string(policy.tmp_bytes) + ",nr_inodes=" + std::to_string(policy.tmp_files) + ",mode=1777";
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    plan.cpu_seconds = static_cast<std::uint64_t>((policy.cpu_seconds > 0 ? policy.cpu_seconds : timeout_s * cores + 5) + 1);
    plan.file_size_bytes = policy.file_size_bytes;
    plan.address_space_bytes = policy.address_space_bytes;
    // A uid of its own (root) or a user namespace of its own counts only the sandbox's processes; an older kernel
    // counts a user namespace's against every process of the grader's uid, which are added.
    const bool own_count = plan.as_root || (support.namespaces == SandboxSupport::Namespaces::AsUser && processes_counted_per_namespace());
    plan.processes = static_cast<std::uint64_t>(policy.processes + (own_count ? 0 : tasks_of_user(geteuid())));
    return plan;
}

bool enter_sandbox(const SandboxPlan& plan, std::string& why) {
    using N = SandboxSupport::Namespaces;
    if (plan.namespaces == N::None) {
        // No namespaces here: a fresh folder, another uid where the grader is root, and the limits.
        return become_student(plan, why);
    }
    int flags = CLONE_NEWNS | CLONE_NEWNET | CLONE_NEWPID | CLONE_NEWIPC | CLONE_NEWUTS;
    if (plan.namespaces == N::AsUser) flags |= CLONE_NEWUSER;
    if (unshare(flags) != 0) return sandbox_fail(why, "cannot make the namespaces");
    if (plan.namespaces == N::AsUser) {
        char map[64];
        if (!write_file("/proc/self/setgroups", "deny")) return sandbox_fail(why, "cannot deny setgroups");
        std::snprintf(map, sizeof map, "%u %u 1", unsigned(plan.host_uid), unsigned(plan.host_uid));
        if (!write_file("/proc/self/uid_map", map)) return sandbox_fail(why, "cannot map the uid");
        std::snprintf(map, sizeof map, "%u %u 1", unsigned(plan.host_gid), unsigned(plan.host_gid));
        if (!write_file("/proc/self/gid_map", map)) return sandbox_fail(why, "cannot map the gid");
    }
    // The status of the student's process crosses the namespace's edge through this pipe: inside, its parent is
    // the namespace's first process, which cannot die of most signals the way an ordinary process does.
    int status_pipe[2];
    if (pipe2(status_pipe, O_CLOEXEC) != 0) return sandbox_fail(why, "cannot make a pipe");
    const pid_t init = fork();
    if (init < 0) return sandbox_fail(why, "cannot fork into the PID namespace");
    if (init > 0) {
        close(status_pipe[1]);
        const int init_status = wait_for(init);
        int student_status = 0;
        if (read(status_pipe[0], &student_status, sizeof student_status) == sizeof student_status) exit_as(student_status);
        exit_as(init_status);
    }
    // The namespace's first process: it dies with the process outside (which waits for it from the moment it is
    // forked), and the namespace with it.
    close(status_pipe[0]);
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    scrub_grader_traces();
    if (!build_root(plan, why)) return false;
    const pid_t student = fork();
    if (student < 0) return sandbox_fail(why, "cannot fork the student's process");
    if (student > 0) {
        const int status = plan.answers_commands ? answer_commands(plan, student) : wait_for(student);
        (void)!write(status_pipe[1], &status, sizeof status);
        say_folder(plan, "folder");
        _exit(0);  // every other process of the namespace ends here
    }
    close(status_pipe[1]);
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    return become_student(plan, why);
}

std::string SandboxSupport::describe(const SandboxPolicy& policy) const {
    const std::string limits = "rlimits on memory, CPU, file size, files, processes; wall-clock timeout; output cap";
    const std::string who = geteuid() == 0 && namespaces != Namespaces::AsUser
                                ? "student code runs as uid " + std::to_string(policy.uid)
                                : "";
    if (!allow_list())
        return "no namespaces here (" + refused + "): the kit and the network are reachable from student code" +
               (who.empty() ? "" : "; " + who) + "; " + limits;
    return std::string("allow-list file system (its folder, its own lab, the kit's public files), ") +
           "private /tmp /var/tmp /dev/shm (" + std::to_string(policy.tmp_bytes >> 20) + " MiB each), " +
           "PID, network and IPC namespaces" + (namespaces == Namespaces::AsUser ? " in a user namespace" : "") +
           (who.empty() ? "" : "; " + who) + "; " + limits;
}

SandboxSupport probe_sandbox(const SandboxPolicy& policy) {
    using N = SandboxSupport::Namespaces;
    SandboxSupport support;
    char pattern[] = "/tmp/gsv-probe-XXXXXX";
    const char* dir = mkdtemp(pattern);
    if (!dir) {
        support.refused = "no temporary folder";
        return support;
    }
    for (const N kind : {geteuid() == 0 ? N::AsRoot : N::AsUser, N::AsUser}) {
        support.namespaces = kind;
        const SandboxPlan plan = plan_sandbox(policy, support, dir, 10, true);
        hand_over(dir, policy, support);
        int out[2];
        if (pipe2(out, O_CLOEXEC) != 0) break;
        const pid_t pid = fork();
        if (pid == 0) {
            dup2(out[1], STDERR_FILENO);
            close(out[0]);
            std::string why;
            if (!enter_sandbox(plan, why)) {
                (void)!write(STDERR_FILENO, why.data(), why.size());
                _exit(1);
            }
            // Every allowed path that exists on the host must be readable inside, and the working folder writable.
            if (access(".", W_OK) != 0) {
                const std::string what = "cannot write the working folder inside";
                (void)!write(STDERR_FILENO, what.data(), what.size());
                _exit(1);
            }
            for (const auto& b : plan.binds)
                if (b.exists && access(b.path.c_str(), R_OK) != 0) {
                    const std::string what = "cannot read " + b.path + " inside";
                    (void)!write(STDERR_FILENO, what.data(), what.size());
                    _exit(1);
                }
            _exit(0);
        }
        close(out[1]);
        char text[512] = {};
        std::size_t got = 0;
        for (ssize_t n; got < sizeof text - 1 && (n = read(out[0], text + got, sizeof text - 1 - got)) > 0;) got += std::size_t(n);
        close(out[0]);
        const int status = pid > 0 ? wait_for(pid) : -1;
        if (pid > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0) {
            std::error_code ec;
            fs::remove_all(dir, ec);
            return support;
        }
        // The first refusal says most: the later tries put up fewer walls.
        if (support.refused.empty()) support.refused = got ? std::string(text, got) : "unshare refused";
    }
    std::error_code ec;
    fs::remove_all(dir, ec);
    support.namespaces = N::None;
    return support;
}

void hand_over(const fs::path& path, const SandboxPolicy& policy, const SandboxSupport& support) {
    if (geteuid() != 0) return;
    // A user namespace maps the grader's own uid: the folder stays (or becomes again) the grader's.
    const uid_t owner = support.namespaces == SandboxSupport::Namespaces::AsUser ? geteuid() : policy.uid;
    (void)!lchown(path.c_str(), owner, owner);
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(path, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
        (void)!lchown(it->path().c_str(), owner, owner);
}

}  // namespace gsv
