#include "grader/src/judge/image_check.h"
#include "grader/src/golden/golden_renderers.h"
#include "grader/src/judge/image_verdict.h"

#include "common/app/kit_layout.h"
#include "common/core/error.h"
#include "common/image/image_compare.h"

#include <algorithm>
#include <cstdio>

namespace fs = std::filesystem;

namespace gsv {

CopySearch::CopySearch(fs::path kit, fs::path student_kit) : kit_(std::move(kit)), student_kit_(std::move(student_kit)) {}

std::string CopySearch::golden_copied(const std::string& lab, const std::string& case_name, const Image& image) {
    auto& goldens = goldens_[lab];
    if (goldens.empty()) {
        const fs::path dir = KitLayout{kit_}.golden_dir(lab);
        if (fs::is_directory(dir))
            for (const auto& e : fs::directory_iterator(dir))
                if (e.path().extension() == ".png") goldens[e.path().stem().string()] = read_png(e.path());
    }
    for (const auto& [name, golden] : goldens)
        if (name != case_name && golden.width == image.width && golden.height == image.height && golden.rgba == image.rgba)
            return name;
    return "";
}

std::string CopySearch::picture_in_submission(const Image& image) const {
    const fs::path labs = KitLayout{student_kit_}.labs();
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(labs, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        // Plain files only (the copy holds nothing else; never follow a link).
        if (!fs::is_regular_file(it->symlink_status(ec)) || it->path().extension() != ".png" || it->file_size(ec) > (16u << 20)) continue;
        try {
            if (read_png(it->path()).rgba == image.rgba) return as_student_sees(it->path().string(), student_kit_);
        } catch (const Error&) {
        }
    }
    return "";
}

namespace {

// A wrong image against a golden made on another renderer, within the margin renderers differ by: say so.
void call_a_gpu_margin(const Image& actual, const Image& expected, const ImageTolerance& tolerance, const OtherRenderer& other,
                       CaseResult& r) {
    const ImageTolerance cross = cross_implementation_tolerance(tolerance);
    if (!compare_images(actual, expected, cross).within(cross)) return;
    r.status = CaseStatus::GpuMargin;
    char budgets[32];
    std::snprintf(budgets, sizeof budgets, "%.3g", kCrossImplementationBudget);
    r.detail = "differs from the " + renderer_family(other.golden) + " golden by a margin seen between GPUs: check with `" +
               other.compare + "` (" + r.detail + "; within " + budgets + " times the case's budget)";
}

}  // namespace

void check_image(const LabCases& lab, const GradeCase& c, const Image& actual, const Image& expected, bool live,
                 const fs::path& out, CopySearch& copies, const std::function<LabRun(const GradeCase&)>& draw,
                 const OtherRenderer* other_renderer, CaseResult& r) {
    const fs::path dir = out / lab.lab / c.name;
    // Re-encoded by the grader: only pixels come back from student code.
    write_png(dir / "actual.png", actual);
    r.actual_png = fs::relative(dir / "actual.png", out).generic_string();
    const ImageTolerance tolerance = lab.tolerance(c, live);
    const ImageDiff diff = judge_image(actual, expected, tolerance, c, r);
    if (r.status == CaseStatus::Passed) return;
    if (!diff.size_mismatch) {
        write_png(dir / "diff.png", difference_heatmap(actual, expected, tolerance.max_channel_diff, tolerance.neighbourhood));
        r.diff_png = fs::relative(dir / "diff.png", out).generic_string();
    }
    if (r.status != CaseStatus::WrongImage) return;
    if (const std::string copied = copies.golden_copied(lab.lab, c.name, actual); !copied.empty()) {
        // An honest bug that ignores what sets this case apart lands on another case's image too; a copy is a
        // copy when the submission holds the picture, or when its own lab does not draw it for that case.
        const std::string file = copies.picture_in_submission(actual);
        const auto other = std::find_if(lab.cases.begin(), lab.cases.end(), [&](const GradeCase& x) { return x.name == copied; });
        const LabRun own = file.empty() && other != lab.cases.end() ? draw(*other) : LabRun{};
        if (file.empty() && own.status == CaseStatus::Passed && own.image && own.image->rgba == actual.rgba) {
            r.status = CaseStatus::WrongImage;
            r.detail = "draws exactly what case '" + copied + "' draws: this case's settings seem to change nothing (" + r.detail + ")";
        } else {
            r.status = CaseStatus::CopiedImage;
            r.detail = "pixel for pixel the committed golden image of case '" + copied + "', " +
                       (file.empty() ? std::string("which the lab does not draw for that case") : "held in the submission as " + file);
        }
    } else if (other_renderer && !live) {
        call_a_gpu_margin(actual, expected, tolerance, *other_renderer, r);
    }
}

}  // namespace gsv
