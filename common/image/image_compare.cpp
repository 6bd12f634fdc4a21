#include "common/image/image_compare.h"

#include "common/core/not_done.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <vector>

#include "common/core/error.h"

namespace gsv {
namespace {

std::string size_text(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

void require_same_size(const Image& a, const Image& b, const char* what) {
    if (a.width != b.width || a.height != b.height)
        throw Error(std::string(what) + ": image sizes differ (" + size_text(a.width, a.height) +
                    " vs " + size_text(b.width, b.height) + ")");
}

int pixel_max_diff(const std::uint8_t* a, const std::uint8_t* b) {
    int largest = 0;
    for (int c = 0; c < 4; ++c) largest = std::max(largest, std::abs(int(a[c]) - int(b[c])));
    return largest;
}

// ITU-R BT.601 luma weights, the common grayscale conversion for SSIM on colour images.
std::vector<double> luma_of(const Image& image) {
    std::vector<double> luma(static_cast<std::size_t>(image.width) * image.height);
    for (std::size_t p = 0; p < luma.size(); ++p) {
        const std::uint8_t* px = image.rgba.data() + p * 4;
        luma[p] = 0.299 * px[0] + 0.587 * px[1] + 0.114 * px[2];
    }
    return luma;
}

// SSIM(x,y) = (2 mu_x mu_y + C1)(2 sigma_xy + C2) / ((mu_x^2 + mu_y^2 + C1)(sigma_x^2 + sigma_y^2 + C2))
// with C1 = (K1 L)^2, C2 = (K2 L)^2 (Wang et al. 2004, eq. 13).
constexpr double kDynamicRange = 255.0;
constexpr double kC1 = (0.01 * kDynamicRange) * (0.01 * kDynamicRange);
constexpr double kC2 = (0.03 * kDynamicRange) * (0.03 * kDynamicRange);

double ssim_formula(double mu_x, double mu_y, double var_x, double var_y, double cov_xy) {
    return ((2 * mu_x * mu_y + kC1) * (2 * cov_xy + kC2)) /
           ((mu_x * mu_x + mu_y * mu_y + kC1) * (var_x + var_y + kC2));
}

// Fallback for images too small for even one full window: the formula once over the whole image,
// every pixel weighted equally, so small test images still get a meaningful score.
double global_ssim(const std::vector<double>& x, const std::vector<double>& y) {
    const double n = double(x.size());
    double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        sx += x[i], sy += y[i];
        sxx += x[i] * x[i], syy += y[i] * y[i], sxy += x[i] * y[i];
    }
    const double mx = sx / n, my = sy / n;
    return ssim_formula(mx, my, sxx / n - mx * mx, syy / n - my * my, sxy / n - mx * my);
}

}  // namespace

// 11-tap Gaussian, sigma 1.5 (Wang et al. 2004, section III-C), population (not sample) moments.
// scikit-image's structural_similarity(gaussian_weights=True, sigma=1.5,
// use_sample_covariance=False) filters the whole image with reflected borders and then averages
// the SSIM map after cropping (11-1)/2 = 5 pixels from every side; every window that survives the
// crop lies inside the image, so filtering only that valid region gives the same mean without any
// border rule.
double ssim_luma(const Image& a, const Image& b) {
    require_same_size(a, b, "ssim_luma");
    if (a.empty()) return 1.0;
    const std::vector<double> x = luma_of(a), y = luma_of(b);

    constexpr int kRadius = 5;
    constexpr int kTaps = 2 * kRadius + 1;
    if (a.width < kTaps || a.height < kTaps) return global_ssim(x, y);

    constexpr double kSigma = 1.5;
    double weight[kTaps];
    double weight_sum = 0;
    for (int k = 0; k < kTaps; ++k) {
        const double d = k - kRadius;
        weight[k] = std::exp(-d * d / (2 * kSigma * kSigma));
        weight_sum += weight[k];
    }
    for (double& w : weight) w /= weight_sum;

    // The 2D window is separable: filter rows first (only the columns whose window fits), then
    // columns of that result (only the rows whose window fits).
    const int W = a.width, H = a.height;
    const int valid_w = W - 2 * kRadius, valid_h = H - 2 * kRadius;
    enum { X, Y, XX, YY, XY, kMoments };
    std::vector<double> rows(static_cast<std::size_t>(H) * valid_w * kMoments);
    for (int r = 0; r < H; ++r) {
        for (int c = 0; c < valid_w; ++c) {
            double m[kMoments] = {};
            for (int k = 0; k < kTaps; ++k) {
                const std::size_t i = static_cast<std::size_t>(r) * W + c + k;
                const double w = weight[k];
                m[X] += w * x[i];
                m[Y] += w * y[i];
                m[XX] += w * x[i] * x[i];
                m[YY] += w * y[i] * y[i];
                m[XY] += w * x[i] * y[i];
            }
            std::copy(m, m + kMoments, &rows[(static_cast<std::size_t>(r) * valid_w + c) * kMoments]);
        }
    }

    double ssim_sum = 0;
    for (int r = 0; r < valid_h; ++r) {
        for (int c = 0; c < valid_w; ++c) {
            double m[kMoments] = {};
            for (int k = 0; k < kTaps; ++k) {
                const double* src = &rows[(static_cast<std::size_t>(r + k) * valid_w + c) * kMoments];
                for (int j = 0; j < kMoments; ++j) m[j] += weight[k] * src[j];
            }
            ssim_sum += ssim_formula(m[X], m[Y], m[XX] - m[X] * m[X], m[YY] - m[Y] * m[Y],
                                     m[XY] - m[X] * m[Y]);
        }
    }
    return ssim_sum / (double(valid_w) * valid_h);
}

std::string neighbourhood_text(int neighbourhood) {
    return neighbourhood > 0 ? "matched within " + std::to_string(neighbourhood) + " px" : "";
}

std::vector<std::uint8_t> matched_differences(const Image& actual, const Image& expected, int neighbourhood) {
    require_same_size(actual, expected, "matched_differences");
    const int w = actual.width, h = actual.height;
    std::vector<std::uint8_t> d(static_cast<std::size_t>(w) * h);
    const int r = std::max(0, neighbourhood);
    // The smallest difference between `of`'s pixel at (x, y) and any pixel of `in` within r.
    const auto best_match = [&](const Image& of, const Image& in, int x, int y) {
        const std::uint8_t* p = of.at(x, y);
        int best = pixel_max_diff(p, in.at(x, y));
        for (int qy = std::max(0, y - r); qy <= std::min(h - 1, y + r) && best > 0; ++qy)
            for (int qx = std::max(0, x - r); qx <= std::min(w - 1, x + r) && best > 0; ++qx)
                best = std::min(best, pixel_max_diff(p, in.at(qx, qy)));
        return best;
    };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            // Both ways: the actual pixel has a match in the expected image, and the expected pixel has one in the
            // actual image. One way alone would match a missing point against the background beside it.
            const int one_way = r == 0 ? pixel_max_diff(actual.at(x, y), expected.at(x, y)) : best_match(actual, expected, x, y);
            const int both = r == 0 || one_way == 255 ? one_way : std::max(one_way, best_match(expected, actual, x, y));
            d[static_cast<std::size_t>(y) * w + x] = static_cast<std::uint8_t>(both);
        }
    return d;
}

