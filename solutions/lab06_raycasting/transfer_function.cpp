#include "transfer_function.h"

#include <algorithm>
#include <array>

namespace lab06 {
namespace {

using Point = std::array<float, 5>;  // intensity, r, g, b, opacity

std::vector<Point> control_points(TransferFunction preset) {
    switch (preset) {
    case TransferFunction::Grey: return {{0.0f, 0, 0, 0, 0}, {0.15f, 0.2f, 0.2f, 0.2f, 0}, {1.0f, 1, 1, 1, 0.4f}};
    case TransferFunction::Bands:
        return {{0.0f, 0, 0, 0, 0},           {0.33f, 0.1f, 0.3f, 0.9f, 0},   {0.4f, 0.1f, 0.4f, 0.95f, 0.3f},
                {0.45f, 0.1f, 0.3f, 0.9f, 0}, {0.47f, 0.95f, 0.85f, 0.2f, 0}, {0.52f, 0.95f, 0.85f, 0.2f, 0.6f},
                {0.57f, 0.9f, 0.8f, 0.2f, 0}, {0.62f, 0.9f, 0.2f, 0.1f, 0},   {0.7f, 0.9f, 0.2f, 0.1f, 0.8f},
                {0.78f, 0.9f, 0.2f, 0.1f, 0}, {1.0f, 0, 0, 0, 0}};
    // The windowed MRI brain (sources.cpp): cerebrospinal fluid about 0.1-0.35, grey matter 0.45-0.65, white matter
    // 0.75-0.95, the brightest 0.5% of voxels at 1. The fluid of the ventricles opaque blue; grey matter all but clear, so
    // the structures inside show through it; white matter from faint to dense cream, the densest (the corpus
    // callosum's arc) opaque enough that MIP, which classifies one sample a ray, shows it bright.
    case TransferFunction::Tissue:
        return {{0.0f, 0, 0, 0, 0},
                {0.08f, 0.2f, 0.4f, 0.9f, 0},
                {0.14f, 0.25f, 0.5f, 1.0f, 0.6f},
                {0.3f, 0.3f, 0.55f, 1.0f, 0.6f},
                {0.38f, 0.4f, 0.5f, 0.8f, 0},
                {0.45f, 0.9f, 0.55f, 0.45f, 0.015f},
                {0.7f, 0.95f, 0.75f, 0.6f, 0.015f},
                {0.8f, 1.0f, 0.9f, 0.8f, 0.1f},
                {0.9f, 1.0f, 0.96f, 0.92f, 0.45f},
                {1.0f, 1, 1, 1, 0.8f}};
    }
    return {};
}

}  // namespace

std::vector<float> transfer_function_table(TransferFunction preset) {
    const std::vector<Point> points = control_points(preset);
    std::vector<float> table;
    table.reserve(4 * kTransferFunctionEntries);
    for (int i = 0; i < kTransferFunctionEntries; ++i) {
        // Entry i is read at its texel centre, intensity (i + 0.5) / N, under linear filtering.
        const float x = (static_cast<float>(i) + 0.5f) / kTransferFunctionEntries;
        auto upper = std::find_if(points.begin(), points.end(), [x](const Point& p) { return p[0] >= x; });
        if (upper == points.begin()) upper = points.begin() + 1;
        if (upper == points.end()) upper = points.end() - 1;
        const Point& a = *(upper - 1);
        const Point& b = *upper;
        const float w = std::clamp((x - a[0]) / (b[0] - a[0]), 0.0f, 1.0f);
        for (int c = 1; c < 5; ++c) table.push_back(a[c] + w * (b[c] - a[c]));
    }
    return table;
}

}  // namespace lab06
