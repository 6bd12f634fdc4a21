#include "tools/ceilings/ceiling_benchmarks.h"

#include "common/core/error.h"
#include "common/gl/buffer.h"
#include "common/gl/buffer_texture.h"
#include "common/gl/compute.h"
#include "common/gl/framebuffer.h"
#include "common/gl/gl.h"
#include "common/gl/gpu_mesh.h"
#include "common/gl/texture.h"
#include "common/scene/mesh_data.h"
#include "common/shader/shader_program.h"
#include "common/timing/timing.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <utility>

namespace gsv {
namespace {

// Lookups a fragment or invocation, and multiply-add iterations: enough that the per-fragment overhead is small.
constexpr int kFetches = 16;
// Lookups a fragment of a pair (fetch_pair.frag): LIC-like, in a loop of a uniform count, not unrolled.
constexpr int kPairFetches = 64;
constexpr int kIterations = 64;
constexpr int kFlopsPerIteration = 32;  // four vec4 multiply-adds
constexpr int kFillQuads = 4;           // full-screen quads a fill frame
constexpr int kCopyGroups = 1024;       // work groups of 128 striding over the copied items
// The textures' sizes: a 2D texture about a LIC frame's, a volume about the ray caster's.
constexpr int kSide2d = 512, kLayers = 4, kSide3d = 64;
// The buffer texture (fetch_buffer.frag): 64 Ki texels, the size every OpenGL allows (GL_MAX_TEXTURE_BUFFER_SIZE is
// at least 65536), 20 times lab 07's default elements' values; a block of 8 x 8 fragments reads the same texels.
constexpr int kBufferTexels = 65536, kBufferTile = 8;
// The triangles' grid: as many cells each way as the target has pixels (drawn into a quarter of it: 16 cells a pixel),
// at most 2048 x 2048 cells (make_grid's limit is 4096 vertices).
constexpr int kMaxGridCells = 2048;

struct TextureKind {
    std::string format;     // "RG32F"
    std::string dimension;  // "2D", "2D array", "3D"
};

// The textures the labs read (their frame_work's names): each measured in a fragment shader, and the ones a compute
// shader reads (lab 05's velocity volume) or would read on a GPU's compute path also there.
const std::vector<TextureKind> kFragmentTextures{{"RGB32F", "2D"}, {"RG32F", "2D"},       {"R32F", "2D"},
                                                 {"RGBA8", "2D"},  {"RGBA32F", "2D"},     {"RG32F", "2D array"},
                                                 {"RG32F", "3D"},  {"R32F", "3D"},        {"RGB32F", "3D"}};
const std::vector<TextureKind> kComputeTextures{{"RG32F", "2D"}, {"R32F", "3D"}, {"RGB32F", "3D"}};
// The pairs LIC reads taking turns (flow, input): lab 02's flow with its noise or its photograph, lab 03's flow in
// each storage with its noise (pair_ceiling_key).
const std::vector<std::pair<TextureKind, TextureKind>> kFragmentPairs{
    {{"RG32F", "2D"}, {"RGB32F", "2D"}},
    {{"RG32F", "2D"}, {"RGBA8", "2D"}},
    {{"RG32F", "2D"}, {"R32F", "2D"}},
    {{"RG32F", "2D array"}, {"R32F", "2D"}},
    {{"RG32F", "3D"}, {"R32F", "2D"}}};

std::string pair_key(const TextureKind& flow, const TextureKind& input) {
    return pair_ceiling_key(flow.format + " " + flow.dimension, input.format + " " + input.dimension, ShaderPath::Fragment);
}

TexelFormat texel_format(const std::string& name) {
    if (name == "R32F") return TexelFormat::R32F;
    if (name == "RG32F") return TexelFormat::RG32F;
    if (name == "RGB32F") return TexelFormat::RGB32F;
    if (name == "RGBA32F") return TexelFormat::RGBA32F;
    if (name == "RGBA8") return TexelFormat::RGBA8;
    throw Error("gsv-ceilings: no benchmark texture of format '" + name + "'");
}

int components(const std::string& format) {
    return format == "R32F" ? 1 : format == "RG32F" ? 2 : format == "RGB32F" ? 3 : 4;
}

// Values that vary from texel to texel, the same on every run.
Texture make_texture(const TextureKind& kind) {
    const bool three_d = kind.dimension == "3D", array = kind.dimension == "2D array";
    const int w = three_d ? kSide3d : kSide2d, h = w, d = three_d ? kSide3d : array ? kLayers : 1;
    const std::size_t texels = static_cast<std::size_t>(w) * h * d;
    const int c = components(kind.format);
    std::vector<float> floats;
    std::vector<std::uint8_t> bytes;
    if (kind.format == "RGBA8") {
        bytes.resize(texels * 4);
        for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<std::uint8_t>((i * 2654435761u) >> 24);
    } else {
        floats.resize(texels * c);
        for (std::size_t i = 0; i < floats.size(); ++i) floats[i] = std::fmod(static_cast<float>(i) * 0.618034f, 1.0f);
    }
    const void* data = bytes.empty() ? static_cast<const void*>(floats.data()) : bytes.data();
    const TexelFormat format = texel_format(kind.format);
    const Sampling sampling{GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE};  // as the labs sample
    if (three_d) return Texture::create_3d(w, h, d, format, data, sampling);
    if (array) return Texture::create_2d_array(w, h, d, format, data, sampling);
    return Texture::create_2d(w, h, format, data, sampling);
}

std::vector<ShaderDefine> dimension_defines(const TextureKind& kind) {
    return {{kind.dimension == "3D" ? "DIM_3D" : kind.dimension == "2D array" ? "DIM_ARRAY" : "DIM_2D", ""}};
}

// One benchmark: what it measures, how much of it a frame does, and the frame.
struct Benchmark {
    std::string key, unit;
    double per_frame = 0;
    std::function<void()> prepare, frame;
};

class Bench {
public:
    explicit Bench(const CeilingOptions& o) : o_(o), quad_(make_fullscreen_quad(), Profile::Core) {
        target_ = Framebuffer(o.side, o.side, ColorFormat::RGBA8, false);
        sums_ = Buffer::create(GL_SHADER_STORAGE_BUFFER, static_cast<std::size_t>(o.side) * o.side * 16, nullptr, GL_DYNAMIC_COPY);
    }

