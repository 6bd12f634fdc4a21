#include "grader/src/margins/margins.h"

#include "grader/src/diagnose/known_mistakes.h"

#include "common/app/kit_layout.h"
#include "common/core/error.h"
#include "common/core/number_text.h"
#include "common/image/image_offset.h"
#include "grader/src/cases/cases.h"
#include "grader/src/grade/grade.h"
#include "grader/src/diagnose/mutant_kit.h"
#include "grader/src/report/report_format.h"
#include "grader/src/run/lab_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <map>
#include <optional>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace gsv {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// over / floor(fraction x of), as the grader's within() judges it (the same slack for decimal fractions).
double share_of(double over, double fraction, double of) {
    const double allowed = std::floor(std::max(0.0, fraction) * of * (1.0 + 1e-12));
    if (allowed <= 0) return over > 0 ? kInf : 0.0;
    return over / allowed;
}

// Sets an implementation's variables over the environment the tool was started with, and puts that back after.
class EnvironmentFor {
public:
    explicit EnvironmentFor(const Implementation& implementation) {
        for (const auto& [name, value] : implementation.environment) {
            const char* before = std::getenv(name.c_str());
            saved_.emplace_back(name, before ? std::optional<std::string>(before) : std::nullopt);
            setenv(name.c_str(), value.c_str(), 1);
        }
    }
    ~EnvironmentFor() {
        for (const auto& [name, value] : saved_) {
            if (value)
                setenv(name.c_str(), value->c_str(), 1);
            else
                unsetenv(name.c_str());
        }
    }
    EnvironmentFor(const EnvironmentFor&) = delete;
    EnvironmentFor& operator=(const EnvironmentFor&) = delete;

private:
    std::vector<std::pair<std::string, std::optional<std::string>>> saved_;
};

// solutions/<lab>_*: the lab's folder.
std::string lab_dir_of(const fs::path& kit_root, const std::string& lab) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(KitLayout{kit_root}.solutions(), ec)) {
        const std::string name = e.path().filename().string();
        if (e.is_directory() && name.rfind(lab + "_", 0) == 0) return name;
    }
    throw Error("no solutions/" + lab + "_* folder in " + kit_root.string() + ": the margin table renders the reference solutions");
}

std::string percent_text(double share) {
    if (std::isinf(share)) return "fails";
    if (share >= 9.995) return ">999%";
    char text[16];
    std::snprintf(text, sizeof text, "%.0f%%", 100.0 * share);
    return text;
}

std::string budget_text(const LabCases& lab, const GradeCase& c) {
    const ImageTolerance t = lab.tolerance(c, false);
    const long pixels = long(lab.width) * lab.height;
    const long allowed = static_cast<long>(std::floor(t.max_differing_fraction * double(pixels) * (1.0 + 1e-12)));
    std::string text = "max channel diff " + std::to_string(t.max_channel_diff) + ", " + std::to_string(allowed) + " of " +
                       std::to_string(pixels) + " px (" + format_number(100.0 * t.max_differing_fraction) + "%)";
    if (t.neighbourhood > 0) text += ", " + neighbourhood_text(t.neighbourhood);
    return text;
}

}  // namespace

std::vector<Implementation> known_implementations() {
    return {
        {"default", "the machine's own GL (llvmpipe on a machine without a GPU)", {}, Profile::Core, {}},
        {"softpipe-es", "GALLIUM_DRIVER=softpipe, --profile es: Mesa's other rasterizer, shaders interpreted",
         {{"GALLIUM_DRIVER", "softpipe"}}, Profile::Es, {"softpipe"}},
        {"llvmpipe-128", "LP_NATIVE_VECTOR_WIDTH=128: llvmpipe with SSE-wide vectors",
         {{"GALLIUM_DRIVER", "llvmpipe"}, {"LP_NATIVE_VECTOR_WIDTH", "128"}}, Profile::Core, {"llvmpipe", "128 bits"}},
        {"llvmpipe-1thread", "LP_NUM_THREADS=1: llvmpipe rasterizing on one thread",
         {{"GALLIUM_DRIVER", "llvmpipe"}, {"LP_NUM_THREADS", "1"}}, Profile::Core, {"llvmpipe"}},
        {"filter-8bit", "GSV_TEXEL_SNAP=256: every texture coordinate snapped to 1/256 of a texel, as GPUs' 8-bit filter weights",
         {{"GSV_TEXEL_SNAP", "256"}}, Profile::Core, {}},
        // What a Chromebook or a phone's browser runs: the same GL on OpenGL ES, each lab at its lowest ES version.
        {"default-es", "the machine's own GL on OpenGL ES (--profile es; llvmpipe on a machine without a GPU)", {}, Profile::Es, {}},
    };
}

