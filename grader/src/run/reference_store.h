#pragma once
// Live references kept across runs: the reference solution's image (and arrays) of a case, stored on disk under a key
// that names everything the render depends on, so that a rerun, the next submission of a batch (each is a gsv-grade
// process of its own) or the next shard on the same machine renders it once. The key is the reference's command
// line with the binary and the kit replaced by fingerprints of their bytes, the GL driver's files and the environment
// variables that choose or tune a driver: any change to the kit, the build, the driver or the case makes another key.
// An entry is one file holding its whole key, checked byte for byte on every hit, and a checksum of the rest; a damaged
// one is removed and the case rendered, never trusted. Only passed renders are stored, and only the image and the arrays
// (timed frames are always rendered live: they are measured against the student's in the same run).
//
// What student code can write must never reach this folder: the grader uses it where the allow-list walls are up
// (grade/walls.cpp), and it lies in the kit's build, which no lab run sees; or, where the walls are down, where a root
// grader runs student code as a leased uid (run/uid_lease.h) and no folder on the store's path lets that uid write
// (writable_by_others below). Entries are written 0644 and one that another user could change is never read.
#include "grader/src/run/lab_run.h"

#include <filesystem>
#include <optional>
#include <string>

namespace gsv {

// What a reference render depends on besides its command line: the kit (grader/src/batch/batch_record.h's
// kit_fingerprint), the GL driver's files (name, size, time) and the environment that picks or tunes the driver.
// Computed once per run; one line per part.
std::string reference_context(const std::filesystem::path& kit_root);
// The fingerprint of a file's bytes (FNV-1a), "" when it cannot be read.
std::string file_fingerprint(const std::filesystem::path& file);

// Why a user other than the grader's (and root) could change what is in `folder`: it, or a folder above it, belongs to
// another user or lets group or others write without the sticky bit. Empty when none could. `folder` is made (0755)
// when missing, so that what the check sees is what the store will use.
std::string writable_by_others(const std::filesystem::path& folder);

class ReferenceStore {
public:
    // `folder` is created on the first store; an unusable one is one line in problem(), and the run goes on.
    explicit ReferenceStore(std::filesystem::path folder);

    // The passed run stored under `key` (image, arrays, renderer); none when there is none, or when the entry is
    // damaged or holds another key (then removed, and counted).
    std::optional<LabRun> load(const std::string& key);
    // Stores a passed run under `key`, written under a private name and renamed in; never throws.
    void store(const std::string& key, const LabRun& run);

    int hits() const { return hits_; }
    int stored() const { return stored_; }
    int damaged() const { return damaged_; }
    // The first thing that went wrong with the folder, in one line; empty when nothing did.
    const std::string& problem() const { return problem_; }
    const std::filesystem::path& folder() const { return folder_; }

private:
    std::filesystem::path entry_path(const std::string& key) const;

    std::filesystem::path folder_;
    int hits_ = 0, stored_ = 0, damaged_ = 0;
    std::string problem_;
};

}  // namespace gsv
