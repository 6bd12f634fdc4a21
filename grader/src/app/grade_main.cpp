// gsv-grade: grades a submission (or the kit's own labs/) headless, prints the score table and writes the
// reports; or grades a folder of submissions with N workers; or rewrites the goldens. Its command line is read in
// grade_command.cpp.
#include "common/app/assets.h"
#include "common/core/error.h"
#include "common/core/progress.h"
#include "common/core/version.h"
#include "common/io/json.h"
#include "common/io/output_folder.h"
#include "grader/src/app/grade_command.h"
#include "grader/src/batch/batch.h"
#include "grader/src/batch/batch_merge.h"
#include "grader/src/batch/class_report.h"
#include "grader/src/batch/batch_record.h"
#include "grader/src/cases/draw.h"
#include "grader/src/update/golden_update.h"
#include "grader/src/update/mistake_update.h"
#include "grader/src/grade/grade.h"
#include "grader/src/grade/grade_exit.h"
#include "grader/src/run/kit_fault.h"
#include "grader/src/grade/regrade.h"
#include "grader/src/lms/export_command.h"
#include "grader/src/report/report.h"
#include "grader/src/report/report_format.h"
#include "grader/src/similarity/similarity_command.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace {

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

// gsv-grade mistake-skeleton OUT CLUSTER: an entry for tests/mutants/<lab>.json from a cluster of the class report.
int skeleton_main(int argc, char** argv) {
    if (argc != 4) throw gsv::Error("needs a batch's --out and a cluster of its class report: gsv-grade mistake-skeleton OUT lab01/gooch/1");
    std::printf("%s", gsv::mistake_skeleton(argv[2], argv[3]).c_str());
    return gsv::kGradeOk;
}

// `gsv-grade merge ...`, `gsv-grade shard ...` and `gsv-grade mistake-skeleton ...`.
int run_subcommand(int argc, char** argv) {
    try {
        const std::string which = argv[1];
        return which == "merge" ? merge_main(argc, argv) : which == "shard" ? shard_main(argc, argv) : skeleton_main(argc, argv);
    } catch (const gsv::Error& e) {
        std::fprintf(stderr, "gsv-grade %s: %s\n", argv[1], e.what());
        return gsv::kGradeNotGraded;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "gsv-grade %s: internal error: %s\n", argv[1], e.what());
        return gsv::kGradeNotGraded;
    }
}

// --batch DIR: each submission by a gsv-grade of its own, then the class's tables and the record `merge` reads.
int grade_class(const gsv::GradeCommand& command, const char* argv0) {
    const gsv::GradeOptions& options = command.options;
    const std::string& shard = command.shard;
    if (!options.submission.empty()) throw gsv::Error("--batch and --submission exclude each other");
    const auto [shard_k, shard_n] = shard.empty() ? std::pair{1, 1} : gsv::parse_shard(shard);
    // Each shard would draw a fresh seed of its own: other hidden cases on every machine.
    if (!shard.empty() && !options.seed)
        throw gsv::Error("--shard " + shard + " needs --seed N: every shard must draw the same hidden cases");
    gsv::BatchOptions b;
    b.grader = gsv::Assets::executable_path(argv0);
    b.submissions = command.batch;
    b.out_dir = options.out_dir;
    b.workers = command.workers;
    b.seed = options.seed ? *options.seed : gsv::fresh_seed();
    b.pass_through = command.pass_through;
    // A class's folders stay small (grader/README.md, "What a class leaves on disk"): a passed case's pictures as a
    // thumbnail, no submission's binaries; either can be asked for.
    if (!command.passed_pictures_given) b.pass_through.insert(b.pass_through.end(), {"--passed-pictures", "thumbnail"});
    if (!command.keep_build_given) b.pass_through.insert(b.pass_through.end(), {"--keep-build", "no"});
    b.shard = shard_k;
    b.shard_count = shard_n;
    if (!command.roster.empty()) b.roster = gsv::read_roster(command.roster);
    gsv::prepare_output_folder(options.out_dir, "--out");
    gsv::BatchRecord record;
    record.seed = b.seed;
    record.shard = shard_k;
    record.shard_count = shard_n;
    record.kit = gsv::kit_fingerprint(options.kit_root);
    record.options = gsv::recorded_options(command.pass_through);
    std::fprintf(stderr, "grading the submissions in %s%s with %d workers, seed %llu\n", command.batch.c_str(),
                 shard.empty() ? "" : (", shard " + shard).c_str(), command.workers, static_cast<unsigned long long>(b.seed));
    batch_start = std::chrono::steady_clock::now();
    record.entries = gsv::grade_batch(b, print_batch_progress, &record.roster);
    std::printf("%s", gsv::class_table(record.entries).c_str());
    gsv::write_batch_record(record, options.out_dir, gsv::write_class_tables(record.entries, options.out_dir));
    std::printf("per-submission reports in %s/<name>/, the class in %s/class.csv\n", options.out_dir.c_str(), options.out_dir.c_str());
    // The kit's fault is no student's 0: the run says what is wrong and fails, so the grades are not taken as given.
    const auto kit_faults = std::count_if(record.entries.begin(), record.entries.end(), [](const gsv::BatchEntry& e) { return e.kit_fault; });
    if (kit_faults > 0) {
        const auto first = std::find_if(record.entries.begin(), record.entries.end(), [](const gsv::BatchEntry& e) { return e.kit_fault; });
        std::fprintf(stderr, "gsv-grade: %ld of %zu submissions were not graded for the kit's reason, not theirs (%s); fix it and grade "
                             "them again\n", static_cast<long>(kit_faults), record.entries.size(), first->problem.c_str());
        return gsv::kGradeKitFault;
    }
    return gsv::kGradeOk;
}