double budget_share(const CaseResult& r) {
    if (!r.image.done || r.image.total_pixels <= 0) return kInf;
    double share = share_of(double(r.image.differing_pixels), r.image.tolerance.max_differing_fraction, double(r.image.total_pixels));
    if (r.data.done)
        for (const auto& a : r.data.arrays) {
            if (!a.problem.empty()) return kInf;
            share = std::max(share, share_of(double(a.differing), r.data.tolerance.max_differing_fraction, double(a.compared)));
        }
    // The whole picture's place as a share too: 1 is the offset the grader refuses (kMaxGlobalOffset), so a correct
    // render under half of it and a picture moved by a pixel (2) hold to the same bars as the pixels.
    return std::max(share, std::max(std::abs(r.image.offset_x), std::abs(r.image.offset_y)) / kMaxGlobalOffset);
}

namespace {

struct LabToMeasure {
    LabCases cases;
    std::string lab_dir;
    std::optional<Json> spec;  // tests/mutants/<lab>.json
    std::map<std::string, std::string> shipped_names;  // the ids the self-check names mistakes by -> the lists' names
};

class Measuring {
public:
    Measuring(const MarginOptions& options, const std::function<void(const std::string&)>& progress)
        : options_(options), progress_(progress) {}

    MarginMeasurement run() {
        load();
        result_.labs_with_mutants = labs_with_mutants(options_.kit_root).size();
        for (const auto& implementation : chosen_implementations()) measure(implementation);
        return result_;
    }

private:
    std::vector<Implementation> chosen_implementations() const {
        const auto known = known_implementations();
        if (options_.implementations.empty()) return known;
        std::vector<Implementation> chosen;
        for (const auto& name : options_.implementations) {
            const auto it = std::find_if(known.begin(), known.end(), [&](const Implementation& i) { return i.name == name; });
            if (it == known.end()) {
                std::string names;
                for (const auto& i : known) names += (names.empty() ? "" : ", ") + i.name;
                throw Error("no implementation named '" + name + "' (known: " + names + ")");
            }
            chosen.push_back(*it);
        }
        return chosen;
    }

    void load() {
        std::set<std::string> found;
        for (const auto& file : case_files(options_.kit_root)) {
            LabCases lab = load_lab_cases(file);
            found.insert(lab.lab);
            if (!options_.labs.empty() && std::find(options_.labs.begin(), options_.labs.end(), lab.lab) == options_.labs.end())
                continue;
            LabToMeasure m;
            m.lab_dir = lab_dir_of(options_.kit_root, lab.lab);
            const auto with_mutants = labs_with_mutants(options_.kit_root);
            const bool any = options_.mutants || options_.variants;
            if (any && std::find(with_mutants.begin(), with_mutants.end(), lab.lab) != with_mutants.end()) {
                m.spec = read_mutant_spec(options_.kit_root, lab.lab);
                m.shipped_names = list_names_of_shipped(options_.kit_root, lab.lab);
            } else if (any)
                result_.notes.push_back(lab.lab + ": no tests/mutants/" + lab.lab + ".json, so no mutants or variants measured");
            for (const auto& c : lab.cases)
                if (c.visibility == "public") result_.cases.push_back({lab.lab, c.name, c.todo, budget_text(lab, c)});
            m.cases = std::move(lab);
            labs_.push_back(std::move(m));
        }
        for (const auto& wanted : options_.labs)
            if (!found.count(wanted)) throw Error("no grading cases for lab '" + wanted + "' (grader/cases/" + wanted + ".json)");
        for (const auto& lab : labs_) {
            if (!lab.spec) continue;
            if (const Json* cpp = lab.spec->find("cpp_mutants"); cpp && !cpp->as_array().empty())
                result_.notes.push_back(lab.cases.lab + ": " + std::to_string(cpp->as_array().size()) +
                                        " C++ mutants left out (they name no case to fail, and each needs a build of the "
                                        "submission; the mutation test grades them)");
        }
    }

