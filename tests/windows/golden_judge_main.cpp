// gsv-golden-judge: pictures drawn elsewhere (the Windows build under Wine) judged against the committed goldens by
// the grader's own comparator (judge_image) under each case's golden tolerance, as the self-check judges them.
//   gsv-golden-judge KIT LAB --sizes      each public case of LAB and its size, "name WxH" a line (what to render)
//   gsv-golden-judge KIT LAB DIR          DIR/<case>.png for every public case: one row per case, then a total
// Exit 0 when every public case passes, 1 when one fails or its picture is missing, 2 on bad use or a bad kit.
#include "common/core/error.h"
#include "common/core/version.h"
#include "common/image/image.h"
#include "grader/src/cases/cases.h"
#include "grader/src/core/case_status.h"
#include "grader/src/core/grade_result.h"
#include "grader/src/judge/image_verdict.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

namespace fs = std::filesystem;

namespace {

int judge(const gsv::LabCases& lab, const fs::path& golden_dir, const fs::path& pictures) {
    int total = 0, passed = 0;
    for (const gsv::GradeCase& c : lab.cases) {
        if (c.visibility != "public") continue;
        ++total;
        const fs::path actual = pictures / (c.name + ".png");
        std::error_code ec;
        if (!fs::is_regular_file(actual, ec)) {
            std::printf("%s/%s: missing: no %s\n", lab.lab.c_str(), c.name.c_str(), actual.string().c_str());
            continue;
        }
        gsv::CaseResult r;
        const gsv::ImageTolerance tolerance = lab.tolerance(c, false);
        const gsv::ImageDiff diff = gsv::judge_image(gsv::read_png(actual), gsv::read_png(golden_dir / (c.name + ".png")),
                                                     tolerance, c, r);
        if (r.status == gsv::CaseStatus::Passed) ++passed;
        // The verdict's own words where they add to the numbers (a flat colour, the starter's magenta).
        const std::string summary = diff.summary();
        if (r.status == gsv::CaseStatus::Passed || r.detail == summary) r.detail.clear();
        std::printf("%s/%s: %s: %s (the golden tolerance: over %d in %.2f%% of pixels at most)%s%s\n", lab.lab.c_str(),
                    c.name.c_str(), gsv::status_name(r.status), summary.c_str(), tolerance.max_channel_diff,
                    100.0 * tolerance.max_differing_fraction, r.detail.empty() ? "" : ": ", r.detail.c_str());
    }
    std::printf("%s: %d of %d public cases match their goldens\n", lab.lab.c_str(), passed, total);
    return total > 0 && passed == total ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    const char* usage =
        "usage: gsv-golden-judge KIT LAB --sizes   each public case of LAB and its size, \"name WxH\" a line\n"
        "       gsv-golden-judge KIT LAB DIR       DIR/<case>.png of every public case against its golden, under the\n"
        "                                          case's golden tolerance (the grader's comparator): a row per case\n"
        "exit status: 0 every public case passes, 1 one fails or its picture is missing, 2 bad use or a bad kit\n";
    if (argc == 2 && std::strcmp(argv[1], "--help") == 0) {
        std::printf("%s", usage);
        return 0;
    }
    if (argc == 2 && std::strcmp(argv[1], "--version") == 0) {
        std::printf("%s\n", gsv::version_line("gsv-golden-judge").c_str());
        return 0;
    }
    if (argc != 4) {
        std::fprintf(stderr, "%s", usage);
        return 2;
    }
    try {
        const fs::path kit = argv[1];
        const std::string lab_id = argv[2];
        const gsv::LabCases lab = gsv::load_lab_cases(kit / "grader" / "cases" / (lab_id + ".json"));
        if (std::string(argv[3]) == "--sizes") {
            for (const gsv::GradeCase& c : lab.cases)
                if (c.visibility == "public") std::printf("%s %dx%d\n", c.name.c_str(), lab.width, lab.height);
            return 0;
        }
        return judge(lab, kit / "grader" / "golden" / lab_id, argv[3]);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "gsv-golden-judge: %s\n", e.what());
        return 2;
    }
}
