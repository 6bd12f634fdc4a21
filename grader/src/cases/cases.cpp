#include "grader/src/cases/cases.h"

#include "common/params/case_file.h"
#include "common/app/cli.h"
#include "common/app/kit_layout.h"
#include "common/core/error.h"
#include "common/io/json.h"
#include "grader/src/cases/draw.h"

#include <algorithm>
#include <cmath>
#include <regex>
#include <set>

namespace gsv {
namespace {

ImageTolerance tolerance_from(const Json& j) {
    ImageTolerance t;
    t.max_channel_diff = static_cast<int>(j.number_at("max_channel_diff"));
    t.max_differing_fraction = j.number_at("max_differing_fraction");
    if (t.max_channel_diff < 0 || t.max_channel_diff > 255 || t.max_differing_fraction < 0 || t.max_differing_fraction > 1)
        throw Error(j.source_name() + ": tolerance out of range (max_channel_diff 0..255, max_differing_fraction 0..1)");
    if (const Json* n = j.find("neighbourhood"); n && !n->is_null()) {
        const double r = n->is_number() ? n->as_number() : -1;
        if (!(r >= 0 && r <= kMaxNeighbourhood && r == std::floor(r)))
            throw Error(j.source_name() + ":" + std::to_string(n->line()) + ": " + n->key_path() + " is " + n->dump(0) +
                        "; a neighbourhood is a whole number of pixels 0.." + std::to_string(kMaxNeighbourhood) +
                        " (0: each pixel at its own place; 1: matched within one pixel)");
        t.neighbourhood = static_cast<int>(r);
    }
    return t;
}

ArrayTolerance array_tolerance_from(const Json& j) {
    ArrayTolerance t;
    t.max_abs = j.number_at("max_abs");
    t.max_differing_fraction = j.number_at("max_differing_fraction");
    if (!std::isfinite(t.max_abs) || t.max_abs < 0 || !(t.max_differing_fraction >= 0 && t.max_differing_fraction <= 1))
        throw Error(j.source_name() + ": " + j.key_path() +
                    " out of range (max_abs a finite number >= 0, max_differing_fraction 0..1)");
    return t;
}

// The case's "arrays" name arrays the lab must hand in: valid, distinct names, and a tolerance to check them by.
void check_case_arrays(const LabCases& lab, const GradeCase& c, const std::string& file) {
    if (!c.arrays) return;
    if (!lab.checks_arrays())
        throw Error(file + ": case '" + c.name + "' lists arrays, but the tolerance has no 'arrays' to check them by");
    std::set<std::string> seen;
    for (const auto& name : *c.arrays) {
        if (!valid_array_name(name))
            throw Error(file + ": case '" + c.name + "' lists array '" + name + "'; an array name is 1.." +
                        std::to_string(kMaxArrayNameBytes) + " of a-z, 0-9 and '_'");
        if (!seen.insert(name).second) throw Error(file + ": case '" + c.name + "' lists array '" + name + "' twice");
    }
}

void parse_size(const std::string& size, const std::string& file, int& width, int& height) {
    static const std::regex size_pattern(R"(^0*([0-9]{1,9})x0*([0-9]{1,9})$)");
    static const std::regex digits_pattern(R"(^[0-9]+x[0-9]+$)");
    std::smatch m;
    // The lab refuses a side over kMaxImageSide: say so here, where the case file can be fixed.
    const bool matched = std::regex_match(size, m, size_pattern);
    if ((matched && (std::stol(m[1]) > kMaxImageSide || std::stol(m[2]) > kMaxImageSide)) ||
        (!matched && std::regex_match(size, digits_pattern)))
        throw Error(file + ": a size of " + size + " is too large: each side is at most " + std::to_string(kMaxImageSide) +
                    " pixels");
    if (!matched || std::stoi(m[1]) < 1 || std::stoi(m[2]) < 1)
        throw Error(file + ": a size must be WIDTHxHEIGHT, got '" + size + "'");
    width = std::stoi(m[1]);
    height = std::stoi(m[2]);
}

GradeCase case_from(const Json& c, const std::string& file) {
    static const std::regex todo_pattern(R"(^L[0-9]{2}-T[0-9]+$)");
    RenderCase named = named_case_from(c);
    GradeCase gc;
    gc.name = std::move(named.name);
    gc.description = std::move(named.description);
    gc.settings = std::move(named.settings);
    gc.todo = c.string_at("todo");
    if (!std::regex_match(gc.todo, todo_pattern))
        throw Error(file + ": case '" + gc.name + "' has todo '" + gc.todo + "', expected an id like L01-T2");
    gc.points = c.number_or("points", 1);
    if (gc.points < 0) throw Error(file + ": case '" + gc.name + "' has negative points");
    if (const Json* timing = c.find("timing")) {
        gc.timing.points = timing->number_at("points");
        gc.timing.max_ratio = timing->number_or("max_ratio", 2);
        if (gc.timing.points < 0 || gc.timing.max_ratio < 1)
            throw Error(file + ": case '" + gc.name + "': timing needs points >= 0 and max_ratio >= 1");
        const Json* vary = timing->find("vary");
        if (gc.timing.points > 0 && (!vary || !vary->is_object() || vary->as_object().empty()))
            throw Error(file + ":" + std::to_string(timing->line()) + ": case '" + gc.name +
                        "': a timed case needs \"vary\", the settings drawn afresh for each timed frame (e.g. "
                        "{\"camera_yaw\": {\"range\": [-30, 30]}}): without them a frame could be drawn before the grader asks for it");
        if (vary && vary->is_object()) {
            // Malformed draws are refused here, not when the first timed frame is asked for.
            SeededDraw trial(0, "check");
            (void)draw_settings(*vary, trial, gc.settings);
            gc.timing.vary = *vary;
        }
    }
    if (const Json* tolerance = c.find("tolerance"); tolerance && !tolerance->is_null()) {
        if (const Json* live = tolerance->find("live")) gc.live_tolerance = tolerance_from(*live);
        if (const Json* golden = tolerance->find("golden")) gc.golden_tolerance = tolerance_from(*golden);
    }
    if (const Json* needs = c.find("needs"); needs && !needs->is_null())
        for (const Json& n : needs->as_array()) {
            gc.needs.push_back(n.as_string());
            if (!std::regex_match(gc.needs.back(), todo_pattern))
                throw Error(file + ": case '" + gc.name + "' needs '" + gc.needs.back() + "', expected an id like L01-T2");
        }
    if (const Json* es = c.find("es"); es && !es->is_null()) {
        try {
            gc.es_version = parse_gl_version(es->as_string(), Profile::Es);
        } catch (const Error& e) {
            throw Error(file + ": case '" + gc.name + "': \"es\": " + e.what());
        }
    }
    if (const Json* feature = c.find("feature"); feature && !feature->is_null()) {
        gc.feature = gl_feature_keyed(feature->as_string());
        if (!gc.feature)
            throw Error(file + ": case '" + gc.name + "': \"feature\": '" + feature->as_string() +
                        "' is no feature the kit knows (common/gl/gl_features.h: compute)");
        if (!gc.es_version) gc.es_version = gc.feature->es;
    }
    if (const Json* arrays = c.find("arrays"); arrays && !arrays->is_null()) {
        gc.arrays.emplace();
        for (const Json& a : arrays->as_array()) gc.arrays->push_back(a.as_string());
    }
    return gc;
}

}  // namespace

ImageTolerance cross_implementation_tolerance(const ImageTolerance& own) {
    ImageTolerance t = own;
    t.max_differing_fraction = std::min(1.0, kCrossImplementationBudget * own.max_differing_fraction);
    return t;
}

LabCases load_lab_cases(const std::filesystem::path& file) {
    const Json root = read_json_file(file);
    LabCases lab;
    lab.lab = root.string_at("lab");
    parse_size(root.string_at("size"), file.string(), lab.width, lab.height);
    const Json& tolerance = root.object_at("tolerance");
    lab.live_tolerance = tolerance_from(tolerance.object_at("live"));
    lab.golden_tolerance = tolerance_from(tolerance.object_at("golden"));
    if (const Json* arrays = tolerance.find("arrays"); arrays && !arrays->is_null()) {
        lab.live_array_tolerance = array_tolerance_from(tolerance.object_at("arrays"));
        lab.golden_array_tolerance = lab.live_array_tolerance;
    }
    if (const Json* golden = tolerance.find("arrays_golden"); golden && !golden->is_null()) {
        if (!lab.checks_arrays())
            throw Error(file.string() + ": tolerance has 'arrays_golden' but no 'arrays' (the live tolerance)");
        lab.golden_array_tolerance = array_tolerance_from(tolerance.object_at("arrays_golden"));
    }
    lab.arrays_are = root.string_or("arrays_are", lab.arrays_are);
    lab.timeout_s = root.number_or("timeout_s", 60);
    if (const Json* timing = root.find("timing")) {
        if (timing->contains("size")) parse_size(timing->string_at("size"), file.string(), lab.timing_width, lab.timing_height);
        lab.timing_frames = timing->int_or("frames", lab.timing_frames);
        lab.timing_warmup = timing->int_or("warmup", lab.timing_warmup);
        lab.timing_rounds = timing->int_or("rounds", lab.timing_rounds);
        if (lab.timing_frames < 1 || lab.timing_warmup < 0 || lab.timing_rounds < 1)
            throw Error(file.string() + ": timing needs frames >= 1, warmup >= 0, rounds >= 1");
    }
    for (const Json& c : root.array_at("cases").as_array()) {
        lab.cases.push_back(case_from(c, file.string()));
        check_case_arrays(lab, lab.cases.back(), file.string());
    }
    if (lab.cases.empty()) throw Error(file.string() + ": no cases");
    // "page_case": the case the browser page opens on where none is asked for (web/page/lab.js): a graded case's name.
    if (const Json* page_case = root.find("page_case")) {
        const std::string name = page_case->as_string();
        if (std::none_of(lab.cases.begin(), lab.cases.end(), [&](const GradeCase& c) { return c.name == name; }))
            throw Error(file.string() + ": \"page_case\" is '" + name + "', which is not one of its cases");
    }
    return lab;
}

void add_hidden_cases(LabCases& lab, const std::filesystem::path& file, std::uint64_t seed) {
    const Json root = read_json_file(file);
    if (root.string_at("lab") != lab.lab)
        throw Error(file.string() + ": 'lab' is '" + root.string_at("lab") + "', expected '" + lab.lab + "'");
    for (const Json& c : root.array_at("cases").as_array()) {
        const GradeCase base = case_from(c, file.string());
        check_case_arrays(lab, base, file.string());
        const int count = c.int_or("count", 1);
        if (count < 1 || count > 50) throw Error(file.string() + ": case '" + base.name + "': count must be 1..50");
        for (int i = 1; i <= count; ++i) {
            GradeCase drawn = base;
            drawn.visibility = "hidden";
            if (count > 1) drawn.name += "-" + std::to_string(i);
            SeededDraw draw(seed, lab.lab + "/" + drawn.name);
            for (auto& s : draw_settings(c.object_at("draw"), draw, base.settings)) drawn.settings.push_back(std::move(s));
            lab.cases.push_back(std::move(drawn));
        }
    }
}

std::vector<std::filesystem::path> case_files(const std::filesystem::path& kit_root) {
    std::vector<std::filesystem::path> files;
    const auto dir = KitLayout{kit_root}.case_dir();
    if (!std::filesystem::is_directory(dir)) throw Error("no grader/cases folder in '" + kit_root.string() + "'");
    for (const auto& e : std::filesystem::directory_iterator(dir))
        if (e.path().extension() == ".json") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

std::filesystem::path hidden_case_file(const std::filesystem::path& kit_root, const std::string& lab) {
    return KitLayout{kit_root}.hidden_case_file(lab);
}

}  // namespace gsv
