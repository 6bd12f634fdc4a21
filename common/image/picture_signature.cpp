#include "common/image/picture_signature.h"

#include "common/core/error.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace gsv {
namespace {

// Below this (levels of 255, over six channels) a mistake's signature is the golden's: nothing to match it by.
constexpr double kLeastDifference = 0.2;
// A picture is a mistake's where it is nearer to it than this share of the way from the mistake to the golden.
constexpr double kNearShare = 1.0 / 3.0;

std::uint8_t level(double v) { return static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L)); }

}  // namespace

int signature_block(int width, int height) { return std::max(1, (std::max(width, height) + 31) / 32); }

PictureSignature picture_signature(const Image& image, int block) {
    if (block <= 0) throw Error("a picture signature needs a positive block size, not " + std::to_string(block));
    if (image.empty()) throw Error("a picture signature needs a picture, not an empty one");
    const int w = image.width, h = image.height;
    std::vector<float> brightness(static_cast<std::size_t>(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::uint8_t* p = image.at(x, y);
            brightness[static_cast<std::size_t>(y) * w + x] = (p[0] + p[1] + p[2]) / 3.0f;
        }
    const auto at = [&](int x, int y) {
        return brightness[static_cast<std::size_t>(std::clamp(y, 0, h - 1)) * w + std::clamp(x, 0, w - 1)];
    };
    PictureSignature s;
    s.block = block;
    const int bw = (w + block - 1) / block, bh = (h + block - 1) / block;
    s.colour = Image(bw, bh);
    s.texture = Image(bw, bh);
    for (int by = 0; by < bh; ++by)
        for (int bx = 0; bx < bw; ++bx) {
            double rgb[3] = {0, 0, 0}, xx = 0, yy = 0, xy = 0;
            int n = 0;
            for (int y = by * block; y < std::min(h, (by + 1) * block); ++y)
                for (int x = bx * block; x < std::min(w, (bx + 1) * block); ++x) {
                    const std::uint8_t* p = image.at(x, y);
                    for (int c = 0; c < 3; ++c) rgb[c] += p[c];
                    const double dx = (at(x + 1, y) - at(x - 1, y)) / 2.0, dy = (at(x, y + 1) - at(x, y - 1)) / 2.0;
                    xx += dx * dx;
                    yy += dy * dy;
                    xy += dx * dy;
                    ++n;
                }
            std::uint8_t* c = s.colour.at(bx, by);
            for (int k = 0; k < 3; ++k) c[k] = level(rgb[k] / n);
            c[3] = 255;
            std::uint8_t* t = s.texture.at(bx, by);
            const double rx = std::sqrt(xx / n), ry = std::sqrt(yy / n);
            // The correlation of the two derivatives: +1 streaks along one diagonal, -1 along the other, 0 along an axis
            // or none (a flat block).
            const double correlation = rx * ry > 1e-6 ? (xy / n) / (rx * ry) : 0.0;
            // Coarse steps: a texture's strength to a quarter, its direction to a sixteenth (they compress, and the
            // next renderer's noise stays in its step).
            t[0] = static_cast<std::uint8_t>(level(rx) / 4 * 4);
            t[1] = static_cast<std::uint8_t>(level(ry) / 4 * 4);
            t[2] = static_cast<std::uint8_t>(level(127.5 + 127.5 * correlation) / 16 * 16);
            t[3] = 255;
        }
    return s;
}

double signature_distance(const PictureSignature& a, const PictureSignature& b) {
    if (a.colour.width != b.colour.width || a.colour.height != b.colour.height || a.texture.width != b.texture.width ||
        a.texture.height != b.texture.height)
        throw Error("picture signatures of different sizes (" + std::to_string(a.colour.width) + "x" + std::to_string(a.colour.height) +
                    " and " + std::to_string(b.colour.width) + "x" + std::to_string(b.colour.height) + " blocks)");
    double sum = 0;
    std::size_t n = 0;
    for (const auto* pair : {&a.colour, &a.texture}) {
        const Image& other = pair == &a.colour ? b.colour : b.texture;
        for (std::size_t i = 0; i < pair->rgba.size(); i += 4)
            for (int c = 0; c < 3; ++c, ++n) sum += std::abs(int(pair->rgba[i + c]) - int(other.rgba[i + c]));
    }
    return n ? sum / static_cast<double>(n) : 0.0;
}

bool signature_matches(const PictureSignature& picture, const PictureSignature& mistake, const PictureSignature& golden) {
    const double apart = signature_distance(mistake, golden);
    return apart >= kLeastDifference && signature_distance(picture, mistake) <= kNearShare * apart;
}

PictureSignature composed_signature(const PictureSignature& first, const PictureSignature& second, const PictureSignature& golden,
                                    Composition how) {
    signature_distance(first, golden);  // the sizes checked
    signature_distance(second, golden);
    PictureSignature out = golden;
    const auto level = [](double v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 255.0))); };
    for (const bool colour : {true, false}) {
        const Image& a = colour ? first.colour : first.texture;
        const Image& b = colour ? second.colour : second.texture;
        Image& o = colour ? out.colour : out.texture;
        for (std::size_t i = 0; i < o.rgba.size(); i += 4)
            for (int c = 0; c < 3; ++c) {
                const double g = o.rgba[i + c], x = a.rgba[i + c], y = b.rgba[i + c];
                o.rgba[i + c] = level(colour && how == Composition::Multiplied ? x * y / std::max(g, 1.0) : x + y - g);
            }
    }
    return out;
}

Image signature_picture(const PictureSignature& signature, int width, int height) {
    const Image& small = signature.colour;
    Image out(width, height);
    if (small.empty()) return out;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            // The block centres: pixel (x, y) of the full picture lies at block coordinate (x + 0.5) / block - 0.5.
            const double fx = std::clamp((x + 0.5) / signature.block - 0.5, 0.0, small.width - 1.0);
            const double fy = std::clamp((y + 0.5) / signature.block - 0.5, 0.0, small.height - 1.0);
            const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
            const int x1 = std::min(x0 + 1, small.width - 1), y1 = std::min(y0 + 1, small.height - 1);
            const double tx = fx - x0, ty = fy - y0;
            std::uint8_t* p = out.at(x, y);
            for (int c = 0; c < 3; ++c) {
                const double top = small.at(x0, y0)[c] * (1 - tx) + small.at(x1, y0)[c] * tx;
                const double bottom = small.at(x0, y1)[c] * (1 - tx) + small.at(x1, y1)[c] * tx;
                p[c] = level(top * (1 - ty) + bottom * ty);
            }
            p[3] = 255;
        }
    return out;
}

}  // namespace gsv
