#include "grader/src/grade/regrade.h"

#include "common/app/kit_layout.h"
#include "common/core/error.h"
#include "common/core/fnv1a.h"
#include "common/io/json.h"
#include "grader/src/cases/cases.h"
#include "grader/src/report/report.h"
#include "grader/src/run/reference_store.h"
#include "grader/src/run/submission.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <random>
#include <regex>
#include <system_error>

namespace fs = std::filesystem;

namespace gsv {
namespace {

constexpr const char* kInputsFormat = "gsv-inputs 1";

// A file by its bytes ("" where it cannot be read, which differs from any file's fingerprint).
void add_file(Fnv1a& hash, const fs::path& file) { hash.add(file_fingerprint(file)); }

std::string file_text(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// A tree by the names, kinds and bytes of what is in it, never following a link. Student trees are hostile: one over
// the submission's limits (run/submission.h) gets a fingerprint of its own each time, so it is always graded (where
// the build refuses what is over).
void add_tree(Fnv1a& hash, const fs::path& root) {
    std::error_code ec;
    const auto status = fs::symlink_status(root, ec);
    if (ec || !fs::exists(status)) {
        hash.add("absent");
        return;
    }
    if (fs::is_regular_file(status)) {
        hash.add("file");
        add_file(hash, root);
        return;
    }
    std::vector<fs::path> entries;
    for (auto it = fs::recursive_directory_iterator(root, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        entries.push_back(it->path());
        if (entries.size() > kMaxSubmissionEntries) break;
    }
    std::sort(entries.begin(), entries.end());
    std::uintmax_t bytes = 0;
    for (const fs::path& entry : entries) {
        hash.add(entry.lexically_relative(root).generic_string());
        const auto s = fs::symlink_status(entry, ec);
        if (fs::is_symlink(s)) {
            hash.add("link " + fs::read_symlink(entry, ec).string());
        } else if (fs::is_directory(s)) {
            hash.add("folder");
        } else if (fs::is_regular_file(s)) {
            const auto size = fs::file_size(entry, ec);
            bytes += size;
            if (size > kMaxSubmissionFileBytes || bytes > kMaxSubmissionBytes) break;
            hash.add("file");
            add_file(hash, entry);
        } else {
            hash.add("special");
        }
    }
    if (ec || entries.size() > kMaxSubmissionEntries || bytes > kMaxSubmissionBytes ||
        std::any_of(entries.begin(), entries.end(), [&](const fs::path& e) {
            std::error_code size_ec;
            return fs::is_regular_file(fs::symlink_status(e, size_ec)) && fs::file_size(e, size_ec) > kMaxSubmissionFileBytes;
        }))
        hash.add(std::to_string(std::random_device{}()) + std::to_string(std::random_device{}()));
}

std::string run_options(const GradeOptions& o, std::uint64_t seed) {
    std::string text = "seed " + std::to_string(seed) + " self-check " + std::to_string(o.self_check) + " timing " +
                       std::to_string(o.timing) + " hidden " + std::to_string(o.hidden) + " sandbox " + std::to_string(o.sandbox) +
                       " namespaces " + std::to_string(o.namespaces) + " readable-kit " + std::to_string(o.allow_readable_kit) +
                       " profile " + profile_name(o.profile) + " todo " + o.todo + " timeout " + std::to_string(o.timeout_s) +
                       " student-bin " + o.student_bin_dir.string() + " student-root " + o.student_root.string() +
                       // How a grade is made changes nothing a student did, but a grade made another way is not the one
                       // recorded: every lab built (--build-all), a process per case, the ES version.
                       " build-all " + std::to_string(!o.reuse_builds) + " processes " +
                       std::to_string(static_cast<int>(o.lab_processes)) + " diagnose " + std::to_string(static_cast<int>(o.diagnose)) + " es-at-least " + (o.es_at_least ? o.es_at_least->str() : "-") +
                       " cases";
    for (const auto& c : o.cases) text += " " + c;
    return text;
}

}  // namespace

std::vector<std::string> labs_of_run(const GradeOptions& options) {
    std::vector<std::string> labs;
    for (const fs::path& file : case_files(options.kit_root)) {
        const std::string lab = file.stem().string();
        if (!options.labs.empty() && std::find(options.labs.begin(), options.labs.end(), lab) == options.labs.end()) continue;
        if (!options.todo.empty() && lab != "lab" + options.todo.substr(1, 2)) continue;
        labs.push_back(lab);
    }
    return labs;
}

LabInputs lab_inputs(const GradeOptions& options, const std::vector<std::string>& labs, std::uint64_t seed, const fs::path& grader) {
    const KitLayout kit{options.kit_root};
    const fs::path bin = options.bin_dir, kit_build = options.bin_dir.parent_path();
    Fnv1a shared;
    shared.add(run_options(options, seed));
    shared.add("grader");
    add_file(shared, grader);
    for (const char* part : {"shaders", "common", "support", "third_party", "data", "reference", "cmake", "grader/submission",
                             "grader/starters.json"}) {
        shared.add(part);
        add_tree(shared, options.kit_root / part);
    }
    // What a submission's build links and configures with: the kit build's exported targets and settings, and each
    // library they name, by its bytes.
    for (const char* settings : {"gsv-targets.cmake", "gsv-build-settings.cmake"}) {
        shared.add(settings);
        add_file(shared, kit_build / settings);
    }
    static const std::regex location("IMPORTED_LOCATION[A-Z_]*\\s+\"([^\"]+)\"");
    const std::string targets = file_text(kit_build / "gsv-targets.cmake");
    for (auto it = std::sregex_iterator(targets.begin(), targets.end(), location); it != std::sregex_iterator(); ++it) {
        shared.add((*it)[1].str());
        add_file(shared, (*it)[1].str());
    }
    const fs::path student_labs = options.submission.empty() ? kit.labs() : KitLayout{options.submission}.labs();
    LabInputs inputs;
    for (const std::string& lab : labs) {
        Fnv1a hash = shared;
        const std::string folder = cmake_cache_value(kit_build, "GSV_LAB_DIR_" + lab);
        hash.add("lab " + lab + " in " + folder);
        // The lab's known mistakes too: the diagnosis puts a failure a mistake explains on the mistake's TODO.
        for (const fs::path& part : {kit.case_file(lab), kit.hidden_case_file(lab), kit.golden_dir(lab), kit.tests() / "mutants" / (lab + ".json"),
                                     folder.empty() ? kit.solutions() : kit.solutions() / folder, bin / lab, bin / (lab + "_solution")}) {
            hash.add(part.lexically_relative(options.kit_root).generic_string());
            add_tree(hash, part);
        }
        // The student's work: the lab's folder, or all of labs/ where the build does not name the folder. Nothing else of
        // the submission reaches the lab: its build and its runs see that folder alone (grade/walls.cpp, run/submission.h).
        hash.add("student");
        add_tree(hash, folder.empty() ? student_labs : student_labs / folder);
        inputs[lab] = hash.hex();
    }
    return inputs;
}

void write_lab_inputs(const fs::path& out, const LabInputs& inputs) {
    Json root = Json::object();
    root["format"] = kInputsFormat;
    Json labs = Json::object();
    for (const auto& [lab, fingerprint] : inputs) labs[lab] = fingerprint;
    root["labs"] = labs;
    const fs::path file = out / "inputs.json";
    std::ofstream stream(file, std::ios::trunc);
    stream << root.dump(2) << "\n";
    stream.close();
    if (!stream) throw Error("cannot write '" + file.string() + "'");
}

RegradePlan plan_regrade(const fs::path& out, const LabInputs& now) {
    RegradePlan plan;
    const auto grade_all = [&](const std::string& why) {
        plan.regrade.clear();
        plan.keep.clear();
        plan.earlier.reset();
        for (const auto& [lab, fingerprint] : now) plan.regrade.push_back(lab);
        plan.note = why + ": every lab graded";
        return plan;
    };
    const fs::path record = out / "inputs.json", report = out / "report.json";
    if (!fs::exists(record) || !fs::exists(report)) return grade_all("no earlier run in " + out.string());
    LabInputs before;
    try {
        const Json root = read_json_file(record);
        if (root.string_at("format") != kInputsFormat) return grade_all(record.string() + " is not a record of inputs");
        for (const auto& [lab, fingerprint] : root.object_at("labs").as_object()) before[lab] = fingerprint.as_string();
        plan.earlier = read_report_json(report);
    } catch (const Error& e) {
        return grade_all(std::string("the last run's record does not read back (") + e.what() + ")");
    }
    for (const auto& [lab, fingerprint] : now) {
        const auto was = before.find(lab);
        const bool has_rows = std::any_of(plan.earlier->results.begin(), plan.earlier->results.end(),
                                          [&](const CaseResult& r) { return r.lab == lab; });
        // A lab whose last rows include the kit's own fault is graded again: that grade did not stand.
        const bool kit_fault = std::any_of(plan.earlier->results.begin(), plan.earlier->results.end(),
                                           [&](const CaseResult& r) { return r.lab == lab && is_kit_fault(r.status); });
        (was != before.end() && was->second == fingerprint && has_rows && !kit_fault ? plan.keep : plan.regrade).push_back(lab);
    }
    return plan;
}

std::optional<GradeOptions> options_for_regrade(const GradeOptions& options, const RegradePlan& plan) {
    GradeOptions narrowed = options;
    narrowed.labs = plan.regrade;
    if (options.cases.empty()) return narrowed;
    const KitLayout kit{options.kit_root};
    std::vector<std::string> names;
    for (const std::string& lab : plan.regrade) {
        LabCases cases = load_lab_cases(kit.case_file(lab));
        if (options.seed && fs::exists(kit.hidden_case_file(lab))) add_hidden_cases(cases, kit.hidden_case_file(lab), *options.seed);
        for (const GradeCase& c : cases.cases) names.push_back(c.name);
    }
    narrowed.cases.clear();
    for (const std::string& c : options.cases)
        if (std::find(names.begin(), names.end(), c) != names.end()) narrowed.cases.push_back(c);
    if (narrowed.cases.empty()) return std::nullopt;
    return narrowed;
}

GradeReport merge_regraded(const GradeReport& earlier, const GradeReport& fresh, const RegradePlan& plan,
                           const std::vector<std::string>& labs) {
    GradeReport merged = fresh;
    merged.results.clear();
    merged.builds.clear();
    const auto kept = [&](const std::string& lab) { return std::find(plan.keep.begin(), plan.keep.end(), lab) != plan.keep.end(); };
    for (const std::string& lab : labs) {
        const GradeReport& from = kept(lab) ? earlier : fresh;
        for (const CaseResult& r : from.results)
            if (r.lab == lab) merged.results.push_back(r);
        for (const LabBuild& b : from.builds)
            if (b.lab == lab) merged.builds.push_back(b);
    }
    // A kept lab's diagnosis is the earlier run's, a regraded one's this run's.
    merged.diagnoses.clear();
    for (const std::string& lab : labs)
        for (const LabDiagnosis& d : (kept(lab) ? earlier : fresh).diagnoses)
            if (d.lab == lab) merged.diagnoses.push_back(d);
    // What only the earlier run saw of a kept lab: its goldens' renderer.
    for (const auto& [lab, renderer] : earlier.golden_renderers)
        if (kept(lab)) merged.golden_renderers[lab] = renderer;
    if (merged.renderer.empty()) merged.renderer = earlier.renderer;
    merged.hidden_included = fresh.hidden_included || earlier.hidden_included;
    merged.timing_included = fresh.timing_included || earlier.timing_included;
    merged.regraded = plan.regrade;
    merged.kept = plan.keep;
    return merged;
}

}  // namespace gsv
