// The sandbox's first process: the PID namespace's init, a fork of the grader, which waits for the student's process
// and, for a served lab, answers the grader's commands between its cases.
#include "grader/src/run/sandbox_steps.h"

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/statvfs.h>
#include <sys/wait.h>
#include <unistd.h>

namespace gsv {
namespace {

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

}  // namespace

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

[[noreturn]] void exit_as(int status) {
    if (WIFEXITED(status)) _exit(WEXITSTATUS(status));
    const int sig = WIFSIGNALED(status) ? WTERMSIG(status) : SIGKILL;
    const rlimit no_core{0, 0};
    setrlimit(RLIMIT_CORE, &no_core);
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

}  // namespace gsv
