#pragma once
// Grades a folder of submissions (one sub-folder each) with N workers: each submission is graded by a
// gsv-grade process of its own into <out>/<name>/, all with the same seed, then one class table. A shard K/N
// grades every N-th name of the class (sorted), so N machines share a class and `gsv-grade merge` joins them.
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace gsv {

// How a batch hands each submission's gsv-grade its seed: an environment variable (not a GSV_ one, which student
// processes inherit), never the command line.
inline constexpr const char* kSeedVariable = "GSVGRADE_SEED";

struct BatchOptions {
    std::filesystem::path grader;       // the gsv-grade executable
    std::filesystem::path submissions;  // one folder per student
    std::filesystem::path out_dir;
    int workers = 2;
    std::uint64_t seed = 0;
    std::vector<std::string> pass_through;  // options given to every submission's run (--kit, --labs, ...)
    int shard = 1, shard_count = 1;         // grade shard K of N (1 <= K <= N)
    // The class: the folder names in `submissions` when empty. With a roster, `submissions` needs to hold only
    // this shard's folders (what a CI job fetched), and a name without a folder is a row "nothing submitted".
    std::vector<std::string> roster;
};

// "K/N" with 1 <= K <= N; throws gsv::Error naming the text otherwise.
std::pair<int, int> parse_shard(const std::string& text);
// The names of shard K of N: every N-th of the sorted, deduplicated class, starting at the K-th.
std::vector<std::string> shard_names(std::vector<std::string> roster, int shard, int shard_count);
// A roster file: one name per line; blank lines and '#' comments skipped; names as folder names allow.
std::vector<std::string> read_roster(const std::filesystem::path& file);

struct BatchEntry {
    std::string name;
    bool graded = false;   // the run ended with a results.json
    double score = 0, max_score = 0;
    double seconds = 0;
    std::string problem;   // why it was not graded
    // Which labs this run graded: "all", or with --regrade-only changed the labs whose inputs changed ("lab03, lab05"),
    // or "none" (every lab's rows kept from the last run).
    std::string regraded = "all";
    // Not graded for the kit's reason, not the submission's (gsv-grade exited kGradeKitFault, or the batch stopped
    // for it): no grade, and the batch fails.
    bool kit_fault = false;
};

// A batch stops starting submissions once this many in a row ended in the kit's fault for the same reason (or all of
// its first ones did): a fault every submission would meet is seen after a few, not after the class.
inline constexpr int kKitFaultsToStop = 3;

// The entries of this shard, in class order; `class_names`, when given, gets the whole class, sorted.
std::vector<BatchEntry> grade_batch(const BatchOptions& options, void (*progress)(const BatchEntry&, int done, int total),
                                    std::vector<std::string>* class_names = nullptr);
// What class.csv adds to the entries: each submission's score in the batch's last run (its batch.json before this one;
// none on a first run) and its points per lab (from class-cases.csv's rows).
struct ClassColumns {
    std::map<std::string, double> previous;
    std::vector<std::string> labs;                                                  // in order
    std::map<std::pair<std::string, std::string>, std::pair<double, double>> lab_points;  // (submission, lab) -> points, max
};
// class.csv: submission,graded,score,max_score,previous_score,changed,<lab>_points,<lab>_max...,seconds,problem,regraded.
// seconds: how long this run took for the submission (a run that kept every lab from the last: its own few seconds);
// regraded: what this run graded ("all", the labs whose inputs changed, or "none").
std::string class_csv(const std::vector<BatchEntry>& entries, const ClassColumns& columns = {});
std::string class_table(const std::vector<BatchEntry>& entries);

}  // namespace gsv
