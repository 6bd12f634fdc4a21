#include "grader/src/run/process.h"

#include "common/core/error.h"
#include "common/io/data_array.h"
#include "common/io/little_endian.h"
#include "common/io/temporary_folder.h"
#include "grader/src/run/uid_lease.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <memory>
#include <optional>
#include <poll.h>
#include <sys/socket.h>
#include <sys/syscall.h>
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

// A descriptor of the grader's: close-on-exec, and numbered 10 or above, so that the child can move its own to
// 0-3 without one overwriting another, whatever the grader had open.
class Fd {
public:
    Fd() = default;
    explicit Fd(int fd) {
        if (fd < 0) return;
        fd_ = fcntl(fd, F_DUPFD_CLOEXEC, 10);
        close(fd);
        if (fd_ < 0) throw Error(std::string("cannot move a descriptor: ") + std::strerror(errno));
    }
    Fd(Fd&& o) noexcept : fd_(o.fd_) { o.fd_ = -1; }
    Fd& operator=(Fd&& o) noexcept {
        reset();
        fd_ = o.fd_;
        o.fd_ = -1;
        return *this;
    }
    ~Fd() { reset(); }
    int get() const { return fd_; }
    void reset() {
        if (fd_ >= 0) close(fd_);
        fd_ = -1;
    }

private:
    int fd_ = -1;
};

void make_pipe(Fd& read_end, Fd& write_end) {
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) throw Error(std::string("cannot make a pipe: ") + std::strerror(errno));
    read_end = Fd(fds[0]);
    write_end = Fd(fds[1]);
}

// In the child, after fork: every descriptor from `first` on but `keep` closed (close_range, or where the
// kernel lacks it a walk of /proc/self/fd with raw system calls: no allocation between fork and exec).
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

void write_line(int fd, const char* text) { (void)!write(fd, text, std::strlen(text)); }

// Reads the hand-in socket into whole messages, checking each header before its payload is taken.
class HandinReader {
public:
    HandinReader(HandinConversation& conversation, std::uint64_t max_bytes) : conversation_(conversation), max_bytes_(max_bytes) {}

    // Everything readable now, each chunk timed by `clock` as it is read. Throws gsv::Error to refuse.
    void read_from(int fd, const std::function<double()>& clock, const HandinConversation::Reply& reply, std::uint64_t& total) {
        std::uint8_t chunk[65536];
        while (true) {
            const ssize_t n = read(fd, chunk, sizeof chunk);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                if (n == 0) closed_ = true;
                return;
            }
            total += static_cast<std::uint64_t>(n);
            if (total > max_bytes_)
                throw Error("sent more than " + std::to_string(max_bytes_ >> 20) + " MiB on the hand-in socket");
            take(chunk, static_cast<std::size_t>(n), clock(), reply);
        }
    }
    bool closed() const { return closed_; }
    // A message begun and not finished when the process ended.
    bool partial() const { return header_got_ > 0 || payload_left_ > 0; }

private:
    void take(const std::uint8_t* data, std::size_t n, double t, const HandinConversation::Reply& reply) {
        while (n > 0) {
            if (header_got_ < kHandinHeaderBytes) {
                const std::size_t k = std::min<std::size_t>(n, kHandinHeaderBytes - header_got_);
                std::memcpy(header_ + header_got_, data, k);
                header_got_ += k;
                data += k;
                n -= k;
                if (header_got_ < kHandinHeaderBytes) return;
                std::memcpy(message_.tag.data(), header_, 4);
                payload_left_ = checked_payload_size(message_.tag, u32_from_le_bytes(header_ + 4),
                                                     conversation_.max_image_pixels(), kMaxArrayFloats);
                message_.payload.clear();
                message_.payload.reserve(payload_left_);
            }
            const std::size_t k = std::min<std::size_t>(n, payload_left_);
            message_.payload.insert(message_.payload.end(), data, data + k);
            data += k;
            n -= k;
            payload_left_ -= k;
            if (payload_left_ == 0) {
                HandinMessage done = std::move(message_);
                message_ = HandinMessage{};
                header_got_ = 0;
                conversation_.received(std::move(done), t, reply);
            }
        }
    }

    HandinConversation& conversation_;
    std::uint64_t max_bytes_;
    std::uint8_t header_[kHandinHeaderBytes] = {};
    std::size_t header_got_ = 0;
    std::size_t payload_left_ = 0;
    HandinMessage message_;
    bool closed_ = false;
};