// --update-mistakes: a line per lab.
int rewrite_mistakes(const gsv::GradeCommand& command) {
    const gsv::GradeReport report = gsv::update_mistake_pictures(command.options, print_progress);
    int failed = 0;
    for (const auto& r : report.results) {
        std::fprintf(r.status == gsv::CaseStatus::Passed ? stdout : stderr, "%s: %s\n", r.lab.c_str(), r.detail.c_str());
        failed += r.status != gsv::CaseStatus::Passed;
    }
    return failed ? gsv::kGradeFailed : gsv::kGradeOk;
}

// --update-goldens: a line for each golden the reference did not render.
int rewrite_goldens(const gsv::GradeCommand& command) {
    const gsv::GradeReport report = gsv::update_goldens(command.options, print_progress);
    int failed = 0;
    for (const auto& r : report.results)
        if (r.status != gsv::CaseStatus::Passed) {
            std::fprintf(stderr, "gsv-grade: %s/%s: %s\n%s\n", r.lab.c_str(), r.name.c_str(), r.detail.c_str(), r.output.c_str());
            ++failed;
        }
    std::printf("updated the goldens of %zu cases, %d failed\n", report.results.size() - static_cast<std::size_t>(failed), failed);
    return failed ? gsv::kGradeFailed : gsv::kGradeOk;
}

// The run, or with --regrade-only changed only the labs whose inputs changed since the last run in --out, merged
// with that run's rows of the others (grader/src/grade/regrade.h). Every run records its labs' inputs for the next.
gsv::GradeReport grade_changed(const gsv::GradeCommand& command, const char* argv0) {
    gsv::GradeOptions options = command.options;
    if (command.regrade_only_changed && !options.seed) {
        // The same hidden cases as the last run, where no seed is given.
        try {
            options.seed = gsv::read_report_json(options.out_dir / "report.json").seed;
        } catch (const gsv::Error&) {
        }
    }
    if (!options.seed) options.seed = gsv::fresh_seed();
    const std::vector<std::string> labs = gsv::labs_of_run(options);
    const gsv::LabInputs inputs = gsv::lab_inputs(options, labs, *options.seed, gsv::Assets::executable_path(argv0));
    gsv::GradeReport report;
    if (!command.regrade_only_changed) {
        report = gsv::grade(options, print_progress);
    } else {
        const gsv::RegradePlan plan = gsv::plan_regrade(options.out_dir, inputs);
        if (!plan.note.empty()) std::fprintf(stderr, "gsv-grade: --regrade-only changed: %s\n", plan.note.c_str());
        if (!plan.earlier) {
            report = gsv::grade(options, print_progress);
            report.regraded = labs;
        } else if (plan.regrade.empty()) {
            report = *plan.earlier;
            report.regraded.clear();
            report.kept = plan.keep;
        } else if (const std::optional<gsv::GradeOptions> regrade = gsv::options_for_regrade(options, plan)) {
            report = gsv::merge_regraded(*plan.earlier, gsv::grade(*regrade, print_progress), plan, labs);
        } else {
            // None of the asked cases is in the labs to regrade: nothing of them to grade.
            report = gsv::merge_regraded(*plan.earlier, *plan.earlier, plan, labs);
        }
    }
    gsv::write_reports(report, options.out_dir,
                       options.passed_pictures == gsv::PassedPictures::Thumbnail ? gsv::InstructorPictures::LinkedThumbnails
                                                                                : gsv::InstructorPictures::Whole);
    gsv::write_lab_inputs(options.out_dir, inputs);
    return report;
}

