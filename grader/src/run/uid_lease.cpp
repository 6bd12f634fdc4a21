#include "grader/src/run/uid_lease.h"

#include "common/core/error.h"
#include "grader/src/run/sandbox.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <string>
#include <dirent.h>
#include <fcntl.h>
#include <grp.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace gsv {
namespace {

// The folder, made root's and closed to everyone else; refused when someone else could plant or hold locks in it.
int open_lock_folder(const fs::path& folder) {
    (void)mkdir(folder.c_str(), 0700);
    const int fd = open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) throw Error("cannot open the uid lock folder " + folder.string() + ": " + std::strerror(errno));
    struct stat st {};
    if (fstat(fd, &st) != 0 || st.st_uid != geteuid() || (st.st_mode & 077) != 0) {
        close(fd);
        throw Error("the uid lock folder " + folder.string() + " is not the grader's alone (mode " +
                    std::to_string(st.st_mode & 0777) + ", owner " + std::to_string(st.st_uid) +
                    "): remove it, or make it mode 700 and owned by the grader's user");
    }
    return fd;
}

// The lock of `uid`, taken without waiting; -1 when another run holds it.
int try_lock(int folder, uid_t uid) {
    const std::string name = std::to_string(uid) + ".lock";
    const int fd = openat(folder, name.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (fd < 0) throw Error("cannot make the uid lock " + name + ": " + std::strerror(errno));
    if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
        close(fd);
        return -1;
    }
    return fd;
}

}  // namespace

fs::path UidLease::lock_folder() {
    std::error_code ec;
    return fs::is_directory("/run/lock", ec) ? fs::path("/run/lock/gsv-grade-uids") : fs::path("/tmp/gsv-grade-uids");
}

UidLease UidLease::any(const fs::path& locks) {
    const int folder = open_lock_folder(locks);
    for (uid_t uid = kSandboxUidBase; uid < kSandboxUidBase + kSandboxUidCount; ++uid) {
        const int fd = try_lock(folder, uid);
        if (fd < 0) continue;
        if (tasks_of_user(uid) > 0) {  // a run before this one left processes behind: not a clean uid
            close(fd);
            continue;
        }
        close(folder);
        return UidLease(fd, uid);
    }
    close(folder);
    throw Error("every sandbox uid from " + std::to_string(kSandboxUidBase) + " is leased to another grader run");
}

UidLease UidLease::exactly(uid_t uid, const fs::path& locks) {
    const int folder = open_lock_folder(locks);
    const int fd = try_lock(folder, uid);
    close(folder);
    if (fd < 0) throw Error("--sandbox-uid " + std::to_string(uid) + ": another grader run on this machine holds that uid");
    if (tasks_of_user(uid) > 0) {
        close(fd);
        throw Error("--sandbox-uid " + std::to_string(uid) + ": processes run as that uid already");
    }
    return UidLease(fd, uid);
}

UidLease::UidLease(UidLease&& other) noexcept : fd_(other.fd_), uid_(other.uid_) { other.fd_ = -1; }

UidLease& UidLease::operator=(UidLease&& other) noexcept {
    if (this != &other) {
        if (fd_ >= 0) close(fd_);
        fd_ = other.fd_;
        uid_ = other.uid_;
        other.fd_ = -1;
    }
    return *this;
}

UidLease::~UidLease() {
    if (fd_ >= 0) close(fd_);
}

long tasks_of_user(uid_t uid) {
    long count = 0;
    DIR* proc = opendir("/proc");
    if (!proc) return 0;
    while (const dirent* e = readdir(proc)) {
        if (e->d_name[0] < '0' || e->d_name[0] > '9') continue;
        const std::string path = std::string("/proc/") + e->d_name + "/task";
        struct stat st {};
        if (stat(path.c_str(), &st) != 0 || st.st_uid != uid) continue;
        if (DIR* tasks = opendir(path.c_str())) {
            while (const dirent* t = readdir(tasks))
                if (t->d_name[0] != '.') ++count;
            closedir(tasks);
        }
    }
    closedir(proc);
    return count;
}

void kill_processes_of(uid_t uid) {
    if (geteuid() != 0 || uid == 0) return;
    const pid_t pid = fork();
    if (pid == 0) {
        // As the uid, kill(-1) reaches exactly its processes (and never the caller itself).
        if (setgroups(0, nullptr) == 0 && setgid(uid) == 0 && setuid(uid) == 0) kill(-1, SIGKILL);
        _exit(0);
    }
    int status = 0;
    while (pid > 0 && waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
}

}  // namespace gsv
