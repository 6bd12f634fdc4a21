// gsv-grade: grades a submission (or the kit's own labs/) headless, prints the score table and writes the
// reports; or grades a folder of submissions with N workers.
#include "common/app/assets.h"
#include "common/context/context.h"
#include "common/core/error.h"
#include "common/core/progress.h"
#include "common/core/version.h"
#include "common/io/json.h"
#include "common/io/output_folder.h"
#include "grader/src/batch/batch.h"
#include "grader/src/batch/batch_merge.h"
#include "grader/src/batch/batch_record.h"
#include "grader/src/cases/draw.h"
#include "grader/src/grade/grade.h"
#include "grader/src/grade/grade_exit.h"
#include "grader/src/report/report.h"
#include "grader/src/report/report_format.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <cstdlib>
#include <regex>
#include <sstream>
#include <unistd.h>

namespace {

const char* kUsage =
    "usage: gsv-grade [--kit DIR] [--bin DIR] [--submission DIR | --batch DIR [--workers N] [--shard K/N] [--roster FILE]]\n"
    "                 [--out DIR]"
    " [--labs lab01,lab02] [--cases gyre,wrap] [--todo L02-T3] [--seed N] [--self-check] [--no-timing]\n"
    "                 [--public-only] [--profile core|es]"
    " [--timeout S] [--fail-under F] [--update-goldens] [--allow-readable-kit] [--no-namespaces]\n"
    "                 [--no-sandbox] [--quiet] [--help] [--version]\n"
    "  --kit DIR         the kit (cases, goldens, hidden cases, solutions); default: the one this was built from\n"
    "  --bin DIR         the kit's built labs and <lab>_solution; default: this build's bin/\n"
    "  --submission DIR  a copy of the kit whose labs/ hold a student's work: built against this kit, then graded\n"
    "  --batch DIR       every folder in DIR is a submission; --workers N grade N at a time (default 2)\n"
    "  --shard K/N       with --batch and --seed: grade every N-th submission (sorted by name) from the K-th, so N\n"
    "                    machines share a class; then gsv-grade merge joins their --out folders\n"
    "  --roster FILE     with --batch: the class, one name per line (default: the folders in DIR); DIR then needs\n"
    "                    only this shard's folders, and a name without one is graded 'nothing submitted'\n"
    "  --out DIR         images and reports: results.json (Gradescope), report.json, junit.xml, report.html\n"
    "  --cases A,B       only these cases (public or hidden names) of the chosen labs: re-check one fix quickly\n"
    "  --todo L02-T3     only the cases of one TODO (its lab's): what the lab sheet's TODO table gives\n"
    "  --seed N          draws the hidden cases; the same seed gives the same cases (default: a fresh one, printed)\n"
    "  --self-check      golden images and public cases only, even where the solutions are built\n"
    "  --no-timing       skip the frame-time checks\n"
    "  --profile P       core (default), compat or es: the profile the student's labs and the references run on; es runs\n"
    "                    each lab at its lowest OpenGL ES version (the self-check still compares with the core goldens)\n"
    "  --public-only     skip the hidden cases\n"
    "  --timeout S       wall-clock limit per student lab process (default: the case file's)\n"
    "  --fail-under F    exit 1 when the score is below F (0..1) of the maximum: a CI gate\n"
    "  --update-goldens  render grader/golden/<lab>/<case>.png (and <case>.<array>.f32s) with the reference solutions\n"
    "  --allow-readable-kit  where the sandbox cannot hide the kit (no namespaces), grade hidden cases and live\n"
    "                    references anyway; without it they are refused there, and the report says which walls were up\n"
    "  --no-namespaces   every wall but the namespaces: how the grader behaves where unshare is refused\n"
    "  --no-sandbox      run student code without namespaces and limits (to debug the grader only)\n"
    "       gsv-grade merge OUT SHARD_OUT...  the --out folders of a batch's shards joined into OUT (new or empty):\n"
    "                    the per-submission folders, class.csv, class.txt, batch.json; refused when the shards were\n"
    "                    graded with other seeds, kits, labs or options, overlap, or one is missing\n"
    "       gsv-grade shard K/N ROSTER       the names of shard K of N of a roster file, one a line (what to fetch)\n"
    "exit status: 0 graded (whatever the score), 1 under --fail-under, 2 usage or internal error\n";

bool quiet = false;

void print_progress(const gsv::GradeProgress& p) {
    if (quiet) return;
    if (!p.result) {
        std::fprintf(stderr, "%s...\n", p.stage.c_str());
        return;
    }
    const gsv::CaseResult& r = *p.result;
    const std::string name = r.lab + "/" + r.name + (r.kind == "timing" ? " [time]" : "");
    std::fprintf(stderr, "[%2d/%2d] %-32s %-14s %5.2f s\n", p.done, p.total, name.c_str(), gsv::status_name(r.status),
                 r.seconds);
}

std::chrono::steady_clock::time_point batch_start;

// One line per submission, whether or not stderr is a terminal: each names a student's result.
void print_batch_progress(const gsv::BatchEntry& e, int done, int total) {
    const std::string result = e.graded ? gsv::format_points(e.score) + " / " + gsv::format_points(e.max_score) : e.problem;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - batch_start).count();
    std::fprintf(stderr, "%s\n", gsv::progress_text(done, total, e.name + ": " + gsv::one_line(result, 200), elapsed).c_str());
}