ImageDiff compare_images(const Image& actual, const Image& expected,
                         const ImageTolerance& tolerance) {
    ImageDiff diff;
    diff.neighbourhood = std::max(0, tolerance.neighbourhood);
    diff.actual_width = actual.width, diff.actual_height = actual.height;
    diff.expected_width = expected.width, diff.expected_height = expected.height;
    if (actual.width != expected.width || actual.height != expected.height) {
        diff.size_mismatch = true;
        diff.ssim = 0;
        diff.rmse = std::numeric_limits<double>::quiet_NaN();
        diff.psnr = std::numeric_limits<double>::quiet_NaN();
        return diff;
    }

    diff.total_pixels = long(actual.width) * actual.height;
    const std::vector<std::uint8_t> matched = matched_differences(actual, expected, diff.neighbourhood);
    double squared_sum = 0;
    for (int y = 0; y < actual.height; ++y) {
        for (int x = 0; x < actual.width; ++x) {
            const std::uint8_t* a = actual.at(x, y);
            const std::uint8_t* e = expected.at(x, y);
            for (int c = 0; c < 3; ++c) {
                const double d = double(a[c]) - double(e[c]);
                squared_sum += d * d;
            }
            const int d = matched[static_cast<std::size_t>(y) * actual.width + x];
            ++diff.pixels_by_max_diff[d];
            diff.max_channel_diff = std::max(diff.max_channel_diff, d);
            if (d > tolerance.max_channel_diff) {
                if (diff.differing_pixels == 0) {
                    diff.diff_x0 = diff.diff_x1 = x;
                    diff.diff_y0 = diff.diff_y1 = y;
                }
                ++diff.differing_pixels;
                diff.diff_x0 = std::min(diff.diff_x0, x), diff.diff_x1 = std::max(diff.diff_x1, x);
                diff.diff_y0 = std::min(diff.diff_y0, y), diff.diff_y1 = std::max(diff.diff_y1, y);
            }
        }
    }
    if (diff.total_pixels > 0) diff.rmse = std::sqrt(squared_sum / (3.0 * double(diff.total_pixels)));
    // PSNR = 20 log10(MAX / RMSE) with MAX = 255.
    diff.psnr = diff.rmse > 0 ? 20.0 * std::log10(255.0 / diff.rmse)
                              : std::numeric_limits<double>::infinity();
    diff.ssim = ssim_luma(actual, expected);
    return diff;
}

