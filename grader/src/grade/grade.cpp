#include "grader/src/grade/grade.h"

#include "common/app/kit_layout.h"
#include "common/core/error.h"
#include "common/core/not_done.h"
#include "common/image/image.h"
#include "common/io/json.h"
#include "grader/src/golden/array_golden.h"
#include "grader/src/cases/cases.h"
#include "grader/src/judge/data_check.h"
#include "grader/src/cases/draw.h"
#include "grader/src/run/process.h"
#include "grader/src/report/report_format.h"
#include "grader/src/run/lab_run.h"
#include "grader/src/run/submission.h"
#include "grader/src/run/uid_lease.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <random>
#include <set>
#include <unistd.h>

namespace fs = std::filesystem;

namespace gsv {
namespace {

// A result row for a case, before anything ran.
CaseResult result_for(const LabCases& lab, const GradeCase& c, Profile profile) {
    CaseResult r;
    r.lab = lab.lab;
    r.name = c.name;
    r.todo = c.todo;
    r.description = c.description;
    r.visibility = c.visibility;
    r.settings = c.settings;
    r.max_points = c.points;
    // What a student types to see what their lab drew: a public case by name, a hidden one by its settings.
    r.reproduce = "build/bin/" + lab.lab + " render --size " + std::to_string(lab.width) + "x" + std::to_string(lab.height);
    if (c.visibility == "public") {
        r.reproduce += " --case " + c.name;
    } else {
        for (const auto& s : c.settings) r.reproduce += " --set " + s;
    }
    if (profile != Profile::Core) r.reproduce += std::string(" --profile ") + profile_name(profile);
    if (profile == Profile::Es && c.es_version) r.reproduce += " --gl " + c.es_version->str();
    r.reproduce += " --out " + c.name + ".png";
    return r;
}

// Everything one grading run needs, built once.
class Grading {
public:
    Grading(const GradeOptions& options, const std::function<void(const GradeProgress&)>& progress)
        : options_(options), progress_(progress), out_(fs::absolute(options.out_dir)), kit_(fs::absolute(options.kit_root)),
          bin_(fs::absolute(options.bin_dir)) {}

    GradeReport run();

private:
    void load_labs();
    // An instructor's mistake in a case file stops grading with one line, before any student code runs: a TODO id
    // no lab has, a parameter the lab does not have or a value out of its range (hidden cases as drawn included).
    void check_cases() const;
    void set_up_sandbox(const fs::path& student_bin, const fs::path& student_root, const fs::path& build_dir);
    void grade_lab(const LabCases& lab, bool live, const LabBuild* build);
    void blame_needed_todos(const LabCases& lab, std::size_t first);
    // The paths in a student process's messages as the student knows them: "labs/lab02_lic/streamline.glsl:12", not
    // the grader's copy of the submission.
    std::string as_student_sees(std::string text) const;
    // A PNG in the student's labs/ whose pixels are `image`'s, as the student names it; empty if none.
    std::string picture_in_submission(const Image& image) const;
    void grade_case(const LabCases& lab, const GradeCase& c, bool live, const LabBuild* build);
    void update_golden(const LabCases& lab, const GradeCase& c);
    void update_golden_arrays(const LabCases& lab, const GradeCase& c, const LabRun& ref, CaseResult& r);
    void check_image(const LabCases& lab, const GradeCase& c, const LabRun& student, const Image& expected, bool live,
                     CaseResult& r);
    CaseResult check_timing(const LabCases& lab, const GradeCase& c, const CaseResult& image);
    // The public case whose committed golden `image` is pixel for pixel; empty if none.
    std::string golden_copied(const std::string& lab, const std::string& case_name, const Image& image);
    void record(CaseResult r);
    ProcessLimits limits(const LabCases& lab, bool student) const;
    LabRun reference_render(const LabCases& lab, const GradeCase& c);

