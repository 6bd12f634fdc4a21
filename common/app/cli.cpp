#include "common/app/cli.h"

#include "common/core/error.h"
#include "common/core/number_text.h"
#include "common/window/scripted_keys.h"

#include <algorithm>
#include <cmath>
#include <regex>
#include <sstream>

namespace gsv {
namespace {

int parse_count(const std::string& option, const std::string& text, int min, int max) {
    const std::optional<double> v = parse_finite_number(text);
    if (!v || *v != std::floor(*v)) throw Error("option " + option + " needs an integer, got '" + text + "'");
    if (*v < min || *v > max)
        throw Error("option " + option + " = " + text + " is out of range [" + std::to_string(min) + ", " +
                    std::to_string(max) + "]");
    return static_cast<int>(*v);
}

double parse_real(const std::string& option, const std::string& text) {
    const std::optional<double> v = parse_finite_number(text);
    if (!v) throw Error("option " + option + " needs a number, got '" + text + "'");
    return *v;
}

}  // namespace

CliOptions parse_cli(int argc, const char* const* argv) {
    CliOptions o;
    int i = 1;
    if (i < argc && argv[i][0] != '-') {
        const std::string mode = argv[i++];
        if (mode == "window") o.mode = RunMode::Window;
        else if (mode == "render") o.mode = RunMode::Render;
        else if (mode == "sweep") o.mode = RunMode::Sweep;
        else if (mode == "animate") o.mode = RunMode::Animate;
        else if (mode == "compare") o.mode = RunMode::Compare;
        else if (mode == "list") o.mode = RunMode::List;
        else if (mode == "web") o.mode = RunMode::Web;
        else throw Error("unknown mode '" + mode + "' (expected window, render, sweep, animate, compare or list; see --help)");
    }
    auto value = [&](const std::string& option) -> std::string {
        if (i + 1 >= argc) throw Error("option " + option + " needs a value");
        return argv[++i];
    };
    std::optional<std::string> gl_text;  // read against --profile, which may come after it
    for (; i < argc; ++i) {
        std::string arg = argv[i];
        std::string inline_value;
        bool has_inline = false;
        if (arg.rfind("--", 0) == 0) {
            if (auto eq = arg.find('='); eq != std::string::npos && arg != "--set") {
                inline_value = arg.substr(eq + 1);
                arg = arg.substr(0, eq);
                has_inline = true;
            }
        }
        auto next = [&]() { return has_inline ? inline_value : value(arg); };
        if (arg == "-h" || arg == "--help") o.help = true;
        else if (arg == "--version") o.version = true;
        else if (arg == "--backend") o.backend = parse_backend(next());
        else if (arg == "--profile") o.profile = parse_profile(next());
        else if (arg == "--gl") gl_text = next();
        else if (arg == "--case") o.case_name = next();
        else if (arg == "--set" || arg == "-s") o.assignments.push_back(next());
        else if (arg == "--size") {
            const std::string text = next();
            static const std::regex pattern(R"(^([0-9]+)x([0-9]+)$)");
            std::smatch m;
            if (!std::regex_match(text, m, pattern)) throw Error("option --size needs WIDTHxHEIGHT, got '" + text + "'");
            // Compared as text first: a side of twenty digits is too large, not a number that overflows.
            auto side = [&](const std::string& digits) {
                const std::string trimmed = digits.substr(std::min(digits.find_first_not_of('0'), digits.size()));
                if (trimmed.size() > 4 || (!trimmed.empty() && std::stoi(trimmed) > kMaxImageSide))
                    throw Error("option --size " + text + " is too large: each side is at most " +
                                std::to_string(kMaxImageSide) + " pixels");
                return parse_count("--size", trimmed.empty() ? "0" : trimmed, 1, kMaxImageSide);
            };
            o.width = side(m[1]);
            o.height = side(m[2]);
            o.size_given = true;
        } else if (arg == "--out" || arg == "-o") o.out = next();
        else if (arg == "--json") o.json = next();
        else if (arg == "--arrays") o.arrays = true;
        else if (arg == "--serve") o.serve = true;
        else if (arg == "--debug-images") o.debug_images = true;
        else if (arg == "--legend") o.legend = true;
        else if (arg == "--out-dir") o.out_dir = next();
        else if (arg == "--count") o.count = parse_count(arg, next(), 1, 9999);
        else if (arg == "--fps") {
            const std::string text = next();
            o.fps = parse_real(arg, text);
            if (o.fps < 0.1 || o.fps > 1000) throw Error("option --fps = " + text + " is out of range [0.1, 1000]");
        } else if (arg == "--from") o.from = parse_real(arg, next());
        else if (arg == "--to") o.to = parse_real(arg, next());
        else if (arg == "--knob") o.knob = next();
        else if (arg == "--values") {
            std::stringstream items(next());
            for (std::string value; std::getline(items, value, ',');) o.values.push_back(value);
        } else if (arg == "--frames") o.frames = parse_count(arg, next(), 1, 100000);
        else if (arg == "--warmup") o.warmup = parse_count(arg, next(), 0, 100000);
        else if (arg == "--screenshot-after") o.screenshot_after = parse_count(arg, next(), 1, 1000000);
        else if (arg == "--press") o.presses.push_back(next());
        else if (arg == "--quit-after") {
            // N frames, or "Ns" seconds of wall time: tests wait the same while a lab's frames take 2 or 100 ms.
            const std::string text = next();
            if (!text.empty() && text.back() == 's') {
                o.quit_after_s = parse_real(arg, text.substr(0, text.size() - 1));
                if (!(o.quit_after_s > 0 && o.quit_after_s <= 3600))
                    throw Error("option --quit-after = " + text + " is out of range (0s, 3600s]");
            } else {
                o.quit_after = parse_count(arg, text, 1, 1000000);
            }
        }
        else throw Error("unknown option '" + arg + "' (see --help)");
    }
    if (gl_text) o.gl = parse_gl_version(*gl_text, o.profile);
    parse_scripted_keys(o.presses);  // a bad key is a bad command line, refused before any window opens
    if (o.legend && o.mode != RunMode::Render && o.mode != RunMode::Animate)
        throw Error("--legend is for render and animate (a window's panel shows the legend by itself)");
    if (o.serve && o.mode != RunMode::Render) throw Error("--serve is for render (the grader's cases, one after another)");
    return o;
}

std::string cli_usage(const std::string& program) {
    return "usage: " + program + " [window|render|sweep|animate|compare|list] [options]\n"
           "  window (default)    interactive: every parameter on keys or sliders, frame time on screen\n"
           "  render              headless: one case to PNG plus a JSON of timings and GL info\n"
           "  sweep               headless: vary the accuracy knob; CSV, table and plot of error against time\n"
           "  animate             headless: step the animated parameter; a PNG per frame plus a looping APNG\n"
           "  compare             headless: your render beside the reference's and their difference, amplified,\n"
           "                      in one PNG; prints RMSE and the largest difference. The reference is\n"
           "                      <lab>_solution beside this binary, else the case's golden image (--case needed)\n"
           "  list                the lab's parameters and cases\n"
           "options:\n"
           "  --case NAME         start from a named case (see list)\n"
           "  --set NAME=VALUE    set a parameter (repeatable); out-of-range values are refused, and so is a\n"
           "                      parameter that has no effect under the others (the error names what enables it)\n"
           "  --size WxH          the picture's size for every mode (default 512x512; compare against a golden image:\n"
           "                      the golden's); in a window the panel's column is added beside it, and resizing\n"
           "                      the window resizes the picture\n"
           "  --out FILE          render: the PNG (default <lab>.png); compare: the PNG (default\n"
           "                      <lab>-compare-<case>.png); window: screenshot file\n"
           "  --legend            render, animate: a colour bar beside the image where colour is data (labs 04-07):\n"
           "                      the values, units and named colours the shaders use; off, images are unchanged\n"
           "  --json FILE         render: the JSON report (default: the PNG's name with .json)\n"
           "  --out-dir DIR       sweep: where the CSV and plot go (default sweep-<lab>);\n"
           "                      animate: where frame_0000.png... and animation.png go (default animate-<lab>)\n"
           "  --knob NAME --values A,B,C   sweep another parameter through these values (least accurate first);\n"
           "                      the error is against the last value unless the lab names a reference\n"
           "  --count N           animate: frames over the range (default 48); --fps F its playback rate (default 20)\n"
           "  --from A --to B     animate: the range to step (default the parameter's); B itself is not drawn, so\n"
           "                      a periodic parameter loops seamlessly\n"
           "  --frames N          timed frames (median reported); --warmup N untimed frames first\n"
           "  --arrays            render: also write the numbers the lab hands the grader beside the image\n"
           "                      (lab 05: every particle's position and velocity, <png stem>.<name>.f32)\n"
           "  --serve             render: the grader's cases one after another in this process, each from the declared\n"
           "                      defaults in a fresh GL context (only under gsv-grade, which sends them)\n"
           "  --debug-images      render: also the lab's intermediate images into <png stem>-debug/ (lab 06: every\n"
           "                      port of its network); in a window, S writes them beside each screenshot\n"
           "  --backend B         egl (headless default), osmesa (where built), window\n"
           "  --profile P         core (default), compat (the seeds' gl_ModelViewProjectionMatrix, gl_Vertex...)\n"
           "                      or es (OpenGL ES 3.x, whose 3.0 is WebGL 2's feature set); the same shader files\n"
           "  --gl X.Y            the version to hold to: core/compat 3.3-4.6 (default: what the lab needs, at\n"
           "                      least 4.1); es 3.0-3.2 (default: the lowest ES version the lab runs on)\n"
           "  --screenshot-after N, --quit-after N|Ns   window: save a screenshot / quit after N frames or N seconds\n"
           "                      (a screenshot is the picture, FILE, and the whole window, FILE-window.png)\n"
           "  --press KEY@N       window: press KEY before frame N (repeatable; U@5 hides the panel): scripted demos\n"
           "  -h, --help          this text; --version: the kit's version\n"
           "window keys: Tab/arrows pick and change parameters, C next case, U hide/show the panel, S screenshot,\n"
           "             H all keys (printed); parameters greyed in the panel have no effect under the current ones\n"
           "exit status: 0 ok, 1 error, 2 bad command line, 3 GL feature not available, 4 NaN/Inf in the image\n";
}

}  // namespace gsv
