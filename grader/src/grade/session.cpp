#include "grader/src/grade/session.h"

#include "common/app/kit_layout.h"
#include "common/app/lab_sources.h"
#include "common/core/error.h"
#include "grader/src/cases/case_row.h"
#include "grader/src/cases/draw.h"
#include "grader/src/golden/golden_renderers.h"
#include "grader/src/run/submission.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <unistd.h>

namespace fs = std::filesystem;

namespace gsv {
namespace {

// Where a folder really is. The sandbox binds each allowed path where it really is; a lab started by a path through
// a symbolic link (a kit under ~/kit -> /mnt/data/kit, or macOS's /tmp) would not be found inside it, and would end
// in "the lab binary could not be started" for every case. So the grader names every folder by its real path.
bool file_bytes_equal(const fs::path& a, const fs::path& b) {
    std::ifstream x(a, std::ios::binary), y(b, std::ios::binary);
    if (!x || !y) return false;
    return std::equal(std::istreambuf_iterator<char>(x), std::istreambuf_iterator<char>(), std::istreambuf_iterator<char>(y),
                      std::istreambuf_iterator<char>());
}

fs::path real_path(const fs::path& p) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(p);
    const fs::path real = fs::weakly_canonical(absolute, ec);
    return ec ? absolute : real;
}

}  // namespace

GradingSession::GradingSession(const GradeOptions& options, const std::function<void(const GradeProgress&)>& progress,
                               RunPurpose purpose)
    : options(options), out(real_path(options.out_dir)), kit(real_path(options.kit_root)), bin(real_path(options.bin_dir)),
      progress_(progress), purpose_(purpose), start_(std::chrono::steady_clock::now()) {}

