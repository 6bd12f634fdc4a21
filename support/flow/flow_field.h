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
//   an ASCII line  "GSVFLOW 1 <width> <height>\n"  (magic, format version 1, decimal sizes 1..8192) for one
//   field, or  "GSVFLOW 1 <width> <height> <frames>\n"  (frames 1..4096) for a time-varying flow,
//   then frames*width*height*2 little-endian IEEE 754 float32 values (vx, vy) in texels per step, frame
//   after frame (a header without <frames> means one), each frame row-major with row 0 = the BOTTOM row
//   (GL texture order), and nothing after them. Every value must be finite, and the values may take at
//   most kMaxFlowBytes (1 GiB). The optional fourth field keeps version 1: every file written before
//   sequences existed still reads the same.
#include "common/core/enum_names.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
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

// A time-varying flow for lab 03: frames sampled at equal steps of time, all width x height, scaled
// together (one factor for all frames, so a slower frame stays slower).
struct FlowSequence {
    int width = 0, height = 0;
    std::vector<FlowField> frames;

    // The largest speed over all frames; 0 for no frames or an all-zero sequence.
    float max_speed() const;
};

// The limits of a field and of a .flow file: sides of 8192 texels, 4096 frames and 1 GiB of velocities (32
// frames of 2048x2048). Far above what a lab uploads as a texture array, but a bound, so that a corrupt
// header is refused before anything is allocated for it rather than after gigabytes of it.
inline constexpr int kMaxFlowSide = 8192;
inline constexpr int kMaxFlowFrames = 4096;
inline constexpr std::uint64_t kMaxFlowBytes = std::uint64_t(1) << 30;

enum class FlowKind { Rotation, Saddle, Source, DoubleGyre, Vortices };
inline constexpr EnumName<FlowKind> kFlowKindNames[] = {{FlowKind::Rotation, "rotation"},
                                                        {FlowKind::Saddle, "saddle"},
                                                        {FlowKind::Source, "source"},
                                                        {FlowKind::DoubleGyre, "double_gyre"},
                                                        {FlowKind::Vortices, "vortices"}};

// A name of kFlowKindNames; any other throws gsv::Error listing them.
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

// A continuous velocity field: the velocity in texels per step at any point in TEXEL coordinates (texel (i, j)'s
// centre at (i + 0.5, j + 0.5), y from the bottom; the grid is [0,width]x[0,height]).
using VelocityAt = std::function<glm::dvec2(glm::dvec2)>;

