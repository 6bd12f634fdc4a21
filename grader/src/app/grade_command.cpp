#include "grader/src/app/grade_command.h"

#include "common/context/context.h"
#include "common/core/error.h"
#include "grader/src/batch/batch.h"

#include <cstdlib>
#include <regex>
#include <sstream>

namespace gsv {

const char* const kGradeUsage =
    "usage: gsv-grade [--kit DIR] [--bin DIR] [--submission DIR | --batch DIR [--workers N] [--shard K/N] [--roster FILE]]\n"
    "                 [--out DIR]"
    " [--labs lab01,lab02] [--cases gyre,wrap] [--todo L02-T3] [--seed N] [--self-check] [--no-timing]\n"
    "                 [--public-only] [--profile core|es]"
    " [--timeout S] [--fail-under F] [--update-goldens] [--update-mistakes] [--allow-readable-kit] [--no-namespaces]\n"
    "                 [--no-sandbox] [--build-all] [--fresh-references] [--grader-cache DIR] [--regrade-only changed]\n"
    "                 [--passed-pictures full|thumbnail] [--keep-build yes|no]\n"
    "                 [--one-process-per-case] [--diagnose off|public|all] [--quiet] [--help] [--version]\n"
    "  --kit DIR         the kit (cases, goldens, hidden cases, solutions); default: the one this was built from\n"
    "  --bin DIR         the kit's built labs and <lab>_solution; default: this build's bin/\n"
    "  --submission DIR  a copy of the kit whose labs/ hold a student's work: built against this kit, then graded\n"
    "  --batch DIR       every folder in DIR is a submission; --workers N grade N at a time (default 2)\n"
    "  --shard K/N       with --batch and --seed: grade every N-th submission (sorted by name) from the K-th, so N\n"
    "                    machines share a class; then gsv-grade merge joins their --out folders\n"
    "  --roster FILE     with --batch: the class, one name per line (default: the folders in DIR); DIR then needs\n"
    "                    only this shard's folders, and a name without one is graded 'nothing submitted'\n"
    "  --out DIR         images and reports: results.json (Gradescope), report.json, junit.xml, report.html; with\n"
    "                    --batch also class.csv, class.txt, batch.json and the class by its mistakes (class-report.html,\n"
    "                    class-mistakes.csv)\n"
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
    "  --update-mistakes render grader/golden/<lab>/mistakes.json and mistakes.png, the known mistakes' pictures a\n"
    "                    student's copy diagnoses with (tests/mutants/<lab>.json on every public case), after the goldens\n"
    "  --allow-readable-kit  where the sandbox cannot hide the kit (no namespaces), grade hidden cases and live\n"
    "                    references anyway; without it they are refused there, and the report says which walls were up\n"
    "  --no-namespaces   every wall but the namespaces: how the grader behaves where unshare is refused\n"
    "  --no-sandbox      run student code without namespaces and limits (to debug the grader only)\n"
    "  --regrade-only changed  grade only the labs whose inputs (the student's lab folder, the kit's files for that lab\n"
    "                    and those all labs share, the built labs and gsv-grade, the seed and options) changed since the\n"
    "                    last run in --out, and keep the others' rows from it; with --batch, for each submission. Without\n"
    "                    --seed, the last run's seed\n"
    "  --fresh-references  render every live reference in this run (and store it anew) rather than take one kept in\n"
    "                    <bin>/../grader-cache/references by an earlier run with the same kit, build, driver and case\n"
    "  --grader-cache DIR  where earlier builds (DIR/builds) and live references (DIR/references) are kept; default\n"
    "                    <bin>/../grader-cache\n"
    "  --passed-pictures full|thumbnail  what a passed image case keeps in --out: its picture and the expected one\n"
    "                    (full, default) or a small JPEG of its picture (thumbnail, default in a batch's runs)\n"
    "  --keep-build yes|no  keep a submission's build (its binaries) in --out/submission-build (yes, default; no in a\n"
    "                    batch's runs); its sources stay either way\n"
    "  --build-all       compile every lab of a submission, even one whose C++ is byte for byte the kit's starter's\n"
    "                    (otherwise the kit's binary) or an earlier build's (kept in <bin>/../grader-cache/builds)\n"
    "  --one-process-per-case  start a lab process for each case, rather than one per lab that renders the lab's cases\n"
    "                    one after another, each from a fresh lab and GL context (the default, but for --cases); the\n"
    "                    grades are the same\n"
    "  --diagnose WHICH  compare failing cases with the kit's known mistakes' pictures and name the mistake that explains\n"
    "                    them: off (exams), public (what a student may be told) or all (hidden cases too: the\n"
    "                    instructor's own reports); default public with --self-check, all otherwise\n"
    "       gsv-grade merge OUT SHARD_OUT...  the --out folders of a batch's shards joined into OUT (new or empty):\n"
    "                    the per-submission folders, class.csv, class.txt, batch.json; refused when the shards were\n"
    "                    graded with other seeds, kits, labs or options, overlap, or one is missing\n"
    "       gsv-grade shard K/N ROSTER       the names of shard K of N of a roster file, one a line (what to fetch)\n"
    "       gsv-grade mistake-skeleton OUT ID  an entry for tests/mutants/<lab>.json from cluster ID (lab01/gooch/1) of\n"
    "                    a batch's class report (OUT/class-report.html): failures no known mistake explains, alike\n"
    "       gsv-grade export --lms canvas|moodle|blackboard --roster FILE OUT  the batch's grades as the file the LMS\n"
    "                    imports, per lab and in total, matched to its students by a roster (gsv-grade export --help)\n"
    "       gsv-grade similarity --batch DIR --out DIR  copied work in the class, the template subtracted: pairs sharing\n"
    "                    own code and pairs with the same rare wrong picture (similarity.html, .csv; --help for more)\n"
    "exit status: 0 graded (whatever the score), 1 under --fail-under, 2 usage or internal error, 3 the kit's fault\n"
    "                    (its set-up, not a student's files: nothing graded; one line says what to fix)\n";

std::uint64_t parse_seed(const std::string& text) {
    std::size_t used = 0;
    unsigned long long value = 0;
    try {
        value = std::stoull(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || text.empty() || text[0] == '-') throw Error("--seed needs a whole number, got '" + text + "'");
    return value;
}

GradeAction read_grade_command(int argc, char** argv, GradeCommand& command) {
    GradeOptions& options = command.options;
    std::vector<std::string>& pass_through = command.pass_through;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw Error("option " + a + " needs a value");
            return argv[++i];
        };
        auto number = [&](double lo, double hi) {
            const std::string text = value();
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            if (text.empty() || *end != '\0' || !(v >= lo && v <= hi))
                throw Error(a + " needs a number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got '" + text + "'");
            return v;
        };
        // A comma-separated list, passed on to each submission's run of a batch.
        auto list = [&](std::vector<std::string>& items) {
            const std::string text = value();
            pass_through.insert(pass_through.end(), {a, text});
            std::stringstream in(text);
            for (std::string item; std::getline(in, item, ',');) items.push_back(item);
        };
        // A switch, passed on to each submission's run of a batch.
        auto flag = [&](bool& option, bool value_when_given) {
            option = value_when_given;
            pass_through.push_back(a);
        };
        if (a == "--kit") { options.kit_root = value(); pass_through.insert(pass_through.end(), {a, std::filesystem::absolute(options.kit_root).string()}); }
        else if (a == "--bin") { options.bin_dir = value(); pass_through.insert(pass_through.end(), {a, std::filesystem::absolute(options.bin_dir).string()}); }
        else if (a == "--submission") options.submission = value();
        else if (a == "--batch") command.batch = value();
        else if (a == "--workers") command.workers = static_cast<int>(number(1, 256));
        else if (a == "--shard") command.shard = value();
        else if (a == "--roster") command.roster = value();
        else if (a == "--out") options.out_dir = value();
        else if (a == "--labs") list(options.labs);
        else if (a == "--cases") list(options.cases);
        else if (a == "--seed") options.seed = parse_seed(value());
        else if (a == "--self-check") flag(options.self_check, true);
        else if (a == "--no-timing") flag(options.timing, false);
        else if (a == "--public-only") flag(options.hidden, false);
        else if (a == "--no-sandbox") flag(options.sandbox, false);
        else if (a == "--build-all") flag(options.reuse_builds, false);
        else if (a == "--fresh-references") flag(options.stored_references, false);
        else if (a == "--passed-pictures") {
            const std::string what = value();
            if (what != "full" && what != "thumbnail")
                throw Error("--passed-pictures takes full or thumbnail, got '" + what + "'");
            options.passed_pictures = what == "full" ? PassedPictures::Full : PassedPictures::Thumbnail;
            command.passed_pictures_given = true;
            pass_through.insert(pass_through.end(), {a, what});
        }
        else if (a == "--keep-build") {
            const std::string what = value();
            if (what != "yes" && what != "no") throw Error("--keep-build takes yes or no, got '" + what + "'");
            options.keep_build = what == "yes";
            command.keep_build_given = true;
            pass_through.insert(pass_through.end(), {a, what});
        }
        else if (a == "--one-process-per-case") {
            options.lab_processes = LabProcesses::PerCase;
            pass_through.push_back(a);
        }
        else if (a == "--grader-cache") {
            const std::filesystem::path cache = std::filesystem::absolute(value());
            options.build_cache = cache / "builds";
            options.reference_store = cache / "references";
            pass_through.insert(pass_through.end(), {a, cache.string()});
        }
        else if (a == "--regrade-only") {
            const std::string what = value();
            if (what != "changed") throw Error("--regrade-only takes 'changed' (the labs whose inputs changed), got '" + what + "'");
            command.regrade_only_changed = true;
            pass_through.insert(pass_through.end(), {a, what});
        }
        else if (a == "--allow-readable-kit") flag(options.allow_readable_kit, true);
        else if (a == "--no-namespaces") flag(options.namespaces, false);
        else if (a == "--todo") {
            options.todo = value();
            static const std::regex id(R"(^L[0-9]{2}-T[0-9]+$)");
            if (!std::regex_match(options.todo, id)) throw Error("--todo needs a TODO id like L02-T3, got '" + options.todo + "'");
            pass_through.insert(pass_through.end(), {a, options.todo});
        }
        else if (a == "--sandbox-uid") options.sandbox_uid = static_cast<unsigned>(number(1000, 4000000000.0));
        else if (a == "--timeout") { options.timeout_s = number(0.1, 3600); pass_through.insert(pass_through.end(), {a, std::to_string(options.timeout_s)}); }
        else if (a == "--update-goldens") command.update_goldens = true;
        else if (a == "--update-mistakes") command.update_mistakes = true;
        else if (a == "--profile") {
            options.profile = parse_profile(value());
            pass_through.insert(pass_through.end(), {a, profile_name(options.profile)});
        }
        else if (a == "--diagnose") {
            const std::string what = value();
            if (what == "off") options.diagnose = DiagnoseCases::Off;
            else if (what == "public") options.diagnose = DiagnoseCases::Public;
            else if (what == "all") options.diagnose = DiagnoseCases::All;
            else throw Error("--diagnose takes off, public or all, got '" + what + "'");
            pass_through.insert(pass_through.end(), {a, what});
        }
        else if (a == "--fail-under") command.fail_under = number(0, 1);
        else if (a == "--quiet") command.quiet = true;
        else if (a == "-h" || a == "--help") return GradeAction::Help;
        else if (a == "--version") return GradeAction::Version;
        else throw Error("unknown option '" + a + "' (see --help)");
    }
    if (const char* seed = std::getenv(kSeedVariable); seed && !options.seed) options.seed = parse_seed(seed);
    if (command.update_goldens && options.profile != Profile::Core)
        throw Error("--update-goldens renders the goldens on the core profile; drop --profile " +
                    std::string(profile_name(options.profile)));
    if (command.batch.empty() && !command.shard.empty()) throw Error("--shard " + command.shard + " needs --batch DIR");
    if (command.batch.empty() && !command.roster.empty()) throw Error("--roster needs --batch DIR");
    if (command.update_mistakes && (command.update_goldens || command.regrade_only_changed || !command.batch.empty()))
        throw Error("--update-mistakes runs alone: after --update-goldens, not with it, and grades nothing");
    if (command.update_mistakes && (options.profile != Profile::Core || !options.cases.empty() || !options.todo.empty()))
        throw Error("--update-mistakes renders every public case on the core profile: drop --profile, --cases and --todo");
    if (command.update_goldens && command.regrade_only_changed) throw Error("--regrade-only grades; --update-goldens rewrites the goldens");
    return GradeAction::Grade;
}

}  // namespace gsv
