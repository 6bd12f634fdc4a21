#pragma once
// A submission is a copy of the kit whose labs/ hold a student's work. Only labs/ is taken from it, and only its
// plain content, copied: symbolic and hard links, devices, FIFOs and files over kMaxSubmissionFileBytes are refused
// and named in the build log. The framework, shared shaders and data are the kit's. Each
// lab is built as its own target, so one lab's compile error leaves the others gradable.
#include "grader/src/core/grade_result.h"
#include "grader/src/run/build_reuse.h"
#include "grader/src/run/process.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

// A submission's file may have at most this many bytes; a larger one is refused, named in the build log. Its labs/
// may hold at most kMaxSubmissionEntries files and folders and kMaxSubmissionBytes in all; what is over is refused.
inline constexpr std::uintmax_t kMaxSubmissionFileBytes = 8ull << 20;
inline constexpr std::uintmax_t kMaxSubmissionEntries = 20000;
inline constexpr std::uintmax_t kMaxSubmissionBytes = 256ull << 20;

struct SubmissionBuild {
    std::filesystem::path root;     // GSV_ROOT for the student's binaries: labs/ copied, shaders/ and data/ the kit's
    std::filesystem::path bin_dir;  // the student's lab binaries
    std::vector<LabBuild> builds;
};

// A lab is compiled only where its C++ differs. Its build inputs are every file of its folder but those the lab reads
// at run time (shaders, network and case files, pictures, text: they reach the binary through GSV_ROOT, never the
// compiler). Where they are byte for byte the kit's starter's (names and contents), the binary is the kit's own
// (built from the same sources by the same cmake/labs.cmake, and no older than them); where they are byte for byte
// those of an earlier build kept in the build cache (`cache_dir`, by default <kit build>/grader-cache/builds; keyed by the kit build's
// libraries and the inputs, holding a copy of the inputs that is compared byte for byte, never trusted by key),
// that build's binary. A cache that cannot be read or written is one line in the build log; the lab is built.
// Throws gsv::Error when the submission has no labs/ folder (the student's), then KitFault (run/kit_fault.h) when the
// kit build is not configured, was made from another checkout than `kit_root`, or lacks a file every build reads.

SubmissionBuild build_submission(const std::filesystem::path& submission, const std::filesystem::path& kit_root,
                                 const std::filesystem::path& kit_build, const std::vector<std::string>& labs,
                                 const std::filesystem::path& work_dir, const ProcessLimits& limits, bool reuse = true,
                                 const std::filesystem::path& cache_dir = {});

}  // namespace gsv
