#pragma once
// 2D velocity fields on a texel grid, the input of the line integral convolution labs. Velocities are in
// TEXELS PER STEP: the shader advances a streamline by velocity / textureSize per step, so a field made
// with max_texels_per_step = 1 never jumps more than one texel and the LIC kernel length in steps is
// also (at most) its length in texels. No GL here, so all of it is testable without a context.
//
// Analytic fields are defined on a domain rectangle that is stretched over the whole grid, and sampled
// at texel CENTRES in double precision. Their velocities are carried from domain units into texel units
// (multiplied by texels per domain unit along each axis) before anything else, so a streamline traced in
// texels is the analytic streamline even when the grid is not square. Then the field is scaled so its
// largest speed is exactly max_texels_per_step (a field that is zero everywhere stays zero).
//
// The .flow file format (also described in data/README.md):
//   an ASCII line  "GSVFLOW 1 <width> <height>\n"  (magic, format version 1, decimal sizes 1..8192),
//   then width*height*2 little-endian IEEE 754 float32 values (vx, vy) in texels per step, row-major,
//   row 0 = the BOTTOM row (GL texture order), and nothing after them. Every value must be finite.
#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

struct FlowField {
    int width = 0, height = 0;
    // Two floats (vx, vy) per texel, row-major, row 0 = the bottom row; size 2*width*height.
    std::vector<float> velocity;

    // Velocity of texel (x, y), y counted from the bottom. Throws gsv::Error outside the grid.
    glm::vec2 at(int x, int y) const;
    // The largest speed |v| over all texels; 0 for an empty or all-zero field.
    float max_speed() const;
};

enum class FlowKind { Rotation, Saddle, Source, DoubleGyre, Vortices };

// "rotation", "saddle", "source", "double_gyre", "vortices"; any other name throws gsv::Error listing
// these.
FlowKind flow_kind_from_name(const std::string& name);
const char* flow_kind_name(FlowKind kind);

// Samples an analytic field (domains and formulas at FlowKind's cases in flow_field.cpp):
//   Rotation    [-1,1]^2      v = (-y, x)        circles about the centre, counter-clockwise
//   Saddle      [-1,1]^2      v = (x, -y)        in along y, out along x
//   Source      [-1,1]^2      v = (x, y)         outward from a stagnation point at the centre
//   DoubleGyre  [0,2]x[0,1]   Shadden, Lekien and Marsden (2005), A = 0.1, eps = 0.25, period 10; uses `time`
//   Vortices    [-1,1]^2      six Lamb-Oseen vortices drawn from `seed` (vortices_from_seed)
// Throws gsv::Error unless 1 <= width, height <= 8192, max_texels_per_step is finite and >= 0, and
// time is finite.
FlowField make_flow(FlowKind kind, int width, int height, double max_texels_per_step, double time = 0,
                    std::uint64_t seed = 0);

// One vortex of the Vortices field, in domain coordinates [-1,1]^2. Its velocity is the Lamb-Oseen
// profile s (-(y-y0), x-x0) / r^2 * (1 - exp(-r^2/c^2)): a solid-body core of radius ~c, and 1/r decay
// like a point vortex outside it.
struct Vortex {
    double x = 0, y = 0;
    int sign = 1;               // +1 counter-clockwise, -1 clockwise
    double core_radius = 0.25;  // c, must be positive
};

inline constexpr int kVortexCount = 6;

// kVortexCount vortices with centres in [-0.8,0.8]^2, random signs and core radii in [0.15,0.4], from
// gsv::hash64 so a seed gives the same field everywhere.
std::vector<Vortex> vortices_from_seed(std::uint64_t seed);

// Velocity of one vortex at domain point p, in domain units. At r = 0 it is the r -> 0 limit (zero),
// and near it the series of the core, so no NaN and no loss of precision at or near a centre.
glm::dvec2 vortex_velocity(const Vortex& vortex, glm::dvec2 p);

// The sum of the given vortices' velocities, sampled and scaled like make_flow. make_flow(Vortices, ...)
// is make_vortex_flow(vortices_from_seed(seed), ...). Throws gsv::Error for bad sizes or scale, or a
// core radius that is not positive and finite.
FlowField make_vortex_flow(const std::vector<Vortex>& vortices, int width, int height,
                           double max_texels_per_step);

// A counter-clockwise swirl for photographic LIC: solid-body rotation about (cx, cy), given in [0,1]^2
// texture coordinates, out to radius/2, then fading smoothly (smoothstep) to exactly zero at `radius`
// and beyond, so LIC smears that disc and leaves the rest of the photo sharp. Distances are measured in
// texels so the disc is round on a non-square photo; `radius` is a fraction of the shorter side (0.5
// with centre (0.5, 0.5) is the largest disc that fits). The centre itself does not move, as in any
// rotation. Throws gsv::Error for bad sizes or scale, non-finite cx, cy, or a radius not finite and >= 0.
FlowField make_photo_swirl(int width, int height, double max_texels_per_step, double cx, double cy,
                           double radius);

// Reads a .flow file (format above). Throws gsv::Error with one line naming the file for: a missing or
// unreadable file, bad magic or version, a size outside 1..8192, too few bytes of velocities ("expected
// N bytes of velocities, found M"), bytes after them, or a NaN or infinite value (naming its texel).
FlowField load_flow(const std::filesystem::path& path);

// Writes `field` as a .flow file, byte-for-byte the same on every host. Throws gsv::Error for a field
// load_flow would refuse (bad size, velocity count not 2*width*height, a non-finite value) or a file that
// cannot be written.
void save_flow(const std::filesystem::path& path, const FlowField& field);

}  // namespace gsv
