#include "grader/src/run/child_start.h"

#include <algorithm>
#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

extern char** environ;

namespace gsv {
namespace {

// What a lab needs from the grader's environment to get a GL context; the rest (tokens, keys, the
// grader's own paths) stays out of student code.
bool passes_to_student(const std::string& entry) {
    static const char* const prefixes[] = {"MESA_", "LIBGL_", "GALLIUM_", "LP_", "EGL_", "__EGL_", "__GLX_", "GSV_",
                                           "LD_LIBRARY_PATH=", "PATH=", "LANG=", "LC_ALL=", "ASAN_OPTIONS=",
                                           "UBSAN_OPTIONS=", "LSAN_OPTIONS="};
    for (const char* prefix : prefixes)
        if (entry.rfind(prefix, 0) == 0) return true;
    return false;
}

}  // namespace

std::vector<std::string> child_environment(const std::filesystem::path& working_dir, bool sandboxed,
                                           const std::vector<std::string>& additions) {
    std::vector<std::string> env;
    for (char** e = environ; *e; ++e)
        if (!sandboxed || passes_to_student(*e)) env.emplace_back(*e);
    std::vector<std::string> set = additions;
    if (sandboxed) {
        set.push_back("HOME=" + working_dir.string());
        set.push_back("TMPDIR=" + working_dir.string());
        set.push_back("XDG_CACHE_HOME=" + (working_dir / ".cache").string());
    }
    for (const auto& assignment : set) {
        const std::string name = assignment.substr(0, assignment.find('=') + 1);
        env.erase(std::remove_if(env.begin(), env.end(), [&](const std::string& e) { return e.rfind(name, 0) == 0; }),
                  env.end());
        env.push_back(assignment);
    }
    return env;
}

void close_descriptors_from(int first, int keep) {
#ifdef SYS_close_range
    const unsigned lo = static_cast<unsigned>(first), hi = keep >= first ? static_cast<unsigned>(keep) : ~0u;
    bool ok = true;
    if (keep >= first) {
        if (keep > first) ok = syscall(SYS_close_range, lo, hi - 1, 0) == 0;
        ok = ok && syscall(SYS_close_range, hi + 1, ~0u, 0) == 0;
    } else {
        ok = syscall(SYS_close_range, lo, ~0u, 0) == 0;
    }
    if (ok) return;
#endif
    const int dir = open("/proc/self/fd", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir < 0) {
        for (int fd = first; fd < 65536; ++fd)
            if (fd != keep) close(fd);
        return;
    }
    char buffer[4096];
    for (long n; (n = syscall(SYS_getdents64, dir, buffer, sizeof buffer)) > 0;) {
        for (long at = 0; at < n;) {
            struct Entry {
                unsigned long long ino;
                long long off;
                unsigned short reclen;
                unsigned char type;
                char name[1];
            };
            const auto* e = reinterpret_cast<const Entry*>(buffer + at);
            int fd = 0;
            bool number = e->name[0] != '\0';
            for (const char* c = e->name; *c; ++c) {
                if (*c < '0' || *c > '9') number = false;
                else fd = fd * 10 + (*c - '0');
            }
            if (number && fd >= first && fd != keep && fd != dir) close(fd);
            at += e->reclen;
        }
    }
    close(dir);
}

}  // namespace gsv
