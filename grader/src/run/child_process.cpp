#include "grader/src/run/child_process.h"

#include "common/core/error.h"
#include "grader/src/run/child_start.h"
#include "grader/src/run/handin_reader.h"
#include "grader/src/run/uid_lease.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <memory>
#include <poll.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

namespace gsv {
namespace {

std::vector<char*> pointers(const std::vector<std::string>& strings) {
    std::vector<char*> p;
    for (const auto& s : strings) p.push_back(const_cast<char*>(s.c_str()));
    p.push_back(nullptr);
    return p;
}

void make_pipe(Fd& read_end, Fd& write_end) {
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) throw Error(std::string("cannot make a pipe: ") + std::strerror(errno));
    read_end = Fd(fds[0]);
    write_end = Fd(fds[1]);
}

void make_socket_pair(Fd& grader_end, Fd& child_end, const char* what) {
    int pair[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, pair) != 0)
        throw Error(std::string("cannot make ") + what + ": " + std::strerror(errno));
    grader_end = Fd(pair[0]);
    child_end = Fd(pair[1]);
}

void write_line(int fd, const char* text) { (void)!write(fd, text, std::strlen(text)); }

// Refuses whatever is handed in while no request is open: between a served lab's cases nothing may be sent.
class UnaskedConversation : public HandinConversation {
public:
    std::uint64_t max_image_pixels() const override { return 0; }
    void announced(const HandinTag& tag, std::uint32_t) override { refuse(tag); }
    void received(HandinMessage message, double, const Reply&) override { refuse(message.tag); }

private:
    [[noreturn]] static void refuse(const HandinTag& tag) {
        throw Error("handed in a " + tag_name(tag) + " message before the grader asked for a case");
    }
};

}  // namespace

void note_cut_output(ProcessResult& result) {
    if (result.output_bytes > result.output.size())
        result.output += "\n[output cut: " + std::to_string(result.output_bytes) + " bytes printed, " +
                         std::to_string(result.output.size()) + " kept]\n";
}

Fd::Fd(int fd) {
    if (fd < 0) return;
    fd_ = fcntl(fd, F_DUPFD_CLOEXEC, 10);
    close(fd);
    if (fd_ < 0) throw Error(std::string("cannot move a descriptor: ") + std::strerror(errno));
}

Fd& Fd::operator=(Fd&& o) noexcept {
    reset();
    fd_ = o.fd_;
    o.fd_ = -1;
    return *this;
}

