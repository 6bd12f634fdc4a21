#pragma once
// The walls around a student's process (Linux), built as an allow-list: the process sees a file system made for
// it, not the grader's with parts covered.
//  - a new root on a tmpfs holding the system read-only (/usr, /etc, /sys and every mount below them, the /lib
//    links), a minimal /dev, a /proc of its own, private size-limited /tmp, /var/tmp and /dev/shm, and at their own
//    paths only what the policy allows: its working folder (read-write: a lab's is a tmpfs of its own with a size
//    and a file-count limit, which goes with the namespace, so nothing it writes reaches the grader's disk) and,
//    read-only, what it must read (its binary, its own lab's files, the kit's public shaders/ and data/, or for a
//    build the framework's headers and libraries). Nothing else of the kit, nothing of other submissions or
//    earlier results;
//  - PID, network and IPC namespaces: no other process is visible, every process the student started ends with its
//    case (setsid daemons included: the namespace's first process is a small init of the grader's that leaves when
//    the student's process ends), and there is no network;
//  - an identity of its own: a grader running as root runs it as the policy's uid, leased to that grader run alone
//    (grader/src/run/uid_lease.h), so two graders on one machine never share one; otherwise a user namespace of its
//    own, which maps the grader's own uid and counts its processes apart from every other namespace's;
//  - rlimits on address space, CPU time, file size, open files and processes.
// The wall-clock timeout, the output cap and the fresh working folder are in process.h.
#include <cstdint>
#include <filesystem>
#include <string>
#include <sys/types.h>
#include <vector>

namespace gsv {

// The uids student code runs as under a root grader: each grader run leases one of them (grader/src/run/uid_lease.h).
inline constexpr uid_t kSandboxUidBase = 1500000;
inline constexpr uid_t kSandboxUidCount = 100000;
// Where a lab's working folder is inside the walls (a tmpfs of its own there).
inline constexpr const char* kCaseFolder = "/case";

struct SandboxPolicy {
    bool enabled = true;
    // Bound at their own paths; a path that does not exist is left out.
    std::vector<std::filesystem::path> read_only;
    std::vector<std::filesystem::path> read_write;   // besides the process's working folder, which always is
    uid_t uid = kSandboxUidBase;                     // root only: the identity inside
    std::uint64_t tmp_bytes = 64ull << 20;           // each of /tmp, /var/tmp, /dev/shm
    std::uint64_t tmp_files = 4096;                  // each of them, files and folders
    // A lab's working folder (a process run with a private folder, process.h): its size and entries.
    std::uint64_t folder_bytes = 128ull << 20;
    std::uint64_t folder_files = 4096;
    std::uint64_t address_space_bytes = 4ull << 30;  // 0: no limit (sanitizer builds reserve terabytes)
    std::uint64_t file_size_bytes = 64ull << 20;
    double cpu_seconds = 0;                          // 0: the wall-clock timeout times the cores, plus 5 s
    long processes = 256;                            // tasks of the sandbox's uid: stops fork bombs
};

// Which walls this machine allows; found once by putting them up in a throw-away child.
struct SandboxSupport {
    enum class Namespaces { None, AsRoot, AsUser } namespaces = Namespaces::None;
    std::string refused;  // why not, where namespaces are None
    bool allow_list() const { return namespaces != Namespaces::None; }
    std::string describe(const SandboxPolicy& policy) const;  // one line for the reports
};

// Puts the walls up with `policy` in a throw-away child and checks that every path it allows can be read inside.
SandboxSupport probe_sandbox(const SandboxPolicy& policy);

// Makes `path` (recursively) the sandbox identity's where student code runs as another uid: its working folder.
void hand_over(const std::filesystem::path& path, const SandboxPolicy& policy, const SandboxSupport& support);

// Everything the child needs, worked out before fork (the child then makes system calls only).
struct SandboxPlan {
    struct Bind {
        std::string path;  // on the host and inside
        bool read_only = true;
        bool exists = true;  // on the host, when planned
    };
    SandboxSupport::Namespaces namespaces = SandboxSupport::Namespaces::None;
    bool as_root = false;
    uid_t uid = 0, host_uid = 0;
    gid_t host_gid = 0;
    std::vector<Bind> binds;
    std::vector<std::string> devices;  // /dev entries bound from the host
    std::string working_dir, tmp_options;
    // Not empty: the working folder is a tmpfs mounted with these options inside (no host folder behind it).
    std::string folder_options;
    // Where the namespace's first process says, once the student's process ended, what the working folder holds
    // ("folder BYTES FILES FULL\n"); -1: not asked.
    int report_fd = -1;
    // A served lab (ServedProcess, process.h): while the student's process runs, the namespace's first process also
    // answers the grader's commands on report_fd: 'p' stops every other process of the namespace and says "paused"
    // with what the working folder holds (as above), 'r' lets them run again.
    bool answers_commands = false;
    std::uint64_t address_space_bytes = 0, file_size_bytes = 0, processes = 0, cpu_seconds = 0;
};
// `private_folder`: the working folder is the tmpfs kCaseFolder inside (with namespaces; `working_dir` is then
// ignored), else the host's `working_dir` bound at its own path.
SandboxPlan plan_sandbox(const SandboxPolicy& policy, const SandboxSupport& support,
                         const std::filesystem::path& working_dir, double timeout_s, bool private_folder = false);

// In the forked child, before exec, with its output already redirected. Puts up the walls and returns true in the
// process that is to exec: inside the new namespaces, in `working_dir`, as the sandbox's identity. The process
// that called it does not return: it waits for the namespace to end and exits as the student's process did.
// Returns false with a reason (in that process) when a wall could not be put up.
bool enter_sandbox(const SandboxPlan& plan, std::string& why);

}  // namespace gsv
