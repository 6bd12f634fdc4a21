#include "grader/process.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

namespace gsv {

ProcessResult run_process(const std::vector<std::string>& argv, const std::filesystem::path& working_dir,
                          const ProcessLimits& limits, const std::vector<std::string>& environment) {
    ProcessResult result;
    int pipe_fds[2];
    if (argv.empty() || pipe(pipe_fds) != 0) {
        result.failed_to_start = true;
        return result;
    }
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
        if (!working_dir.empty() && chdir(working_dir.c_str()) != 0) _exit(126);
        for (const auto& assignment : environment) putenv(const_cast<char*>(assignment.c_str()));
        std::vector<char*> args;
        for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
        args.push_back(nullptr);
        execv(args[0], args.data());
        const char* message = "cannot start the program\n";
        (void)!write(STDERR_FILENO, message, std::strlen(message));
        _exit(127);
    }
    close(pipe_fds[1]);
    fcntl(pipe_fds[0], F_SETFL, O_NONBLOCK);
    bool open = true;
    int status = 0;
    bool reaped = false;
    char buffer[4096];
    while (true) {
        const auto elapsed = std::chrono::steady_clock::now() - start;
        if (elapsed > limits.timeout) {
            kill(-pid, SIGKILL);
            kill(pid, SIGKILL);
            result.timed_out = true;
            break;
        }
        if (open) {
            pollfd p{pipe_fds[0], POLLIN, 0};
            poll(&p, 1, 20);
            const ssize_t n = read(pipe_fds[0], buffer, sizeof buffer);
            if (n > 0) {
                const std::size_t room = limits.max_output_bytes - std::min(limits.max_output_bytes, result.output.size());
                result.output.append(buffer, std::min<std::size_t>(room, static_cast<std::size_t>(n)));
            } else if (n == 0) {
                open = false;
            }
        } else {
            usleep(5000);
        }
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) {
            reaped = true;
            // Drain what is left in the pipe.
            ssize_t n;
            while (open && (n = read(pipe_fds[0], buffer, sizeof buffer)) > 0) {
                const std::size_t room = limits.max_output_bytes - std::min(limits.max_output_bytes, result.output.size());
                result.output.append(buffer, std::min<std::size_t>(room, static_cast<std::size_t>(n)));
            }
            break;
        }
    }
    if (!reaped) waitpid(pid, &status, 0);
    close(pipe_fds[0]);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (result.timed_out) return result;
    if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
    else if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
    if (result.exit_code == 127 && result.output.find("cannot start the program") != std::string::npos)
        result.failed_to_start = true;
    return result;
}

}  // namespace gsv