void GradingSession::set_up() {
    report.seed = options.seed ? *options.seed : fresh_seed();
    report.submission = options.submission.empty() ? KitLayout{kit}.labs().string() : real_path(options.submission).string();
    load_labs();
    const bool any_live = std::find(live.begin(), live.end(), true) != live.end();
    report.mode = purpose_ == RunPurpose::UpdateGoldens ? "update goldens" : any_live ? "instructor" : "self-check";
    diagnose = purpose_ == RunPurpose::UpdateGoldens ? DiagnoseCases::Off
               : options.diagnose != DiagnoseCases::Default ? options.diagnose
               : any_live ? DiagnoseCases::All : DiagnoseCases::Public;
    report.diagnose = diagnose == DiagnoseCases::Off ? "off" : diagnose == DiagnoseCases::Public ? "public" : "all";
    report.profile = profile_name(options.profile);
    if (purpose_ == RunPurpose::Grade) {
        const auto renderers = read_golden_renderers(KitLayout{kit}.golden_renderers());
        for (std::size_t i = 0; i < labs.size(); ++i)
            if (const auto it = renderers.find(labs[i].lab); !live[i] && it != renderers.end()) report.golden_renderers[it->first] = it->second;
    }
    fs::create_directories(out);

    fs::path student_bin = bin, student_root = kit;
    if (!options.submission.empty()) {
        const fs::path work = out / "submission-build";
        student_root = work / "kit";
        student_bin = work / "build" / "bin";
        set_up_sandbox(student_bin, student_root, work);
        std::vector<std::string> lab_ids;
        for (const auto& lab : labs) lab_ids.push_back(lab.lab);
        if (progress_) progress_({0, total_, nullptr, "building the submission's labs"});
        ProcessLimits build_limits = limits(labs.empty() ? LabCases{} : labs.front(), true);
        if (build_limits.sandbox) build_limits.sandbox = &build_policy_;
        build_limits.timeout = std::chrono::minutes(5);
        build_limits.max_output_bytes = 256 * 1024;
        const SubmissionBuild built = build_submission(options.submission, kit, bin.parent_path(), lab_ids, work, build_limits,
                                                       options.reuse_builds, options.build_cache);
        report.builds = built.builds;
    } else {
        if (!options.student_bin_dir.empty()) {
            student_bin = real_path(options.student_bin_dir);
            student_root = real_path(options.student_root);
        }
        set_up_sandbox(student_bin, student_root, {});
    }
    // The kit's own labs find their files as they would when a student runs them (GSV_ROOT included).
    const bool own_labs = options.submission.empty() && options.student_bin_dir.empty();
    for (const auto& lab : labs) {
        const std::string folder = cmake_cache_value(bin.parent_path(), "GSV_LAB_DIR_" + lab.lab);
        const fs::path binary = student_bin / lab.lab, solution = bin / (lab.lab + "_solution");
        bool kits = !folder.empty() && is_starter_cpp(kit, folder, KitLayout{student_root}.labs() / folder);
        // A test kit's binary (options.student_bin_dir) may be the solution's own: its C++ is the kit's, whatever the
        // folder beside it holds.
        std::error_code ec;
        if (!kits && !own_labs && options.submission.empty() && fs::file_size(binary, ec) == fs::file_size(solution, ec) && !ec)
            kits = file_bytes_equal(binary, solution);
        kit_cpp_[lab.lab] = kits;
    }
    student = LabRunner{student_bin, own_labs ? fs::path() : student_root, true, options.profile};
    reference = LabRunner{bin, "", false, options.profile};
    // Live references kept across runs, but only where student code cannot write them: behind the allow-list.
    // The known mistakes' pictures (diagnose/) are kept there too.
    if (purpose_ == RunPurpose::Grade && (any_live || diagnose != DiagnoseCases::Off)) {
        const fs::path folder = options.reference_store.empty() ? bin.parent_path() / "grader-cache" / "references"
                                                                 : fs::absolute(options.reference_store);
        // Where the walls are down, a root grader still runs student code as a leased uid (Gradescope's and Docker's
        // case): the store stays out of its reach where no folder on its path lets that uid write.
        std::string reachable;
        if (options.sandbox && !support_.allow_list() && geteuid() == 0) reachable = writable_by_others(folder);
        if (options.sandbox && (support_.allow_list() || (geteuid() == 0 && reachable.empty()))) {
            try {
                reference_context_ = reference_context(kit);
                reference_store_.emplace(folder);
            } catch (const Error& e) {
                report.references = std::string("rendered in this run; none kept on disk: ") + e.what();
            }
        } else if (!reachable.empty()) {
            report.references = "rendered in this run; none kept on disk, where student code could change them: " + reachable;
        } else {
            report.references = "rendered in this run; none kept on disk, where the walls are down student code could change them";
        }
    }
}

GradeReport GradingSession::finish() {
    if (reference_store_) {
        report.references = std::to_string(references_rendered_) + " rendered, " + std::to_string(reference_store_->hits() - mistake_store_hits) +
                            " from the store (" + reference_store_->folder().string() + ")" +
                            (options.stored_references ? "" : " (--fresh-references: none read)");
        if (!reference_store_->problem().empty()) report.references += "; " + reference_store_->problem();
    }
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    return report;
}

CaseResult GradingSession::result_for(const LabCases& lab, const GradeCase& c) const {
    CaseResult r = case_row(lab, c);
    // What a student types to see what their lab drew: a public case by name, a hidden one by its settings.
    r.reproduce = "build/bin/" + lab.lab + " render --size " + std::to_string(lab.width) + "x" + std::to_string(lab.height);
    if (c.visibility == "public") {
        r.reproduce += " --case " + c.name;
    } else {
        for (const auto& s : c.settings) r.reproduce += " --set " + s;
    }
    if (options.profile != Profile::Core) r.reproduce += std::string(" --profile ") + profile_name(options.profile);
    if (options.profile == Profile::Es && c.es_version) r.reproduce += " --gl " + c.es_version->str();
    r.reproduce += " --out " + c.name + ".png";
    return r;
}

void GradingSession::record(CaseResult r) {
    report.results.push_back(std::move(r));
    if (progress_) progress_({static_cast<int>(report.results.size()), total_, &report.results.back(), ""});
}

