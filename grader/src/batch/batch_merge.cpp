#include "grader/src/batch/batch_merge.h"

#include "common/core/error.h"

#include <algorithm>
#include <map>

namespace fs = std::filesystem;

namespace gsv {

namespace {

std::string joined(const std::vector<std::string>& items, std::size_t at_most = 5) {
    std::string text;
    for (std::size_t i = 0; i < items.size() && i < at_most; ++i) text += (i ? ", " : "") + items[i];
    if (items.size() > at_most) text += ", ... (" + std::to_string(items.size()) + " in all)";
    return text.empty() ? "none" : text;
}

std::string option_value(const std::vector<std::string>& options, const std::string& name, const std::string& fallback) {
    const auto at = std::find(options.begin(), options.end(), name);
    return at != options.end() && at + 1 != options.end() ? *(at + 1) : fallback;
}

// Refuses a shard that was not graded like the first one, naming what differs.
void check_alike(const BatchRecord& first, const fs::path& first_dir, const BatchRecord& other, const fs::path& other_dir) {
    const std::string pair = "'" + first_dir.string() + "' and '" + other_dir.string() + "'";
    if (other.seed != first.seed)
        throw Error(pair + " were graded with different seeds (" + std::to_string(first.seed) + ", " + std::to_string(other.seed) +
                    "): their hidden cases differ");
    if (other.kit != first.kit) throw Error(pair + " were graded by different kits (fingerprints " + first.kit + ", " + other.kit + ")");
    const std::string labs_a = option_value(first.options, "--labs", "all"), labs_b = option_value(other.options, "--labs", "all");
    if (labs_a != labs_b) throw Error(pair + " graded different labs (" + labs_a + "; " + labs_b + ")");
    if (other.options != first.options)
        throw Error(pair + " were graded with different options (" + joined(first.options, 99) + "; " + joined(other.options, 99) + ")");
    if (other.roster != first.roster) throw Error(pair + " were graded for different classes (" + std::to_string(first.roster.size()) +
                                                  " and " + std::to_string(other.roster.size()) + " names)");
    if (other.shard_count != first.shard_count)
        throw Error(pair + " split the class differently (" + std::to_string(first.shard_count) + " and " +
                    std::to_string(other.shard_count) + " shards)");
}

}  // namespace

BatchRecord merge_shards(const std::vector<fs::path>& shard_dirs, const fs::path& out) {
    if (shard_dirs.empty()) throw Error("merge needs the output folders of the shards");
    if (fs::exists(out) && !(fs::is_directory(out) && fs::is_empty(out)))
        throw Error("merge: '" + out.string() + "' must be a new or empty folder");
    std::vector<BatchRecord> records;
    std::map<int, fs::path> by_shard;
    std::map<std::string, fs::path> by_student;
    for (const fs::path& dir : shard_dirs) {
        records.push_back(read_batch_record(dir));
        const BatchRecord& r = records.back();
        check_alike(records.front(), shard_dirs.front(), r, dir);
        const std::string shard = std::to_string(r.shard) + "/" + std::to_string(r.shard_count);
        if (const auto [at, fresh] = by_shard.emplace(r.shard, dir); !fresh)
            throw Error("'" + at->second.string() + "' and '" + dir.string() + "' are both shard " + shard);
        // A shard holds exactly its share of the class: anything else is a record edited or run another way.
        std::vector<std::string> names;
        for (const BatchEntry& e : r.entries) names.push_back(e.name);
        if (names != shard_names(r.roster, r.shard, r.shard_count))
            throw Error("'" + dir.string() + "' (shard " + shard + ") does not hold that shard's students");
        for (const std::string& name : names)
            if (const auto [at, fresh] = by_student.emplace(name, dir); !fresh)
                throw Error("'" + at->second.string() + "' and '" + dir.string() + "' both graded '" + name + "'");
    }
    const BatchRecord& first = records.front();
    std::vector<std::string> missing_shards, missing_students;
    for (int k = 1; k <= first.shard_count; ++k)
        if (!by_shard.count(k)) {
            missing_shards.push_back(std::to_string(k) + "/" + std::to_string(first.shard_count));
            for (const std::string& name : shard_names(first.roster, k, first.shard_count)) missing_students.push_back(name);
        }
    if (!missing_shards.empty())
        throw Error("merge: shard " + joined(missing_shards) + " missing, so are the students " + joined(missing_students));

    BatchRecord merged = first;
    merged.shard = merged.shard_count = 1;
    merged.entries.clear();
    std::map<std::string, const BatchEntry*> rows;
    for (const BatchRecord& r : records)
        for (const BatchEntry& e : r.entries) rows[e.name] = &e;
    try {
        fs::create_directories(out);
        for (const std::string& name : merged.roster) {
            merged.entries.push_back(*rows.at(name));
            // A row has its folder where grading got far enough to write one (a name with nothing submitted has none).
            const fs::path from = by_student.at(name) / name;
            if (fs::is_directory(from)) fs::copy(from, out / name, fs::copy_options::recursive);
        }
    } catch (const fs::filesystem_error& e) {
        throw Error("merge: cannot write into '" + out.string() + "': " + e.code().message() +
                    (e.path1().empty() ? "" : " ('" + e.path1().string() + "')"));
    }
    write_batch_record(merged, out, write_class_tables(merged.entries, out));
    return merged;
}

}  // namespace gsv
