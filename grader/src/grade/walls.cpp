// The walls of a run (grader/src/run/sandbox.h): what a student's lab run and a submission's build may read and write,
// the uid student code runs as, and which walls this machine lets the grader put up.
#include "grader/src/grade/session.h"

#include "common/app/kit_layout.h"
#include "common/core/error.h"
#include "grader/src/run/build_reuse.h"

#include <algorithm>
#include <unistd.h>

namespace fs = std::filesystem;

namespace gsv {

void GradingSession::set_up_sandbox(const fs::path& student_bin, const fs::path& student_root, const fs::path& build_dir) {
    // An allow-list: what a student's process may read. A lab run: its own binary, its own lab's folder of labs/ (and
    // of a test kit's solutions/, where the tests grade edited references as students), the kit's public shaders/ and
    // data/. Nothing of the student's other labs: a lab's grade depends on its own folder alone (grade/regrade.h).
    const KitLayout layout{kit}, student_layout{student_root};
    policy_.read_only.insert(policy_.read_only.end(), {student_layout.shaders(), student_layout.data(), layout.shaders(), layout.data()});
    const fs::path kit_build = bin.parent_path();
    for (const auto& lab : labs) {
        SandboxPolicy& own = lab_policies_[lab.lab];
        own = policy_;
        own.read_only.push_back(student_bin / lab.lab);
        const std::string folder = cmake_cache_value(kit_build, "GSV_LAB_DIR_" + lab.lab);
        // A kit build that does not name the folder: all of labs/, as before there were folders to tell apart.
        own.read_only.push_back(folder.empty() ? student_layout.labs() : student_layout.labs() / folder);
        if (!options.student_bin_dir.empty())
            own.read_only.push_back(folder.empty() ? student_layout.solutions() : student_layout.solutions() / folder);
    }
    // A build: the framework's headers and sources, its CMake files and the libraries it links, and the build's
    // own folder (read-write); nothing of solutions/, tests/, grader/ but the submission project, or build/ but those.
    build_policy_.read_only = {kit / "common", kit / "support", kit / "third_party", kit / "cmake",
                               layout.submission_project(), layout.shaders(), layout.data(),
                               kit_build / "gsv-targets.cmake", kit_build / "gsv-build-settings.cmake",
                               kit_build / "common", kit_build / "support", kit_build / "third_party"};
    // The build writes only its build folder; of the submission's labs/ (the grader's copy) it may only read, and only
    // what build_submission adds for each step (configuring: labs/; a lab's build: that lab's folder).
    if (!build_dir.empty()) build_policy_.read_write = {build_dir / "build"};
    // A root grader runs student code as a uid leased to this run alone (grader/src/run/uid_lease.h).
    if (geteuid() == 0 && options.sandbox)
        uid_lease_.emplace(options.sandbox_uid ? UidLease::exactly(options.sandbox_uid) : UidLease::any());
    policy_.uid = build_policy_.uid = uid_lease_ ? uid_lease_->uid() : kSandboxUidBase;
    for (auto& [lab, own] : lab_policies_) own.uid = policy_.uid;
#if defined(__SANITIZE_ADDRESS__)
    // The labs of a sanitizer build reserve terabytes of shadow memory.
    policy_.address_space_bytes = build_policy_.address_space_bytes = 0;
    for (auto& [lab, own] : lab_policies_) own.address_space_bytes = 0;
#endif
    build_policy_.address_space_bytes = 0;  // compilers and linkers: their time limit is the guard
    build_policy_.file_size_bytes = 512ull << 20;
    if (!options.sandbox) {
        report.sandbox = "off (--no-sandbox): student code runs with the grader's rights";
        return;
    }
    if (options.namespaces) {
        support_ = probe_sandbox(policy_);
    } else {
        support_.refused = "--no-namespaces";
    }
    report.sandbox = support_.describe(policy_);
    const bool secrets = purpose_ != RunPurpose::UpdateGoldens && (std::find(live.begin(), live.end(), true) != live.end());
    if (!support_.allow_list() && secrets && !options.allow_readable_kit)
        throw Error("the sandbox cannot hide the kit here (" + support_.refused +
                    "): live references and hidden cases are refused; grade with --self-check, or pass "
                    "--allow-readable-kit to grade with the kit readable by student code");
    if (!support_.allow_list()) report.sandbox += options.allow_readable_kit && secrets ? " (--allow-readable-kit)" : "";
}

}  // namespace gsv