    const GradeOptions& options_;
    const std::function<void(const GradeProgress&)>& progress_;
    fs::path out_, kit_, bin_;
    GradeReport report_;
    std::vector<LabCases> labs_;
    std::vector<bool> live_;
    SandboxPolicy policy_;        // running a student's lab
    SandboxPolicy build_policy_;  // building a submission's labs
    SandboxSupport support_;
    std::optional<UidLease> uid_lease_;  // a root grader's uid for student code, held until grading ends
    LabRunner student_, reference_;
    std::map<std::string, std::map<std::string, Image>> goldens_;  // lab -> case -> image
    int total_ = 0;
};

LabRun Grading::reference_render(const LabCases& lab, const GradeCase& c) {
    if (!options_.reference_cache) return reference_.render(lab.lab + "_solution", lab, c, limits(lab, false));
    std::string key = lab.lab + "|" + std::to_string(lab.width) + "x" + std::to_string(lab.height) + "|" + bin_.string() +
                      "|" + profile_name(options_.profile);
    for (const auto& s : c.settings) key += "|" + s;
    auto& runs = options_.reference_cache->runs;
    if (auto it = runs.find(key); it != runs.end()) return it->second;
    LabRun run = reference_.render(lab.lab + "_solution", lab, c, limits(lab, false));
    if (run.status == CaseStatus::Passed) runs.emplace(key, run);
    return run;
}

ProcessLimits Grading::limits(const LabCases& lab, bool student) const {
    ProcessLimits l;
    // --timeout is a limit on the student's code; the reference is trusted, and timing it out under a
    // loaded machine would fail the student's case for the grader's own reason.
    const double timeout_s = student && options_.timeout_s > 0 ? options_.timeout_s : lab.timeout_s;
    l.timeout = std::chrono::milliseconds(static_cast<long>(timeout_s * 1000));
    if (student && options_.sandbox) {
        l.sandbox = &policy_;
        l.support = &support_;
    }
    return l;
}

void Grading::check_cases() const {
    // The TODO ids the kit's labs have: the reference's blocks, or in a student edition the starters' TODO comments.
    std::set<std::string> todos;
    static const std::regex id(R"((?://@solution |TODO\()(L[0-9]{2}-T[0-9]+))");
    const KitLayout kit{kit_};
    for (const fs::path& folder : {kit.solutions(), kit.labs()}) {
        std::error_code ec;
        for (auto it = fs::recursive_directory_iterator(folder, fs::directory_options::follow_directory_symlink, ec);
             !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
            if (!it->is_regular_file(ec) || it->file_size(ec) > (1u << 20)) continue;
            std::ifstream in(it->path());
            for (std::string line; std::getline(in, line);)
                for (std::sregex_iterator m(line.begin(), line.end(), id), end; m != end; ++m) todos.insert((*m)[1]);
        }
    }
    for (std::size_t i = 0; i < labs_.size(); ++i) {
        const LabCases& lab = labs_[i];
        const fs::path file = KitLayout{kit_}.case_file(lab.lab);
        for (const auto& c : lab.cases) {
            const std::string where = (c.visibility == "public" ? file : hidden_case_file(kit_, lab.lab)).string() + ": case '" + c.name + "'";
            if (!todos.empty() && !todos.count(c.todo)) throw Error(where + ": no lab has a TODO '" + c.todo + "'");
            for (const auto& n : c.needs)
                if (!todos.empty() && !todos.count(n)) throw Error(where + " needs '" + n + "', which no lab has");
        }
        // The settings, through the reference's own parameters (where it is built): `list` reads the public case file
        // and refuses an unknown name or a value out of range at its file:line:column; with a hidden case's settings
        // given, it applies those.
        const fs::path reference = bin_ / (lab.lab + "_solution");
        if (!fs::exists(reference)) continue;
        const auto refused = [&](const std::vector<std::string>& settings) {
            std::vector<std::string> argv{reference.string(), "list"};
            for (const auto& s : settings) argv.insert(argv.end(), {"--set", s});
            ProcessLimits l;
            l.timeout = std::chrono::seconds(20);
            const ProcessResult checked = run_process(argv, kit_, l, {"GSV_ROOT=" + kit_.string()});
            if (checked.exit_code == 0) return std::string();
            std::string why = checked.output;
            if (const auto at = why.find(lab.lab + ": "); at != std::string::npos) why = why.substr(at + lab.lab.size() + 2);
            return why.substr(0, why.find('\n'));
        };
        if (const std::string why = refused({}); !why.empty()) throw Error(why);
        for (const auto& c : lab.cases)
            if (c.visibility != "public")
                if (const std::string why = refused(c.settings); !why.empty())
                    throw Error(hidden_case_file(kit_, lab.lab).string() + ": case '" + c.name + "' (as drawn): " + why);
        // A timed case's "vary", drawn once as the timed frames will be: a setting the lab refuses stops grading here.
        for (const auto& c : lab.cases)
            if (c.timing.vary) {
                SeededDraw trial(report_.seed, lab.lab + "/" + c.name + "/check");
                std::vector<std::string> settings = c.settings;
                for (auto& s : draw_settings(*c.timing.vary, trial, c.settings)) settings.push_back(std::move(s));
                if (const std::string why = refused(settings); !why.empty())
                    throw Error(file.string() + ": case '" + c.name + "': timing \"vary\" (as drawn): " + why);
            }
    }
}

void Grading::load_labs() {
    std::vector<std::string> known;
    for (const auto& file : case_files(kit_)) {
        LabCases lab = load_lab_cases(file);
        known.push_back(lab.lab);
        if (!options_.labs.empty() && std::find(options_.labs.begin(), options_.labs.end(), lab.lab) == options_.labs.end())
            continue;
        // --todo L02-T3: lab02's cases of that TODO.
        if (!options_.todo.empty() && lab.lab != "lab" + options_.todo.substr(1, 2)) continue;
        const bool live = !options_.self_check && !options_.update_goldens && fs::exists(bin_ / (lab.lab + "_solution"));
        const fs::path hidden = hidden_case_file(kit_, lab.lab);
        if (live && options_.hidden && fs::exists(hidden)) {
            add_hidden_cases(lab, hidden, report_.seed);
            report_.hidden_included = true;
        }
        if (!options_.cases.empty())
            lab.cases.erase(std::remove_if(lab.cases.begin(), lab.cases.end(),
                                           [&](const GradeCase& c) {
                                               return std::find(options_.cases.begin(), options_.cases.end(), c.name) ==
                                                      options_.cases.end();
                                           }),
                            lab.cases.end());
        if (!options_.todo.empty())
            lab.cases.erase(std::remove_if(lab.cases.begin(), lab.cases.end(), [&](const GradeCase& c) { return c.todo != options_.todo; }),
                            lab.cases.end());
        if (live && options_.timing)
            for (const auto& c : lab.cases) report_.timing_included = report_.timing_included || c.timing.points > 0;
        labs_.push_back(std::move(lab));
        live_.push_back(live);
    }
    for (const auto& wanted : options_.labs)
        if (std::find(known.begin(), known.end(), wanted) == known.end()) {
            std::string list;
            for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
            throw Error("no grading cases for lab '" + wanted + "' (grader/cases/" + wanted + ".json); labs with cases: " + list);
        }
    for (const auto& wanted : options_.cases) {
        bool found = false;
        for (const auto& lab : labs_)
            for (const auto& c : lab.cases) found = found || c.name == wanted;
        if (!found) throw Error("no case named '" + wanted + "' in the labs being graded (`<lab> list` and grader/cases/<lab>.json name them)");
    }
    check_cases();
    if (!options_.todo.empty()) {
        std::size_t cases = 0;
        for (const auto& lab : labs_) cases += lab.cases.size();
        if (cases == 0) throw Error("no case checks TODO '" + options_.todo + "' (each case's \"todo\" in grader/cases/<lab>.json)");
    }
    for (std::size_t i = 0; i < labs_.size(); ++i)
        for (const auto& c : labs_[i].cases) total_ += 1 + (live_[i] && options_.timing && c.timing.points > 0 ? 1 : 0);
}

void Grading::set_up_sandbox(const fs::path& student_bin, const fs::path& student_root, const fs::path& build_dir) {
    // An allow-list: what a student's process may read. A lab run: its own binary, its own labs/ (and a test kit's
    // solutions/, where the tests grade edited references as students), the kit's public shaders/ and data/.
    const KitLayout kit{kit_}, student{student_root};
    for (const auto& lab : labs_) policy_.read_only.push_back(student_bin / lab.lab);
    policy_.read_only.insert(policy_.read_only.end(), {student.labs(), student.shaders(), student.data(), kit.shaders(), kit.data()});
    if (!options_.student_bin_dir.empty()) policy_.read_only.push_back(student.solutions());
    // A build: the framework's headers and sources, its CMake files and the libraries it links, and the build's
    // own folder (read-write); nothing of solutions/, tests/, grader/ but the submission project, or build/ but those.
    const fs::path kit_build = bin_.parent_path();
    build_policy_.read_only = {kit_ / "common", kit_ / "support", kit_ / "third_party", kit_ / "cmake",
                               kit.submission_project(), kit.shaders(), kit.data(),
                               kit_build / "gsv-targets.cmake", kit_build / "gsv-build-settings.cmake",
                               kit_build / "common", kit_build / "support", kit_build / "third_party"};
    // The build writes only its build folder; the submission's labs/ (the grader's copy) it may only read.
    if (!build_dir.empty()) {
        build_policy_.read_only.push_back(student_root);
        build_policy_.read_write = {build_dir / "build"};
    }
    // A root grader runs student code as a uid leased to this run alone (grader/src/run/uid_lease.h).
    if (geteuid() == 0 && options_.sandbox)
        uid_lease_.emplace(options_.sandbox_uid ? UidLease::exactly(options_.sandbox_uid) : UidLease::any());
    policy_.uid = build_policy_.uid = uid_lease_ ? uid_lease_->uid() : kSandboxUidBase;
#if defined(__SANITIZE_ADDRESS__)
    // The labs of a sanitizer build reserve terabytes of shadow memory.
    policy_.address_space_bytes = build_policy_.address_space_bytes = 0;
#endif
    build_policy_.address_space_bytes = 0;  // compilers and linkers: their time limit is the guard
    build_policy_.file_size_bytes = 512ull << 20;
    if (!options_.sandbox) {
        report_.sandbox = "off (--no-sandbox): student code runs with the grader's rights";
        return;
    }
    if (options_.namespaces) {
        support_ = probe_sandbox(policy_);
    } else {
        support_.refused = "--no-namespaces";
    }
    report_.sandbox = support_.describe(policy_);
    const bool secrets = !options_.update_goldens && (std::find(live_.begin(), live_.end(), true) != live_.end());
    if (!support_.allow_list() && secrets && !options_.allow_readable_kit)
        throw Error("the sandbox cannot hide the kit here (" + support_.refused +
                    "): live references and hidden cases are refused; grade with --self-check, or pass "
                    "--allow-readable-kit to grade with the kit readable by student code");
    if (!support_.allow_list()) report_.sandbox += options_.allow_readable_kit && secrets ? " (--allow-readable-kit)" : "";
}

GradeReport Grading::run() {
    const auto start = std::chrono::steady_clock::now();
    report_.seed = options_.seed ? *options_.seed : fresh_seed();
    report_.submission = options_.submission.empty() ? KitLayout{kit_}.labs().string() : fs::absolute(options_.submission).string();
    load_labs();
    const bool any_live = std::find(live_.begin(), live_.end(), true) != live_.end();
    report_.mode = options_.update_goldens ? "update goldens" : any_live ? "instructor" : "self-check";
    report_.profile = profile_name(options_.profile);
    fs::create_directories(out_);

    fs::path student_bin = bin_, student_root = kit_;
    std::vector<LabBuild> builds;
    if (!options_.submission.empty()) {
        const fs::path work = out_ / "submission-build";
        student_root = work / "kit";
        student_bin = work / "build" / "bin";
        set_up_sandbox(student_bin, student_root, work);
        std::vector<std::string> lab_ids;
        for (const auto& lab : labs_) lab_ids.push_back(lab.lab);
        if (progress_) progress_({0, total_, nullptr, "building the submission's labs"});
        ProcessLimits build_limits = limits(labs_.empty() ? LabCases{} : labs_.front(), true);
        if (build_limits.sandbox) build_limits.sandbox = &build_policy_;
        build_limits.timeout = std::chrono::minutes(5);
        build_limits.max_output_bytes = 256 * 1024;
        const SubmissionBuild built =
            build_submission(options_.submission, kit_, bin_.parent_path(), lab_ids, work, build_limits);
        report_.builds = built.builds;
    } else {
        if (!options_.student_bin_dir.empty()) {
            student_bin = fs::absolute(options_.student_bin_dir);
            student_root = fs::absolute(options_.student_root);
        }
        set_up_sandbox(student_bin, student_root, {});
    }
    // The kit's own labs find their files as they would when a student runs them (GSV_ROOT included).
    const bool own_labs = options_.submission.empty() && options_.student_bin_dir.empty();
    student_ = LabRunner{student_bin, own_labs ? fs::path() : student_root, true, options_.profile};
    reference_ = LabRunner{bin_, "", false, options_.profile};
    for (std::size_t i = 0; i < labs_.size(); ++i) {
        const LabBuild* build = nullptr;
        for (const auto& b : report_.builds)
            if (b.lab == labs_[i].lab) build = &b;
        grade_lab(labs_[i], live_[i], build);
    }
    report_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report_;
}

void Grading::record(CaseResult r) {
    report_.results.push_back(std::move(r));
    if (progress_) progress_({static_cast<int>(report_.results.size()), total_, &report_.results.back(), ""});
}

void Grading::grade_lab(const LabCases& lab, bool live, const LabBuild* build) {
    const std::size_t first = report_.results.size();
    for (const auto& c : lab.cases) {
        if (options_.update_goldens) {
            if (c.visibility == "public") update_golden(lab, c);
            continue;
        }
        try {
            grade_case(lab, c, live, build);
        } catch (const std::exception& e) {
            // One case's trouble never stops the rest.
            CaseResult r = result_for(lab, c, options_.profile);
            r.status = CaseStatus::Error;
            r.detail = std::string("grader: ") + e.what();
            record(r);
        }
    }
    blame_needed_todos(lab, first);
}

// A case that fails while a TODO it needs fails its own cases says so: that TODO first. Blame lands where the work is.
void Grading::blame_needed_todos(const LabCases& lab, std::size_t first) {
    std::map<std::string, std::string> failing;  // TODO -> its first failing case
    for (std::size_t i = first; i < report_.results.size(); ++i) {
        const CaseResult& r = report_.results[i];
        if (r.kind == "image" && r.status != CaseStatus::Passed && !failing.count(r.todo)) failing[r.todo] = r.name;
    }
    for (std::size_t i = first; i < report_.results.size(); ++i) {
        CaseResult& r = report_.results[i];
        if (r.status == CaseStatus::Passed || r.status == CaseStatus::BuildError || is_kit_fault(r.status)) continue;
        const auto c = std::find_if(lab.cases.begin(), lab.cases.end(), [&](const GradeCase& x) { return x.name == r.name; });
        if (c == lab.cases.end()) continue;
        for (const auto& needed : c->needs) {
            const auto f = failing.find(needed);
            if (f == failing.end() || needed == r.todo) continue;
            r.status = CaseStatus::NeedsFirst;
            r.detail = "needs " + needed + " first (its case '" + f->second + "' fails); here: " + r.detail;
            break;
        }
    }
}

std::string Grading::picture_in_submission(const Image& image) const {
    const fs::path labs = KitLayout{student_.root.empty() ? kit_ : student_.root}.labs();
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(labs, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        // Plain files only (the copy holds nothing else; never follow a link).
        if (!fs::is_regular_file(it->symlink_status(ec)) || it->path().extension() != ".png" || it->file_size(ec) > (16u << 20)) continue;
        try {
            if (read_png(it->path()).rgba == image.rgba) return as_student_sees(it->path().string());
        } catch (const Error&) {
        }
    }
    return "";
}

std::string Grading::as_student_sees(std::string text) const {
    const std::string root = (student_.root.empty() ? kit_ : student_.root).string() + "/";
    for (auto at = text.find(root); at != std::string::npos; at = text.find(root, at)) text.erase(at, root.size());
    return text;
}

void Grading::update_golden(const LabCases& lab, const GradeCase& c) {
    CaseResult r = result_for(lab, c, options_.profile);
    const LabRun ref = reference_.render(lab.lab + "_solution", lab, c, limits(lab, false));
    r.status = ref.status;
    r.output = ref.process.output;
    r.detail = ref.detail;
    if (ref.status == CaseStatus::Passed) {
        const fs::path golden = KitLayout{kit_}.golden_image(lab.lab, c.name);
        fs::create_directories(golden.parent_path());
        write_png(golden, *ref.image);
        r.detail = "wrote " + golden.string();
        if (lab.checks_arrays()) update_golden_arrays(lab, c, ref, r);
    }
    record(r);
}

// A sampled golden of each array the case checks; goldens of arrays it no longer checks go, so that the
// self-check (which checks every golden a case has) does not look for them.
void Grading::update_golden_arrays(const LabCases& lab, const GradeCase& c, const LabRun& ref, CaseResult& r) {
    std::vector<std::string> names;
    if (c.arrays) {
        names = *c.arrays;
    } else {
        for (const auto& a : ref.arrays) names.push_back(a.name);
    }
    for (const auto& name : golden_array_names(kit_, lab.lab, c.name))
        if (std::find(names.begin(), names.end(), name) == names.end()) fs::remove(array_golden_path(kit_, lab.lab, c.name, name));
    for (const auto& name : names) {
        const auto a = std::find_if(ref.arrays.begin(), ref.arrays.end(), [&](const DataArray& x) { return x.name == name; });
        if (a == ref.arrays.end()) {
            r.status = CaseStatus::ReferenceFailed;
            r.detail = "the reference solution handed in no '" + name + "' array, which the case checks";
            return;
        }
        write_array_golden(array_golden_path(kit_, lab.lab, c.name, name), sample_array(*a));
    }
    if (!names.empty()) r.detail += " and " + std::to_string(names.size()) + (names.size() == 1 ? " array" : " arrays");
}

void Grading::grade_case(const LabCases& lab, const GradeCase& c, bool live, const LabBuild* build) {
    CaseResult r = result_for(lab, c, options_.profile);
    r.reference = live ? "live" : "golden";
    const bool timed = live && options_.timing && c.timing.points > 0;
    auto timing_row_like = [&](const CaseResult& image_row) {
        if (!timed) return;
        CaseResult t = image_row;
        t.kind = "timing";
        t.points = 0;
        t.max_points = c.timing.points;
        t.actual_png = t.expected_png = t.diff_png = "";
        t.detail = "not timed: " + std::string(status_name(image_row.status));
        record(t);
    };
    const fs::path dir = out_ / lab.lab / c.name;
    remove_folder(dir);
    fs::create_directories(dir);
    // What the grader writes here (expected.png, a hidden case's reference) is the grader's alone: a student
    // process running as another uid, where no namespace hides this folder, cannot read it.
    if (geteuid() == 0) fs::permissions(out_ / lab.lab, fs::perms::owner_all);

    if (build && !build->ok) {
        r.status = CaseStatus::BuildError;
        r.detail = as_student_sees(first_error_line(build->log));
        r.output = as_student_sees(build->log);
        record(r);
        timing_row_like(report_.results.back());
        return;
    }
    // The student first: this case's expected image does not exist yet while student code runs.
    const LabRun student = student_.render(lab.lab, lab, c, limits(lab, true));
    r.seconds = student.process.seconds;
    r.frame_ms = student.reported_ms;
    r.output = as_student_sees(student.process.output);
    r.status = student.status;
    r.detail = as_student_sees(student.detail);

    Image expected;
    std::optional<LabRun> reference;
    if (live) {
        reference = reference_render(lab, c);
        r.reference_seconds = reference->process.seconds;
        if (reference->status != CaseStatus::Passed) {
            r.status = CaseStatus::ReferenceFailed;
            r.detail = "the reference solution failed (" + std::string(status_name(reference->status)) + "): " + reference->detail;
            r.output = reference->process.output;
            record(r);
            timing_row_like(report_.results.back());
            return;
        }
        expected = *reference->image;
    } else {
        const fs::path golden = KitLayout{kit_}.golden_image(lab.lab, c.name);
        if (!fs::exists(golden)) {
            r.status = CaseStatus::ReferenceFailed;
            r.detail = "no golden image " + golden.string() + " (run gsv-grade --update-goldens)";
            record(r);
            return;
        }
        try {
            expected = read_png(golden);
        } catch (const Error& e) {
            r.status = CaseStatus::ReferenceFailed;
            r.detail = std::string("the golden image is unreadable: ") + e.what();
            record(r);
            return;
        }
    }
    write_png(dir / "expected.png", expected);
    r.expected_png = fs::relative(dir / "expected.png", out_).generic_string();
    if (student.status == CaseStatus::Passed) check_image(lab, c, student, expected, live, r);
    // The numbers after the image, whatever it showed (grader/src/judge/data_check.h has the order).
    if (reference)
        check_case_data(lab, c, student, *reference, r);
    else
        check_case_data(lab, c, student, kit_, r);
    record(r);
    const CaseResult image_row = report_.results.back();
    if (!timed) return;
    if (image_row.status != CaseStatus::Passed) return timing_row_like(image_row);
    record(check_timing(lab, c, image_row));
}

void Grading::check_image(const LabCases& lab, const GradeCase& c, const LabRun& student, const Image& expected,
                          bool live, CaseResult& r) {
    const fs::path dir = out_ / lab.lab / c.name;
    const Image& actual = *student.image;
    // Re-encoded by the grader: only pixels come back from student code.
    write_png(dir / "actual.png", actual);
    r.actual_png = fs::relative(dir / "actual.png", out_).generic_string();
    const ImageTolerance tolerance = lab.tolerance(c, live);
    const ImageDiff diff = compare_images(actual, expected, tolerance);
    r.image.done = true;
    r.image.tolerance = tolerance;
    r.image.max_channel_diff = diff.max_channel_diff;
    r.image.differing_pixels = diff.differing_pixels;
    r.image.total_pixels = diff.total_pixels;
    r.image.psnr = diff.psnr;
    r.image.ssim = diff.ssim;
    r.image.diff_x0 = diff.diff_x0;
    r.image.diff_y0 = diff.diff_y0;
    r.image.diff_x1 = diff.diff_x1;
    r.image.diff_y1 = diff.diff_y1;
    if (diff.within(tolerance)) {
        r.status = CaseStatus::Passed;
        r.points = c.points;
        r.detail = diff.max_channel_diff == 0 ? "identical" : "max diff " + std::to_string(diff.max_channel_diff);
        return;
    }
    r.detail = diff.summary();
    if (!diff.size_mismatch) {
        write_png(dir / "diff.png", difference_heatmap(actual, expected, tolerance.max_channel_diff));
        r.diff_png = fs::relative(dir / "diff.png", out_).generic_string();
    }
    // The starter's magenta where the reference has none: the TODO is open, however much else is drawn.
    const long open = not_done_pixels(actual) - not_done_pixels(expected);
    const long pixels = static_cast<long>(actual.width) * actual.height;
    if (!diff.size_mismatch && open > pixels / 200) {
        r.status = CaseStatus::NotDone;
        char share[32];
        std::snprintf(share, sizeof share, "%.1f%%", 100.0 * double(open) / double(pixels));
        r.detail = "not done: " + c.todo + " (the starter's magenta on " + share + " of the image)";
        return;
    }
    if (is_blank(actual) && !is_blank(expected)) {
        r.status = CaseStatus::BlankImage;
        const std::uint8_t* p = actual.at(0, 0);
        // kNotDone: the starter's own "this TODO is open" colour.
        r.detail = p[0] == kNotDoneRgb[0] && p[1] == kNotDoneRgb[1] && p[2] == kNotDoneRgb[2]
                       ? "all magenta, the starter's 'not done' colour: this case's TODO (or one it needs) is still open"
                       : "one flat colour where the reference has a picture (is anything drawn?)";
    } else if (const std::string copied = golden_copied(lab.lab, c.name, actual); !copied.empty()) {
        // An honest bug that ignores what sets this case apart lands on another case's image too; a copy is a
        // copy when the submission holds the picture, or when its own lab does not draw it for that case.
        const std::string file = picture_in_submission(actual);
        const auto other = std::find_if(lab.cases.begin(), lab.cases.end(), [&](const GradeCase& x) { return x.name == copied; });
        const LabRun own = file.empty() && other != lab.cases.end() ? student_.render(lab.lab, lab, *other, limits(lab, true)) : LabRun{};
        if (file.empty() && own.status == CaseStatus::Passed && own.image && own.image->rgba == actual.rgba) {
            r.status = CaseStatus::WrongImage;
            r.detail = "draws exactly what case '" + copied + "' draws: this case's settings seem to change nothing (" + r.detail + ")";
        } else {
            r.status = CaseStatus::CopiedImage;
            r.detail = "pixel for pixel the committed golden image of case '" + copied + "', " +
                       (file.empty() ? std::string("which the lab does not draw for that case") : "held in the submission as " + file);
        }
    } else {
        r.status = CaseStatus::WrongImage;
    }
}

std::string Grading::golden_copied(const std::string& lab, const std::string& case_name, const Image& image) {
    auto& goldens = goldens_[lab];
    if (goldens.empty()) {
        const fs::path dir = KitLayout{kit_}.golden_dir(lab);
        if (fs::is_directory(dir))
            for (const auto& e : fs::directory_iterator(dir))
                if (e.path().extension() == ".png") goldens[e.path().stem().string()] = read_png(e.path());
    }
    for (const auto& [name, golden] : goldens)
        if (name != case_name && golden.width == image.width && golden.height == image.height && golden.rgba == image.rgba)
            return name;
    return "";
}

CaseResult Grading::check_timing(const LabCases& lab, const GradeCase& c, const CaseResult& image) {
    CaseResult t = image;
    t.kind = "timing";
    t.max_points = c.timing.points;
    t.points = 0;
    t.actual_png = t.expected_png = t.diff_png = "";
    t.output.clear();
    t.seconds = 0;
    std::vector<double> s, ref;
    std::optional<LabRun> failure;
    // The settings of every timed frame are drawn afresh, from entropy no one else sees: a frame cannot be drawn
    // (or copied from an earlier one) before the grader asks for it.
    std::random_device entropy;
    SeededDraw fresh((std::uint64_t(entropy()) << 32) ^ entropy(), lab.lab + "/" + c.name + "/timing");
    // Interleaved, so a machine that slows down slows both alike; the reference draws the same frames.
    auto measure = [&](int rounds) {
        for (int i = 0; i < rounds && !failure; ++i) {
            std::vector<std::vector<std::string>> challenges;
            for (int f = 0; f < lab.timing_frames; ++f) challenges.push_back(draw_settings(*c.timing.vary, fresh, c.settings));
            const LabRun a = student_.render(lab.lab, lab, c, limits(lab, true), &challenges);
            t.seconds += a.process.seconds;
            if (a.status != CaseStatus::Passed) {
                failure = a;
                return;
            }
            const LabRun b = reference_.render(lab.lab + "_solution", lab, c, limits(lab, false), &challenges);
            if (b.status != CaseStatus::Passed) continue;
            // What was timed must be what was asked for: each timed frame against the reference's frame drawn with the
            // same settings, so a frame that skips its work, or an answer made before its challenge, is refused.
            for (std::size_t k = 0; k < a.frames.size() && k < b.frames.size(); ++k) {
                const ImageDiff diff = compare_images(a.frames[k], b.frames[k], lab.tolerance(c, true));
                if (diff.within(lab.tolerance(c, true))) continue;
                std::string asked;
                for (const auto& setting : challenges[k]) asked += (asked.empty() ? "" : " ") + setting;
                failure = a;
                failure->status = CaseStatus::Refused;
                failure->detail = "timed frame " + std::to_string(k + 1) + " of " + std::to_string(a.frames.size()) + " (" + asked +
                                  ") is not the frame the reference draws with those settings: " + diff.summary() +
                                  " (each timed frame must be the frame the grader asked for)";
                return;
            }
            s.push_back(a.median_ms);
            ref.push_back(b.median_ms);
        }
    };
    const double band = c.timing.max_ratio;
    auto ratio = [&] { return median(s) / std::max(1e-6, median(ref)); };
    measure(lab.timing_rounds);
    // Over the band, or near it (within 25% either way), one more measurement decides: with two rounds a single slow
    // process (a burst of other load) makes the median of the rounds' medians their mean, and failed an honest lab 01
    // at 2.31x once; the median of four rounds is not moved by one. Work that is truly slower is slower in every round.
    if (!failure && (ratio() > band || std::fabs(std::log(ratio() / band)) < std::log(1.25))) {
        measure(lab.timing_rounds);
        t.timing.remeasured = true;
    }
    t.timing.done = true;
    t.timing.student_ms = median(s);
    t.timing.reference_ms = median(ref);
    t.timing.ratio = ratio();
    t.timing.max_ratio = band;
    t.timing.rounds = static_cast<int>(s.size());
    if (failure) {
        t.status = failure->status;
        t.detail = "while timing: " + failure->detail;
        t.output = failure->process.output;
        return t;
    }
    char line[160];
    std::snprintf(line, sizeof line, "%.2f ms vs the reference's %.2f ms: %.2fx (band %.2gx)%s", t.timing.student_ms,
                  t.timing.reference_ms, t.timing.ratio, band, t.timing.remeasured ? ", measured twice" : "");
    t.detail = line;
    if (t.timing.ratio <= band) {
        t.status = CaseStatus::Passed;
        t.points = c.timing.points;
    } else {
        t.status = CaseStatus::TooSlow;
    }
    return t;
}

}  // namespace

GradeReport grade(const GradeOptions& options, const std::function<void(const GradeProgress&)>& progress) {
    return Grading(options, progress).run();
}

}  // namespace gsv
