#include "common/app/subprocess.h"

#include "common/core/error.h"

#include <cerrno>
#include <cstring>

#if defined(_WIN32)
#include <process.h>
#else
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
extern char** environ;
#endif

namespace gsv {

#if defined(_WIN32)

namespace {
// _spawnv joins its arguments with spaces: each is quoted as the C runtime's parser expects.
std::string quoted(const std::string& arg) {
    if (!arg.empty() && arg.find_first_of(" \t\"") == std::string::npos) return arg;
    std::string out = "\"";
    std::size_t backslashes = 0;
    for (char c : arg) {
        if (c == '\\') {
            ++backslashes;
            continue;
        }
        out.append(c == '"' ? 2 * backslashes + 1 : backslashes, '\\');
        backslashes = 0;
        out += c;
    }
    out.append(2 * backslashes, '\\');
    return out + "\"";
}
}  // namespace

ProgramExit run_program(const std::vector<std::string>& argv, const std::filesystem::path&) {
    if (argv.empty()) throw Error("run_program: no program given");
    std::vector<std::string> args;
    for (const auto& a : argv) args.push_back(quoted(a));
    std::vector<const char*> pointers;
    for (const auto& a : args) pointers.push_back(a.c_str());
    pointers.push_back(nullptr);
    const intptr_t status = _spawnv(_P_WAIT, argv[0].c_str(), pointers.data());
    if (status == -1) throw Error("cannot start '" + argv[0] + "': " + std::strerror(errno));
    return {static_cast<int>(status), 0};
}

#else

ProgramExit run_program(const std::vector<std::string>& argv, const std::filesystem::path& output) {
    if (argv.empty()) throw Error("run_program: no program given");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    std::vector<char*> pointers;
    for (const auto& a : argv) pointers.push_back(const_cast<char*>(a.c_str()));
    pointers.push_back(nullptr);
    pid_t pid = 0;
    const int error = posix_spawn(&pid, argv[0].c_str(), &actions, nullptr, pointers.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0) throw Error("cannot start '" + argv[0] + "': " + std::strerror(error));
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) throw Error("lost track of '" + argv[0] + "': " + std::strerror(errno));
    if (WIFSIGNALED(status)) return {-1, WTERMSIG(status)};
    return {WEXITSTATUS(status), 0};
}

#endif

}  // namespace gsv
