#pragma once
// gsv-ceilings' benchmarks: small GL programs that each saturate one resource (bilinear lookups of one texel format in
// a fragment or a compute shader, storage-buffer bandwidth, fill, FP32 arithmetic), timed against each other,
// interleaved, with glFinish and a steady clock (common/timing/timing.h). On llvmpipe they measure the CPU, on a GPU
// the GPU; the renderer string says which. Their keys are WorkItem::ceiling_key()'s, so a lab's work per frame
// (Lab::frame_work) meets its ceiling by name.
#include "common/timing/frame_work.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace gsv {

struct CeilingOptions {
    std::filesystem::path shader_dir;  // tools/ceilings/ (its .frag and .comp files)
    std::filesystem::path kit_shaders; // shaders/ (the prelude, gsv/fullscreen.vert)
    int side = 512;                    // fragment targets and compute grids are side x side
    std::size_t storage_items = 1 << 21;  // vec4s copied a dispatch: 2 Mi items are 32 MiB each way
    int frames = 3, rounds = 5;
    std::vector<std::string> only;     // keys to measure; empty: all
};

// Every benchmark's key, in the order they are measured.
std::vector<std::string> ceiling_keys();

// Measures the ceilings on the current context (OpenGL 4.3 or later: the compute ones need it). Each rate is the
// median over all rounds; low and high the slowest and fastest round's median. Throws gsv::Error naming a
// benchmark that fails to build or draw.
Ceilings measure_ceilings(const CeilingOptions& options, const std::string& renderer);

// One benchmark's frame, to draw `frames` times as measure_ceilings does (no glFinish: the caller times it): for a
// test that times the same work another way. Throws gsv::Error for a key ceiling_keys() does not list.
std::function<void(int frames)> ceiling_frame(const CeilingOptions& options, const std::string& key);

// The table gsv-ceilings prints: key, rate, spread (the rounds' range as a share of the median) and unit.
std::string ceilings_table(const Ceilings& ceilings);

}  // namespace gsv
