// gsv-bench-grader: how long grading every public case of every lab takes (student and live reference,
// no timing checks), and where that time goes. A benchmark, not a test: it prints, it never fails on speed.
#include "common/core/error.h"
#include "common/core/version.h"
#include "grader/src/grade/grade.h"

#include <chrono>
#include <cstdio>
#include <map>

namespace fs = std::filesystem;

int main(int argc, char** argv) {
    gsv::GradeOptions options;
    options.kit_root = GSV_SOURCE_ROOT;
    options.bin_dir = GSV_BIN_DIR;
    options.out_dir = fs::temp_directory_path() / "gsv-bench-grader";
    options.hidden = false;
    options.timing = false;
    const std::string usage = "usage: gsv-bench-grader [--help|--version]\n"
                              "  grades every public case of the kit's own labs against their solutions (no hidden cases,\n"
                              "  no timing checks) and prints where the time goes; a benchmark that never fails on speed\n";
    if (argc == 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
        std::printf("%s", usage.c_str());
        return 0;
    }
    if (argc == 2 && std::string(argv[1]) == "--version") {
        std::printf("%s\n", gsv::version_line("gsv-bench-grader").c_str());
        return 0;
    }
    if (argc > 1) {
        std::fprintf(stderr, "gsv-bench-grader: unknown argument '%s' (see --help)\n", argv[1]);
        return 2;
    }
    try {
        const auto start = std::chrono::steady_clock::now();
        const gsv::GradeReport report = gsv::grade(options);
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        struct Row { int checks = 0; double student = 0, reference = 0, frames = 0; };
        std::map<std::string, Row> labs;
        Row all;
        for (const auto& r : report.results) {
            for (Row* row : {&labs[r.lab], &all}) {
                row->checks += 1;
                row->student += r.seconds;
                row->reference += r.reference_seconds;
                row->frames += r.frame_ms / 1000.0;
            }
        }
        std::printf("grading every public case, student and live reference, %s\n", report.sandbox.c_str());
        std::printf("%-7s %6s %9s %12s %12s %12s %10s\n", "lab", "checks", "wall s", "student s", "reference s",
                    "in frames", "s/check");
        auto line = [&](const std::string& name, const Row& row, double seconds) {
            const double processes = row.student + row.reference;
            std::printf("%-7s %6d %9.2f %12.2f %12.2f %11.0f%% %10.3f\n", name.c_str(), row.checks, seconds, row.student,
                        row.reference, processes > 0 ? 100.0 * 2 * row.frames / processes : 0.0,
                        row.checks ? seconds / row.checks : 0.0);
        };
        for (const auto& [lab, row] : labs) line(lab, row, row.student + row.reference);
        line("all", all, wall);
        const double processes = all.student + all.reference;
        std::printf("\nlab processes: %.0f%% of the wall time; the rest is the grader (image compare, PNG I/O, reports, "
                    "sandbox set-up).\n'in frames': the share of process time inside the one timed frame (the student's, counted for "
                    "both; llvmpipe compiles shaders at the first draw, so it is mostly JIT); the rest is process "
                    "start-up (loader, EGL context, GLSL front end, mesh set-up).\n",
                    wall > 0 ? 100.0 * processes / wall : 0.0);
        return 0;
    } catch (const gsv::Error& e) {
        std::fprintf(stderr, "gsv-bench-grader: %s\n", e.what());
        return 2;
    }
}
