#include "common/image/comparison_image.h"

#include "common/core/error.h"
#include "common/image/image_compare.h"
#include "common/image/text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace gsv {
namespace {

constexpr Rgba8 kGround{28, 28, 32, 255};
constexpr Rgba8 kText{236, 236, 236, 255};
constexpr Rgba8 kDim{165, 165, 172, 255};

void check_sizes(const Image& yours, const Image& reference) {
    if (yours.width != reference.width || yours.height != reference.height)
        throw Error("cannot compare a " + std::to_string(yours.width) + "x" + std::to_string(yours.height) + " image with a " +
                    std::to_string(reference.width) + "x" + std::to_string(reference.height) + " one");
}

void paste(Image& into, const Image& image, int x0, int y0) {
    for (int y = 0; y < image.height; ++y)
        std::copy(image.at(0, y), image.at(0, y) + 4 * static_cast<std::size_t>(image.width), into.at(x0, y0 + y));
}

}  // namespace

ImageDifference image_difference(const Image& yours, const Image& reference) {
    check_sizes(yours, reference);
    ImageDifference d;
    d.rmse = compare_images(yours, reference, {}).rmse;
    for (int y = 0; y < yours.height; ++y)
        for (int x = 0; x < yours.width; ++x) {
            const std::uint8_t* a = yours.at(x, y);
            const std::uint8_t* b = reference.at(x, y);
            int largest = 0;
            for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(a[c] - b[c]));
            d.max_rgb = std::max(d.max_rgb, largest);
            if (largest > 0) ++d.differing_pixels;
        }
    return d;
}

int difference_factor(int max_rgb) {
    int factor = 1;
    while (max_rgb > 0 && factor < 64 && max_rgb * factor * 2 <= 255) factor *= 2;
    return factor;
}

Image amplified_difference(const Image& yours, const Image& reference, int factor) {
    check_sizes(yours, reference);
    Image out(yours.width, yours.height);
    for (int y = 0; y < yours.height; ++y)
        for (int x = 0; x < yours.width; ++x) {
            const std::uint8_t* a = yours.at(x, y);
            const std::uint8_t* b = reference.at(x, y);
            std::uint8_t* o = out.at(x, y);
            for (int c = 0; c < 3; ++c) o[c] = static_cast<std::uint8_t>(std::min(255, std::abs(a[c] - b[c]) * factor));
            o[3] = 255;
        }
    return out;
}

Image compose_comparison(const Image& yours, const Image& reference, const std::string& yours_label,
                         const std::string& reference_label, ComparisonLayout* layout, const MistakePanel* mistake) {
    const ImageDifference d = image_difference(yours, reference);
    const int factor = difference_factor(d.max_rgb);
    const int w = yours.width, h = yours.height;
    const int px = std::clamp(static_cast<int>(std::lround(h / 24.0)), 12, 32);
    const int margin = px / 2 + 2, gap = px / 2 + 2;
    const int line = measure_text("Ag", px).height + px / 5;

    const std::string difference_label =
        d.max_rgb == 0 ? "difference: none, identical" : "difference \xC3\x97" + std::to_string(factor) + " (|yours - reference|)";
    std::vector<std::vector<std::string>> labels = {wrap_text(yours_label, w, px), wrap_text(reference_label, w, px),
                                                    wrap_text(difference_label, w, px)};
    if (mistake) {
        if (mistake->picture.width != w || mistake->picture.height != h)
            throw Error("a known mistake's picture of " + std::to_string(mistake->picture.width) + "x" +
                        std::to_string(mistake->picture.height) + " beside renders of " + std::to_string(w) + "x" + std::to_string(h));
        labels.push_back(wrap_text(mistake->label, w, px));
    }
    const int n = static_cast<int>(labels.size());
    std::size_t label_lines = 1;
    for (const auto& l : labels) label_lines = std::max(label_lines, l.size());
    char numbers[160];
    std::snprintf(numbers, sizeof numbers, "RMSE %.3g, max difference %d of 255 (RGB), %ld of %ld pixels differ",
                  d.rmse, d.max_rgb, d.differing_pixels, static_cast<long>(w) * h);
    const std::vector<std::string> caption = wrap_text(numbers, n * w + (n - 1) * gap, px);

    const int top = margin + static_cast<int>(label_lines) * line + px / 4;
    Image out(n * w + (n - 1) * gap + 2 * margin, top + h + px / 3 + static_cast<int>(caption.size()) * line + margin);
    fill_rect(out, 0, 0, out.width, out.height, kGround);
    const Image difference = amplified_difference(yours, reference, factor);
    const Image* panels[4] = {&yours, &reference, &difference, mistake ? &mistake->picture : nullptr};
    ComparisonLayout where;
    where.font_px = px;
    for (int i = 0; i < n; ++i) {
        const int x0 = margin + i * (w + gap);
        paste(out, *panels[i], x0, top);
        where.panels[static_cast<std::size_t>(i)] = {x0, top, x0 + w, top + h};
        int y = margin;
        for (const std::string& text : labels[static_cast<std::size_t>(i)]) {
            draw_text(out, x0, y, text, px, kText);
            y += line;
        }
    }
    int y = top + h + px / 3;
    for (const std::string& text : caption) {
        draw_text(out, margin, y, text, px, kDim);
        y += line;
    }
    if (layout) *layout = where;
    return out;
}

}  // namespace gsv
