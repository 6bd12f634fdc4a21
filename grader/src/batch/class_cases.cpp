#include "grader/src/batch/class_cases.h"

#include "common/core/error.h"
#include "common/io/json.h"
#include "grader/src/batch/csv_field.h"

#include <cstdio>
#include <ctime>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

namespace fs = std::filesystem;

namespace gsv {
namespace {

std::string number(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

using RowKey = std::tuple<std::string, std::string, std::string, std::string>;  // submission, lab, check, kind
RowKey key_of(const ClassCaseRow& r) { return {r.submission, r.lab, r.check, r.kind}; }

}  // namespace

std::vector<ClassCaseRow> class_case_rows(const fs::path& out_dir, const std::vector<BatchEntry>& entries) {
    std::vector<ClassCaseRow> rows;
    for (const BatchEntry& e : entries) {
        if (!e.graded) continue;
        const fs::path file = out_dir / e.name / "report.json";
        if (!fs::is_regular_file(file)) {
            // Every graded run writes one; a record put together by hand (or a folder since removed) has none: said, not
            // dropped silently, and the class's other tables still written.
            std::fprintf(stderr, "gsv-grade: %s has no report.json: no case rows for '%s' in class-cases.csv\n",
                         (out_dir / e.name).string().c_str(), e.name.c_str());
            continue;
        }
        const Json report = read_json_file(file);
        for (const Json& r : report.array_at("results").as_array())
            rows.push_back({e.name, r.string_at("lab"), r.string_or("todo", ""), r.string_at("name"), r.string_or("kind", "image"),
                            r.string_at("status"), r.number_or("points", 0), r.number_or("max_points", 0)});
    }
    return rows;
}

std::string class_cases_csv(const std::vector<ClassCaseRow>& rows) {
    std::string out = "submission,lab,todo,check,kind,status,points,max_points\n";
    for (const ClassCaseRow& r : rows)
        out += csv_field(r.submission) + "," + csv_field(r.lab) + "," + csv_field(r.todo) + "," + csv_field(r.check) + "," +
               csv_field(r.kind) + "," + csv_field(r.status) + "," + number(r.points) + "," + number(r.max_points) + "\n";
    return out;
}

std::string class_todos_csv(const std::vector<ClassCaseRow>& rows) {
    // In the class's order: a submission's TODOs in the order its report first names them.
    std::vector<std::tuple<std::string, std::string, std::string>> order;
    std::map<std::tuple<std::string, std::string, std::string>, std::pair<double, double>> sums;
    for (const ClassCaseRow& r : rows) {
        const auto key = std::make_tuple(r.submission, r.lab, r.todo.empty() ? std::string("(demo)") : r.todo);
        if (!sums.count(key)) order.push_back(key);
        sums[key].first += r.points;
        sums[key].second += r.max_points;
    }
    std::string out = "submission,lab,todo,points,max_points\n";
    for (const auto& key : order)
        out += csv_field(std::get<0>(key)) + "," + csv_field(std::get<1>(key)) + "," + csv_field(std::get<2>(key)) + "," +
               number(sums[key].first) + "," + number(sums[key].second) + "\n";
    return out;
}

std::vector<ClassCaseRow> read_class_cases_csv(const fs::path& file) {
    std::vector<ClassCaseRow> rows;
    std::ifstream in(file);
    if (!in) return rows;
    std::string line;
    std::getline(in, line);  // the header
    for (int number = 2; std::getline(in, line); ++number) {
        if (line.empty()) continue;
        const std::vector<std::string> f = csv_record(line);
        if (f.size() != 8) throw Error(file.string() + ":" + std::to_string(number) + ": " + std::to_string(f.size()) + " fields, expected 8");
        try {
            rows.push_back({f[0], f[1], f[2], f[3], f[4], f[5], std::stod(f[6]), std::stod(f[7])});
        } catch (const std::exception&) {
            throw Error(file.string() + ":" + std::to_string(number) + ": points '" + f[6] + "' or '" + f[7] + "' is not a number");
        }
    }
    return rows;
}

std::string history_lines(const std::vector<ClassCaseRow>& before, const std::vector<ClassCaseRow>& now,
                          const std::vector<BatchEntry>& entries, const std::string& when) {
    std::map<RowKey, const ClassCaseRow*> old_rows, new_rows;
    for (const ClassCaseRow& r : before) old_rows[key_of(r)] = &r;
    for (const ClassCaseRow& r : now) new_rows[key_of(r)] = &r;
    std::map<std::string, const BatchEntry*> entry_of;
    for (const BatchEntry& e : entries) entry_of[e.name] = &e;
    const auto why = [&](const std::string& submission, const std::string& lab, bool first) -> std::string {
        const auto it = entry_of.find(submission);
        if (it == entry_of.end() || !it->second->graded) return it == entry_of.end() ? "not in this run" : "not graded: " + it->second->problem;
        if (first) return "first graded";
        const std::string& graded = it->second->regraded;
        if (graded == "all") return "graded again in full (every lab)";
        if (graded.find(lab) != std::string::npos) return lab + " graded again: its inputs changed";
        return "kept from the last run";
    };
    std::string out;
    const auto line = [&](const ClassCaseRow& r, const std::string& old_points, const std::string& new_points, const std::string& reason) {
        out += csv_field(when) + "," + csv_field(r.submission) + "," + csv_field(r.lab) + "," + csv_field(r.check) + "," +
               csv_field(r.kind) + "," + old_points + "," + new_points + "," + number(r.max_points) + "," + csv_field(reason) + "\n";
    };
    for (const ClassCaseRow& r : now) {
        const auto it = old_rows.find(key_of(r));
        if (it == old_rows.end()) {
            line(r, "", number(r.points), why(r.submission, r.lab, true));
        } else if (it->second->points != r.points || it->second->max_points != r.max_points) {
            line(r, number(it->second->points), number(r.points), why(r.submission, r.lab, false));
        }
    }
    for (const ClassCaseRow& r : before)
        if (!new_rows.count(key_of(r))) line(r, number(r.points), "", "no longer graded: " + why(r.submission, r.lab, false));
    return out;
}

std::vector<ClassCaseRow> write_class_cases(const fs::path& out_dir, const std::vector<BatchEntry>& entries) {
    const std::vector<ClassCaseRow> before = read_class_cases_csv(out_dir / "class-cases.csv");
    // A submission this run did not grade (nothing handed in this time, a fault) keeps no rows: the history says so.
    const std::vector<ClassCaseRow> now = class_case_rows(out_dir, entries);
    const auto write = [&](const char* name, const std::string& text, bool append) {
        const fs::path file = out_dir / name;
        const bool fresh = !fs::exists(file);
        std::ofstream out(file, append ? std::ios::app : std::ios::trunc);
        if (append && fresh) out << kHistoryHeader;
        out << text;
        if (!out) throw Error("cannot write '" + file.string() + "'");
    };
    write("class-cases.csv", class_cases_csv(now), false);
    write("class-todos.csv", class_todos_csv(now), false);
    std::time_t t = std::time(nullptr);
    char when[32];
    std::strftime(when, sizeof when, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
    write("history.csv", history_lines(before, now, entries, when), true);
    return now;
}

}  // namespace gsv