void write_failure_results(const std::filesystem::path& out_dir, const std::string& why) {
    std::error_code ec;
    std::filesystem::create_directories(out_dir, ec);
    gsv::Json root = gsv::Json::object();
    root["score"] = 0;
    root["output"] = "The submission could not be graded: " + why;
    root["tests"] = gsv::Json::array();
    std::ofstream(out_dir / "results.json") << root.dump(2) << "\n";
}

std::uint64_t parse_seed(const std::string& text) {
    std::size_t used = 0;
    unsigned long long value = 0;
    try {
        value = std::stoull(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || text.empty() || text[0] == '-') throw gsv::Error("--seed needs a whole number, got '" + text + "'");
    return value;
}

// gsv-grade merge OUT SHARD_OUT... and gsv-grade shard K/N ROSTER.
int merge_main(int argc, char** argv) {
    if (argc < 4) throw gsv::Error("needs OUT and at least one shard's output folder: gsv-grade merge OUT SHARD_OUT...");
    std::vector<std::filesystem::path> shards(argv + 3, argv + argc);
    const gsv::BatchRecord merged = gsv::merge_shards(shards, argv[2]);
    std::printf("%s", gsv::class_table(merged.entries).c_str());
    std::printf("%zu shards merged: per-submission reports in %s/<name>/, the class in %s/class.csv\n", shards.size(), argv[2], argv[2]);
    return gsv::kGradeOk;
}

int shard_main(int argc, char** argv) {
    if (argc != 4) throw gsv::Error("needs K/N and a roster file: gsv-grade shard K/N ROSTER");
    const auto [k, n] = gsv::parse_shard(argv[2]);
    for (const std::string& name : gsv::shard_names(gsv::read_roster(argv[3]), k, n)) std::printf("%s\n", name.c_str());
    return gsv::kGradeOk;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 1 && (std::string(argv[1]) == "merge" || std::string(argv[1]) == "shard")) {
        try {
            return std::string(argv[1]) == "merge" ? merge_main(argc, argv) : shard_main(argc, argv);
        } catch (const gsv::Error& e) {
            std::fprintf(stderr, "gsv-grade %s: %s\n", argv[1], e.what());
            return gsv::kGradeNotGraded;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "gsv-grade %s: internal error: %s\n", argv[1], e.what());
            return gsv::kGradeNotGraded;
        }
    }
    gsv::GradeOptions options;
    options.kit_root = GSV_SOURCE_ROOT;
    options.bin_dir = GSV_BIN_DIR;
    options.out_dir = "grade-results";
    double fail_under = -1;
    std::filesystem::path batch;
    int workers = 2;
    std::string shard;                 // K/N, checked once every option is read
    std::filesystem::path roster;
    std::vector<std::string> pass_through;  // what each batch run gets too
    try {
        for (int i = 1; i < argc; ++i) {
            const std::string a = argv[i];
            auto value = [&]() -> std::string {
                if (i + 1 >= argc) throw gsv::Error("option " + a + " needs a value");
                return argv[++i];
            };
            auto number = [&](double lo, double hi) {
                const std::string text = value();
                char* end = nullptr;
                const double v = std::strtod(text.c_str(), &end);
                if (text.empty() || *end != '\0' || !(v >= lo && v <= hi))
                    throw gsv::Error(a + " needs a number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got '" + text + "'");
                return v;
            };
            if (a == "--kit") { options.kit_root = value(); pass_through.insert(pass_through.end(), {a, std::filesystem::absolute(options.kit_root).string()}); }
            else if (a == "--bin") { options.bin_dir = value(); pass_through.insert(pass_through.end(), {a, std::filesystem::absolute(options.bin_dir).string()}); }
            else if (a == "--submission") options.submission = value();
            else if (a == "--batch") batch = value();
            else if (a == "--workers") workers = static_cast<int>(number(1, 256));
            else if (a == "--shard") shard = value();
            else if (a == "--roster") roster = value();
            else if (a == "--out") options.out_dir = value();
            else if (a == "--labs") {
                const std::string list = value();
                pass_through.insert(pass_through.end(), {a, list});
                std::stringstream items(list);
                for (std::string lab; std::getline(items, lab, ',');) options.labs.push_back(lab);
            } else if (a == "--cases") {
                const std::string list = value();
                pass_through.insert(pass_through.end(), {a, list});
                std::stringstream items(list);
                for (std::string name; std::getline(items, name, ',');) options.cases.push_back(name);
            } else if (a == "--seed") options.seed = parse_seed(value());
            else if (a == "--self-check") { options.self_check = true; pass_through.push_back(a); }
            else if (a == "--no-timing") { options.timing = false; pass_through.push_back(a); }
            else if (a == "--public-only") { options.hidden = false; pass_through.push_back(a); }
            else if (a == "--no-sandbox") { options.sandbox = false; pass_through.push_back(a); }
            else if (a == "--allow-readable-kit") { options.allow_readable_kit = true; pass_through.push_back(a); }
            else if (a == "--no-namespaces") { options.namespaces = false; pass_through.push_back(a); }
            else if (a == "--todo") {
                options.todo = value();
                static const std::regex id(R"(^L[0-9]{2}-T[0-9]+$)");
                if (!std::regex_match(options.todo, id)) throw gsv::Error("--todo needs a TODO id like L02-T3, got '" + options.todo + "'");
                pass_through.insert(pass_through.end(), {a, options.todo});
            }
            else if (a == "--sandbox-uid") options.sandbox_uid = static_cast<unsigned>(number(1000, 4000000000.0));
            else if (a == "--timeout") { options.timeout_s = number(0.1, 3600); pass_through.insert(pass_through.end(), {a, std::to_string(options.timeout_s)}); }
            else if (a == "--update-goldens") options.update_goldens = true;
            else if (a == "--profile") {
                options.profile = gsv::parse_profile(value());
                pass_through.insert(pass_through.end(), {a, gsv::profile_name(options.profile)});
            }
            else if (a == "--fail-under") fail_under = number(0, 1);
            else if (a == "--quiet") quiet = true;
            else if (a == "-h" || a == "--help") {
                std::printf("%s", kUsage);
                return gsv::kGradeOk;
            } else if (a == "--version") {
                std::printf("%s\n", gsv::version_line("gsv-grade").c_str());
                return gsv::kGradeOk;
            } else throw gsv::Error("unknown option '" + a + "' (see --help)");
        }
        if (const char* seed = std::getenv(gsv::kSeedVariable); seed && !options.seed) options.seed = parse_seed(seed);
        if (options.update_goldens && options.profile != gsv::Profile::Core)
            throw gsv::Error("--update-goldens renders the goldens on the core profile; drop --profile " +
                             std::string(gsv::profile_name(options.profile)));
        if (batch.empty() && !shard.empty()) throw gsv::Error("--shard " + shard + " needs --batch DIR");
        if (batch.empty() && !roster.empty()) throw gsv::Error("--roster needs --batch DIR");
        // Before any build or lab runs: a grading that cannot write its reports says so first (a batch once its
        // command line is known good, so that a refused one leaves no folder behind).
        if (batch.empty()) gsv::prepare_output_folder(options.out_dir, "--out");
        if (!batch.empty()) {
            if (!options.submission.empty()) throw gsv::Error("--batch and --submission exclude each other");
            const auto [shard_k, shard_n] = shard.empty() ? std::pair{1, 1} : gsv::parse_shard(shard);
            // Each shard would draw a fresh seed of its own: other hidden cases on every machine.
            if (!shard.empty() && !options.seed)
                throw gsv::Error("--shard " + shard + " needs --seed N: every shard must draw the same hidden cases");
            gsv::BatchOptions b;
            b.grader = gsv::Assets::executable_path(argv[0]);
            b.submissions = batch;
            b.out_dir = options.out_dir;
            b.workers = workers;
            b.seed = options.seed ? *options.seed : gsv::fresh_seed();
            b.pass_through = pass_through;
            b.shard = shard_k;
            b.shard_count = shard_n;
            if (!roster.empty()) b.roster = gsv::read_roster(roster);
            gsv::prepare_output_folder(options.out_dir, "--out");
            gsv::BatchRecord record;
            record.seed = b.seed;
            record.shard = shard_k;
            record.shard_count = shard_n;
            record.kit = gsv::kit_fingerprint(options.kit_root);
            record.options = gsv::recorded_options(pass_through);
            std::fprintf(stderr, "grading the submissions in %s%s with %d workers, seed %llu\n", batch.c_str(),
                         shard.empty() ? "" : (", shard " + shard).c_str(), workers, static_cast<unsigned long long>(b.seed));
            batch_start = std::chrono::steady_clock::now();
            record.entries = gsv::grade_batch(b, print_batch_progress, &record.roster);
            std::printf("%s", gsv::class_table(record.entries).c_str());
            gsv::write_class_tables(record.entries, options.out_dir);
            gsv::write_batch_record(record, options.out_dir);
            std::printf("per-submission reports in %s/<name>/, the class in %s/class.csv\n", options.out_dir.c_str(), options.out_dir.c_str());
            return gsv::kGradeOk;
        }
        const gsv::GradeReport report = gsv::grade(options, print_progress);
        if (options.update_goldens) {
            int failed = 0;
            for (const auto& r : report.results)
                if (r.status != gsv::CaseStatus::Passed) {
                    std::fprintf(stderr, "gsv-grade: %s/%s: %s\n%s\n", r.lab.c_str(), r.name.c_str(), r.detail.c_str(), r.output.c_str());
                    ++failed;
                }
            std::printf("updated the goldens of %zu cases, %d failed\n", report.results.size() - static_cast<std::size_t>(failed), failed);
            return failed ? gsv::kGradeFailed : gsv::kGradeOk;
        }
        gsv::write_reports(report, options.out_dir);
        if (!quiet) {
            std::printf("%s", gsv::score_table(report).c_str());
            std::printf("reports (report.html, junit.xml, results.json, report.json) and images in %s\n", options.out_dir.c_str());
        }
        // A reference that failed is the kit's fault: no grade rests on it.
        const auto kit_faults = std::count_if(report.results.begin(), report.results.end(),
                                              [](const gsv::CaseResult& r) { return gsv::is_kit_fault(r.status); });
        if (kit_faults > 0) {
            std::fprintf(stderr, "gsv-grade: the reference failed on %ld checks (marked 'reference failed'): fix the kit before "
                                 "grading; no grade was given\n", static_cast<long>(kit_faults));
            return gsv::kGradeNotGraded;
        }
        if (fail_under >= 0 && report.max_score() > 0 && report.score() < fail_under * report.max_score()) {
            std::fprintf(stderr, "gsv-grade: score %.1f / %.1f is under --fail-under %.2f\n", report.score(), report.max_score(), fail_under);
            return gsv::kGradeFailed;
        }
        return gsv::kGradeOk;
    } catch (const gsv::Error& e) {
        std::fprintf(stderr, "gsv-grade: %s\n", e.what());
        // A submission that could not be graded at all still gets a results.json saying why (Gradescope
        // shows it to the student); an internal error leaves one for the instructor too.
        if (!options.submission.empty() && batch.empty()) write_failure_results(options.out_dir, e.what());
        return gsv::kGradeNotGraded;
    } catch (const std::filesystem::filesystem_error& e) {
        // A folder or file the grader could not read or write: the user's to fix, named in the message.
        std::fprintf(stderr, "gsv-grade: %s\n", e.what());
        return gsv::kGradeNotGraded;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "gsv-grade: internal error: %s\n", e.what());
        return gsv::kGradeNotGraded;
    }
}
