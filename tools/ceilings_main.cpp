// gsv-ceilings: what this device allows, measured: one small benchmark a resource (tools/ceilings/), interleaved, with
// the spread of the rounds (and of the runs, --runs); the table printed and the ceilings written where the labs look
// for them (a lab's window and sweeps, scripts/kit bench: build/ceilings.json), named by the GL renderer they were
// measured on.
#include "common/context/context.h"
#include "common/core/error.h"
#include "common/core/version.h"
#include "common/timing/frame_work.h"
#include "tools/ceilings/ceiling_benchmarks.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

namespace {

constexpr const char* kUsage =
    "usage: gsv-ceilings [--out FILE] [--side N] [--items N] [--rounds N] [--frames N] [--runs N] [--only KEY]...\n"
    "                    [--list]\n"
    "  measures this device's ceilings (bilinear lookups by texel format in fragment and compute shaders, buffer-\n"
    "  texture texelFetch, storage-buffer bandwidth, fill, triangles, FP32 arithmetic), interleaved: each ceiling is\n"
    "  the fastest round (what the bounds use), printed beside the median of the rounds and their spread\n"
    "  --out FILE    where to write them (default: ceilings.json in the build folder, where the labs look)\n"
    "  --side N      fragment targets and compute grids N x N (default 512)\n"
    "  --items N     vec4s the storage benchmark copies a dispatch (default 2097152: 32 MiB each way)\n"
    "  --rounds N    rounds over every benchmark (default 9);  --frames N  timed frames a round (default 3)\n"
    "  --runs N      the whole set N times, each run its own rounds (default 1): each run's ceiling printed, and how\n"
    "                far apart the runs are; the file holds the fastest round of all runs, and each run's\n"
    "  --only KEY    measure only this one (repeatable);  --list  the keys\n"
    "  --version     the kit's version\n";

namespace fs = std::filesystem;

int number_after(int& i, int argc, char** argv, int low, int high) {
    if (i + 1 >= argc) throw gsv::Error(std::string(argv[i]) + " needs a number");
    const std::string text = argv[++i];
    char* end = nullptr;
    const long value = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || value < low || value > high)
        throw gsv::Error(std::string(argv[i - 1]) + " " + text + ": a whole number " + std::to_string(low) + ".." +
                         std::to_string(high) + " is needed");
    return static_cast<int>(value);
}

}  // namespace

int main(int argc, char** argv) {
    try {
        gsv::CeilingOptions options;
        options.shader_dir = fs::path(GSV_SOURCE_ROOT) / "tools" / "ceilings";
        options.kit_shaders = fs::path(GSV_SOURCE_ROOT) / "shaders";
        fs::path out = fs::absolute(argv[0]).parent_path().parent_path() / "ceilings.json";
        for (int i = 1; i < argc; ++i) {
            const std::string a = argv[i];
            if (a == "--help" || a == "-h") {
                std::printf("gsv-ceilings: what this device allows, one benchmark a resource\n%s", kUsage);
                return 0;
            } else if (a == "--version") {
                std::printf("%s\n", gsv::version_line("gsv-ceilings").c_str());
                return 0;
            } else if (a == "--list") {
                for (const auto& key : gsv::ceiling_keys()) std::printf("%s\n", key.c_str());
                return 0;
            } else if (a == "--out" && i + 1 < argc) {
                out = argv[++i];
            } else if (a == "--side") {
                options.side = number_after(i, argc, argv, 8, 4096);
            } else if (a == "--items") {
                options.storage_items = static_cast<std::size_t>(number_after(i, argc, argv, 1024, 1 << 26));
            } else if (a == "--rounds") {
                options.rounds = number_after(i, argc, argv, 1, 100);
            } else if (a == "--runs") {
                options.runs = number_after(i, argc, argv, 1, 20);
            } else if (a == "--frames") {
                options.frames = number_after(i, argc, argv, 1, 100);
            } else if (a == "--only" && i + 1 < argc) {
                options.only.push_back(argv[++i]);
            } else {
                throw gsv::Error("unknown option '" + a + "' (see --help)");
            }
        }
        gsv::ContextOptions context_options;
        context_options.backend = gsv::Backend::Egl;
        context_options.version = {4, 5};
        const auto context = gsv::create_context(context_options);
        context->require({4, 3}, "the compute benchmarks");
        std::fprintf(stderr, "gsv-ceilings: measuring on %s\n", context->describe().c_str());
        const gsv::Ceilings ceilings = gsv::measure_ceilings(options, context->info().renderer);
        std::printf("%s", gsv::ceilings_table(ceilings).c_str());
        gsv::write_ceilings(out, ceilings);
        std::printf("wrote %s\n", out.string().c_str());
        return 0;
    } catch (const gsv::Error& e) {
        std::fprintf(stderr, "gsv-ceilings: %s\n", e.what());
        return 2;
    }
}