    void say(const std::string& line) const {
        if (progress_) progress_(line);
    }

    // The renderer the implementation gives, from one render of the first case; empty run.renderer: it did not render.
    MarginImplementationRun probe(const Implementation& implementation) const {
        MarginImplementationRun run;
        run.implementation = implementation;
        const LabToMeasure& lab = labs_.front();
        const LabRunner runner{options_.bin_dir, "", false, implementation.profile};
        ProcessLimits limits;
        limits.timeout = std::chrono::milliseconds(static_cast<long>(lab.cases.timeout_s * 1000 * 4));
        const LabRun probe = runner.render(lab.cases.lab + "_solution", lab.cases, lab.cases.cases.front(), limits);
        run.renderer = probe.renderer;
        if (probe.status != CaseStatus::Passed) {
            run.why_not = "its probe render (" + lab.cases.lab + "/" + lab.cases.cases.front().name + ") ended in " +
                          status_name(probe.status) + ": " + probe.detail;
            return run;
        }
        for (const auto& word : implementation.renderer_holds)
            if (probe.renderer.find(word) == std::string::npos) {
                run.why_not = "GL_RENDERER is '" + probe.renderer + "', without '" + word + "'";
                return run;
            }
        run.available = true;
        return run;
    }

    // Grades `lab` with `edit` made to its solution, as a student's, against the goldens; records each image result.
    GradeReport grade_edited(const Implementation& implementation, const LabToMeasure& lab,
                             const std::function<void(const fs::path&)>& edit, const std::string& todo,
                             const std::vector<std::string>& cases, const std::string& kind, const std::string& source) {
        const fs::path work = options_.work_dir / "kit";
        std::error_code ec;
        fs::remove_all(work, ec);
        make_edited_kit(work, options_.kit_root, options_.bin_dir, lab.cases.lab, lab.lab_dir, edit);
        GradeOptions g;
        g.kit_root = options_.kit_root;
        g.bin_dir = options_.bin_dir;
        g.out_dir = work / "out";
        g.student_bin_dir = work / "bin";
        g.student_root = work / "kit";
        g.labs = {lab.cases.lab};
        g.self_check = true;
        g.hidden = false;
        g.timing = false;
        g.profile = implementation.profile;
        if (implementation.profile == Profile::Es) g.es_at_least = options_.es_at_least;
        g.todo = todo;
        g.cases = cases;
        // A mutant's failures are named from the pictures the kit ships, as a student's self-check names them there
        // (nothing rendered for it); the rest are not diagnosed.
        g.diagnose = kind == "mutant" ? DiagnoseCases::Public : DiagnoseCases::Off;
        g.mistake_pictures = MistakePictureSource::Shipped;
        GradeReport report = grade(g);
        record(implementation, report, kind, source);
        if (kind == "mutant") record_diagnosis(implementation, lab, report, source);
        fs::remove_all(work, ec);
        return report;
    }