// One submission, or the kit's own labs/: the reports, the table, and the exit status a CI gate reads.
int grade_one(const gsv::GradeCommand& command, const char* argv0) {
    const gsv::GradeOptions& options = command.options;
    const gsv::GradeReport report = grade_changed(command, argv0);
    if (!quiet) {
        std::printf("%s", gsv::score_table(report).c_str());
        std::printf("reports (report.html, junit.xml, results.json, report.json) and images in %s\n", options.out_dir.c_str());
    }
    // A reference that failed is the kit's fault: no grade rests on it.
    const auto kit_faults = std::count_if(report.results.begin(), report.results.end(),
                                          [](const gsv::CaseResult& r) { return gsv::is_kit_fault(r.status); });
    if (kit_faults > 0) {
        const auto first = std::find_if(report.results.begin(), report.results.end(),
                                        [](const gsv::CaseResult& r) { return gsv::is_kit_fault(r.status); });
        std::fprintf(stderr, "gsv-grade: the kit's fault, not the student's, on %ld checks (marked '%s', first %s/%s: %s): fix the kit "
                             "before grading; no grade was given\n", static_cast<long>(kit_faults), gsv::status_name(first->status),
                     first->lab.c_str(), first->name.c_str(), gsv::one_line(first->detail, 200).c_str());
        return gsv::kGradeKitFault;
    }
    if (command.fail_under >= 0 && report.max_score() > 0 && report.score() < command.fail_under * report.max_score()) {
        std::fprintf(stderr, "gsv-grade: score %.1f / %.1f is under --fail-under %.2f\n", report.score(), report.max_score(),
                     command.fail_under);
        return gsv::kGradeFailed;
    }
    return gsv::kGradeOk;
}

}  // namespace

int main(int argc, char** argv) {
    // The grades out to an LMS: its own options and help (grader/src/lms/export_command.h).
    if (argc > 1 && std::string(argv[1]) == "export") return gsv::run_export_command({argv + 2, argv + argc});
    // Copied work in a class, the template subtracted: its own options and help (grader/src/similarity/).
    if (argc > 1 && std::string(argv[1]) == "similarity") return gsv::run_similarity_command({argv + 2, argv + argc}, GSV_SOURCE_ROOT);
    if (argc > 1 && (std::string(argv[1]) == "merge" || std::string(argv[1]) == "shard" || std::string(argv[1]) == "mistake-skeleton"))
        return run_subcommand(argc, argv);
    gsv::GradeCommand command;
    command.options.kit_root = GSV_SOURCE_ROOT;
    command.options.bin_dir = GSV_BIN_DIR;
    command.options.out_dir = "grade-results";
    try {
        switch (gsv::read_grade_command(argc, argv, command)) {
        case gsv::GradeAction::Help: std::printf("%s", gsv::kGradeUsage); return gsv::kGradeOk;
        case gsv::GradeAction::Version: std::printf("%s\n", gsv::version_line("gsv-grade").c_str()); return gsv::kGradeOk;
        case gsv::GradeAction::Grade: break;
        }
        quiet = command.quiet;
        if (!command.batch.empty()) return grade_class(command, argv[0]);
        // Before any build or lab runs: a grading that cannot write its reports says so first (a batch once its
        // command line is known good, so that a refused one leaves no folder behind).
        gsv::prepare_output_folder(command.options.out_dir, "--out");
        if (command.update_mistakes) return rewrite_mistakes(command);
        return command.update_goldens ? rewrite_goldens(command) : grade_one(command, argv[0]);
    } catch (const gsv::KitFault& e) {
        // The kit's own fault: one line saying what to fix; the student's results.json says it is not theirs.
        std::fprintf(stderr, "gsv-grade: the kit's fault, not the submission's: %s\n", e.what());
        if (!command.options.submission.empty() && command.batch.empty())
            write_failure_results(command.options.out_dir, std::string("the kit's fault, not yours (tell your instructor): ") + e.what());
        return gsv::kGradeKitFault;
    } catch (const gsv::Error& e) {
        std::fprintf(stderr, "gsv-grade: %s\n", e.what());
        // A submission that could not be graded at all still gets a results.json saying why (Gradescope
        // shows it to the student); an internal error leaves one for the instructor too.
        if (!command.options.submission.empty() && command.batch.empty()) write_failure_results(command.options.out_dir, e.what());
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
