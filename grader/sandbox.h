#pragma once
// The walls around a student's process (Linux). Each is used where the platform allows it, and the
// report says which were up:
//  - mount and network namespaces: reference solutions, golden images, hidden case data and the other
//    results are covered by empty mounts, and there is no network;
//  - not root: a grader running as root runs student code as nobody;
//  - rlimits on address space, CPU time, file size and process count.
// The wall-clock timeout, the output cap and the fresh working directory are in process.h.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

struct SandboxPolicy {
    bool enabled = true;
    std::vector<std::filesystem::path> hidden;      // folders get an empty read-only tmpfs, files /dev/null
    std::uint64_t address_space_bytes = 4ull << 30; // 0: no limit (sanitizer builds reserve terabytes)
    std::uint64_t file_size_bytes = 64ull << 20;
    double cpu_seconds = 0;                         // 0: the wall-clock timeout times the cores, plus 5 s
    long extra_processes = 256;                     // over what the user runs already: stops fork bombs
};

// Which walls this machine allows; found once by trying them in a throw-away child.
struct SandboxSupport {
    enum class Namespaces { None, AsRoot, AsUser } namespaces = Namespaces::None;
    bool drops_root = false;       // root: student code runs as nobody
    std::string describe() const;  // one line for the reports
};

// `must_reach`: what the student process must still read after dropping root (its binary, the kit);
// `hidden`: what the namespaces must be able to cover.
SandboxSupport probe_sandbox(const std::vector<std::filesystem::path>& must_reach,
                             const std::vector<std::filesystem::path>& hidden);

// Makes `path` (recursively) the student's, where student code runs as nobody: its working folder.
void hand_over(const std::filesystem::path& path, const SandboxSupport& support);

// In the forked child, before exec: enters the walls `support` allows. Returns false with a reason
// when a wall that the probe found working could not be put up.
bool enter_sandbox(const SandboxPolicy& policy, const SandboxSupport& support, double timeout_s, std::string& why);

}  // namespace gsv
