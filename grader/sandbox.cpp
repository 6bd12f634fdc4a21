#include "grader/sandbox.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <grp.h>
#include <sched.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace gsv {
namespace {

constexpr uid_t kNobody = 65534;

bool write_file(const char* path, const char* text) {
    const int fd = open(path, O_WRONLY);
    if (fd < 0) return false;
    const auto length = static_cast<ssize_t>(std::strlen(text));
    const bool ok = write(fd, text, static_cast<size_t>(length)) == length;
    close(fd);
    return ok;
}

bool drop_root() {
    return setgroups(0, nullptr) == 0 && setgid(kNobody) == 0 && setuid(kNobody) == 0 && getuid() == kNobody;
}

// An unprivileged user namespace maps only the caller's own ids; inside it the mounts are allowed.
bool enter_user_namespace() {
    const uid_t uid = geteuid();
    const gid_t gid = getegid();
    if (unshare(CLONE_NEWUSER | CLONE_NEWNS | CLONE_NEWNET) != 0) return false;
    char map[64];
    if (!write_file("/proc/self/setgroups", "deny")) return false;
    std::snprintf(map, sizeof map, "%u %u 1", static_cast<unsigned>(uid), static_cast<unsigned>(uid));
    if (!write_file("/proc/self/uid_map", map)) return false;
    std::snprintf(map, sizeof map, "%u %u 1", static_cast<unsigned>(gid), static_cast<unsigned>(gid));
    return write_file("/proc/self/gid_map", map);
}

bool hide_paths(const std::vector<std::filesystem::path>& hidden) {
    if (mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0) return false;
    for (const auto& path : hidden) {
        struct stat st {};
        if (stat(path.c_str(), &st) != 0) continue;  // nothing there to hide
        const bool ok = S_ISDIR(st.st_mode)
                            ? mount("tmpfs", path.c_str(), "tmpfs", MS_RDONLY | MS_NOSUID | MS_NODEV | MS_NOEXEC,
                                    "size=4k,mode=0555") == 0
                            : mount("/dev/null", path.c_str(), nullptr, MS_BIND, nullptr) == 0;
        if (!ok) return false;
    }
    return true;
}

bool namespaces_as(SandboxSupport::Namespaces kind, const std::vector<std::filesystem::path>& hidden) {
    if (kind == SandboxSupport::Namespaces::AsRoot) {
        if (unshare(CLONE_NEWNS | CLONE_NEWNET) != 0) return false;
    } else if (!enter_user_namespace()) {
        return false;
    }
    return hide_paths(hidden);
}

// Tasks (threads count, as RLIMIT_NPROC counts them) that this uid runs now.
long tasks_of_user(uid_t uid) {
    long count = 0;
    DIR* proc = opendir("/proc");
    if (!proc) return 0;
    while (const dirent* e = readdir(proc)) {
        if (e->d_name[0] < '0' || e->d_name[0] > '9') continue;
        char path[64];
        std::snprintf(path, sizeof path, "/proc/%s/task", e->d_name);
        struct stat st {};
        if (stat(path, &st) != 0 || st.st_uid != uid) continue;
        if (DIR* tasks = opendir(path)) {
            while (const dirent* t = readdir(tasks))
                if (t->d_name[0] != '.') ++count;
            closedir(tasks);
        }
    }
    closedir(proc);
    return count;
}

bool set_limit(int resource, rlim_t value) {
    const rlimit limit{value, value};
    return setrlimit(resource, &limit) == 0;
}

// Tries one combination of walls in a child that exits 0 when all of them went up.
bool try_in_child(SandboxSupport::Namespaces kind, bool drop, const std::vector<std::filesystem::path>& must_reach,
                  const std::vector<std::filesystem::path>& hidden) {
    const pid_t pid = fork();
    if (pid < 0) return false;
    if (pid == 0) {
        const bool root_first = kind != SandboxSupport::Namespaces::AsUser;
        if (!root_first && drop && !drop_root()) _exit(1);
        if (kind != SandboxSupport::Namespaces::None && !namespaces_as(kind, hidden)) _exit(1);
        if (root_first && drop && !drop_root()) _exit(1);
        for (const auto& path : must_reach)
            if (access(path.c_str(), R_OK) != 0) _exit(1);
        _exit(0);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace

std::string SandboxSupport::describe() const {
    std::string text;
    switch (namespaces) {
    case Namespaces::AsRoot:
    case Namespaces::AsUser: text = "mount and network namespaces (reference files hidden, no network)"; break;
    case Namespaces::None: text = "no namespaces here (unshare refused): reference files readable, network open"; break;
    }
    if (geteuid() == 0) text += drops_root ? "; student code runs as nobody" : "; student code runs as root (the kit is not readable by nobody)";
    return text + "; rlimits on memory, CPU, file size, processes; wall-clock timeout; output cap";
}

SandboxSupport probe_sandbox(const std::vector<std::filesystem::path>& must_reach,
                             const std::vector<std::filesystem::path>& hidden) {
    using N = SandboxSupport::Namespaces;
    const bool root = geteuid() == 0;
    SandboxSupport support;
    // Most walls first: namespaces and not root, then each alone.
    const std::pair<N, bool> tries[] = {{N::AsRoot, true}, {N::AsUser, true}, {N::AsRoot, false},
                                        {N::AsUser, false}, {N::None, true}};
    for (const auto& [kind, drop] : tries) {
        if (drop && !root) continue;
        if (kind == N::AsRoot && !root) continue;
        if (try_in_child(kind, drop, must_reach, hidden)) {
            support.namespaces = kind;
            support.drops_root = drop;
            return support;
        }
    }
    return support;
}

void hand_over(const std::filesystem::path& path, const SandboxSupport& support) {
    if (!support.drops_root) return;
    (void)!lchown(path.c_str(), kNobody, kNobody);
    std::error_code ec;
    for (auto it = std::filesystem::recursive_directory_iterator(path, ec); !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec))
        (void)!lchown(it->path().c_str(), kNobody, kNobody);
}

bool enter_sandbox(const SandboxPolicy& policy, const SandboxSupport& support, double timeout_s, std::string& why) {
    if (!policy.enabled) return true;
    using N = SandboxSupport::Namespaces;
    // Without CAP_SYS_ADMIN a user namespace is the only way to mount, so root turns nobody before it.
    const bool user_first = support.namespaces == N::AsUser;
    if (user_first && support.drops_root && !drop_root()) { why = "cannot run as nobody"; return false; }
    if (support.namespaces != N::None && !namespaces_as(support.namespaces, policy.hidden)) {
        why = std::string("cannot hide the reference files: ") + std::strerror(errno);
        return false;
    }
    if (!user_first && support.drops_root && !drop_root()) { why = "cannot run as nobody"; return false; }
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    const double cpu = policy.cpu_seconds > 0 ? policy.cpu_seconds : timeout_s * cores + 5;
    bool ok = set_limit(RLIMIT_CPU, static_cast<rlim_t>(cpu + 1)) && set_limit(RLIMIT_FSIZE, policy.file_size_bytes) &&
              set_limit(RLIMIT_CORE, 0);
    if (policy.address_space_bytes > 0) ok = ok && set_limit(RLIMIT_AS, policy.address_space_bytes);
    // Counted as the user the student code runs as; root ignores the limit.
    if (geteuid() != 0) ok = ok && set_limit(RLIMIT_NPROC, static_cast<rlim_t>(tasks_of_user(geteuid()) + policy.extra_processes));
    if (!ok) why = std::string("cannot set the resource limits: ") + std::strerror(errno);
    return ok;
}

}  // namespace gsv
