#pragma once
// `gsv-grade merge OUT SHARD_OUT...`: the outputs of the shards of one batch (gsv-grade --batch --shard K/N, run on
// as many machines) joined into one: the per-submission folders, class.csv, class.txt and a batch.json of the
// whole class, as if one machine had graded it.
#include "grader/src/batch/batch_record.h"

#include <filesystem>
#include <vector>

namespace gsv {

// Throws gsv::Error (one line) when a folder is not a shard's output, when the shards were graded with different
// seeds, kits, labs or other options, or for different classes, when two hold the same shard or student, or when a
// shard of the N is missing. Nothing is written to `out` then. `out` must be new or empty.
BatchRecord merge_shards(const std::vector<std::filesystem::path>& shard_dirs, const std::filesystem::path& out);

}  // namespace gsv
