#include "grader/src/judge/image_verdict.h"

#include "common/core/not_done.h"
#include "common/image/image_offset.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace gsv {

bool image_passes(const Image& actual, const Image& expected, const ImageTolerance& tolerance) {
    if (actual.width != expected.width || actual.height != expected.height) return false;
    if (actual.rgba == expected.rgba) return true;
    const long total = static_cast<long>(actual.width) * actual.height;
    const double fraction = std::max(0.0, tolerance.max_differing_fraction);
    const double allowed = std::floor(fraction * double(total) * (1.0 + 1e-12));  // as ImageDiff::within counts
    long over = 0;
    if (tolerance.neighbourhood <= 0) {
        // Each pixel at its own place: stop at the first pixel over the budget.
        for (std::size_t i = 0; i < actual.rgba.size(); i += 4) {
            int d = 0;
            for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(actual.rgba[i + c]) - int(expected.rgba[i + c])));
            if (d > tolerance.max_channel_diff && double(++over) > allowed) return false;
        }
    } else {
        for (const std::uint8_t d : matched_differences(actual, expected, tolerance.neighbourhood))
            if (d > tolerance.max_channel_diff && double(++over) > allowed) return false;
    }
    return !global_offset(actual, expected).shifted();
}

ImageDiff judge_image(const Image& actual, const Image& expected, const ImageTolerance& tolerance, const GradeCase& c,
                      CaseResult& r) {
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
    // Where the whole picture sits: a neighbourhood forgives a point a rasterizer put a pixel off, never a picture
    // moved as a whole, and a wrong image that is only moved says so.
    // Not skipped where every pixel matched: within a neighbourhood a picture moved whole matches everywhere.
    const ImageOffset offset = diff.size_mismatch || actual.rgba == expected.rgba ? ImageOffset{} : global_offset(actual, expected);
    r.image.offset_x = offset.dx;
    r.image.offset_y = offset.dy;
    if (offset.shifted()) {
        r.status = CaseStatus::WrongImage;
        r.detail = offset.text() + " (" + diff.summary() + ")";
        return diff;
    }
    if (diff.within(tolerance)) {
        r.status = CaseStatus::Passed;
        r.points = c.points;
        r.detail = diff.max_channel_diff == 0 ? "identical" : "max diff " + std::to_string(diff.max_channel_diff);
        // Matched within a neighbourhood, a 0 means every pixel found its match near by, not that none moved.
        if (tolerance.neighbourhood > 0)
            r.detail = (diff.max_channel_diff == 0 ? "every pixel " : r.detail + ", ") + neighbourhood_text(tolerance.neighbourhood);
        return diff;
    }
    r.detail = diff.summary();
    // The starter's magenta where the reference has none: the TODO is open, however much else is drawn.
    const long open = not_done_pixels(actual) - not_done_pixels(expected);
    const long pixels = static_cast<long>(actual.width) * actual.height;
    if (!diff.size_mismatch && open > pixels / 200) {
        r.status = CaseStatus::NotDone;
        char share[32];
        std::snprintf(share, sizeof share, "%.1f%%", 100.0 * double(open) / double(pixels));
        r.detail = "not done: " + c.todo + " (the starter's magenta on " + share + " of the image)";
        return diff;
    }
    if (is_blank(actual) && !is_blank(expected)) {
        r.status = CaseStatus::BlankImage;
        const std::uint8_t* p = actual.at(0, 0);
        // kNotDone: the starter's own "this TODO is open" colour.
        r.detail = p[0] == kNotDoneRgb[0] && p[1] == kNotDoneRgb[1] && p[2] == kNotDoneRgb[2]
                       ? "all magenta, the starter's 'not done' colour: this case's TODO (or one it needs) is still open"
                       : "one flat colour where the reference has a picture (is anything drawn?)";
        return diff;
    }
    r.status = CaseStatus::WrongImage;
    return diff;
}

}  // namespace gsv
