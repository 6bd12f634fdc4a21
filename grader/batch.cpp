#include "grader/batch.h"

#include "common/core/error.h"
#include "common/io/json.h"
#include "grader/process.h"
#include "grader/report_format.h"
#include "grader/sandbox.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <mutex>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;

namespace gsv {

std::vector<BatchEntry> grade_batch(const BatchOptions& options, void (*progress)(const BatchEntry&, int, int)) {
    if (!fs::is_directory(options.submissions)) throw Error("no folder of submissions '" + options.submissions.string() + "'");
    std::vector<fs::path> folders;
    for (const auto& e : fs::directory_iterator(options.submissions))
        if (e.is_directory() && e.path().filename().string()[0] != '.') folders.push_back(e.path());
    std::sort(folders.begin(), folders.end());
    if (folders.empty()) throw Error("'" + options.submissions.string() + "' holds no submission folders");
    fs::create_directories(options.out_dir);

    std::vector<BatchEntry> entries(folders.size());
    std::atomic<std::size_t> next{0};
    std::mutex report_mutex;
    int done = 0;
    auto worker = [&] {
        for (std::size_t i = next++; i < folders.size(); i = next++) {
            BatchEntry& entry = entries[i];
            entry.name = folders[i].filename().string();
            const fs::path out = fs::absolute(options.out_dir) / entry.name;
            // The seed goes through the environment, not the command line that /proc shows every process; each
            // submission runs as a uid of its own, so one cannot read or signal another's files or processes.
            std::vector<std::string> argv{options.grader.string(), "--submission", fs::absolute(folders[i]).string(),
                                          "--out", out.string(), "--quiet",
                                          "--sandbox-uid", std::to_string(kSandboxUidBase + 1 + i)};
            argv.insert(argv.end(), options.pass_through.begin(), options.pass_through.end());
            ProcessLimits limits;
            limits.timeout = std::chrono::hours(1);
            limits.max_output_bytes = 16 * 1024;
            const ProcessResult run =
                run_process(argv, fs::current_path(), limits, {std::string(kSeedVariable) + "=" + std::to_string(options.seed)});
            entry.seconds = run.seconds;
            try {
                if (run.exit_code == 2 || run.signal != 0 || run.timed_out)
                    throw Error(run.timed_out ? "timed out" : "gsv-grade failed: " + run.output.substr(0, 300));
                const Json results = read_json_file(out / "results.json");
                entry.score = results.number_at("score");
                for (const Json& t : results.array_at("tests").as_array()) entry.max_score += t.number_at("max_score");
                entry.graded = true;
            } catch (const Error& e) {
                entry.problem = e.what();
            }
            std::lock_guard<std::mutex> lock(report_mutex);
            ++done;
            if (progress) progress(entry, done, static_cast<int>(folders.size()));
        }
    };
    std::vector<std::thread> pool;
    for (int w = 0; w < std::max(1, options.workers); ++w) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
    return entries;
}

std::string class_csv(const std::vector<BatchEntry>& entries) {
    std::ostringstream out;
    out << "submission,graded,score,max_score,seconds,problem\n";
    for (const auto& e : entries) {
        std::string problem = e.problem;
        std::replace(problem.begin(), problem.end(), '"', '\'');
        std::replace(problem.begin(), problem.end(), '\n', ' ');
        char line[128];
        std::snprintf(line, sizeof line, ",%s,%g,%g,%.1f,", e.graded ? "yes" : "no", e.score, e.max_score, e.seconds);
        out << '"' << e.name << '"' << line << '"' << problem << "\"\n";
    }
    return out.str();
}

std::string class_table(const std::vector<BatchEntry>& entries) {
    std::ostringstream out;
    char line[512];
    std::snprintf(line, sizeof line, "%-24s %12s %8s  %s\n", "submission", "score", "seconds", "problem");
    out << line;
    for (const auto& e : entries) {
        const std::string score = e.graded ? format_points(e.score) + " / " + format_points(e.max_score) : "-";
        std::snprintf(line, sizeof line, "%-24s %12s %8.1f  %s\n", e.name.c_str(), score.c_str(), e.seconds,
                      e.graded ? "" : e.problem.substr(0, 80).c_str());
        out << line;
    }
    return out.str();
}

}  // namespace gsv
