// gsv-grade: grades every lab of a kit tree headless and prints the score table.
#include "common/error.h"
#include "grader/grade.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace {

void print_progress(const gsv::CaseResult& r) {
    std::fprintf(stderr, "  %-7s %-12s %s\n", r.lab.c_str(), r.name.c_str(), gsv::status_name(r.status));
}

const char* kUsage =
    "usage: gsv-grade [--kit DIR] [--bin DIR] [--out DIR] [--labs lab01,lab02] [--self-check] [--fail-under F]\n"
    "                 [--update-goldens]\n"
    "  --self-check      compare with the committed golden images even when the solutions are built\n"
    "  --fail-under F    exit 1 when the score is below F (0..1) of the maximum: a CI gate\n"
    "  --update-goldens  render grader/golden/<lab>/<case>.png with the reference solutions\n";

}  // namespace

int main(int argc, char** argv) {
    gsv::GradeOptions options;
    options.kit_root = GSV_SOURCE_ROOT;
    options.bin_dir = GSV_BIN_DIR;
    options.out_dir = "grade-results";
    double fail_under = -1;
    try {
        for (int i = 1; i < argc; ++i) {
            const std::string a = argv[i];
            auto value = [&]() -> std::string {
                if (i + 1 >= argc) throw gsv::Error("option " + a + " needs a value");
                return argv[++i];
            };
            if (a == "--kit") options.kit_root = value();
            else if (a == "--bin") options.bin_dir = value();
            else if (a == "--out") options.out_dir = value();
            else if (a == "--labs") {
                std::stringstream list(value());
                for (std::string lab; std::getline(list, lab, ',');) options.labs.push_back(lab);
            } else if (a == "--self-check") options.self_check = true;
            else if (a == "--update-goldens") options.update_goldens = true;
            else if (a == "--fail-under") fail_under = std::stod(value());
            else if (a == "-h" || a == "--help") {
                std::printf("%s", kUsage);
                return 0;
            } else throw gsv::Error("unknown option '" + a + "' (see --help)");
        }
        const auto results = gsv::grade(options, print_progress);
        if (options.update_goldens) {
            int failed = 0;
            for (const auto& r : results)
                if (r.status != gsv::CaseStatus::Passed) {
                    std::fprintf(stderr, "gsv-grade: %s/%s: %s\n%s\n", r.lab.c_str(), r.name.c_str(), r.detail.c_str(), r.output.c_str());
                    ++failed;
                }
            std::printf("updated %zu golden images, %d failed\n", results.size() - static_cast<std::size_t>(failed), failed);
            return failed ? 1 : 0;
        }
        std::printf("%s", gsv::score_table(results).c_str());
        const auto json_path = options.out_dir / "results.json";
        std::ofstream(json_path) << gsv::results_json(results);
        std::printf("images and results.json in %s\n", options.out_dir.string().c_str());
        double score = 0, max_score = 0;
        for (const auto& r : results) {
            score += r.points;
            max_score += r.max_points;
        }
        if (fail_under >= 0 && max_score > 0 && score < fail_under * max_score) {
            std::fprintf(stderr, "gsv-grade: score %.1f / %.1f is under --fail-under %.2f\n", score, max_score, fail_under);
            return 1;
        }
        return 0;
    } catch (const gsv::Error& e) {
        std::fprintf(stderr, "gsv-grade: %s\n", e.what());
        return 2;
    }
}