    std::vector<Benchmark> all() {
        std::vector<Benchmark> list;
        const double pixels = static_cast<double>(o_.side) * o_.side;
        for (const TextureKind& kind : kFragmentTextures) {
            const std::size_t t = keep_texture(kind);
            const ShaderProgram& p = keep_program({"fullscreen.vert", "fetch.frag"}, with_counts(dimension_defines(kind)));
            list.push_back({"fetch " + kind.format + " " + kind.dimension + " fragment", "fetches/s", pixels * kFetches, {},
                            [this, &p, t] { draw_quad(p, t); }});
        }
        {
            std::vector<float> values(kBufferTexels);
            for (std::size_t i = 0; i < values.size(); ++i) values[i] = std::fmod(static_cast<float>(i) * 0.618034f, 1.0f);
            buffer_texture_ = BufferTexture::create_r32f(values.data(), values.size());
            const ShaderProgram& p = keep_program({"fullscreen.vert", "fetch_buffer.frag"},
                                                  with_counts({{"TILE", std::to_string(kBufferTile)},
                                                               {"BUFFER_TEXELS", std::to_string(kBufferTexels)}}));
            list.push_back({"fetch R32F buffer fragment", "fetches/s", pixels * kFetches, {}, [this, &p] {
                                target_.bind();
                                glDisable(GL_DEPTH_TEST);
                                glDisable(GL_BLEND);
                                p.use();
                                p.bind("uValues", buffer_texture_);
                                quad_.draw();
                            }});
        }
        for (const auto& [flow, input] : kFragmentPairs) {
            const std::size_t f = keep_texture(flow), i = keep_texture(input);
            const std::string dim = flow.dimension == "3D" ? "FLOW_3D" : flow.dimension == "2D array" ? "FLOW_ARRAY" : "FLOW_2D";
            const ShaderProgram& p = keep_program({"fullscreen.vert", "fetch_pair.frag"}, with_counts({{dim, ""}}, kPairFetches));
            list.push_back({pair_key(flow, input), "fetches/s", pixels * kPairFetches, {}, [this, &p, f, i] {
                                target_.bind();
                                glDisable(GL_DEPTH_TEST);
                                glDisable(GL_BLEND);
                                p.use();
                                p.bind("uFlow", textures_[f]);
                                p.bind("uInput", textures_[i]);
                                p.set("uStep", steps_[i] * 16.0f);  // a texel
                                glUniform1i(p.location("uSteps"), kPairFetches / 2);
                                quad_.draw();
                            }});
        }
        for (const TextureKind& kind : kComputeTextures) {
            const std::size_t t = keep_texture(kind);
            const ShaderProgram& p = keep_program({"fetch.comp"}, with_counts(dimension_defines(kind)));
            list.push_back({"fetch " + kind.format + " " + kind.dimension + " compute", "fetches/s", pixels * kFetches, {},
                            [this, &p, t] { dispatch_grid_of_pixels(p, t); }});
        }
        {
            source_ = Buffer::create(GL_SHADER_STORAGE_BUFFER, o_.storage_items * 16, nullptr, GL_DYNAMIC_COPY);
            copy_ = Buffer::create(GL_SHADER_STORAGE_BUFFER, o_.storage_items * 16, nullptr, GL_DYNAMIC_COPY);
            const ShaderProgram& p = keep_program({"copy.comp"}, {{"GROUPS", std::to_string(kCopyGroups)}});
            list.push_back({"storage compute", "bytes/s", static_cast<double>(o_.storage_items) * 32, {}, [this, &p] {
                                p.use();
                                glUniform1ui(p.location("uCount"), static_cast<GLuint>(o_.storage_items));
                                source_.bind_base(0);
                                copy_.bind_base(1);
                                glDispatchCompute(kCopyGroups, 1, 1);
                                glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
                            }});
        }
        {
            const ShaderProgram& p = keep_program({"fullscreen.vert", "fill.frag"}, {});
            list.push_back({"fragments", "fragments/s", pixels * kFillQuads, {}, [this, &p] {
                                target_.bind();
                                p.use();
                                p.set("uColor", glm::vec4(0.2f, 0.4f, 0.6f, 1.0f));
                                glDisable(GL_DEPTH_TEST);
                                glDisable(GL_BLEND);
                                for (int i = 0; i < kFillQuads; ++i) quad_.draw();
                            }});
        }
        {
            // A grid drawn twice a frame as lab 01 draws its mesh: back faces culled, then front faces, so each
            // triangle is drawn once (its setup and raster) and culled once, the mix of any closed mesh drawn that
            // way (on llvmpipe a culled triangle cost a tenth of a drawn one, so the mix matters). The best case of
            // that mix: triangles far under a pixel (the grid drawn into a quarter of the target each way, 16 cells a
            // pixel), so that most cover no pixel centre and the fill is a fragment a pixel; half a vertex a triangle,
            // shared along the rows in index order, so the vertex cache reuses them; a vertex shader that only places
            // the vertex and a fragment shader that only writes a colour. With a cell a pixel (half a pixel a
            // triangle) lab 01's finest sphere drawn at 64x64, its triangles smaller still, reached 99.7% of it: not
            // a ceiling. A frame goes faster only where more than half its triangles are culled or fall outside the
            // target: lab 01's camera frames the whole model, and culls half.
            const int cells = std::min(o_.side, kMaxGridCells);
            grid_ = GpuMesh(make_grid(cells + 1), Profile::Core);
            const ShaderProgram& p = keep_program({"triangles.vert", "fill.frag"}, {});
            list.push_back({"triangles", "triangles/s", 2.0 * 2.0 * cells * cells, {}, [this, &p] {
                                target_.bind();
                                glViewport(0, 0, std::max(1, o_.side / 4), std::max(1, o_.side / 4));
                                p.use();
                                p.set("uColor", glm::vec4(0.2f, 0.4f, 0.6f, 1.0f));
                                glDisable(GL_DEPTH_TEST);
                                glDisable(GL_BLEND);
                                glEnable(GL_CULL_FACE);
                                glCullFace(GL_BACK);
                                grid_.draw();
                                glCullFace(GL_FRONT);
                                grid_.draw();
                                glCullFace(GL_BACK);
                                glDisable(GL_CULL_FACE);
                                glViewport(0, 0, o_.side, o_.side);
                            }});
        }
        const ShaderProgram& ff = keep_program({"fullscreen.vert", "flops.frag"}, with_counts({}));
        list.push_back({"flops fragment", "flops/s", pixels * kIterations * kFlopsPerIteration, {}, [this, &ff] {
                            set_chain(ff);
                            draw_quad(ff, kNoTexture);
                        }});
        const ShaderProgram& fc = keep_program({"flops.comp"}, with_counts({}));
        list.push_back({"flops compute", "flops/s", pixels * kIterations * kFlopsPerIteration, {}, [this, &fc] {
                            set_chain(fc);
                            dispatch_grid_of_pixels(fc, kNoTexture);
                        }});
        if (o_.only.empty()) return list;
        std::vector<Benchmark> chosen;
        for (const auto& key : o_.only) {
            const auto found = std::find_if(list.begin(), list.end(), [&](const Benchmark& b) { return b.key == key; });
            if (found == list.end()) throw Error("gsv-ceilings: no benchmark '" + key + "' (--list names them)");
            chosen.push_back(*found);
        }
        return chosen;
    }

private:
    static constexpr std::size_t kNoTexture = static_cast<std::size_t>(-1);