void Fd::reset() {
    if (fd_ >= 0) close(fd_);
    fd_ = -1;
}

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& working_dir, const ProcessLimits& limits,
                           const std::vector<std::string>& environment, bool served)
    : limits_(limits) {
    if (argv.empty()) {
        result.failed_to_start = true;
        return;
    }
    sandboxed_ = limits.sandbox && limits.support && limits.sandbox->enabled;
    const bool folder_inside = limits.private_folder && sandboxed_ && limits.support->allow_list();
    // Without namespaces a private folder is the grader's, on its disk: made here, measured and removed after.
    std::filesystem::path dir = working_dir;
    if (limits.private_folder && !folder_inside) {
        host_folder_.emplace("gsv-case-");
        dir = host_folder_->path();
        if (sandboxed_) hand_over(dir, *limits.sandbox, *limits.support);
    }
    if (sandboxed_) {
        result.folder_limit_bytes = limits.sandbox->folder_bytes;
        result.folder_limit_files = limits.sandbox->folder_files;
    }
    const double timeout_s = std::chrono::duration<double>(limits.timeout).count();

    // The report channel goes both ways: a served lab's sandbox also takes the grader's commands on it.
    // A served lab always has its hand-in socket: its cases come over it.
    const bool handin = limits.handin || served;
    Fd output_child, report_child, handin_child;
    make_pipe(output_, output_child);
    make_socket_pair(report_, report_child, "the sandbox's report channel");
    if (handin) make_socket_pair(handin_, handin_child, "the hand-in socket");
    const Fd null_input(open("/dev/null", O_RDONLY | O_CLOEXEC));
    if (null_input.get() < 0) throw Error(std::string("cannot open /dev/null: ") + std::strerror(errno));

    // Built before fork: the child only makes system calls.
    std::vector<std::string> additions = environment;
    if (handin) additions.push_back(std::string(kHandinVariable) + "=" + std::to_string(kHandinFd));
    plan_ = sandboxed_ ? plan_sandbox(*limits.sandbox, *limits.support, dir, timeout_s, folder_inside) : SandboxPlan{};
    plan_->report_fd = report_child.get();
    plan_->answers_commands = served && sandboxed_ && limits.support->allow_list();
    const std::filesystem::path seen_dir = sandboxed_ && !plan_->working_dir.empty() ? std::filesystem::path(plan_->working_dir) : dir;
    const std::vector<std::string> env = child_environment(seen_dir, sandboxed_, additions);
    std::vector<char*> envp = pointers(env);
    std::vector<char*> args = pointers(argv);
    const SandboxPlan& plan = *plan_;
    start_ = Clock::now();
    const pid_t pid = fork();
    if (pid < 0) {
        result.failed_to_start = true;
        return;
    }
    if (pid == 0) {
        // A session of its own: no controlling terminal (nothing to inject keystrokes into), and a process group
        // the timeout kills whole.
        setsid();
        dup2(null_input.get(), STDIN_FILENO);
        dup2(output_child.get(), STDOUT_FILENO);
        dup2(output_child.get(), STDERR_FILENO);
        if (handin) dup2(handin_child.get(), kHandinFd);
        close_descriptors_from(handin ? kHandinFd + 1 : STDERR_FILENO + 1, report_child.get());
        std::string why;
        if (sandboxed_ && !enter_sandbox(plan, why)) {
            const std::string line = "sandbox-error " + why + "\n";
            write_line(report_child.get(), line.c_str());
            _exit(125);
        }
        if (!sandboxed_ && !dir.empty() && chdir(dir.c_str()) != 0) _exit(126);
        execve(args[0], args.data(), envp.data());
        write_line(report_child.get(), "exec-failed\n");
        _exit(127);
    }
    pid_ = pid;
    fcntl(output_.get(), F_SETFL, O_NONBLOCK);
    fcntl(report_.get(), F_SETFL, O_NONBLOCK);
    if (handin) {
        fcntl(handin_.get(), F_SETFL, O_NONBLOCK);
        reader_ = std::make_unique<HandinReader>(limits.max_handin_bytes);
    }
}

ChildProcess::~ChildProcess() {
    if (pid_ > 0 && !reaped_) {
        kill_all();
        int status = 0;
        while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
        }
    }
}

void ChildProcess::kill_all() {
    if (pid_ <= 0) return;
    kill(-pid_, SIGKILL);
    kill(pid_, SIGKILL);
    killed_ = true;
}

double ChildProcess::send(const HandinTag& tag, const std::vector<std::uint8_t>& payload) {
    // Messages to the lab are small (a challenge at most 4 KiB, a case 16 KiB), so the socket's buffer takes each whole.
    const std::vector<std::uint8_t> message = encode_message(tag, payload);
    const double written_from = seconds();
    std::size_t sent = 0;
    while (sent < message.size()) {
        const ssize_t n = ::send(handin_.get(), message.data() + sent, message.size() - sent, MSG_NOSIGNAL);
        if (n > 0) {
            sent += static_cast<std::size_t>(n);
        } else if (n < 0 && errno == EAGAIN) {
            pollfd p{handin_.get(), POLLOUT, 0};
            if (poll(&p, 1, 1000) <= 0) throw Error("does not read the grader's messages on the hand-in socket");
        } else if (n < 0 && errno != EINTR) {
            break;  // the lab closed its end; what it handed in so far stands
        }
    }
    return written_from;
}

void ChildProcess::command(char c) {
    // MSG_NOSIGNAL: a sandbox that has gone is no SIGPIPE for the grader.
    while (::send(report_.get(), &c, 1, MSG_NOSIGNAL) < 0 && errno == EINTR) {
    }
}

void ChildProcess::take_handin(HandinConversation* conversation) {
    if (!reader_ || reader_->closed() || !result.refused.empty()) return;
    UnaskedConversation unasked;
    HandinConversation& answering = conversation ? *conversation : unasked;
    const HandinConversation::Reply reply = [this](const HandinTag& tag, const std::vector<std::uint8_t>& payload) {
        return send(tag, payload);
    };
    try {
        reader_->read_from(handin_.get(), answering, [this] { return seconds(); }, reply, result.handin_bytes);
    } catch (const Error& e) {
        result.refused = e.what();
        kill_all();
    }
}

