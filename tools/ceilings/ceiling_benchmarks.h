#pragma once
// gsv-ceilings' benchmarks: small GL programs that each saturate one resource (bilinear lookups of one texel format in
// a fragment or a compute shader, texelFetch from a buffer texture, storage-buffer bandwidth, fill, triangles, FP32
// arithmetic), timed against each other, interleaved, with glFinish and a steady clock (common/timing/timing.h). On
// llvmpipe they measure the CPU, on a GPU the GPU; the renderer string says which. Their keys are WorkItem::ceiling_key()'s, so a lab's work per frame
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
    // 9 rounds: on a 2-core machine with llvmpipe a stray process slows a round or two of five, and three runs of
    // 5 rounds differed by up to 13.9%; with 9 each benchmark has rounds enough to meet a quiet moment (three times
    // three runs within 7.1%, 7.6% and 7.2%).
    int frames = 3, rounds = 9;
    int runs = 1;                      // the whole set measured this many times, each run its own rounds
    std::vector<std::string> only;     // keys to measure; empty: all
};

// Every benchmark's key, in the order they are measured.
std::vector<std::string> ceiling_keys();

// Measures the ceilings on the current context (OpenGL 4.3 or later: the compute ones need it), options.runs times,
// each run its own interleaved rounds. A round's rate is its frames' median; each ceiling's rate is the median of
// every round of every run, low and high the slowest and the fastest round of all (high: what a bound uses), and,
// for more than one run, runs holds each run's fastest round. Throws gsv::Error naming a benchmark that fails to build
// or draw.
Ceilings measure_ceilings(const CeilingOptions& options, const std::string& renderer);

// One benchmark's frame, to draw `frames` times as measure_ceilings does (no glFinish: the caller times it): for a
// test that times the same work another way. Throws gsv::Error for a key ceiling_keys() does not list.
std::function<void(int frames)> ceiling_frame(const CeilingOptions& options, const std::string& key);

// The table gsv-ceilings prints: key, the ceiling the bounds use (the fastest round), the median with the rounds'
// range as a share of it, the unit; measured in several runs, each run's ceiling and how far apart they are ("runs
// within 7.8%": the largest over the smallest), and a last line naming the widest.
std::string ceilings_table(const Ceilings& ceilings);

}  // namespace gsv