    // The first name of the report's diagnosis in the lists' names (the kit ships ids, in the lists' order).
    void record_diagnosis(const Implementation& implementation, const LabToMeasure& lab, const GradeReport& report, const std::string& mutant) {
        bool failed = false;
        for (const auto& r : report.results) failed = failed || r.status == CaseStatus::WrongImage || r.status == CaseStatus::BlankImage;
        if (!failed) return;  // nothing a picture could name: passed, or failed for a reason that is not a picture
        MarginDiagnosis d{implementation.name, lab.cases.lab, mutant, "", false};
        for (const auto& diagnosis : report.diagnoses) {
            if (diagnosis.found.empty()) continue;
            for (const std::string& id : diagnosis.found.front().names) {
                const auto it = lab.shipped_names.find(id);
                const std::string name = it == lab.shipped_names.end() ? id : it->second;
                d.named += (d.named.empty() ? "" : "; ") + name;
                d.right = d.right || name == mutant;
            }
            break;
        }
        result_.diagnoses.push_back(d);
    }

    static bool all_passed(const GradeReport& report) {
        return std::all_of(report.results.begin(), report.results.end(),
                           [](const CaseResult& r) { return r.status == CaseStatus::Passed; });
    }

    void record(const Implementation& implementation, const GradeReport& report, const std::string& kind, const std::string& source) {
        for (const auto& r : report.results) {
            if (r.kind != "image") continue;
            result_.renders.push_back({implementation.name, r.lab, r.name, kind, source, budget_share(r), status_name(r.status),
                                       one_line(r.detail, 300), std::max(std::abs(r.image.offset_x), std::abs(r.image.offset_y))});
        }
    }

    void measure(const Implementation& implementation) {
        const auto start = std::chrono::steady_clock::now();
        const EnvironmentFor environment(implementation);
        MarginImplementationRun run = probe(implementation);
        say(implementation.name + ": " + (run.available ? "GL_RENDERER " + run.renderer : "not available here: " + run.why_not));
        if (run.available) {
            for (const auto& lab : labs_) {
                const auto noop = [](const fs::path&) {};
                grade_edited(implementation, lab, noop, "", {}, "solution", "");
                say(implementation.name + ": " + lab.cases.lab + ": the solution graded");
                if (!lab.spec) continue;
                if (const Json* variants = lab.spec->find("variants"); variants && options_.variants) {
                    for (const Json& v : variants->as_array()) {
                        const auto edit = [&](const fs::path& folder) { apply_mutant_edits(folder, v, options_.kit_root); };
                        grade_edited(implementation, lab, edit, v.string_at("todo"), {}, "variant", v.string_at("name"));
                    }
                    say(implementation.name + ": " + lab.cases.lab + ": the correct variants graded");
                }
                int count = 0;
                for (const Json& m : lab.spec->array_at("mutants").as_array()) {
                    if (!options_.mutants) break;
                    std::vector<std::string> cases;
                    if (const Json* must = m.find("must_fail"))
                        for (const Json& c : must->as_array())
                            for (const auto& known : lab.cases.cases)
                                if (known.visibility == "public" && known.name == c.as_string()) cases.push_back(c.as_string());
                    if (cases.empty()) continue;
                    const auto edit = [&](const fs::path& folder) { apply_mutant_edits(folder, m, options_.kit_root); };
                    if (options_.mutant_until_first_failure) {
                        for (const auto& c : cases)
                            if (!all_passed(grade_edited(implementation, lab, edit, "", {c}, "mutant", m.string_at("name")))) break;
                    } else {
                        grade_edited(implementation, lab, edit, "", cases, "mutant", m.string_at("name"));
                    }
                    ++count;
                }
                say(implementation.name + ": " + lab.cases.lab + ": " + std::to_string(count) + " mutants graded");
            }
        }
        run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        result_.implementations.push_back(run);
    }

