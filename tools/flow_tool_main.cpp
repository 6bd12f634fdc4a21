// gsv-flow: writes the kit's analytic flows as .flow files and describes .flow files. data/flows/ is made
// with it (data/README.md), and a test regenerates that data to prove it still matches this generator.
#include "common/core/error.h"
#include "common/core/number_text.h"
#include "common/core/version.h"
#include "support/flow/flow_field.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace {

constexpr const char* kUsage =
    "usage: gsv-flow write <kind> <width> <height> [<frames>] <out.flow>\n"
    "       gsv-flow info <file.flow>\n"
    "       gsv-flow --help | --version\n"
    "kinds: rotation, saddle, source, double_gyre, vortices, vortex_street\n"
    "Fields are scaled so the fastest texel moves 1 texel per step. Without <frames>: one field with the\n"
    "three-field header (double_gyre at t = 0, vortex_street at phase 0, vortices from seed 0). With <frames>:\n"
    "a sequence; double_gyre and vortex_street span one period, so it loops, and the steady kinds repeat\n"
    "one field in every frame.\n";

constexpr const char* kKinds[] = {"rotation", "saddle", "source", "double_gyre", "vortices", "vortex_street"};
constexpr double kMaxTexelsPerStep = 1.0;

// A mistake in the command line itself (exit 2), as opposed to a file that cannot be read or written (1).
struct UsageError : gsv::Error {
    using gsv::Error::Error;
};

// Plain decimal digits in [1, max]; the range is checked here so the message names the argument as typed.
int parse_count(const char* name, const std::string& text, int max) {
    const bool digits = !text.empty() && text.size() <= 5 &&
                        std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
    const int value = digits ? std::stoi(text) : -1;
    if (value < 1 || value > max)
        throw UsageError(std::string(name) + " '" + text + "' is not a whole number in 1.." + std::to_string(max));
    return value;
}

std::string describe(const gsv::FlowSequence& sequence) {
    const std::string speed = gsv::format_number(sequence.max_speed());
    return std::to_string(sequence.width) + "x" + std::to_string(sequence.height) + " texels, " +
           std::to_string(sequence.frames.size()) + (sequence.frames.size() == 1 ? " frame" : " frames") +
           ", max speed " + speed + " texels per step";
}

// frames == 0: no <frames> argument, so one field.
gsv::FlowSequence generate(const std::string& kind, int width, int height, int frames) {
    const int count = std::max(frames, 1);
    if (kind == "vortex_street") return gsv::make_vortex_street(width, height, count, kMaxTexelsPerStep);
    if (kind == "double_gyre" && frames > 0)
        return gsv::make_double_gyre_sequence(width, height, count, kMaxTexelsPerStep);
    // A steady flow as a sequence is the same field in every frame: lab 03 can then show that time-varying
    // LIC of a steady flow looks like plain LIC.
    const gsv::FlowField field = gsv::make_flow(gsv::flow_kind_from_name(kind), width, height, kMaxTexelsPerStep);
    return gsv::FlowSequence{width, height, std::vector<gsv::FlowField>(static_cast<std::size_t>(count), field)};
}

int write(const std::vector<std::string>& args) {
    if (args.size() != 5 && args.size() != 6)
        throw UsageError("write needs <kind> <width> <height> [<frames>] <out.flow>");
    const std::string& kind = args[1];
    if (std::find(std::begin(kKinds), std::end(kKinds), kind) == std::end(kKinds)) {
        std::string valid;
        for (const char* k : kKinds) valid += (valid.empty() ? "" : ", ") + std::string(k);
        throw UsageError("unknown kind '" + kind + "' (valid: " + valid + ")");
    }
    const int width = parse_count("width", args[2], gsv::kMaxFlowSide);
    const int height = parse_count("height", args[3], gsv::kMaxFlowSide);
    const int frames = args.size() == 6 ? parse_count("frames", args[4], gsv::kMaxFlowFrames) : 0;
    const std::filesystem::path out = args.back();
    // Before generating: a steady kind copied into thousands of frames would exhaust memory first.
    const std::uint64_t bytes = std::uint64_t(std::max(frames, 1)) * std::uint64_t(width) * std::uint64_t(height) * 8;
    if (bytes > gsv::kMaxFlowBytes)
        throw UsageError(std::to_string(bytes) + " bytes of velocities is more than a .flow file may hold (" +
                         std::to_string(gsv::kMaxFlowBytes) + ", 1 GiB)");

    gsv::FlowSequence sequence;
    try {
        sequence = generate(kind, width, height, frames);
    } catch (const gsv::Error& e) {
        throw UsageError(e.what());  // nothing but the arguments can be wrong before the file is written
    }
    if (frames == 0)
        gsv::save_flow(out, sequence.frames.front());
    else
        gsv::save_flow_sequence(out, sequence);
    std::printf("wrote %s: %s %s\n", out.string().c_str(), kind.c_str(), describe(sequence).c_str());
    return 0;
}

int info(const std::vector<std::string>& args) {
    if (args.size() != 2) throw UsageError("info needs one <file.flow>");
    const gsv::FlowSequence sequence = gsv::load_flow_sequence(args[1]);
    std::printf("%s: %s\n", args[1].c_str(), describe(sequence).c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv + std::min(argc, 1), argv + argc);
    if (args.empty()) {
        std::fputs(kUsage, stderr);
        return 2;
    }
    if (args[0] == "--help" || args[0] == "-h") {
        std::fputs(kUsage, stdout);
        return 0;
    }
    if (args[0] == "--version") {
        std::printf("%s\n", gsv::version_line("gsv-flow").c_str());
        return 0;
    }
    try {
        if (args[0] == "write") return write(args);
        if (args[0] == "info") return info(args);
        throw UsageError("unknown command '" + args[0] + "' (valid: write, info; see gsv-flow --help)");
    } catch (const UsageError& e) {
        std::fprintf(stderr, "gsv-flow: %s\n", e.what());
        return 2;
    } catch (const gsv::Error& e) {
        std::fprintf(stderr, "gsv-flow: %s\n", e.what());
        return 1;
    }
}
