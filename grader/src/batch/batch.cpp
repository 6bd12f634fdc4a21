#include "grader/src/batch/batch.h"

#include "common/core/error.h"
#include "common/io/json.h"
#include "grader/src/grade/grade_exit.h"
#include "grader/src/report/report_format.h"
#include "grader/src/run/process.h"
#include "grader/src/run/sandbox.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <mutex>
#include <regex>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;

namespace gsv {

std::pair<int, int> parse_shard(const std::string& text) {
    static const std::regex form(R"(^([0-9]{1,6})/([0-9]{1,6})$)");
    std::smatch m;
    if (!std::regex_match(text, m, form)) throw Error("--shard needs K/N (shard K of N, e.g. 2/8), got '" + text + "'");
    const int k = std::stoi(m[1]), n = std::stoi(m[2]);
    if (n < 1) throw Error("--shard " + text + ": N (the number of shards) must be at least 1");
    if (k < 1 || k > n) throw Error("--shard " + text + ": K must be in 1.." + std::to_string(n));
    return {k, n};
}

std::vector<std::string> shard_names(std::vector<std::string> roster, int shard, int shard_count) {
    std::sort(roster.begin(), roster.end());
    roster.erase(std::unique(roster.begin(), roster.end()), roster.end());
    std::vector<std::string> mine;
    for (std::size_t i = static_cast<std::size_t>(shard - 1); i < roster.size(); i += static_cast<std::size_t>(shard_count))
        mine.push_back(roster[i]);
    return mine;
}

std::vector<std::string> read_roster(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) throw Error("cannot read the roster '" + file.string() + "'");
    std::vector<std::string> names;
    int line_number = 0;
    for (std::string line; std::getline(in, line);) {
        ++line_number;
        line.erase(std::find_if(line.rbegin(), line.rend(), [](unsigned char c) { return !std::isspace(c); }).base(), line.end());
        line.erase(line.begin(), std::find_if(line.begin(), line.end(), [](unsigned char c) { return !std::isspace(c); }));
        if (line.empty() || line[0] == '#') continue;
        // A name becomes a folder under --out and a quoted CSV field: nothing that could leave either.
        const bool bad_char = std::any_of(line.begin(), line.end(), [](unsigned char c) { return c < 0x20 || c == '/' || c == '"' || c == 0x7f; });
        if (bad_char || line[0] == '.')
            throw Error(file.string() + ":" + std::to_string(line_number) + ": '" + line + "' is not a submission folder name");
        names.push_back(line);
    }
    if (names.empty()) throw Error("the roster '" + file.string() + "' names no submissions");
    return names;
}

