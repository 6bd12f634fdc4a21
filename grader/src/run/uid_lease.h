#pragma once
// A uid for one grader run's student code, held by that run alone. A root grader runs student code as another
// uid; two graders on one machine (two CI jobs on one runner, two terminals, a batch's workers) each lease their
// own from [kSandboxUidBase, kSandboxUidBase + kSandboxUidCount), so one student's fork bomb meets its own
// process limit only, and no student process can signal or read another run's. The lease is an exclusive flock
// on a file per uid in a root-only folder, held as long as the lease lives and dropped by the kernel when its
// process ends however it ends; a uid that still runs processes (left by a run that could not kill them) is
// skipped.
#include <filesystem>
#include <sys/types.h>

namespace gsv {

class UidLease {
public:
    // The first free uid of the range. Throws gsv::Error when the lock folder is unsafe or every uid is taken.
    static UidLease any(const std::filesystem::path& locks = lock_folder());
    // This uid (--sandbox-uid); throws gsv::Error when another grader run holds it or it runs processes.
    static UidLease exactly(uid_t uid, const std::filesystem::path& locks = lock_folder());
    // Where the locks are: /run/lock/gsv-grade-uids, or /tmp/gsv-grade-uids without /run/lock.
    static std::filesystem::path lock_folder();

    UidLease(UidLease&& other) noexcept;
    UidLease& operator=(UidLease&& other) noexcept;
    UidLease(const UidLease&) = delete;
    UidLease& operator=(const UidLease&) = delete;
    ~UidLease();

    uid_t uid() const { return uid_; }

private:
    UidLease(int fd, uid_t uid) : fd_(fd), uid_(uid) {}
    int fd_ = -1;
    uid_t uid_ = 0;
};

// Processes (tasks, as RLIMIT_NPROC counts them) that `uid` runs now.
long tasks_of_user(uid_t uid);
// Ends every process `uid` runs (from a child that becomes `uid` and signals all it may). Root only.
void kill_processes_of(uid_t uid);

}  // namespace gsv
