// The file system the student's process sees: only what the plan allows, bound from the host, on a root of its own.
#include "grader/src/run/sandbox_steps.h"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fcntl.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace gsv {
namespace {

// Where the host's file system hangs while the new root is built, and the new root itself, both on a tmpfs that
// first covers /tmp in the child's own mount namespace (the bubblewrap way: the host stays reachable until the
// second pivot drops it).
constexpr const char* kBase = "/tmp";
constexpr const char* kOld = "/oldroot";
constexpr const char* kNew = "/newroot";

const char* const kSystemPaths[] = {"/usr", "/etc", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32", "/sys"};

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
    if (errno != ENOSYS) return sandbox_fail(why, std::string("cannot make ") + path + " read-only");
#endif
    if (mount(nullptr, path, nullptr, MS_BIND | MS_REMOUNT | MS_RDONLY | kept_flags(path), nullptr) != 0)
        return sandbox_fail(why, std::string("cannot make ") + path + " read-only");
    // The mounts below: field 5 of each mountinfo line is its mount point (spaces escaped as \040).
    static char info[1 << 16];
    const int fd = open("/proc/self/mountinfo", O_RDONLY | O_CLOEXEC);
    if (fd < 0) return sandbox_fail(why, "cannot read /proc/self/mountinfo");
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
                return sandbox_fail(why, std::string("cannot make ") + point + " read-only");
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
    if (!make_dirs(parent)) return sandbox_fail(why, "cannot make " + parent);
    if (S_ISLNK(st.st_mode)) {
        char target[4096];
        const ssize_t n = readlink(from.c_str(), target, sizeof target - 1);
        if (n < 0) return sandbox_fail(why, "cannot read the link " + path);
        target[n] = '\0';
        if (symlink(target, to.c_str()) != 0 && errno != EEXIST) return sandbox_fail(why, "cannot link " + path);
        return true;
    }
    if (S_ISDIR(st.st_mode)) {
        if (mkdir(to.c_str(), 0755) != 0 && errno != EEXIST) return sandbox_fail(why, "cannot make " + path);
    } else {
        const int fd = open(to.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
        if (fd < 0 && errno != EEXIST) return sandbox_fail(why, "cannot make " + path);
        if (fd >= 0) close(fd);
    }
    if (mount(from.c_str(), to.c_str(), nullptr, MS_BIND | MS_REC, nullptr) != 0) return sandbox_fail(why, "cannot bind " + path);
    return !read_only || read_only_tree(to.c_str(), why);
}

bool tmpfs(const std::string& path, const std::string& options, std::string& why) {
    if (!make_dirs(path)) return sandbox_fail(why, "cannot make " + path);
    if (mount("tmpfs", path.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, options.c_str()) != 0)
        return sandbox_fail(why, "cannot mount a tmpfs on " + path);
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
        if (symlink(link[0], (dev + "/" + link[1]).c_str()) != 0) return sandbox_fail(why, std::string("cannot link /dev/") + link[1]);
    return tmpfs(dev + "/shm", plan.tmp_options, why);
}

}  // namespace

bool build_root(const SandboxPlan& plan, std::string& why) {
    if (mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0) return sandbox_fail(why, "cannot make the mounts private");
    if (mount("tmpfs", kBase, "tmpfs", MS_NOSUID | MS_NODEV, "size=1m,mode=0755") != 0) return sandbox_fail(why, "cannot mount the base tmpfs");
    const std::string base_old = std::string(kBase) + kOld, base_new = std::string(kBase) + kNew;
    if (mkdir(base_old.c_str(), 0755) != 0 || mkdir(base_new.c_str(), 0755) != 0) return sandbox_fail(why, "cannot make the base");
    if (syscall(SYS_pivot_root, kBase, base_old.c_str()) != 0) return sandbox_fail(why, "cannot pivot into the base");
    if (chdir("/") != 0) return sandbox_fail(why, "cannot enter the base");
    if (mount("tmpfs", kNew, "tmpfs", MS_NOSUID | MS_NODEV, "size=1m,mode=0755") != 0) return sandbox_fail(why, "cannot mount the new root");
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
    if (!make_dirs(proc)) return sandbox_fail(why, "cannot make /proc");
    // Only this namespace's processes. Where the kernel refuses (a /proc with masked paths, as in Docker), /proc
    // stays empty rather than showing the host's.
    (void)mount("proc", proc.c_str(), "proc", MS_NOSUID | MS_NODEV | MS_NOEXEC, nullptr);
    const std::string new_old = std::string(kNew) + kOld;
    if (mkdir(new_old.c_str(), 0755) != 0) return sandbox_fail(why, "cannot make the old root's place");
    if (syscall(SYS_pivot_root, kNew, new_old.c_str()) != 0) return sandbox_fail(why, "cannot pivot into the new root");
    if (chdir("/") != 0) return sandbox_fail(why, "cannot enter the new root");
    if (umount2(kOld, MNT_DETACH) != 0) return sandbox_fail(why, "cannot drop the host's file system");
    if (rmdir(kOld) != 0) return sandbox_fail(why, "cannot remove the old root's place");
    if (mount(nullptr, "/", nullptr, MS_BIND | MS_REMOUNT | MS_RDONLY | MS_NOSUID | MS_NODEV, nullptr) != 0)
        return sandbox_fail(why, "cannot make the new root read-only");
    if (mount(nullptr, "/dev", nullptr, MS_BIND | MS_REMOUNT | MS_RDONLY | MS_NOSUID, nullptr) != 0)
        return sandbox_fail(why, "cannot make /dev read-only");
    return true;
}

}  // namespace gsv
