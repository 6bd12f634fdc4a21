// gsv-margins: the margin table (grader/margins.h). Renders every public case of every lab on every implementation
// available here (the solutions, and the mutants and correct variants of tests/mutants/), graded against the goldens
// as the self-check grades, and prints per case how much of its budget correct renders use and how far the nearest
// must-fail mutant is. A measurement: it exits 0 whatever it finds, unless asked to hold a line (--fail-if-missed, or
// --check, what the softpipe kind of test runs).
#include "common/context/context.h"
#include "common/core/error.h"
#include "common/core/version.h"
#include "common/io/json.h"
#include "common/io/output_folder.h"
#include "grader/src/margins/margins.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

const char* kUsage =
    "usage: gsv-margins [--kit DIR] [--bin DIR] [--labs lab01,lab02] [--impl NAME,...] [--no-mutants] [--no-variants]\n"
    "                   [--json FILE] [--work DIR] [--fail-if-missed] [--check] [--es-version V] [--list-impl] [--help]\n"
    "                   [--version]\n"
    "       gsv-margins --table FILE.json...\n"
    "  renders every public case on each implementation (the solutions, and the mutants and correct variants of\n"
    "  tests/mutants/), graded against the goldens, and prints per case the worst correct render and the nearest\n"
    "  must-fail mutant as shares of the case's budget; the bar: correct under 50%, must-fail mutants over 150%\n"
    "  --impl NAMES      only these implementations (--list-impl lists them; default: all, those not here skipped)\n"
    "  --labs LABS       only these labs\n"
    "  --no-mutants      no mutants\n"
    "  --no-variants     no correct variants\n"
    "  --es-version V    on OpenGL ES, every case at least at version V (3.0, 3.1, 3.2); default: each lab's lowest\n"
    "  --json FILE       also write the measurement (what --table reads)\n"
    "  --table FILES     print the table of measurements written by --json (one per implementation, say), joined\n"
    "  --work DIR        scratch folder (default: a fresh one under the system's temporary folder)\n"
    "  --fail-if-missed  exit 1 when a case misses the bar\n"
    "  --check           exit 1 unless every correct render passes and every mutant fails a case it must fail, on\n"
    "                    each implementation, naming the implementation in each failure; 77 when none is here. Each\n"
    "                    mutant is graded up to the first case it fails (the table's nearest mutant is of those)\n"
    "exit status: 0 measured, 1 a case missed the bar (--fail-if-missed) or a check failed (--check), 2 usage or\n"
    "internal error, 77 (--check) none of the implementations is available here\n";

std::vector<std::string> split_list(const std::string& text) {
    std::vector<std::string> items;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');)
        if (!item.empty()) items.push_back(item);
    return items;
}

}  // namespace

int main(int argc, char** argv) {
    gsv::MarginOptions options;
    options.kit_root = GSV_SOURCE_ROOT;
    options.bin_dir = GSV_BIN_DIR;
    std::string json_out;
    std::vector<std::string> tables;
    bool fail_if_missed = false, check = false;
    try {
        for (int i = 1; i < argc; ++i) {
            const std::string a = argv[i];
            auto value = [&]() -> std::string {
                if (i + 1 >= argc) throw gsv::Error(a + " needs a value (see --help)");
                return argv[++i];
            };
            if (a == "--help" || a == "-h") {
                std::printf("%s", kUsage);
                return 0;
            } else if (a == "--version") {
                std::printf("%s\n", gsv::version_line("gsv-margins").c_str());
                return 0;
            } else if (a == "--list-impl") {
                for (const auto& impl : gsv::known_implementations()) std::printf("%-17s %s\n", impl.name.c_str(), impl.how.c_str());
                return 0;
            } else if (a == "--kit") {
                options.kit_root = value();
            } else if (a == "--bin") {
                options.bin_dir = value();
            } else if (a == "--labs") {
                options.labs = split_list(value());
            } else if (a == "--impl") {
                options.implementations = split_list(value());
            } else if (a == "--no-mutants") {
                options.mutants = false;
            } else if (a == "--no-variants") {
                options.variants = false;
            } else if (a == "--es-version") {
                options.es_at_least = gsv::parse_gl_version(value(), gsv::Profile::Es);
            } else if (a == "--check") {
                check = true;
                options.mutant_until_first_failure = true;
            } else if (a == "--json") {
                json_out = value();
            } else if (a == "--work") {
                options.work_dir = value();
            } else if (a == "--fail-if-missed") {
                fail_if_missed = true;
            } else if (a == "--table") {
                while (i + 1 < argc && std::string(argv[i + 1]).rfind("--", 0) != 0) tables.push_back(argv[++i]);
                if (tables.empty()) throw gsv::Error("--table needs at least one FILE.json (written by --json)");
            } else {
                throw gsv::Error("unknown argument '" + a + "' (see --help)");
            }
        }
        gsv::MarginMeasurement measurement;
        if (!tables.empty()) {
            std::vector<gsv::MarginMeasurement> parts;
            for (const auto& file : tables) parts.push_back(gsv::margins_from_json(gsv::read_json_file(file)));
            measurement = gsv::merge_margins(parts);
        } else {
            const bool own_work = options.work_dir.empty();
            if (own_work) options.work_dir = fs::temp_directory_path() / ("gsv-margins-" + std::to_string(getpid()));
            if (!json_out.empty()) gsv::prepare_output_file(json_out, "--json");
            fs::create_directories(options.work_dir);
            measurement = gsv::measure_margins(options, [](const std::string& line) { std::fprintf(stderr, "margins: %s\n", line.c_str()); });
            if (own_work) fs::remove_all(options.work_dir);
            if (!json_out.empty()) std::ofstream(json_out) << gsv::margins_json(measurement).dump(2) << "\n";
        }
        std::printf("%s", gsv::margins_table(measurement).c_str());
        if (check) {
            const bool any = std::any_of(measurement.implementations.begin(), measurement.implementations.end(),
                                         [](const gsv::MarginImplementationRun& run) { return run.available; });
            if (!any) {
                std::printf("\nskipped: none of the implementations asked for is available here\n");
                return 77;
            }
            const auto failures = gsv::grading_failures(measurement);
            for (const auto& line : failures) std::printf("FAILED %s\n", line.c_str());
            if (failures.empty()) std::printf("\nevery correct render passed and every mutant failed a case it must fail\n");
            if (!failures.empty()) return 1;
        }
        return fail_if_missed && !gsv::cases_missing_the_bar(measurement).empty() ? 1 : 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "gsv-margins: %s\n", e.what());
        return 2;
    }
}