void ChildProcess::read_output() {
    char buffer[65536];
    while (output_open_) {
        const ssize_t n = read(output_.get(), buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n == 0) output_open_ = false;
        if (n <= 0) return;
        result.output_bytes += static_cast<std::size_t>(n);
        const std::size_t room = limits_.max_output_bytes - std::min(limits_.max_output_bytes, result.output.size());
        result.output.append(buffer, std::min(room, static_cast<std::size_t>(n)));
    }
}

// The lines the sandboxed child and the namespace's init leave on the report channel (never student code's: it is
// close-on-exec).
void ChildProcess::read_report(bool to_the_end) {
    char buffer[1024];
    while (report_open_) {
        const ssize_t n = read(report_.get(), buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n == 0) report_open_ = false;  // every process that could write it has gone (or exec'd)
        if (n <= 0) break;
        report_text_.append(buffer, static_cast<std::size_t>(n));
    }
    for (std::size_t end; (end = report_text_.find('\n')) != std::string::npos;) {
        take_report_line(report_text_.substr(0, end));
        report_text_.erase(0, end + 1);
    }
    if (to_the_end && !report_text_.empty()) take_report_line(report_text_);
}

void ChildProcess::take_report_line(const std::string& line) {
    if (line.rfind("sandbox-error ", 0) == 0) {
        result.sandbox_error = "grader sandbox: " + line.substr(14);
    } else if (line == "exec-failed") {
        result.failed_to_start = true;
    } else if (line.rfind("folder ", 0) == 0 || line.rfind("paused", 0) == 0) {
        if (line.rfind("paused", 0) == 0) ++paused_;
        unsigned long long bytes = 0, files = 0;
        int full = 0;
        if (std::sscanf(line.c_str(), "%*s %llu %llu %d", &bytes, &files, &full) == 3) {
            result.folder.bytes = bytes;
            result.folder.files = files;
            result.folder_full = full != 0;
        }
    }
}

ChildProcess::Pumped ChildProcess::pump(HandinConversation* conversation, Clock::time_point deadline, const std::function<bool()>& done) {
    while (true) {
        if (done && done()) return Pumped::Done;
        if (Clock::now() > deadline) {
            kill_all();
            result.timed_out = true;
            return Pumped::Killed;
        }
        if (result.output_bytes > limits_.flood_bytes) {
            kill_all();
            result.flooded = true;
            return Pumped::Killed;
        }
        const bool reading_handin = reader_ && !reader_->closed();
        pollfd p[3] = {{output_open_ ? output_.get() : -1, POLLIN, 0}, {reading_handin ? handin_.get() : -1, POLLIN, 0},
                       {report_open_ ? report_.get() : -1, POLLIN, 0}};
        poll(p, 3, 20);
        take_handin(conversation);
        read_output();
        read_report(false);
        if (waitpid(pid_, &status_, WNOHANG) == pid_) {
            reaped_ = true;
            read_output();
            take_handin(conversation);
            return Pumped::Ended;
        }
    }
}

void ChildProcess::finish() {
    if (pid_ > 0 && !reaped_) {
        while (waitpid(pid_, &status_, 0) < 0 && errno == EINTR) {
        }
        reaped_ = true;
    }
    read_report(true);
    if (reader_ && reader_->partial() && result.refused.empty() && !result.timed_out && !result.flooded)
        result.refused = "ended in the middle of a message on the hand-in socket";
    // Without a PID namespace, what the student started may outlive it: its uid is this run's alone, so every
    // process of that uid goes.
    if (sandboxed_ && !limits_.support->allow_list() && plan_->as_root) kill_processes_of(plan_->uid);
    if (host_folder_) {
        try {
            result.folder = host_folder_->remove();
            result.folder_full = sandboxed_ && (result.folder.bytes >= limits_.sandbox->folder_bytes ||
                                                result.folder.files >= limits_.sandbox->folder_files);
        } catch (const Error& e) {
            result.cleanup_error = e.what();
        }
        host_folder_.reset();
    }
    result.seconds = seconds();
    note_cut_output(result);
    if (result.timed_out || result.flooded) return;
    if (WIFSIGNALED(status_)) result.signal = WTERMSIG(status_);
    else if (WIFEXITED(status_)) result.exit_code = WEXITSTATUS(status_);
}

}  // namespace gsv