long ImageDiff::pixels_over(int max_channel_diff) const {
    long over = 0;
    for (int d = std::clamp(max_channel_diff + 1, 0, 256); d < 256; ++d) over += pixels_by_max_diff[d];
    return over;
}

bool ImageDiff::within(const ImageTolerance& tolerance) const {
    if (std::max(0, tolerance.neighbourhood) != neighbourhood)
        throw Error("image comparison: judged with a neighbourhood of " + std::to_string(tolerance.neighbourhood) +
                    " but compared with " + std::to_string(neighbourhood) + " (compare again with that neighbourhood)");
    if (size_mismatch) return false;
    const long over = pixels_over(tolerance.max_channel_diff);
    // A budget is written as a decimal fraction, and e.g. 0.29 * 100 is 28.999999999999996 in
    // binary; the tiny relative slack lets exactly the written number of pixels pass.
    const double fraction = std::max(0.0, tolerance.max_differing_fraction);
    const double allowed = std::floor(fraction * double(total_pixels) * (1.0 + 1e-12));
    return double(over) <= allowed;
}

std::string ImageDiff::summary() const {
    if (size_mismatch)
        return "size mismatch: actual " + size_text(actual_width, actual_height) + ", expected " +
               size_text(expected_width, expected_height);
    char line[256];
    const double percent = total_pixels > 0 ? 100.0 * double(differing_pixels) / double(total_pixels) : 0.0;
    int n = std::snprintf(line, sizeof line, "max diff %d, %ld of %ld px differ (%.2f%%)",
                          max_channel_diff, differing_pixels, total_pixels, percent);
    if (neighbourhood > 0) n += std::snprintf(line + n, sizeof line - n, ", %s", neighbourhood_text(neighbourhood).c_str());
    if (differing_pixels > 0)
        n += std::snprintf(line + n, sizeof line - n, " in [%d,%d]-[%d,%d]", diff_x0, diff_y0,
                           diff_x1, diff_y1);
    if (std::isinf(psnr))
        n += std::snprintf(line + n, sizeof line - n, ", PSNR inf dB");
    else
        n += std::snprintf(line + n, sizeof line - n, ", PSNR %.1f dB", psnr);
    std::snprintf(line + n, sizeof line - n, ", SSIM %.3f", ssim);
    return line;
}

Image difference_heatmap(const Image& actual, const Image& expected, int max_channel_diff, int neighbourhood) {
    require_same_size(actual, expected, "difference_heatmap");
    Image heatmap(actual.width, actual.height);
    const std::vector<std::uint8_t> matched = matched_differences(actual, expected, neighbourhood);
    const std::size_t pixel_count = heatmap.rgba.size() / 4;
    for (std::size_t p = 0; p < pixel_count; ++p) {
        const std::uint8_t* e = expected.rgba.data() + p * 4;
        const int over = int(matched[p]) - max_channel_diff;
        std::uint8_t* out = heatmap.rgba.data() + p * 4;
        if (over > 0) {
            out[0] = 255;
            out[1] = std::uint8_t(std::min(255, 4 * (over - 1)));
            out[2] = 0;
        } else {
            out[0] = out[1] = out[2] = std::uint8_t((e[0] + e[1] + e[2]) / 9);  // a third of the grey
        }
        out[3] = 255;
    }
    return heatmap;
}

long not_done_pixels(const Image& image) {
    static_assert(kNotDoneRgb[0] == kNotDoneRgb[2] && kNotDoneRgb[1] == 0, "the test below is for magenta");
    long count = 0;
    const std::size_t bytes = image.rgba.size();
    for (std::size_t i = 0; i + 4 <= bytes; i += 4) {
        const int r = image.rgba[i], g = image.rgba[i + 1], b = image.rgba[i + 2];
        count += r > 100 && g < 20 && std::abs(r - b) < 4;
    }
    return count;
}

bool is_blank(const Image& image) {
    const std::size_t bytes = image.rgba.size();
    for (std::size_t i = 4; i + 4 <= bytes; i += 4)
        if (std::memcmp(image.rgba.data() + i, image.rgba.data(), 4) != 0) return false;
    return true;
}

FloatStats float_stats(const ImageF& image) {
    FloatStats stats;
    bool seen_finite = false;
    for (float v : image.rgba) {
        if (std::isnan(v)) {
            ++stats.nan_count;
        } else if (std::isinf(v)) {
            ++stats.inf_count;
        } else if (!seen_finite) {
            stats.min = stats.max = v;
            seen_finite = true;
        } else {
            stats.min = std::min(stats.min, v);
            stats.max = std::max(stats.max, v);
        }
    }
    return stats;
}

}  // namespace gsv
