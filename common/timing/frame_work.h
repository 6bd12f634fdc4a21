#pragma once
// What a frame asks of the device, and what the device allows: the roofline of issue 44.
// A lab states its work per frame from its settings and its own loop structure (Lab::frame_work): texture fetches by
// format, filter and shader path, bytes moved through storage buffers, fragments written, floating-point operations,
// triangles drawn.
// gsv-ceilings (tools/) measures each resource's ceiling on this device, one benchmark saturating each. A frame's
// bound is the time its most demanding resource needs at its ceiling; the fraction reached is that bound over the
// measured frame time, and it cannot exceed 1: a frame measured faster than its bound was not waited for.
#include "common/io/json.h"

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gsv {

// Triangles: each one a draw call sends down the pipeline (indexed, as the labs' meshes are), culled or drawn: its
// share of the vertex shading, its assembly, its cull test or its setup and raster. A mesh of many small triangles is
// bound by them, not by its fill.
enum class WorkKind { Fetch, StorageBytes, Fragments, Flops, Triangles };
// Datacenter GPUs run fragment shaders on a few units only: a ceiling belongs to a path, not to the device.
enum class ShaderPath { Fragment, Compute };

const char* work_kind_name(WorkKind kind);
const char* shader_path_name(ShaderPath path);

// One resource a frame uses, and how much of it. A fetch names its texture: the texel format and dimension as
// gsv-ceilings measures them ("RG32F 2D", "R32F 3D"), filtered bilinearly (trilinearly in 3D), or "R32F buffer": a
// buffer texture's texels, read with texelFetch (no filter). Fragments and triangles have no shader path: they are
// the pipeline's fixed stages (their path stays Fragment).
struct WorkItem {
    WorkKind kind = WorkKind::Fetch;
    ShaderPath path = ShaderPath::Fragment;
    std::string texture;  // Fetch only
    double amount = 0;    // fetches, bytes, fragments, operations or triangles per frame
    std::string what;     // where it comes from, in words: "1 + 4L per pixel, L = 25"

    // The ceiling it is measured against: "fetch RG32F 2D fragment", "fetch R32F buffer fragment", "storage compute",
    // "fragments", "flops fragment", "triangles".
    std::string ceiling_key() const;
    std::string unit() const;  // "fetches", "bytes", "fragments", "flops", "triangles"
    // The resource it takes its turn on: every lookup of a shader path shares the texture units ("texture
    // (fragment)"); the others are their ceilings'.
    std::string resource() const;
};

struct FrameWork {
    std::vector<WorkItem> items;
    // "at most": the count is the loop's full length (a streamline or ray that ends early does less).
    bool upper_bound = false;
    bool empty() const { return items.empty(); }
    // One line per item: "  106.0 M fetches, RG32F 2D, fragment: 1 + 4L per pixel ...".
    std::string describe(const std::string& indent = "  ") const;
    // One short cell for a table or CSV: "106M fetch RG32F 2D fragment + 26M fetch RGB32F 2D fragment".
    std::string summary() const;
};

// The key of two textures' lookups taking turns ("fetch RG32F 2D + RGB32F 2D fragment"): LIC's flow, then its input.
std::string pair_ceiling_key(const std::string& flow_texture, const std::string& input_texture, ShaderPath path);

// A measured ceiling: the resource's rate per second over interleaved rounds, the median with the spread of the
// rounds. What a bound uses is fastest(): the fastest round, the most this device was seen to do.
struct Ceiling {
    Ceiling() = default;
    Ceiling(std::string key, double rate, double low, double high, std::string unit, std::vector<double> runs = {})
        : key(std::move(key)), rate(rate), low(low), high(high), unit(std::move(unit)), runs(std::move(runs)) {}

    std::string key;
    double rate = 0;          // per second, the median of every round
    double low = 0, high = 0; // the slowest and the fastest round
    std::string unit;
    // Measured in several runs (gsv-ceilings --runs): each run's fastest round, in order; high is the fastest of
    // them. Empty for one run.
    std::vector<double> runs;
    double fastest() const { return high > rate ? high : rate; }
};

struct Ceilings {
    std::string renderer;  // the GL renderer string: the device they were measured on
    std::vector<Ceiling> rates;
    const Ceiling* find(const std::string& key) const;

    Json to_json() const;
    // Throws gsv::Error naming the file and the member on a malformed file.
    static Ceilings from_json(const Json& json);
};

Ceilings read_ceilings(const std::filesystem::path& path);
void write_ceilings(const std::filesystem::path& path, const Ceilings& ceilings);
// Where a lab looks for the ceilings measured once on this machine: $GSV_CEILINGS, else ceilings.json in the build
// folder (beside bin/, where gsv-ceilings writes it). Read only when their renderer is `renderer`: another
// device's ceilings would give another device's fractions. None when there are none (nothing is measured at start:
// a window must never stall).
std::optional<Ceilings> cached_ceilings(const std::filesystem::path& executable, const std::string& renderer);

// A frame's work against the ceilings: the bound (the slowest resource at its ceiling), the resource named, and
// the fraction of that bound a measured frame time reaches.
struct Roofline {
    // The bound: the work at every benchmark's fastest round, the most this device was seen to do. A machine's load
    // only ever slows a round, so the fastest is the ceiling, and no frame of this work can take less; a frame faster
    // than it did not wait for the device (check_within_ceiling).
    double bound_ms = 0;
    // The same work at the benchmarks' median rounds: the spread a busy machine adds (render's JSON shows it).
    double median_bound_ms = 0;
    std::string limiter;          // the resource that bounds the frame (WorkItem::resource)
    std::vector<std::string> unmeasured;  // work whose resource has no ceiling measured
    // The work was the most the frame can do (FrameWork::upper_bound): the fraction is then at most this, and a frame
    // faster than the bound says the statement is loose (rays that end early), not that the timing is wrong.
    bool upper_bound = false;
    double fraction(double measured_ms) const { return measured_ms > 0 ? bound_ms / measured_ms : 0; }
    // "41% of this device's texture (fragment) ceiling"; "at most 41% ..." for an upper bound of the work.
    std::string describe(double measured_ms) const;
};

// None when no item of the work has a ceiling.
std::optional<Roofline> roofline(const FrameWork& work, const Ceilings& ceilings);

// Throws gsv::Error when the measured time is below the fastest bound: the frame ran faster than the device allows
// (its fraction is above 1 however the ceilings' rounds are taken), so the timing did not wait for the device (the
// seed's mistake) or the work is overstated.
void check_within_ceiling(const Roofline& bound, double measured_ms, const std::string& what);

}  // namespace gsv