// The field make_flow samples, everywhere: the same domain, the same carrying into texels and the same scale
// factor (which make_flow finds at the texel centres), so at a texel centre it is make_flow's velocity before
// the rounding to float, bit for bit. Beyond the grid it continues the formulas. For exact streamlines (the
// reference of lab 02's sweep, lic_reference.h) rather than a texture. Throws as make_flow does.
VelocityAt analytic_flow(FlowKind kind, int width, int height, double max_texels_per_step, double time = 0,
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

// make_photo_swirl's field everywhere, as analytic_flow is make_flow's. Throws as make_photo_swirl does.
VelocityAt analytic_photo_swirl(int width, int height, double max_texels_per_step, double cx, double cy,
                                double radius);

// A von Karman vortex street on [0,2]x[0,1] (formulas and sources in vortex_street.cpp): a uniform stream
// to the right plus two staggered rows of counter-rotating Lamb-Oseen vortices (vortex_velocity) that
// drift downstream, slower than the stream. `phase` is time in periods: after one period the pattern has
// drifted exactly one vortex spacing and is the same again, so phase and phase + 1 give the same velocity
// (to rounding) at every point. Velocity in domain units; throws gsv::Error for a non-finite phase.
glm::dvec2 vortex_street_velocity(glm::dvec2 p, double phase);

// The speed at which the street's vortices drift downstream, U - u_s, in the domain units of
// vortex_street_velocity: the velocity of the frame in which they stand still.
double vortex_street_drift();

// `frames` frames of the vortex street, frame k at phase k / frames: one period, so the sequence loops
// seamlessly (the frame after the last would be frame 0 again). All frames share one scale factor that
// makes the largest speed over the whole sequence max_texels_per_step. Throws gsv::Error for sizes or
// scale make_flow refuses, frames outside 1..kMaxFlowFrames, or a sequence over kMaxFlowBytes.
FlowSequence make_vortex_street(int width, int height, int frames, double max_texels_per_step);

// `frames` frames of the double gyre, frame k at time 10 k / frames: one period, so this sequence loops
// too. Scaled like make_vortex_street, with one factor for all frames: frame k is
// make_flow(DoubleGyre, width, height, max_texels_per_step, 10 k / frames) times a ratio <= 1, the same
// for every texel of the frame. Throws as make_vortex_street does.
FlowSequence make_double_gyre_sequence(int width, int height, int frames, double max_texels_per_step);

// The time-varying flows, each periodic with period 10 (the double gyre's; one vortex spacing of drift
// for the street).
enum class UnsteadyKind { DoubleGyre, VortexStreet };
inline constexpr EnumName<UnsteadyKind> kUnsteadyKindNames[] = {{UnsteadyKind::DoubleGyre, "double_gyre"},
                                                                {UnsteadyKind::VortexStreet, "vortex_street"}};
inline constexpr double kUnsteadyPeriod = 10.0;

// How T time slices of such a flow are read at a playhead (lab 03; reference/flow/time_slices.h mixes them on the CPU):
// a periodic flow wraps, after slice T - 1 comes slice 0, any other stops at the last; the nearest slice, or linear
// in time between two.
enum class TimeWrap { Repeat, Clamp };
enum class TimeBlend { Nearest, Linear };
inline constexpr EnumName<TimeWrap> kTimeWrapNames[] = {{TimeWrap::Repeat, "repeat"}, {TimeWrap::Clamp, "clamp"}};
inline constexpr EnumName<TimeBlend> kTimeBlendNames[] = {{TimeBlend::Nearest, "nearest"}, {TimeBlend::Linear, "linear"}};
inline constexpr int kUnsteadyScaleTimes = 64;

// A name of kUnsteadyKindNames; any other throws gsv::Error listing them.
UnsteadyKind unsteady_kind_from_name(const std::string& name);

// Frames at the given times, scaled by ONE factor that depends on the flow and the grid only, not on the
// times asked for: the one that makes the largest speed over kUnsteadyScaleTimes evenly spaced times of
// the period max_texels_per_step. So sequences made for different sets of times agree wherever their
// times coincide (lab 03's T slices against its 256-slice reference), which make_double_gyre_sequence's
// scale over the requested frames does not promise. Throws as make_vortex_street does, and for a
// non-finite time.
FlowSequence make_unsteady_flow(UnsteadyKind kind, int width, int height, const std::vector<double>& times,
                                double max_texels_per_step);

// Reads a .flow file (format above) that holds one field. Throws gsv::Error with one line naming the file
// for: a missing or unreadable file, bad magic or version, a size outside 1..8192, frames outside
// 1..4096 or more than one frame ("holds N frames; a single field is needed (lab 03 reads sequences)"),
// too few bytes of velocities ("expected N bytes of velocities, found M"), bytes after them, or a NaN or
// infinite value (naming its texel).
FlowField load_flow(const std::filesystem::path& path);

// Reads a .flow file with any number of frames (a file with the three-field header is one frame). Throws
// as load_flow does, except that many frames are welcome; a short file says in which frame the bytes ran
// out ("expected N bytes of velocities for F frames, found M: ..."), a non-finite value names its frame
// and texel (frames count from 0, like texels), and a header promising more than kMaxFlowBytes of
// velocities is refused before any is read.
FlowSequence load_flow_sequence(const std::filesystem::path& path);

// Writes `field` as a .flow file with the three-field header, byte-for-byte the same on every host.
// Throws gsv::Error for a field load_flow would refuse (bad size, velocity count not 2*width*height, a
// non-finite value) or a file that cannot be written.
void save_flow(const std::filesystem::path& path, const FlowField& field);

// Writes `sequence` with the four-field header (even for one frame, so the file says it is a sequence).
// Throws gsv::Error, before creating the file, for a sequence load_flow_sequence would refuse: a bad size
// or frame count, a frame whose size differs from the sequence's (naming the frame), a wrong velocity
// count, a non-finite value (naming frame and texel), or more than kMaxFlowBytes; or if the file cannot
// be written.
void save_flow_sequence(const std::filesystem::path& path, const FlowSequence& sequence);

}  // namespace gsv
