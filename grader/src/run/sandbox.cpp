#include "grader/src/run/sandbox.h"

#include "grader/src/run/uid_lease.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <sched.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <sys/syscall.h>
#include <sys/utsname.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;

namespace gsv {
namespace {

// Where the host's file system hangs while the new root is built, and the new root itself, both on a tmpfs that
// first covers /tmp in the child's own mount namespace (the bubblewrap way: the host stays reachable until the
// second pivot drops it).
constexpr const char* kBase = "/tmp";
constexpr const char* kOld = "/oldroot";
constexpr const char* kNew = "/newroot";

const char* const kSystemPaths[] = {"/usr", "/etc", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32", "/sys"};
const char* const kDeviceNodes[] = {"null", "zero", "full", "random", "urandom", "tty"};

bool fail(std::string& why, const std::string& what) {
    why = what + ": " + std::strerror(errno);
    return false;
}

bool write_file(const char* path, const char* text) {
    const int fd = open(path, O_WRONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const auto length = static_cast<ssize_t>(std::strlen(text));
    const bool ok = write(fd, text, static_cast<size_t>(length)) == length;
    close(fd);
    return ok;
}

// mkdir -p for a path inside the new root (components are created 0755).
bool make_dirs(const std::string& path) {
    for (std::size_t at = 1; at <= path.size(); ++at) {
        if (at < path.size() && path[at] != '/') continue;
        const std::string part = path.substr(0, at);
        if (mkdir(part.c_str(), 0755) != 0 && errno != EEXIST) return false;
    }
    return true;
}

// The flags a read-only remount must keep: in a user namespace the source mount's locked flags cannot be cleared.
unsigned long kept_flags(const char* path) {
    struct statvfs s {};
    if (statvfs(path, &s) != 0) return 0;
    unsigned long flags = 0;
    if (s.f_flag & ST_NOSUID) flags |= MS_NOSUID;
    if (s.f_flag & ST_NODEV) flags |= MS_NODEV;
    if (s.f_flag & ST_NOEXEC) flags |= MS_NOEXEC;
    if (s.f_flag & ST_NOATIME) flags |= MS_NOATIME;
    if (s.f_flag & ST_NODIRATIME) flags |= MS_NODIRATIME;
    if (s.f_flag & ST_RELATIME) flags |= MS_RELATIME;
    return flags;
}

// Makes the mount at `path` and every mount below it read-only. A bind with MS_REC takes the mounts below along
// (under /sys: cgroups, debugfs, bpf, ...), but a remount changes only the top one: mount_setattr (Linux 5.12)
// sets the flag on the whole tree; before it, each mount below is remounted by itself, found in mountinfo.
bool read_only_tree(const char* path, std::string& why) {
#ifdef SYS_mount_setattr
    struct {
        std::uint64_t attr_set, attr_clr, propagation, userns_fd;
    } attr{0x00000001 /* MOUNT_ATTR_RDONLY */, 0, 0, 0};
    if (syscall(SYS_mount_setattr, AT_FDCWD, path, 0x8000 /* AT_RECURSIVE */, &attr, sizeof attr) == 0) return true;
    if (errno != ENOSYS) return fail(why, std::string("cannot make ") + path + " read-only");
#endif
    if (mount(nullptr, path, nullptr, MS_BIND | MS_REMOUNT | MS_RDONLY | kept_flags(path), nullptr) != 0)
        return fail(why, std::string("cannot make ") + path + " read-only");
    // The mounts below: field 5 of each mountinfo line is its mount point (spaces escaped as \040).
    static char info[1 << 16];
    const int fd = open("/proc/self/mountinfo", O_RDONLY | O_CLOEXEC);
    if (fd < 0) return fail(why, "cannot read /proc/self/mountinfo");
    ssize_t n = 0, got;
    while (n < static_cast<ssize_t>(sizeof info) - 1 && (got = read(fd, info + n, sizeof info - 1 - n)) > 0) n += got;
    close(fd);
    info[n] = '\0';
    const std::size_t length = std::strlen(path);
    for (char* line = info; line && *line;) {
        char* end = std::strchr(line, '\n');
        if (end) *end = '\0';
        char* field = line;
        for (int i = 0; i < 4 && field; ++i) field = std::strchr(field + 1, ' ');
        if (field) {
            char* point = field + 1;
            if (char* stop = std::strchr(point, ' ')) *stop = '\0';
            if (std::strncmp(point, path, length) == 0 && point[length] == '/' &&
                mount(nullptr, point, nullptr, MS_BIND | MS_REMOUNT | MS_RDONLY | kept_flags(point), nullptr) != 0)
                return fail(why, std::string("cannot make ") + point + " read-only");
        }
        line = end ? end + 1 : nullptr;
    }
    return true;
}

// Binds the host's `path` at the same path in the new root; a symlink is recreated, a missing path left out.
bool bind(const std::string& path, bool read_only, std::string& why) {
    const std::string from = std::string(kOld) + path, to = std::string(kNew) + path;
    struct stat st {};
    if (lstat(from.c_str(), &st) != 0) return true;
    const std::string parent = to.substr(0, to.rfind('/'));
    if (!make_dirs(parent)) return fail(why, "cannot make " + parent);
    if (S_ISLNK(st.st_mode)) {
        char target[4096];
        const ssize_t n = readlink(from.c_str(), target, sizeof target - 1);
        if (n < 0) return fail(why, "cannot read the link " + path);
        target[n] = '\0';
        if (symlink(target, to.c_str()) != 0 && errno != EEXIST) return fail(why, "cannot link " + path);
        return true;
    }
    if (S_ISDIR(st.st_mode)) {
        if (mkdir(to.c_str(), 0755) != 0 && errno != EEXIST) return fail(why, "cannot make " + path);
    } else {
        const int fd = open(to.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
        if (fd < 0 && errno != EEXIST) return fail(why, "cannot make " + path);
        if (fd >= 0) close(fd);
    }
    if (mount(from.c_str(), to.c_str(), nullptr, MS_BIND | MS_REC, nullptr) != 0) return fail(why, "cannot bind " + path);
    return !read_only || read_only_tree(to.c_str(), why);
}

bool tmpfs(const std::string& path, const std::string& options, std::string& why) {
    if (!make_dirs(path)) return fail(why, "cannot make " + path);
    if (mount("tmpfs", path.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, options.c_str()) != 0)
        return fail(why, "cannot mount a tmpfs on " + path);
    return true;
}

bool make_dev(const SandboxPlan& plan, std::string& why) {
    const std::string dev = std::string(kNew) + "/dev";
    if (!tmpfs(dev, "size=64k,mode=0755", why)) return false;
    for (const std::string& name : plan.devices)
        if (!bind("/dev/" + name, false, why)) return false;
    const char* const links[][2] = {{"/proc/self/fd", "fd"}, {"/proc/self/fd/0", "stdin"}, {"/proc/self/fd/1", "stdout"},
                                    {"/proc/self/fd/2", "stderr"}};
    for (const auto& link : links)
        if (symlink(link[0], (dev + "/" + link[1]).c_str()) != 0) return fail(why, std::string("cannot link /dev/") + link[1]);
    return tmpfs(dev + "/shm", plan.tmp_options, why);
}

// In the first process of the new PID namespace, inside the new mount namespace: the new root, then pivot into it.
bool build_root(const SandboxPlan& plan, std::string& why) {
    if (mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0) return fail(why, "cannot make the mounts private");
    if (mount("tmpfs", kBase, "tmpfs", MS_NOSUID | MS_NODEV, "size=1m,mode=0755") != 0) return fail(why, "cannot mount the base tmpfs");
    const std::string base_old = std::string(kBase) + kOld, base_new = std::string(kBase) + kNew;
    if (mkdir(base_old.c_str(), 0755) != 0 || mkdir(base_new.c_str(), 0755) != 0) return fail(why, "cannot make the base");
    if (syscall(SYS_pivot_root, kBase, base_old.c_str()) != 0) return fail(why, "cannot pivot into the base");
    if (chdir("/") != 0) return fail(why, "cannot enter the base");
    if (mount("tmpfs", kNew, "tmpfs", MS_NOSUID | MS_NODEV, "size=1m,mode=0755") != 0) return fail(why, "cannot mount the new root");
    for (const char* path : kSystemPaths)
        if (!bind(path, true, why)) return false;
    if (!make_dev(plan, why)) return false;
    if (!tmpfs(std::string(kNew) + "/tmp", plan.tmp_options, why) || !tmpfs(std::string(kNew) + "/var/tmp", plan.tmp_options, why))
        return false;
    // After the private /tmp, so what is allowed under /tmp (a build's working folder) is bound on top of it.
    for (const auto& b : plan.binds)
        if (!bind(b.path, b.read_only, why)) return false;
    if (!plan.folder_options.empty() && !tmpfs(std::string(kNew) + plan.working_dir, plan.folder_options, why)) return false;
    const std::string proc = std::string(kNew) + "/proc";
    if (!make_dirs(proc)) return fail(why, "cannot make /proc");
    // Only this namespace's processes. Where the kernel refuses (a /proc with masked paths, as in Docker), /proc
    // stays empty rather than showing the host's.
    (void)mount("proc", proc.c_str(), "proc", MS_NOSUID | MS_NODEV | MS_NOEXEC, nullptr);
    const std::string new_old = std::string(kNew) + kOld;
    if (mkdir(new_old.c_str(), 0755) != 0) return fail(why, "cannot make the old root's place");
    if (syscall(SYS_pivot_root, kNew, new_old.c_str()) != 0) return fail(why, "cannot pivot into the new root");
    if (chdir("/") != 0) return fail(why, "cannot enter the new root");
    if (umount2(kOld, MNT_DETACH) != 0) return fail(why, "cannot drop the host's file system");
    if (rmdir(kOld) != 0) return fail(why, "cannot remove the old root's place");
    if (mount(nullptr, "/", nullptr, MS_BIND | MS_REMOUNT | MS_RDONLY | MS_NOSUID | MS_NODEV, nullptr) != 0)
        return fail(why, "cannot make the new root read-only");
    if (mount(nullptr, "/dev", nullptr, MS_BIND | MS_REMOUNT | MS_RDONLY | MS_NOSUID, nullptr) != 0)
        return fail(why, "cannot make /dev read-only");
    return true;
}

bool set_limit(int resource, rlim_t value) {
    const rlimit limit{value, value};
    return setrlimit(resource, &limit) == 0;
}

bool become_student(const SandboxPlan& plan, std::string& why) {
    if (plan.as_root && (setgroups(0, nullptr) != 0 || setgid(plan.uid) != 0 || setuid(plan.uid) != 0 || getuid() != plan.uid))
        return fail(why, "cannot run as uid " + std::to_string(plan.uid));
    bool ok = set_limit(RLIMIT_CPU, plan.cpu_seconds) && set_limit(RLIMIT_FSIZE, plan.file_size_bytes) &&
              set_limit(RLIMIT_CORE, 0) && set_limit(RLIMIT_NOFILE, 1024);
    if (plan.address_space_bytes > 0) ok = ok && set_limit(RLIMIT_AS, plan.address_space_bytes);
    // Counted per real uid: the sandbox's own under root; under a user namespace the grader's, so the count adds
    // what the grader's uid runs already (plan.processes was worked out that way).
    ok = ok && set_limit(RLIMIT_NPROC, plan.processes);
    if (!ok) return fail(why, "cannot set the resource limits");
    if (chdir(plan.working_dir.c_str()) != 0) return fail(why, "cannot enter the working folder " + plan.working_dir);
    return true;
}

// The namespace's first process is a fork of the grader, so /proc/1/cmdline would show the grader's command line
// (a --seed among it) to student code. Its argument and environment memory is zeroed, and it is made undumpable,
// which closes its other /proc files to the student's process.
void scrub_grader_traces() {
    prctl(PR_SET_DUMPABLE, 0);
    char stat[4096];
    const int fd = open("/proc/self/stat", O_RDONLY | O_CLOEXEC);
    if (fd < 0) return;
    const ssize_t n = read(fd, stat, sizeof stat - 1);
    close(fd);
    if (n <= 0) return;
    stat[n] = '\0';
    const char* at = std::strrchr(stat, ')');
    if (!at) return;
    // After the name come fields 3 onwards; arg_start, arg_end, env_start and env_end are fields 48 to 51.
    unsigned long long field[52] = {};
    int index = 2;
    for (const char* p = at + 1; *p && index < 51;) {
        while (*p == ' ') ++p;
        ++index;
        field[index] = std::strtoull(p, nullptr, 10);
        while (*p && *p != ' ') ++p;
    }
    if (index < 51) return;
    for (int first : {48, 50})
        if (field[first + 1] > field[first])
            std::memset(reinterpret_cast<void*>(static_cast<std::uintptr_t>(field[first])), 0, field[first + 1] - field[first]);
}

// Ends this process as `status` ended its child: the same exit code, or the same signal.
[[noreturn]] void exit_as(int status) {
    if (WIFEXITED(status)) _exit(WEXITSTATUS(status));
    const int sig = WIFSIGNALED(status) ? WTERMSIG(status) : SIGKILL;
    set_limit(RLIMIT_CORE, 0);
    signal(sig, SIG_DFL);
    kill(getpid(), sig);
    _exit(128 + sig);
}

int wait_for(pid_t pid) {
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return status;
}

// What the working folder holds now, from inside (it goes with the namespace, so only here can it be seen), said on the
// report channel as "<word> BYTES FILES FULL"; just "<word>" where the folder is not the namespace's own.
void say_folder(const SandboxPlan& plan, const char* word) {
    if (plan.report_fd < 0) return;
    char line[128];
    int n = std::snprintf(line, sizeof line, "%s\n", word);
    struct statvfs use {};
    if (!plan.folder_options.empty() && statvfs(plan.working_dir.c_str(), &use) == 0) {
        const unsigned long long bytes = (use.f_blocks - use.f_bfree) * use.f_frsize, files = use.f_files - use.f_ffree;
        // Full: less room left than one more block, or no entry left.
        const int full = use.f_bavail == 0 || use.f_favail == 0;
        n = std::snprintf(line, sizeof line, "%s %llu %llu %d\n", word, bytes, files, full);
    }
    (void)!write(plan.report_fd, line, static_cast<std::size_t>(n));
}

// Whether every thread of every process of the namespace but this one (its first) is stopped or gone, as its /proc
// says (a /proc the kernel refused to mount shows none).
bool all_stopped() {
    DIR* proc = opendir("/proc");
    if (!proc) return true;
    bool stopped = true;
    char path[600], stat[512];  // path: room for two names of up to 255 bytes
    while (const dirent* e = readdir(proc)) {
        if (e->d_name[0] < '1' || e->d_name[0] > '9' || std::strcmp(e->d_name, "1") == 0) continue;
        std::snprintf(path, sizeof path, "/proc/%s/task", e->d_name);
        DIR* tasks = opendir(path);
        if (!tasks) continue;  // gone meanwhile
        while (const dirent* t = readdir(tasks)) {
            if (t->d_name[0] < '1' || t->d_name[0] > '9') continue;
            std::snprintf(path, sizeof path, "/proc/%s/task/%s/stat", e->d_name, t->d_name);
            const int fd = open(path, O_RDONLY | O_CLOEXEC);
            if (fd < 0) continue;
            const ssize_t n = read(fd, stat, sizeof stat - 1);
            close(fd);
            if (n <= 0) continue;
            stat[n] = '\0';
            // The state follows the name, which is in parentheses and may hold anything.
            const char* at = std::strrchr(stat, ')');
            const char state = at && at[1] == ' ' ? at[2] : 'R';
            if (state != 'T' && state != 't' && state != 'Z' && state != 'X') stopped = false;
        }
        closedir(tasks);
    }
    closedir(proc);
    return stopped;
}

// The namespace's first process while a served lab runs (ServedProcess, process.h): it waits for the student's process
// and answers the grader's commands on the report channel, a byte each. 'p' stops every other process of the namespace
// and says "paused" with what the working folder holds once each of their threads has stopped, so nothing of the
// student's runs between its cases: not while the grader judges, the reference renders or anything is timed, and no
// message can reach the hand-in socket then. 'r' lets them run again. The grader gone (its end closed), all end.
int answer_commands(const SandboxPlan& plan, pid_t student) {
    while (true) {
        int status = 0;
        if (waitpid(student, &status, WNOHANG) == student) return status;
        pollfd p{plan.report_fd, POLLIN, 0};
        if (poll(&p, 1, 50) <= 0) continue;
        char command = 0;
        const ssize_t n = read(plan.report_fd, &command, 1);
        if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
        if (n <= 0) {
            kill(-1, SIGKILL);
            return wait_for(student);
        }
        if (command == 'p') {
            // Again until every thread has stopped: a process forked while the signal went round was not sent it.
            for (int tries = 0; tries < 4000; ++tries) {
                kill(-1, SIGSTOP);
                if (all_stopped()) break;
                usleep(500);
            }
            say_folder(plan, "paused");
        } else if (command == 'r') {
            kill(-1, SIGCONT);
        }
    }
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
    if (unshare(flags) != 0) return fail(why, "cannot make the namespaces");
    if (plan.namespaces == N::AsUser) {
        char map[64];
        if (!write_file("/proc/self/setgroups", "deny")) return fail(why, "cannot deny setgroups");
        std::snprintf(map, sizeof map, "%u %u 1", unsigned(plan.host_uid), unsigned(plan.host_uid));
        if (!write_file("/proc/self/uid_map", map)) return fail(why, "cannot map the uid");
        std::snprintf(map, sizeof map, "%u %u 1", unsigned(plan.host_gid), unsigned(plan.host_gid));
        if (!write_file("/proc/self/gid_map", map)) return fail(why, "cannot map the gid");
    }
    // The status of the student's process crosses the namespace's edge through this pipe: inside, its parent is
    // the namespace's first process, which cannot die of most signals the way an ordinary process does.
    int status_pipe[2];
    if (pipe2(status_pipe, O_CLOEXEC) != 0) return fail(why, "cannot make a pipe");
    const pid_t init = fork();
    if (init < 0) return fail(why, "cannot fork into the PID namespace");
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
    if (student < 0) return fail(why, "cannot fork the student's process");
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