    std::vector<ShaderDefine> with_counts(std::vector<ShaderDefine> defines, int fetches = kFetches) const {
        defines.push_back({"FETCHES", std::to_string(fetches)});
        defines.push_back({"ITERATIONS", std::to_string(kIterations)});
        defines.push_back({"SIDE", std::to_string(o_.side)});
        return defines;
    }

    std::size_t keep_texture(const TextureKind& kind) {
        textures_.push_back(make_texture(kind));
        // A sixteenth of a texel a lookup: the 16 lookups of a fragment move about one texel, as LIC's do where the
        // flow is slow, so they hit the cache and the filter, not memory, is measured (the best case: a ceiling).
        steps_.push_back(kind.dimension == "3D" ? glm::vec3(0.7f, 0.3f, 0.64f) / float(16 * kSide3d)
                                                : glm::vec3(0.7f, 0.3f, 0.0f) / float(16 * kSide2d));
        return textures_.size() - 1;
    }

    const ShaderProgram& keep_program(const std::vector<std::string>& files, const std::vector<ShaderDefine>& defines) {
        ProgramSpec spec;
        spec.name = "gsv-ceilings " + files.back();
        for (const auto& f : files)
            spec.files.push_back(f == "fullscreen.vert" ? o_.kit_shaders / "gsv" / f : o_.shader_dir / f);
        spec.defines = defines;
        PreprocessOptions options;
        options.profile = Profile::Core;
        options.version = {4, 3};
        options.include_dirs = {o_.kit_shaders};
        programs_.push_back(std::make_unique<ShaderProgram>(ShaderProgram::build(spec, options)));
        return *programs_.back();
    }