    const MarginOptions& options_;
    const std::function<void(const std::string&)>& progress_;
    std::vector<LabToMeasure> labs_;
    MarginMeasurement result_;
};

Json number_or_null(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

}  // namespace

MarginMeasurement measure_margins(const MarginOptions& options, const std::function<void(const std::string&)>& progress) {
    return Measuring(options, progress).run();
}

Json margins_json(const MarginMeasurement& m) {
    // An object with these members, in this order.
    const auto object = [](std::initializer_list<std::pair<const char*, Json>> members) {
        Json j = Json::object();
        for (const auto& [key, value] : members) j[key] = value;
        return j;
    };
    Json implementations = Json::array(), cases = Json::array(), renders = Json::array(), notes = Json::array();
    for (const auto& run : m.implementations)
        implementations.push_back(object({{"name", run.implementation.name}, {"how", run.implementation.how},
                                          {"renderer", valid_utf8(run.renderer)}, {"available", run.available},
                                          {"why_not", valid_utf8(run.why_not)}, {"seconds", number_or_null(run.seconds)}}));
    for (const auto& c : m.cases) cases.push_back(object({{"lab", c.lab}, {"case", c.name}, {"todo", c.todo}, {"budget", c.budget}}));
    // A share of null: the render could not be compared (its status says why).
    for (const auto& r : m.renders)
        renders.push_back(object({{"implementation", r.implementation}, {"lab", r.lab}, {"case", r.case_name}, {"kind", r.kind},
                                  {"source", r.source}, {"share", number_or_null(r.share)}, {"status", r.status},
                                  {"detail", valid_utf8(r.detail)}, {"offset", number_or_null(r.offset)}}));
    for (const auto& n : m.notes) notes.push_back(n);
    Json diagnoses = Json::array();
    for (const auto& d : m.diagnoses)
        diagnoses.push_back(object({{"implementation", d.implementation}, {"lab", d.lab}, {"mutant", d.mutant}, {"named", d.named},
                                    {"right", d.right}}));
    return object({{"implementations", implementations}, {"cases", cases}, {"renders", renders}, {"diagnoses", diagnoses},
                   {"labs_with_mutants", m.labs_with_mutants}, {"notes", notes}});
}

MarginMeasurement margins_from_json(const Json& root) {
    MarginMeasurement m;
    for (const Json& j : root.array_at("implementations").as_array()) {
        MarginImplementationRun run;
        run.implementation.name = j.string_at("name");
        run.implementation.how = j.string_at("how");
        run.renderer = j.string_at("renderer");
        run.available = j.bool_at("available");
        run.why_not = j.string_at("why_not");
        run.seconds = j.number_or("seconds", 0);
        m.implementations.push_back(run);
    }
    for (const Json& j : root.array_at("cases").as_array())
        m.cases.push_back({j.string_at("lab"), j.string_at("case"), j.string_at("todo"), j.string_at("budget")});
    for (const Json& j : root.array_at("renders").as_array())
        m.renders.push_back({j.string_at("implementation"), j.string_at("lab"), j.string_at("case"), j.string_at("kind"),
                             j.string_at("source"), j.number_or("share", kInf), j.string_at("status"),
                             j.string_at("detail"), j.number_or("offset", 0)});
    for (const Json& n : root.array_at("notes").as_array()) m.notes.push_back(n.as_string());
    m.labs_with_mutants = static_cast<std::size_t>(root.number_or("labs_with_mutants", 0));
    if (const Json* list = root.find("diagnoses"))
        for (const Json& j : list->as_array())
            m.diagnoses.push_back({j.string_at("implementation"), j.string_at("lab"), j.string_at("mutant"), j.string_at("named"),
                                   j.bool_at("right")});
    return m;
}

MarginMeasurement merge_margins(const std::vector<MarginMeasurement>& parts) {
    MarginMeasurement all;
    std::set<std::string> seen_cases, seen_notes;
    for (const auto& part : parts) {
        all.implementations.insert(all.implementations.end(), part.implementations.begin(), part.implementations.end());
        for (const auto& c : part.cases)
            if (seen_cases.insert(c.lab + "/" + c.name).second) all.cases.push_back(c);
        all.renders.insert(all.renders.end(), part.renders.begin(), part.renders.end());
        all.diagnoses.insert(all.diagnoses.end(), part.diagnoses.begin(), part.diagnoses.end());
        all.labs_with_mutants = std::max(all.labs_with_mutants, part.labs_with_mutants);
        for (const auto& n : part.notes)
            if (seen_notes.insert(n).second) all.notes.push_back(n);
    }
    return all;
}

namespace {

// What one case's renders say against the bar.
struct CaseVerdict {
    std::map<std::string, double> correct_by_implementation;  // the worst correct render on each
    double worst_correct = -1;
    double nearest_wrong = kInf;
    std::string nearest_wrong_what;
    int wrong_renders = 0;
    std::vector<std::string> misses;
};

std::string why_correct(const MarginRender& r) {
    return std::string(r.kind == "variant" ? "correct variant '" + r.source + "'" : "the solution") + " uses " +
           percent_text(r.share) + " of the budget on " + r.implementation + " (" + r.status + (r.detail.empty() ? "" : ": " + r.detail) + ")";
}

// The same verdict whatever order the renders were measured or joined in.
CaseVerdict verdict_of(const MarginMeasurement& m, const MarginCase& c) {
    CaseVerdict v;
    std::map<std::pair<std::string, std::string>, std::vector<std::string>> wrong_where;  // (before, after) -> where
    for (const auto& r : m.renders) {
        if (r.lab != c.lab || r.case_name != c.name) continue;
        if (r.kind == "mutant") {
            ++v.wrong_renders;
            const std::string what = "'" + r.source + "' on " + r.implementation;
            if (v.nearest_wrong_what.empty() || r.share < v.nearest_wrong || (r.share == v.nearest_wrong && what < v.nearest_wrong_what)) {
                v.nearest_wrong = r.share;
                v.nearest_wrong_what = what;
            }
            if (r.share <= kWrongBar) {
                // One line for a mutant as far away on several implementations.
                const std::string key = "must-fail mutant '" + r.source + "' is " + percent_text(r.share) + " of the budget on ";
                const std::string why = r.share <= 1 ? " (it passes: " + r.detail + ")"
                                                     : " (it fails, but by under 150% of the budget)";
                wrong_where[{key, why}].push_back(r.implementation);
            }
            continue;
        }
        auto& worst = v.correct_by_implementation.emplace(r.implementation, -1.0).first->second;
        worst = std::max(worst, r.share);
        v.worst_correct = std::max(v.worst_correct, r.share);
        if (r.share >= kCorrectBar) v.misses.push_back(why_correct(r));
    }
    std::sort(v.misses.begin(), v.misses.end());
    for (auto [line, where] : wrong_where) {
        std::sort(where.begin(), where.end());
        std::string joined;
        for (const auto& name : where) joined += (joined.empty() ? "" : ", ") + name;
        v.misses.push_back(line.first + joined + line.second);
    }
    return v;
}

std::string pad(const std::string& text, std::size_t width) { return text.size() >= width ? text : text + std::string(width - text.size(), ' '); }
std::string pad_left(const std::string& text, std::size_t width) {
    return text.size() >= width ? text : std::string(width - text.size(), ' ') + text;
}

std::string renderer_of(const MarginMeasurement& m, const std::string& implementation) {
    for (const auto& run : m.implementations)
        if (run.implementation.name == implementation) return run.renderer;
    return "";
}

}  // namespace

std::vector<std::string> cases_missing_the_bar(const MarginMeasurement& m) {
    std::vector<std::string> lines;
    for (const auto& c : m.cases) {
        const CaseVerdict v = verdict_of(m, c);
        for (const auto& why : v.misses) lines.push_back(c.lab + "/" + c.name + " (" + c.todo + "): " + why);
    }
    return lines;
}

std::vector<std::string> grading_failures(const MarginMeasurement& m) {
    std::vector<std::string> lines;
    const auto on = [&](const std::string& implementation) {
        return implementation + " (GL_RENDERER '" + renderer_of(m, implementation) + "')";
    };
    // A mutant holds when it lost points on one of the cases it must fail, as the mutation test asks on llvmpipe.
    std::map<std::string, bool> mutant_failed;  // implementation|lab|mutant
    for (const auto& r : m.renders) {
        if (r.kind == "mutant") {
            mutant_failed[r.implementation + "|" + r.lab + "|" + r.source] |= r.status != "passed";
        } else if (r.status != "passed") {
            lines.push_back("on " + on(r.implementation) + ": " + r.lab + "/" + r.case_name + ": " +
                            (r.kind == "variant" ? "the correct variant '" + r.source + "'" : std::string("the solution")) +
                            " is graded " + r.status + (r.detail.empty() ? "" : ": " + r.detail));
        }
    }
    for (const auto& [key, failed] : mutant_failed) {
        if (failed) continue;
        const auto bar = key.find('|'), bar2 = key.find('|', bar + 1);
        lines.push_back("on " + on(key.substr(0, bar)) + ": " + key.substr(bar + 1, bar2 - bar - 1) + ": mutant '" + key.substr(bar2 + 1) +
                        "' passes every case it must fail");
    }
    // The diagnosis: never another mistake's name for a mutant, on any implementation (none at all is honest: "no
    // known mistake matches"); and, where the measurement holds every lab with mutants, the mutant itself named first
    // for kDiagnosisBar of them on each implementation (the bar is over the kit's mistakes, not a lab's few).
    std::map<std::string, std::pair<int, int>> named;  // implementation -> right, all
    std::map<std::string, std::string> missed;
    std::set<std::string> labs;
    for (const auto& d : m.diagnoses) {
        labs.insert(d.lab);
        auto& [right, all] = named[d.implementation];
        ++all;
        right += d.right;
        if (!d.right) missed[d.implementation] += (missed[d.implementation].empty() ? "" : "; ") + d.lab + " '" + d.mutant + "'";
        if (!d.right && !d.named.empty())
            lines.push_back("on " + on(d.implementation) + ": " + d.lab + ": mutant '" + d.mutant + "' is named as '" + d.named + "'");
    }
    if (labs.size() >= m.labs_with_mutants)
        for (const auto& [implementation, count] : named)
            if (count.first < kDiagnosisBar * count.second)
                lines.push_back("on " + on(implementation) + ": the self-check names " + std::to_string(count.first) + " of " +
                                std::to_string(count.second) + " mutants first, under " + percent_text(kDiagnosisBar) + ": not " +
                                missed[implementation]);
    for (const auto& run : m.implementations)
        if (!run.available) lines.push_back(run.implementation.name + " was not measured: " + run.why_not);
    return lines;
}

std::string margins_table(const MarginMeasurement& m) {
    std::ostringstream out;
    out << "implementations\n";
    std::vector<std::string> measured;
    for (const auto& run : m.implementations) {
        out << "  " << pad(run.implementation.name, 17) << " ";
        if (run.available) {
            measured.push_back(run.implementation.name);
            out << run.renderer << "; " << run.implementation.how << " (" << fixed(run.seconds / 60.0, 1) << " min)\n";
        } else {
            out << "not measured: " << run.why_not << "\n";
        }
    }
    out << "\nper case: the worst correct render (the solution and the correct variants of tests/mutants/) on each "
           "implementation, and the nearest\nmutant that must fail the case (over all implementations), as shares of the "
           "case's golden budget. The bar: correct under "
        << percent_text(kCorrectBar) << ", must-fail\nmutants over " << percent_text(kWrongBar)
        << " (a failing self-check within that, on another renderer, is told it differs by a margin seen between GPUs).\n";
    std::size_t w_case = 4;
    for (const auto& c : m.cases) w_case = std::max(w_case, c.name.size());
    int missing = 0, cases = 0, without_mutants = 0;
    for (std::size_t i = 0; i < m.cases.size(); ++i) {
        const MarginCase& c = m.cases[i];
        if (i == 0 || m.cases[i - 1].lab != c.lab) {
            // The budget once for a lab whose cases share it.
            bool one_budget = true;
            for (const auto& other : m.cases)
                if (other.lab == c.lab && other.budget != c.budget) one_budget = false;
            out << "\n" << c.lab << (one_budget ? "  (budget: " + c.budget + ")" : "") << "\n  " << pad("case", w_case) << "  "
                << pad("todo", 6);
            for (const auto& name : measured) out << "  " << pad_left(name.size() > 12 ? name.substr(0, 12) : name, 12);
            out << "  " << pad_left("mutant", 7) << "  verdict\n";
        }
        const CaseVerdict v = verdict_of(m, c);
        ++cases;
        out << "  " << pad(c.name, w_case) << "  " << pad(c.todo, 6);
        for (const auto& name : measured) {
            const auto it = v.correct_by_implementation.find(name);
            out << "  " << pad_left(it == v.correct_by_implementation.end() ? "-" : percent_text(it->second), 12);
        }
        out << "  " << pad_left(v.wrong_renders ? percent_text(v.nearest_wrong) : "-", 7) << "  ";
        if (!v.misses.empty()) {
            ++missing;
            out << "MISSES THE BAR";
        } else {
            out << "ok";
        }
        if (v.wrong_renders) {
            out << " (nearest: " << v.nearest_wrong_what << ")";
        } else {
            ++without_mutants;
            out << " (no mutant must fail it)";
        }
        out << "\n";
        bool one_budget = true;
        for (const auto& other : m.cases)
            if (other.lab == c.lab && other.budget != c.budget) one_budget = false;
        if (!one_budget) out << "    budget: " << c.budget << "\n";
    }
    // The whole picture's place: correct renders within half of what the grader refuses as a shifted picture.
    // The same words whatever order the renders were measured or joined in: the largest, and of equals the first by name.
    double worst_offset = 0;
    std::string worst_offset_what = "no correct render moved";
    for (const auto& r : m.renders) {
        const std::string what = r.lab + "/" + r.case_name + " on " + r.implementation;
        if (r.kind != "mutant" && r.offset > 0 && (r.offset > worst_offset || (r.offset == worst_offset && what < worst_offset_what))) {
            worst_offset = r.offset;
            worst_offset_what = what;
        }
    }
    out << "\nthe whole picture's offset: the largest of a correct render " << fixed(worst_offset, 2) << " px (" << worst_offset_what
        << "); a share of the budget above is also the offset over the " << fixed(kMaxGlobalOffset, 2)
        << " px the grader refuses, so correct renders stay under " << fixed(kCorrectBar * kMaxGlobalOffset, 2) << " px\n";
    // The diagnosis: per implementation, how many mutants the self-check named first, from the shipped pictures.
    if (!m.diagnoses.empty()) {
        out << "\nthe diagnosis (the self-check's first name, from the pictures the kit ships) of the mutants graded; at least "
            << percent_text(kDiagnosisBar) << " right on each:\n";
        for (const auto& name : measured) {
            int right = 0, all = 0;
            std::string wrong;
            for (const auto& d : m.diagnoses) {
                if (d.implementation != name) continue;
                ++all;
                right += d.right;
                if (!d.right) wrong += (wrong.empty() ? "" : "; ") + d.lab + " '" + d.mutant + "' as " + (d.named.empty() ? "none" : "'" + d.named + "'");
            }
            if (all == 0) continue;
            out << "  " << pad(name, 17) << " " << right << " of " << all << " named first" << (wrong.empty() ? "" : ": not " + wrong) << "\n";
        }
    }
    out << "\n" << cases - missing << " of " << cases << " cases meet the bar";
    if (without_mutants) out << " (" << without_mutants << " with no mutant that must fail them: correct renders only)";
    out << "\n";
    const auto lines = cases_missing_the_bar(m);
    if (!lines.empty()) {
        out << "\nwhy cases miss the bar\n";
        for (const auto& line : lines) out << "  " << line << "\n";
    }
    if (!m.notes.empty()) {
        out << "\nnotes\n";
        for (const auto& n : m.notes) out << "  " << n << "\n";
    }
    return out.str();
}

}  // namespace gsv
