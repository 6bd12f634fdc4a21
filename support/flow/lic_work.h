#pragma once
// The work of a LIC frame (labs 02 and 03), counted from the shaders' loops: the pixel's own sample, then per
// direction `length` steps, each reading the flow once (Euler) or twice (midpoint: at the point and half way) and the
// input once at the new point. With Euler both ways that is 1 + 4L fetches a pixel (issue 44's bound for the seed).
// It is the most a pixel does: a streamline that leaves the field stops there.
#include "common/timing/frame_work.h"

#include <string>

namespace gsv {

struct LicLoops {
    int width = 0, height = 0;
    int length = 0;          // steps each way
    int directions = 2;      // 2: both ways; 1: forward only
    int flow_reads_per_step = 1;  // 1: Euler; 2: midpoint
    std::string input_texture;    // "RGB32F 2D", ...
    std::string flow_texture;     // "RG32F 2D", ...
    int flow_fetches_per_read = 1;  // lab 03: a read of the flow between two time slices can take two lookups
};

FrameWork lic_work(const LicLoops& loops);

}  // namespace gsv
