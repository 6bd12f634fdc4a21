#include "grader/src/batch/batch_record.h"
#include "grader/src/batch/class_cases.h"
#include "grader/src/batch/class_report.h"

#include "common/core/error.h"
#include "common/io/json.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>

namespace fs = std::filesystem;

namespace gsv {
namespace {

constexpr const char* kRecordFormat = "gsv-batch 1";

}  // namespace

std::vector<std::string> recorded_options(const std::vector<std::string>& pass_through) {
    std::vector<std::string> kept;
    for (std::size_t i = 0; i < pass_through.size(); ++i) {
        if (pass_through[i] == "--kit" || pass_through[i] == "--bin") {
            ++i;
            continue;
        }
        // The grades are the same either way (run/submission.h, run/reference_store.h): shards may differ in them.
        if (pass_through[i] == "--build-all" || pass_through[i] == "--fresh-references" || pass_through[i] == "--one-process-per-case")
            continue;
        // What a run keeps on disk, not what it grades.
        if (pass_through[i] == "--regrade-only" || pass_through[i] == "--grader-cache" || pass_through[i] == "--passed-pictures" ||
            pass_through[i] == "--keep-build") {
            ++i;
            continue;
        }
        kept.push_back(pass_through[i]);
    }
    return kept;
}

void write_batch_record(const BatchRecord& record, const fs::path& out_dir, const std::vector<ClassCaseRow>& cases) {
    Json root = Json::object();
    root["format"] = kRecordFormat;
    root["seed"] = std::to_string(record.seed);  // a string: a JSON number holds 53 bits, a seed 64
    root["shard"] = std::to_string(record.shard) + "/" + std::to_string(record.shard_count);
    root["kit"] = record.kit;
    Json options = Json::array();
    for (const auto& o : record.options) options.push_back(o);
    root["options"] = options;
    Json roster = Json::array();
    for (const auto& name : record.roster) roster.push_back(name);
    root["class"] = roster;
    Json rows = Json::array();
    for (const BatchEntry& e : record.entries) {
        Json row = Json::object();
        row["name"] = e.name;
        row["graded"] = e.graded;
        row["score"] = e.score;
        row["max_score"] = e.max_score;
        row["seconds"] = e.seconds;
        row["problem"] = e.problem;
        row["regraded"] = e.regraded;
        row["kit_fault"] = e.kit_fault;
        rows.push_back(row);
    }
    root["entries"] = rows;
    // The class case by case, as class-cases.csv has it: for a script that reads JSON rather than CSV.
    Json case_rows = Json::array();
    for (const ClassCaseRow& r : cases) {
        Json row = Json::object();
        row["submission"] = r.submission;
        row["lab"] = r.lab;
        row["todo"] = r.todo;
        row["check"] = r.check;
        row["kind"] = r.kind;
        row["status"] = r.status;
        row["points"] = r.points;
        row["max_points"] = r.max_points;
        case_rows.push_back(row);
    }
    root["cases"] = case_rows;
    const fs::path file = out_dir / "batch.json";
    std::ofstream out(file);
    out << root.dump(2) << "\n";
    if (!out) throw Error("cannot write '" + file.string() + "'");
}

BatchRecord read_batch_record(const fs::path& out_dir) {
    const fs::path file = out_dir / "batch.json";
    if (!fs::is_regular_file(file))
        throw Error("'" + out_dir.string() + "' holds no batch.json: not the --out of a gsv-grade --batch");
    const Json root = read_json_file(file);
    if (root.string_at("format") != kRecordFormat)
        throw Error(file.string() + ": format '" + root.string_at("format") + "', expected '" + kRecordFormat + "'");
    BatchRecord record;
    const std::string seed = root.string_at("seed");
    if (seed.empty() || seed.find_first_not_of("0123456789") != std::string::npos)
        throw Error(file.string() + ": seed '" + seed + "' is not a whole number");
    record.seed = std::stoull(seed);
    const auto [k, n] = parse_shard(root.string_at("shard"));
    record.shard = k;
    record.shard_count = n;
    record.kit = root.string_at("kit");
    for (const Json& o : root.array_at("options").as_array()) record.options.push_back(o.as_string());
    for (const Json& name : root.array_at("class").as_array()) record.roster.push_back(name.as_string());
    for (const Json& row : root.array_at("entries").as_array()) {
        BatchEntry e;
        e.name = row.string_at("name");
        e.graded = row.bool_at("graded");
        e.score = row.number_at("score");
        e.max_score = row.number_at("max_score");
        e.seconds = row.number_at("seconds");
        e.problem = row.string_at("problem");
        if (const Json* regraded = row.find("regraded")) e.regraded = regraded->as_string();
        e.kit_fault = row.bool_or("kit_fault", false);
        record.entries.push_back(e);
    }
    return record;
}

std::optional<std::vector<ClassCaseRow>> read_batch_cases(const fs::path& out_dir) {
    read_batch_record(out_dir);  // a folder without a record, or another format, is refused in its words
    const Json root = read_json_file(out_dir / "batch.json");
    const Json* cases = root.find("cases");
    if (!cases) return std::nullopt;
    std::vector<ClassCaseRow> rows;
    for (const Json& r : cases->as_array())
        rows.push_back({r.string_at("submission"), r.string_at("lab"), r.string_at("todo"), r.string_at("check"), r.string_at("kind"),
                        r.string_at("status"), r.number_at("points"), r.number_at("max_points")});
    return rows;
}

std::vector<ClassCaseRow> write_class_tables(const std::vector<BatchEntry>& entries, const fs::path& out_dir) {
    ClassColumns columns;
    // The last run's scores, from its batch.json, before this run's replaces it.
    if (fs::is_regular_file(out_dir / "batch.json")) {
        try {
            for (const BatchEntry& e : read_batch_record(out_dir).entries)
                if (e.graded) columns.previous[e.name] = e.score;
        } catch (const Error&) {
            // A record that does not read back has no scores to compare with: the columns stay empty.
        }
    }
    // Case by case, per TODO, and the history of changes (class_cases.h); per lab for class.csv.
    std::vector<ClassCaseRow> cases = write_class_cases(out_dir, entries);
    for (const ClassCaseRow& r : cases) {
        if (std::find(columns.labs.begin(), columns.labs.end(), r.lab) == columns.labs.end()) columns.labs.push_back(r.lab);
        auto& sum = columns.lab_points[{r.submission, r.lab}];
        sum.first += r.points;
        sum.second += r.max_points;
    }
    std::sort(columns.labs.begin(), columns.labs.end());
    for (const auto& [name, text] : {std::pair{"class.csv", class_csv(entries, columns)}, std::pair{"class.txt", class_table(entries)}}) {
        std::ofstream out(out_dir / name);
        out << text;
        if (!out) throw Error("cannot write '" + (out_dir / name).string() + "'");
    }
    // The class by its mistakes (class_report.h): class-report.html and class-mistakes.csv.
    write_class_report(out_dir, entries);
    return cases;
}

}  // namespace gsv