// The lines the sandboxed child and the namespace's init leave on the report pipe (never student code's: the
// pipe is close-on-exec).
void read_report(int fd, ProcessResult& result) {
    std::string text;
    char buffer[1024];
    for (ssize_t n; (n = read(fd, buffer, sizeof buffer)) > 0;) text.append(buffer, static_cast<std::size_t>(n));
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t end = std::min(text.find('\n', at), text.size());
        const std::string line = text.substr(at, end - at);
        at = end + 1;
        if (line.rfind("sandbox-error ", 0) == 0) {
            result.sandbox_error = "grader sandbox: " + line.substr(14);
        } else if (line == "exec-failed") {
            result.failed_to_start = true;
        } else if (line.rfind("folder ", 0) == 0) {
            unsigned long long bytes = 0, files = 0;
            int full = 0;
            if (std::sscanf(line.c_str(), "folder %llu %llu %d", &bytes, &files, &full) == 3) {
                result.folder.bytes = bytes;
                result.folder.files = files;
                result.folder_full = full != 0;
            }
        }
    }
}

}  // namespace

ProcessResult run_process(const std::vector<std::string>& argv, const std::filesystem::path& working_dir,
                          const ProcessLimits& limits, const std::vector<std::string>& environment) {
    ProcessResult result;
    if (argv.empty()) {
        result.failed_to_start = true;
        return result;
    }
    const bool sandboxed = limits.sandbox && limits.support && limits.sandbox->enabled;
    const bool folder_inside = limits.private_folder && sandboxed && limits.support->allow_list();
    // Without namespaces a private folder is the grader's, on its disk: made here, measured and removed after.
    std::optional<TemporaryFolder> host_folder;
    std::filesystem::path dir = working_dir;
    if (limits.private_folder && !folder_inside) {
        host_folder.emplace("gsv-case-");
        dir = host_folder->path();
        if (sandboxed) hand_over(dir, *limits.sandbox, *limits.support);
    }
    if (sandboxed) {
        result.folder_limit_bytes = limits.sandbox->folder_bytes;
        result.folder_limit_files = limits.sandbox->folder_files;
    }
    const double timeout_s = std::chrono::duration<double>(limits.timeout).count();

    Fd output, output_child, report, report_child, handin, handin_child;
    make_pipe(output, output_child);
    make_pipe(report, report_child);
    if (limits.handin) {
        int pair[2];
        if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, pair) != 0) throw Error(std::string("cannot make the hand-in socket: ") + std::strerror(errno));
        handin = Fd(pair[0]);
        handin_child = Fd(pair[1]);
    }
    const Fd null_input(open("/dev/null", O_RDONLY | O_CLOEXEC));
    if (null_input.get() < 0) throw Error(std::string("cannot open /dev/null: ") + std::strerror(errno));

    // Built before fork: the child only makes system calls.
    std::vector<std::string> additions = environment;
    if (limits.handin) additions.push_back(std::string(kHandinVariable) + "=" + std::to_string(kHandinFd));
    SandboxPlan plan = sandboxed ? plan_sandbox(*limits.sandbox, *limits.support, dir, timeout_s, folder_inside) : SandboxPlan{};
    plan.report_fd = report_child.get();
    const std::filesystem::path seen_dir = sandboxed && !plan.working_dir.empty() ? std::filesystem::path(plan.working_dir) : dir;
    const std::vector<std::string> env = child_environment(seen_dir, sandboxed, additions);
    std::vector<char*> envp = pointers(env);
    std::vector<char*> args = pointers(argv);
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid < 0) {
        result.failed_to_start = true;
        return result;
    }
    if (pid == 0) {
        // A session of its own: no controlling terminal (nothing to inject keystrokes into), and a process group
        // the timeout kills whole.
        setsid();
        dup2(null_input.get(), STDIN_FILENO);
        dup2(output_child.get(), STDOUT_FILENO);
        dup2(output_child.get(), STDERR_FILENO);
        if (limits.handin) dup2(handin_child.get(), kHandinFd);
        close_descriptors_from(limits.handin ? kHandinFd + 1 : STDERR_FILENO + 1, report_child.get());
        std::string why;
        if (sandboxed && !enter_sandbox(plan, why)) {
            const std::string line = "sandbox-error " + why + "\n";
            write_line(report_child.get(), line.c_str());
            _exit(125);
        }
        if (!sandboxed && !dir.empty() && chdir(dir.c_str()) != 0) _exit(126);
        execve(args[0], args.data(), envp.data());
        write_line(report_child.get(), "exec-failed\n");
        _exit(127);
    }
    output_child.reset();
    report_child.reset();
    handin_child.reset();
    fcntl(output.get(), F_SETFL, O_NONBLOCK);
    fcntl(report.get(), F_SETFL, O_NONBLOCK);
    if (limits.handin) fcntl(handin.get(), F_SETFL, O_NONBLOCK);

    const auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    auto kill_all = [&] {
        kill(-pid, SIGKILL);
        kill(pid, SIGKILL);
    };
    // Replies are small (a challenge at most 4 KiB) and one at a time, so the socket's buffer takes each whole.
    const HandinConversation::Reply reply = [&](const HandinTag& tag, const std::vector<std::uint8_t>& payload) {
        const std::vector<std::uint8_t> message = encode_message(tag, payload);
        const double written_from = seconds();
        std::size_t sent = 0;
        while (sent < message.size()) {
            const ssize_t n = send(handin.get(), message.data() + sent, message.size() - sent, MSG_NOSIGNAL);
            if (n > 0) {
                sent += static_cast<std::size_t>(n);
            } else if (n < 0 && errno == EAGAIN) {
                pollfd p{handin.get(), POLLOUT, 0};
                if (poll(&p, 1, 1000) <= 0) throw Error("does not read the grader's messages on the hand-in socket");
            } else if (n < 0 && errno != EINTR) {
                break;  // the lab closed its end; what it handed in so far stands
            }
        }
        return written_from;
    };
    std::optional<HandinReader> reader;
    if (limits.handin) reader.emplace(*limits.handin, limits.max_handin_bytes);
    const auto take_handin = [&] {
        if (!reader || reader->closed() || !result.refused.empty()) return;
        try {
            reader->read_from(handin.get(), seconds, reply, result.handin_bytes);
        } catch (const Error& e) {
            result.refused = e.what();
            kill_all();
        }
    };
    auto keep = [&](const char* data, std::size_t n) {
        result.output_bytes += n;
        const std::size_t room = limits.max_output_bytes - std::min(limits.max_output_bytes, result.output.size());
        result.output.append(data, std::min(room, n));
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
        pollfd p[2] = {{open ? output.get() : -1, POLLIN, 0}, {reader && !reader->closed() ? handin.get() : -1, POLLIN, 0}};
        poll(p, 2, 20);
        take_handin();
        if (open) {
            const ssize_t n = read(output.get(), buffer, sizeof buffer);
            if (n > 0) keep(buffer, static_cast<std::size_t>(n));
            else if (n == 0) open = false;
        }
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) {
            reaped = true;
            ssize_t n;
            while (open && (n = read(output.get(), buffer, sizeof buffer)) > 0) keep(buffer, static_cast<std::size_t>(n));
            take_handin();
            break;
        }
    }
    if (!reaped) waitpid(pid, &status, 0);
    read_report(report.get(), result);
    if (reader && reader->partial() && result.refused.empty() && !result.timed_out && !result.flooded)
        result.refused = "ended in the middle of a message on the hand-in socket";
    // Without a PID namespace, what the student started may outlive it: its uid is this run's alone, so every
    // process of that uid goes.
    if (sandboxed && !limits.support->allow_list() && plan.as_root) kill_processes_of(plan.uid);
    if (host_folder) {
        try {
            result.folder = host_folder->remove();
            result.folder_full = sandboxed && (result.folder.bytes >= limits.sandbox->folder_bytes ||
                                               result.folder.files >= limits.sandbox->folder_files);
        } catch (const Error& e) {
            result.cleanup_error = e.what();
        }
    }
    result.seconds = seconds();
    if (result.output_bytes > result.output.size())
        result.output += "\n[output cut: " + std::to_string(result.output_bytes) + " bytes printed, " +
                         std::to_string(result.output.size()) + " kept]\n";
    if (result.timed_out || result.flooded) return result;
    if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
    else if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
    return result;
}

}  // namespace gsv
