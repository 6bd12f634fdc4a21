#include "grader/src/judge/image_check.h"

#include "common/app/kit_layout.h"
#include "common/core/error.h"
#include "common/core/not_done.h"
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

void check_image(const LabCases& lab, const GradeCase& c, const Image& actual, const Image& expected, bool live,
                 const fs::path& out, CopySearch& copies, const std::function<LabRun(const GradeCase&)>& draw,
                 CaseResult& r) {
    const fs::path dir = out / lab.lab / c.name;
    // Re-encoded by the grader: only pixels come back from student code.
    write_png(dir / "actual.png", actual);
    r.actual_png = fs::relative(dir / "actual.png", out).generic_string();
    const ImageTolerance tolerance = lab.tolerance(c, live);
    const ImageDiff diff = compare_images(actual, expected, tolerance);
    r.image.done = true;
    r.image.tolerance = tolerance;
    r.image.max_channel_diff = diff.max_channel_diff;
    r.image.differing_pixels = diff.differing_pixels;
    r.image.total_pixels = diff.total_pixels;
    r.image.psnr = diff.psnr;
    r.image.ssim = diff.ssim;
    r.image.diff_x0 = diff.diff_x0;
    r.image.diff_y0 = diff.diff_y0;
    r.image.diff_x1 = diff.diff_x1;
    r.image.diff_y1 = diff.diff_y1;
    if (diff.within(tolerance)) {
        r.status = CaseStatus::Passed;
        r.points = c.points;
        r.detail = diff.max_channel_diff == 0 ? "identical" : "max diff " + std::to_string(diff.max_channel_diff);
        return;
    }
    r.detail = diff.summary();
    if (!diff.size_mismatch) {
        write_png(dir / "diff.png", difference_heatmap(actual, expected, tolerance.max_channel_diff));
        r.diff_png = fs::relative(dir / "diff.png", out).generic_string();
    }
    // The starter's magenta where the reference has none: the TODO is open, however much else is drawn.
    const long open = not_done_pixels(actual) - not_done_pixels(expected);
    const long pixels = static_cast<long>(actual.width) * actual.height;
    if (!diff.size_mismatch && open > pixels / 200) {
        r.status = CaseStatus::NotDone;
        char share[32];
        std::snprintf(share, sizeof share, "%.1f%%", 100.0 * double(open) / double(pixels));
        r.detail = "not done: " + c.todo + " (the starter's magenta on " + share + " of the image)";
        return;
    }
    if (is_blank(actual) && !is_blank(expected)) {
        r.status = CaseStatus::BlankImage;
        const std::uint8_t* p = actual.at(0, 0);
        // kNotDone: the starter's own "this TODO is open" colour.
        r.detail = p[0] == kNotDoneRgb[0] && p[1] == kNotDoneRgb[1] && p[2] == kNotDoneRgb[2]
                       ? "all magenta, the starter's 'not done' colour: this case's TODO (or one it needs) is still open"
                       : "one flat colour where the reference has a picture (is anything drawn?)";
    } else if (const std::string copied = copies.golden_copied(lab.lab, c.name, actual); !copied.empty()) {
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
    } else {
        r.status = CaseStatus::WrongImage;
    }
}

}  // namespace gsv