std::vector<BatchEntry> grade_batch(const BatchOptions& options, void (*progress)(const BatchEntry&, int, int),
                                    std::vector<std::string>* class_names) {
    if (!fs::is_directory(options.submissions)) throw Error("no folder of submissions '" + options.submissions.string() + "'");
    std::vector<std::string> roster = options.roster;
    if (roster.empty()) {
        for (const auto& e : fs::directory_iterator(options.submissions))
            if (e.is_directory() && e.path().filename().string()[0] != '.') roster.push_back(e.path().filename().string());
        if (roster.empty()) throw Error("'" + options.submissions.string() + "' holds no submission folders");
    }
    std::sort(roster.begin(), roster.end());
    roster.erase(std::unique(roster.begin(), roster.end()), roster.end());
    if (class_names) *class_names = roster;
    const std::vector<std::string> names = shard_names(roster, options.shard, options.shard_count);
    fs::create_directories(options.out_dir);

    std::vector<BatchEntry> entries(names.size());
    std::atomic<std::size_t> next{0};
    std::mutex report_mutex;
    int done = 0;
    // The kit's fault seen again and again: the submissions not started yet are left, saying why.
    std::string stopped_for, last_fault;
    int faults_in_a_row = 0, faults = 0, clean = 0;
    auto worker = [&] {
        for (std::size_t i = next++; i < names.size(); i = next++) {
            BatchEntry& entry = entries[i];
            entry.name = names[i];
            {
                std::lock_guard<std::mutex> lock(report_mutex);
                if (!stopped_for.empty()) {
                    entry.kit_fault = true;
                    entry.problem = "not graded: the batch stopped: " + stopped_for;
                    ++done;
                    if (progress) progress(entry, done, static_cast<int>(names.size()));
                    continue;
                }
            }
            const fs::path folder = options.submissions / entry.name;
            const fs::path out = fs::absolute(options.out_dir) / entry.name;
            if (!fs::is_directory(folder)) {
                entry.problem = "nothing submitted (no folder '" + entry.name + "')";
                std::lock_guard<std::mutex> lock(report_mutex);
                ++done;
                if (progress) progress(entry, done, static_cast<int>(names.size()));
                continue;
            }
            // The seed goes through the environment, not the command line that /proc shows every process. Each run
            // leases a uid of its own for its student code (grader/src/run/uid_lease.h), from the same locks as every
            // other grader on the machine, so no two submissions, shards or batches share one.
            std::vector<std::string> argv{options.grader.string(), "--submission", fs::absolute(folder).string(),
                                          "--out", out.string(), "--quiet"};
            argv.insert(argv.end(), options.pass_through.begin(), options.pass_through.end());
            ProcessLimits limits;
            limits.timeout = std::chrono::hours(1);
            limits.max_output_bytes = 16 * 1024;
            const ProcessResult run =
                run_process(argv, fs::current_path(), limits, {std::string(kSeedVariable) + "=" + std::to_string(options.seed)});
            entry.seconds = run.seconds;
            try {
                if (run.exit_code == kGradeKitFault) {
                    entry.kit_fault = true;
                    // gsv-grade's own line says what is wrong with the kit and how to fix it.
                    std::string line = run.output.substr(0, run.output.find('\n'));
                    if (line.rfind("gsv-grade: ", 0) == 0) line.erase(0, 11);
                    throw Error(line.empty() ? "the kit's fault (gsv-grade said nothing more)" : line);
                }
                if (run.exit_code == kGradeNotGraded || run.signal != 0 || run.timed_out)
                    throw Error(run.timed_out ? "timed out" : "gsv-grade failed: " + run.output.substr(0, 300));
                const Json results = read_json_file(out / "results.json");
                entry.score = results.number_at("score");
                for (const Json& t : results.array_at("tests").as_array()) entry.max_score += t.number_at("max_score");
                entry.graded = true;
                // --regrade-only changed: which labs were graded again (grader/src/grade/regrade.h).
                const Json report = fs::exists(out / "report.json") ? read_json_file(out / "report.json") : Json::object();
                if (const Json* kept = report.find("kept"); kept && kept->size() > 0) {
                    entry.regraded.clear();
                    for (const Json& lab : report.array_at("regraded").as_array())
                        entry.regraded += (entry.regraded.empty() ? "" : ", ") + lab.as_string();
                    if (entry.regraded.empty()) entry.regraded = "none";
                }
            } catch (const Error& e) {
                entry.problem = e.what();
            }
            std::lock_guard<std::mutex> lock(report_mutex);
            if (entry.kit_fault) {
                faults_in_a_row = entry.problem == last_fault ? faults_in_a_row + 1 : 1;
                last_fault = entry.problem;
                ++faults;
                if (faults_in_a_row >= kKitFaultsToStop || (clean == 0 && faults >= kKitFaultsToStop))
                    stopped_for = std::to_string(clean == 0 ? faults : faults_in_a_row) +
                                  " submissions in a row failed for the kit's reason: " + entry.problem;
            } else {
                faults_in_a_row = 0;
                ++clean;
            }
            ++done;
            if (progress) progress(entry, done, static_cast<int>(names.size()));
        }
    };
    std::vector<std::thread> pool;
    for (int w = 0; w < std::max(1, options.workers); ++w) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
    return entries;
}

std::string class_csv(const std::vector<BatchEntry>& entries, const ClassColumns& columns) {
    std::ostringstream out;
    out << "submission,graded,score,max_score,previous_score,changed";
    for (const auto& lab : columns.labs) out << "," << lab << "_points," << lab << "_max";
    out << ",seconds,problem,regraded\n";
    for (const auto& e : entries) {
        std::string problem = e.problem;
        std::replace(problem.begin(), problem.end(), '"', '\'');
        std::replace(problem.begin(), problem.end(), '\n', ' ');
        char line[128];
        std::snprintf(line, sizeof line, ",%s,%g,%g,", e.graded ? "yes" : "no", e.score, e.max_score);
        out << '"' << e.name << '"' << line;
        const auto previous = columns.previous.find(e.name);
        if (previous != columns.previous.end()) {
            std::snprintf(line, sizeof line, "%g,%s", previous->second, previous->second != e.score ? "yes" : "no");
            out << line;
        } else {
            out << ",";  // a first run, or new to the class: nothing to compare with
        }
        for (const auto& lab : columns.labs) {
            const auto it = columns.lab_points.find({e.name, lab});
            if (it == columns.lab_points.end()) {
                out << ",,";
                continue;
            }
            std::snprintf(line, sizeof line, ",%g,%g", it->second.first, it->second.second);
            out << line;
        }
        std::snprintf(line, sizeof line, ",%.1f,", e.seconds);
        out << line << '"' << problem << "\",\"" << (e.graded ? e.regraded : "") << "\"\n";
    }
    return out.str();
}

std::string class_table(const std::vector<BatchEntry>& entries) {
    std::ostringstream out;
    char line[512];
    // The regraded column only where some submission kept rows from the last run.
    const bool regrade = std::any_of(entries.begin(), entries.end(), [](const BatchEntry& e) { return e.graded && e.regraded != "all"; });
    std::snprintf(line, sizeof line, "%-24s %12s %8s  %s\n", "submission", "score", "seconds", regrade ? "regraded / problem" : "problem");
    out << line;
    for (const auto& e : entries) {
        const std::string score = e.graded ? format_points(e.score) + " / " + format_points(e.max_score) : "-";
        const std::string last = e.graded ? (regrade ? e.regraded : "") : e.problem;
        std::snprintf(line, sizeof line, "%-24s %12s %8.1f  %s\n", e.name.c_str(), score.c_str(), e.seconds, last.substr(0, 80).c_str());
        out << line;
    }
    return out.str();
}

}  // namespace gsv