ProcessLimits GradingSession::limits(const LabCases& lab, bool student) const {
    ProcessLimits l;
    // --timeout is a limit on the student's code; the reference is trusted, and timing it out under a
    // loaded machine would fail the student's case for the grader's own reason.
    const double timeout_s = student && options.timeout_s > 0 ? options.timeout_s : lab.timeout_s;
    l.timeout = std::chrono::milliseconds(static_cast<long>(timeout_s * 1000));
    if (student && options.sandbox) {
        const auto own = lab_policies_.find(lab.lab);
        l.sandbox = own == lab_policies_.end() ? &policy_ : &own->second;
        l.support = &support_;
    }
    return l;
}

// Everything the reference's render of a case depends on: its command line (grader/src/run/lab_run.cpp's render), with
// the binary and the kit as fingerprints of their bytes, and the driver and its environment (reference_context).
std::string GradingSession::reference_key(const LabCases& lab, const GradeCase& c) {
    const std::string binary = lab.lab + "_solution";
    auto fingerprint = solution_fingerprints_.find(binary);
    if (fingerprint == solution_fingerprints_.end())
        fingerprint = solution_fingerprints_.emplace(binary, file_fingerprint(bin / binary)).first;
    std::string key = reference_context_ + "binary " + binary + " " + fingerprint->second + "\nrender --size " +
                      std::to_string(lab.width) + "x" + std::to_string(lab.height) + (lab.checks_arrays() ? " --arrays" : "") +
                      " --profile " + profile_name(options.profile);
    if (options.profile == Profile::Es && c.es_version) key += " --gl " + c.es_version->str();
    for (const auto& s : c.settings) key += "\n--set " + s;
    return key + "\n";
}

LabRun GradingSession::reference_render(const LabCases& lab, const GradeCase& c) {
    const auto render = [&] {
        ++references_rendered_;
        return reference.render(lab.lab + "_solution", lab, c, limits(lab, false));
    };
    const auto from_store = [&] {
        if (!reference_store_) return render();
        const std::string key = reference_key(lab, c);
        if (options.stored_references)
            if (std::optional<LabRun> stored = reference_store_->load(key)) return *stored;
        LabRun run = render();
        reference_store_->store(key, run);
        return run;
    };
    if (!options.reference_cache) return from_store();
    std::string key = lab.lab + "|" + std::to_string(lab.width) + "x" + std::to_string(lab.height) + "|" + bin.string() +
                      "|" + profile_name(options.profile) + "|" + (c.es_version ? c.es_version->str() : "");
    for (const auto& s : c.settings) key += "|" + s;
    auto& runs = options.reference_cache->runs;
    if (auto it = runs.find(key); it != runs.end()) return it->second;
    LabRun run = from_store();
    if (run.status == CaseStatus::Passed) runs.emplace(key, run);
    return run;
}

void GradingSession::serve(const LabCases& lab) {
    end_serving();
    const bool per_lab = options.lab_processes == LabProcesses::PerLab ||
                         (options.lab_processes == LabProcesses::Default && options.cases.empty());
    if (!per_lab) return;
    // Student code is served only where its sandbox can stop it between its cases (sandbox.h): without namespaces its
    // processes would run on while the grader judges, the reference renders or anything is timed.
    if (options.sandbox && support_.allow_list()) {
        served_student_ = std::make_unique<ServedLab>(lab.lab);
        student.served = served_student_.get();
    }
    served_reference_ = std::make_unique<ServedLab>(lab.lab + "_solution");
    reference.served = served_reference_.get();
}

void GradingSession::end_serving() {
    student.served = reference.served = nullptr;
    served_student_.reset();
    served_reference_.reset();
}

bool GradingSession::cpp_is_the_kits(const std::string& lab) const {
    const auto it = kit_cpp_.find(lab);
    return it != kit_cpp_.end() && it->second;
}

fs::path GradingSession::student_kit() const { return student.root.empty() ? kit : student.root; }

const LabBuild* GradingSession::build_of(const std::string& lab) const {
    const LabBuild* build = nullptr;
    for (const auto& b : report.builds)
        if (b.lab == lab) build = &b;
    return build;
}

}  // namespace gsv
