#pragma once
// What a batch (or one shard of it) leaves beside its per-submission folders, <out>/batch.json: the seed, the
// kit, the options and the class it was graded with, and its rows. `gsv-grade merge` joins shards by these
// records and refuses ones that were not graded alike, so a merged class table is one grading, not a mixture.
#include "grader/src/batch/batch.h"
#include "grader/src/batch/class_cases.h"
#include "grader/src/core/kit_fingerprint.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gsv {

struct BatchRecord {
    std::uint64_t seed = 0;
    int shard = 1, shard_count = 1;
    std::string kit;                   // kit_fingerprint() of the kit that graded (grader/src/core/kit_fingerprint.h)
    std::vector<std::string> options;  // what every submission's run got, less the machine's own paths
    std::vector<std::string> roster;   // the whole class, sorted
    std::vector<BatchEntry> entries;   // this shard's rows, in class order
};

// The options of a batch as recorded: --kit and --bin with their values left out (they name this machine's folders).
std::vector<std::string> recorded_options(const std::vector<std::string>& pass_through);

// `cases`: the class case by case as write_class_tables returned it (batch.json's "cases", for scripts that read JSON).
void write_batch_record(const BatchRecord& record, const std::filesystem::path& out_dir, const std::vector<ClassCaseRow>& cases = {});
// Throws gsv::Error naming the folder when it holds no batch.json or one that is not a batch record.
BatchRecord read_batch_record(const std::filesystem::path& out_dir);
// The record's class case by case ("cases": class-cases.csv's rows when it was written); none where the record was
// written before it kept them. Throws gsv::Error naming the file and the key of a malformed row.
std::optional<std::vector<ClassCaseRow>> read_batch_cases(const std::filesystem::path& out_dir);

// Writes <out>/class.csv and <out>/class.txt (the table gsv-grade prints) for these rows, and the class case by case
// (class_cases.h), whose rows it returns.
std::vector<ClassCaseRow> write_class_tables(const std::vector<BatchEntry>& entries, const std::filesystem::path& out_dir);

}  // namespace gsv