    void bind_texture(const ShaderProgram& p, std::size_t t) const {
        if (t == kNoTexture) return;
        p.bind("uTexture", textures_[t]);
        p.set("uStep", steps_[t]);
    }

    void draw_quad(const ShaderProgram& p, std::size_t t) {
        target_.bind();
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_BLEND);
        p.use();
        bind_texture(p, t);
        quad_.draw();
    }

    void dispatch_grid_of_pixels(const ShaderProgram& p, std::size_t t) {
        p.use();
        bind_texture(p, t);
        sums_.bind_base(0);
        const auto groups = static_cast<GLuint>((o_.side + 7) / 8);
        glDispatchCompute(groups, groups, 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }

    static void set_chain(const ShaderProgram& p) {
        p.use();
        p.set("uA", glm::vec4(0.9999f));
        p.set("uB", glm::vec4(0.0001f));
    }

    const CeilingOptions& o_;
    GpuMesh quad_, grid_;
    Framebuffer target_;
    BufferTexture buffer_texture_;
    Buffer sums_, source_, copy_;
    std::vector<Texture> textures_;
    std::vector<glm::vec3> steps_;
    std::vector<std::unique_ptr<ShaderProgram>> programs_;
};

}  // namespace

std::vector<std::string> ceiling_keys() {
    std::vector<std::string> keys;
    for (const auto& k : kFragmentTextures) keys.push_back("fetch " + k.format + " " + k.dimension + " fragment");
    keys.push_back("fetch R32F buffer fragment");
    for (const auto& [flow, input] : kFragmentPairs) keys.push_back(pair_key(flow, input));
    for (const auto& k : kComputeTextures) keys.push_back("fetch " + k.format + " " + k.dimension + " compute");
    for (const char* k : {"storage compute", "fragments", "triangles", "flops fragment", "flops compute"}) keys.push_back(k);
    return keys;
}

Ceilings measure_ceilings(const CeilingOptions& options, const std::string& renderer) {
    if (options.runs < 1) throw Error("gsv-ceilings: " + std::to_string(options.runs) + " runs: at least 1 is needed");
    Bench bench(options);
    const std::vector<Benchmark> benchmarks = bench.all();
    std::vector<TimedWork> work;
    for (const auto& b : benchmarks) work.push_back({b.prepare, b.frame});
    // Every round's rate, all runs together, and each run's fastest: a run is its own interleaved rounds (its own
    // warm-up and batch sizes), so runs far apart say whether the ceilings reproduce.
    std::vector<std::vector<double>> rounds(benchmarks.size());
    std::vector<std::vector<double>> run_fastest(benchmarks.size());
    for (int run = 0; run < options.runs; ++run) {
        const InterleavedTimes times = time_interleaved(work, 1, options.frames, options.rounds);
        check_gl_error("measuring the ceilings");
        for (std::size_t i = 0; i < benchmarks.size(); ++i) {
            double fastest = 0;
            for (const double ms : times.round_medians[i]) {
                rounds[i].push_back(1000.0 * benchmarks[i].per_frame / ms);
                fastest = std::max(fastest, rounds[i].back());
            }
            run_fastest[i].push_back(fastest);
        }
    }
    Ceilings out;
    out.renderer = renderer;
    for (std::size_t i = 0; i < benchmarks.size(); ++i) {
        const Benchmark& b = benchmarks[i];
        std::vector<double>& r = rounds[i];
        std::sort(r.begin(), r.end());
        const std::size_t n = r.size();
        const double median = n % 2 ? r[n / 2] : 0.5 * (r[n / 2 - 1] + r[n / 2]);
        out.rates.emplace_back(b.key, median, r.front(), r.back(), b.unit,
                               options.runs > 1 ? run_fastest[i] : std::vector<double>{});
    }
    return out;
}

std::function<void(int)> ceiling_frame(const CeilingOptions& options, const std::string& key) {
    struct Held {
        CeilingOptions options;
        std::unique_ptr<Bench> bench;
        Benchmark benchmark;
    };
    auto held = std::make_shared<Held>();
    held->options = options;
    held->options.only = {key};
    held->bench = std::make_unique<Bench>(held->options);
    held->benchmark = held->bench->all().front();
    return [held](int frames) {
        if (held->benchmark.prepare) held->benchmark.prepare();
        for (int i = 0; i < frames; ++i) held->benchmark.frame();
    };
}

std::string ceilings_table(const Ceilings& ceilings) {
    std::size_t runs = 0;
    for (const auto& c : ceilings.rates) runs = std::max(runs, c.runs.size());
    std::string out = "ceilings on " + ceilings.renderer +
                      " (ceiling: the fastest round, what the bounds use; the median of the rounds, and the slowest and "
                      "fastest round beside it" +
                      (runs > 1 ? "; each run's ceiling, and how far apart the runs are" : "") + ")\n";
    char line[400];
    std::snprintf(line, sizeof line, "  %-40s %11s %11s %18s  %s\n", "resource", "ceiling", "median", "rounds",
                  runs > 1 ? "unit          runs" : "unit");
    out += line;
    const Ceiling* widest = nullptr;
    double widest_ratio = 1;
    for (const auto& c : ceilings.rates) {
        std::snprintf(line, sizeof line, "  %-40s %11.4g %11.4g   %+6.1f%% .. %+5.1f%%  %-12s", c.key.c_str(), c.fastest(),
                      c.rate, 100.0 * (c.low / c.rate - 1.0), 100.0 * (c.high / c.rate - 1.0), c.unit.c_str());
        out += line;
        if (c.runs.size() > 1) {
            const auto [smallest, largest] = std::minmax_element(c.runs.begin(), c.runs.end());
            const double ratio = *largest / *smallest;
            out += " ";
            for (const double r : c.runs) {
                std::snprintf(line, sizeof line, " %.4g", r);
                out += line;
            }
            std::snprintf(line, sizeof line, "  (runs within %.1f%%)", 100.0 * (ratio - 1.0));
            out += line;
            if (!widest || ratio > widest_ratio) widest = &c, widest_ratio = ratio;
        }
        out.erase(out.find_last_not_of(' ') + 1);  // the unit's padding, where no runs follow
        out += "\n";
    }
    if (widest) {
        std::snprintf(line, sizeof line, "%zu runs: every ceiling within %.1f%% of itself from run to run; the widest: %s\n",
                      runs, 100.0 * (widest_ratio - 1.0), widest->key.c_str());
        out += line;
    }
    return out;
}

}  // namespace gsv
