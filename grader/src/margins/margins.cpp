// Measuring the margins (margins.h): each implementation's renders of the public cases, the solutions', the must-fail
// mutants' and the correct variants', graded as a self-check; the JSON is margins_json.cpp's, the table margins_table.cpp's.
#include "grader/src/margins/margins.h"

#include "grader/src/diagnose/known_mistakes.h"

#include "common/app/kit_layout.h"
#include "common/core/error.h"
#include "common/core/number_text.h"
#include "common/image/image_offset.h"
#include "grader/src/cases/cases.h"
#include "grader/src/grade/grade.h"
#include "grader/src/diagnose/mutant_kit.h"
#include "grader/src/core/safe_text.h"
#include "grader/src/run/lab_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>

namespace fs = std::filesystem;

namespace gsv {
namespace {

// over / floor(fraction x of), as the grader's within() judges it (the same slack for decimal fractions).
double share_of(double over, double fraction, double of) {
    const double allowed = std::floor(std::max(0.0, fraction) * of * (1.0 + 1e-12));
    if (allowed <= 0) return over > 0 ? kInfiniteShare : 0.0;
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
    if (!r.image.done || r.image.total_pixels <= 0) return kInfiniteShare;
    double share = share_of(double(r.image.differing_pixels), r.image.tolerance.max_differing_fraction, double(r.image.total_pixels));
    if (r.data.done)
        for (const auto& a : r.data.arrays) {
            if (!a.problem.empty()) return kInfiniteShare;
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

}  // namespace

MarginMeasurement measure_margins(const MarginOptions& options, const std::function<void(const std::string&)>& progress) {
    return Measuring(options, progress).run();
}

}  // namespace gsv
