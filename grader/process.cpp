#include "grader/process.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
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

std::vector<char*> pointers(const std::vector<std::string>& strings) {
    std::vector<char*> p;
    for (const auto& s : strings) p.push_back(const_cast<char*>(s.c_str()));
    p.push_back(nullptr);
    return p;
}

}  // namespace

ProcessResult run_process(const std::vector<std::string>& argv, const std::filesystem::path& working_dir,
                          const ProcessLimits& limits, const std::vector<std::string>& environment) {
    ProcessResult result;
    int pipe_fds[2];
    int mark_fds[2] = {-1, -1};
    if (argv.empty() || pipe(pipe_fds) != 0) {
        result.failed_to_start = true;
        return result;
    }
    if (limits.frame_marks && pipe(mark_fds) != 0) {
        close(pipe_fds[0]);
        close(pipe_fds[1]);
        result.failed_to_start = true;
        return result;
    }
    const bool sandboxed = limits.sandbox && limits.support && limits.sandbox->enabled;
    const double timeout_s = std::chrono::duration<double>(limits.timeout).count();
    // Built before fork: the child only makes system calls.
    std::vector<std::string> additions = environment;
    if (limits.frame_marks) additions.push_back("GSV_FRAME_MARKS_FD=3");
    const std::vector<std::string> env = child_environment(working_dir, sandboxed, additions);
    const SandboxPlan plan = sandboxed ? plan_sandbox(*limits.sandbox, *limits.support, working_dir, timeout_s) : SandboxPlan{};
    std::vector<char*> envp = pointers(env);
    std::vector<char*> args = pointers(argv);
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid < 0) {
        close(pipe_fds[0]);
        close(pipe_fds[1]);
        result.failed_to_start = true;
        return result;
    }
    if (pid == 0) {
        // Own process group, so the timeout kills anything the lab started too.
        setpgid(0, 0);
        dup2(pipe_fds[1], STDOUT_FILENO);
        dup2(pipe_fds[1], STDERR_FILENO);
        close(pipe_fds[0]);
        close(pipe_fds[1]);
        if (limits.frame_marks) {
            const int high = fcntl(mark_fds[1], F_DUPFD, 10);
            close(mark_fds[0]);
            close(mark_fds[1]);
            dup2(high, 3);
            close(high);
        }
        std::string why;
        if (sandboxed && !enter_sandbox(plan, why)) {
            const std::string message = "grader sandbox: " + why + "\n";
            (void)!write(STDERR_FILENO, message.data(), message.size());
            _exit(125);
        }
        if (!working_dir.empty() && chdir(working_dir.c_str()) != 0) _exit(126);
        execve(args[0], args.data(), envp.data());
        const char* message = "cannot start the program\n";
        (void)!write(STDERR_FILENO, message, std::strlen(message));
        _exit(127);
    }
    close(pipe_fds[1]);
    fcntl(pipe_fds[0], F_SETFL, O_NONBLOCK);
    if (limits.frame_marks) {
        close(mark_fds[1]);
        fcntl(mark_fds[0], F_SETFL, O_NONBLOCK);
    }
    // Each byte on the marks pipe is one mark, timed when it arrives.
    auto take_marks = [&] {
        char marks[256];
        ssize_t n;
        while (mark_fds[0] >= 0 && (n = read(mark_fds[0], marks, sizeof marks)) > 0) {
            const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            result.marks.insert(result.marks.end(), static_cast<std::size_t>(n), t);
            if (result.marks.size() > 1000000) break;  // a flood of marks is the lab's own garbage
        }
    };
    auto keep = [&](const char* data, std::size_t n) {
        result.output_bytes += n;
        const std::size_t room = limits.max_output_bytes - std::min(limits.max_output_bytes, result.output.size());
        result.output.append(data, std::min(room, n));
    };
    auto kill_all = [&] {
        kill(-pid, SIGKILL);
        kill(pid, SIGKILL);
    };
    bool open = true;
    int status = 0;
    bool reaped = false;
    char buffer[65536];
    while (true) {
        if (std::chrono::steady_clock::now() - start > limits.timeout) {
            kill_all();
            result.timed_out = true;
            break;
        }
        if (result.output_bytes > limits.flood_bytes) {
            kill_all();
            result.flooded = true;
            break;
        }
        if (open) {
            pollfd p[2] = {{pipe_fds[0], POLLIN, 0}, {mark_fds[0], POLLIN, 0}};
            poll(p, mark_fds[0] >= 0 ? 2 : 1, 20);
            take_marks();
            const ssize_t n = read(pipe_fds[0], buffer, sizeof buffer);
            if (n > 0) keep(buffer, static_cast<std::size_t>(n));
            else if (n == 0) open = false;
        } else {
            pollfd p{mark_fds[0], POLLIN, 0};
            poll(&p, mark_fds[0] >= 0 ? 1 : 0, 5);
            take_marks();
        }
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) {
            reaped = true;
            ssize_t n;
            while (open && (n = read(pipe_fds[0], buffer, sizeof buffer)) > 0) keep(buffer, static_cast<std::size_t>(n));
            break;
        }
    }
    if (!reaped) waitpid(pid, &status, 0);
    take_marks();
    close(pipe_fds[0]);
    if (mark_fds[0] >= 0) close(mark_fds[0]);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (result.output_bytes > result.output.size())
        result.output += "\n[output cut: " + std::to_string(result.output_bytes) + " bytes printed, " +
                         std::to_string(result.output.size()) + " kept]\n";
    if (result.timed_out || result.flooded) return result;
    if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
    else if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
    if (result.exit_code == 127 && result.output.find("cannot start the program") != std::string::npos)
        result.failed_to_start = true;
    if (result.exit_code == 125) {
        const auto at = result.output.find("grader sandbox: ");
        if (at != std::string::npos) result.sandbox_error = result.output.substr(at, result.output.find('\n', at) - at);
    }
    return result;
}

}  // namespace gsv
