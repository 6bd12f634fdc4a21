#include "grader/src/grade/grade.h"

#include "common/app/kit_layout.h"
#include "common/core/error.h"
#include "common/image/image.h"
#include "common/io/folder_tree.h"
#include "grader/src/grade/diagnose_lab.h"
#include "grader/src/grade/mistake_pictures.h"
#include "grader/src/grade/session.h"
#include "grader/src/judge/data_check.h"
#include "grader/src/judge/image_check.h"
#include "grader/src/judge/needs.h"
#include "grader/src/judge/timing_check.h"
#include "grader/src/report/report.h"
#include "grader/src/report/report_format.h"

#include <fstream>
#include <optional>
#include <unistd.h>

namespace fs = std::filesystem;

namespace gsv {
namespace {

// The image, then the arrays, of one render of the student's lab against the expected image: the row as it stands
// before the frame time. `student` draws other cases for the copy check.
// A passed case in a class's folders (--passed-pictures thumbnail): its picture matched, so a small JPEG of it stands in
// for the two full PNGs (a lab of 25 cases is 6 MB of them); what a failing case shows is kept whole.
void keep_thumbnail_only(const fs::path& out, const fs::path& dir, const Image& picture, CaseResult& r) {
    const std::vector<std::uint8_t> jpeg = encode_jpeg(thumbnail(picture, kThumbnailSide), kThumbnailQuality);
    const fs::path file = dir / "actual.jpg";
    std::ofstream(file, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(jpeg.data()),
                                                                   static_cast<std::streamsize>(jpeg.size()));
    std::error_code ec;
    for (const char* png : {"actual.png", "expected.png", "diff.png"}) fs::remove(dir / png, ec);
    r.actual_png = fs::relative(file, out).generic_string();
    r.expected_png.clear();
    r.diff_png.clear();
}

CaseResult judge_render(GradingSession& s, CopySearch& copies, const LabCases& lab, const GradeCase& c, bool live,
                        const CaseResult& row, const LabRun& run, const LabRunner& student, const Image& expected,
                        const std::optional<LabRun>& reference) {
    CaseResult r = row;
    r.seconds = run.process.seconds;
    r.frame_ms = run.reported_ms;
    r.output = as_student_sees(run.process.output, s.student_kit());
    r.status = run.status;
    r.detail = as_student_sees(run.detail, s.student_kit());
    if (run.status == CaseStatus::Passed) {
        const auto draw = [&](const GradeCase& other) { return student.render(lab.lab, lab, other, s.limits(lab, true)); };
        // Only where the student's renderer is not the goldens' own: on that one a difference is the student's.
        std::optional<OtherRenderer> other;
        if (const auto golden = s.report.golden_renderers.find(lab.lab);
            !live && golden != s.report.golden_renderers.end() && !run.renderer.empty() && run.renderer != golden->second) {
            other = OtherRenderer{golden->second, run.renderer, "build/bin/" + lab.lab + " compare --case " + c.name};
            if (s.options.profile != Profile::Core) other->compare += std::string(" --profile ") + profile_name(s.options.profile);
        }
        check_image(lab, c, *run.image, expected, live, s.out, copies, draw, other ? &*other : nullptr, r);
    }
    // The numbers after the image, whatever it showed (grader/src/judge/data_check.h has the order).
    if (reference)
        check_case_data(lab, c, run, *reference, r);
    else
        check_case_data(lab, c, run, s.kit, r);
    return r;
}

// One case: the student's lab runs, then the reference (live, or its committed golden); the image is judged, then the
// arrays, then, where the case is timed and its image passed, the frame time. Each check is a row. A check that fails
// on what a served process drew after other cases is judged again on a render of the case alone (below).
void grade_case(GradingSession& s, CopySearch& copies, const LabCases& lab, const GradeCase& c, bool live,
                const LabBuild* build, LabRenders& renders) {
    CaseResult r = s.result_for(lab, c);
    r.reference = live ? "live" : "golden";
    const bool timed = live && s.options.timing && c.timing.points > 0;
    auto timing_row_like = [&](const CaseResult& image_row) {
        if (!timed) return;
        CaseResult t = image_row;
        t.kind = "timing";
        t.points = 0;
        t.max_points = c.timing.points;
        t.actual_png = t.expected_png = t.diff_png = "";
        t.detail = "not timed: " + std::string(status_name(image_row.status));
        s.record(t);
    };
    const fs::path dir = s.out / lab.lab / c.name;
    remove_folder(dir);
    fs::create_directories(dir);
    // What the grader writes here (expected.png, a hidden case's reference) is the grader's alone: a student
    // process running as another uid, where no namespace hides this folder, cannot read it.
    if (geteuid() == 0) fs::permissions(s.out / lab.lab, fs::perms::owner_all);

    if (build && !build->ok) {
        r.status = build->kit_fault ? CaseStatus::KitFault : CaseStatus::BuildError;
        r.detail = as_student_sees(first_error_line(build->log), s.student_kit());
        r.output = as_student_sees(build->log, s.student_kit());
        s.record(r);
        timing_row_like(s.report.results.back());
        return;
    }
    // The student first: this case's expected image does not exist yet while student code runs.
    const LabRun student = s.student.render(lab.lab, lab, c, s.limits(lab, true));
    if (s.report.renderer.empty()) s.report.renderer = student.renderer;

    Image expected;
    std::optional<LabRun> reference;
    if (live) {
        reference = s.reference_render(lab, c);
        r.reference_seconds = reference->process.seconds;
        if (reference->status != CaseStatus::Passed) {
            r.seconds = student.process.seconds;
            r.status = CaseStatus::ReferenceFailed;
            r.detail = "the reference solution failed (" + std::string(status_name(reference->status)) + "): " + reference->detail;
            r.output = reference->process.output;
            s.record(r);
            timing_row_like(s.report.results.back());
            return;
        }
        expected = *reference->image;
    } else {
        const fs::path golden = KitLayout{s.kit}.golden_image(lab.lab, c.name);
        if (!fs::exists(golden)) {
            r.status = CaseStatus::ReferenceFailed;
            r.detail = "no golden image " + golden.string() + " (run gsv-grade --update-goldens)";
            s.record(r);
            return;
        }
        try {
            expected = read_png(golden);
        } catch (const Error& e) {
            r.status = CaseStatus::ReferenceFailed;
            r.detail = std::string("the golden image is unreadable: ") + e.what();
            s.record(r);
            return;
        }
    }
    // The case's TODO runs on a GL feature this context lacks (lab 05's dispatch on macOS's 4.1): the lab drew the case
    // without the student's code for it, so it is not counted here, and the row says why. Live, the reference must
    // lack it too: what a student's lab reports alone takes no case out of the grade.
    if (!student.lacks.empty() && (!live || !reference->lacks.empty())) {
        r.seconds = student.process.seconds;
        r.status = CaseStatus::Unsupported;
        r.max_points = 0;
        r.detail = "not counted on this context: " + c.todo + " " + student.lacks;
        s.record(r);
        return;
    }
    write_png(dir / "expected.png", expected);
    r.expected_png = fs::relative(dir / "expected.png", s.out).generic_string();
    CaseResult judged = judge_render(s, copies, lab, c, live, r, student, s.student, expected, reference);
    const LabRun* judged_on = &student;
    // Served equals alone: a check that fails on a render made after other cases in the same process is judged on the
    // case rendered again in a process of its own, as --one-process-per-case renders it; where that passes, the row
    // says the lab kept something between cases. Not for a lab whose C++ is the kit's own (its starter's, or the
    // solution's), which the kit's tests prove keeps nothing: only its GLSL is the student's, and a GL context is new
    // for every case.
    std::optional<LabRun> again;  // the case rendered alone, where it was
    const bool alone_needed = judged.status != CaseStatus::Passed && student.after_other_cases && !s.cpp_is_the_kits(lab.lab);
    if (alone_needed) {
        const LabRunner alone = s.student.alone();
        again = alone.render(lab.lab, lab, c, s.limits(lab, true));
        judged = judge_render(s, copies, lab, c, live, r, *again, alone, expected, reference);
        if (judged.status == CaseStatus::Passed) judged.detail += kPassedOnlyAlone;
        judged_on = &*again;
    }
    // A wrong picture or wrong numbers, kept for the diagnosis after the lab's last case; and what a passed case expected.
    if (is_diagnosable(judged.status) && diagnoses(s, c))
        renders.failed.push_back({s.report.results.size(), &c, *judged_on, {expected, reference, live}});
    // A case passed: a mistake that would fail it is not the student's (diagnose_lab.h).
    if (judged.status == CaseStatus::Passed && diagnoses(s, c)) renders.passed.push_back({&c, {expected, reference, live}});
    if (judged.status == CaseStatus::Passed && judged_on->image && s.options.passed_pictures == PassedPictures::Thumbnail)
        keep_thumbnail_only(s.out, dir, *judged_on->image, judged);
    s.record(judged);
    const CaseResult image_row = s.report.results.back();
    if (!timed) return;
    if (image_row.status != CaseStatus::Passed) return timing_row_like(image_row);
    CaseResult timing = check_timing(lab, c, image_row, s.student, s.limits(lab, true), s.reference, s.limits(lab, false));
    // The timed frames likewise: timed again with a process of its own for each round where served ones failed.
    if (timing.status != CaseStatus::Passed && s.student.served && !s.cpp_is_the_kits(lab.lab)) {
        timing = check_timing(lab, c, image_row, s.student.alone(), s.limits(lab, true), s.reference, s.limits(lab, false));
        if (timing.status == CaseStatus::Passed) timing.detail += kPassedOnlyAlone;
    }
    s.record(timing);
}

// A lab's served processes (GradingSession::serve) for the length of its cases, ended however grading it ends.
class ServedWhileGrading {
public:
    ServedWhileGrading(GradingSession& s, const LabCases& lab) : s_(s) { s_.serve(lab); }
    ~ServedWhileGrading() { s_.end_serving(); }
    ServedWhileGrading(const ServedWhileGrading&) = delete;
    ServedWhileGrading& operator=(const ServedWhileGrading&) = delete;

private:
    GradingSession& s_;
};

}  // namespace

GradeReport grade(const GradeOptions& options, const std::function<void(const GradeProgress&)>& progress) {
    GradingSession s(options, progress, RunPurpose::Grade);
    s.set_up();
    CopySearch copies(s.kit, s.student_kit());
    MistakePictures mistake_pictures(s);
    for (std::size_t i = 0; i < s.labs.size(); ++i) {
        const LabCases& lab = s.labs[i];
        const LabBuild* build = s.build_of(lab.lab);
        const std::size_t first = s.report.results.size();
        LabRenders renders;
        {
            const ServedWhileGrading served(s, lab);
            for (const auto& c : lab.cases) {
                try {
                    grade_case(s, copies, lab, c, s.live[i], build, renders);
                } catch (const std::exception& e) {
                    // One case's trouble never stops the rest.
                    CaseResult r = s.result_for(lab, c);
                    r.status = CaseStatus::Error;
                    r.detail = std::string("grader: ") + e.what();
                    s.record(r);
                }
            }
        }
        // After the student's processes for the lab have ended: the mistakes' kits hold answers.
        try {
            diagnose_lab(s, mistake_pictures, lab, first, renders);
        } catch (const std::exception& e) {
            s.report.diagnosis_note += std::string(s.report.diagnosis_note.empty() ? "" : "; ") + lab.lab + ": " + e.what();
        }
        blame_needed_todos(lab, s.report.results, first);
    }
    // The submission's binaries, tens of MB, once no process of the student's runs (--keep-build no); its sources stay.
    if (!options.keep_build && !options.submission.empty()) {
        std::error_code ec;
        fs::remove_all(s.out / "submission-build" / "build", ec);
    }
    GradeReport report = s.finish();
    if (mistake_pictures.looked_up() > 0)
        report.references += std::string(report.references.empty() ? "" : "; ") + "known mistakes' pictures: " +
                             std::to_string(mistake_pictures.rendered()) + " rendered, " +
                             std::to_string(mistake_pictures.looked_up() - mistake_pictures.rendered()) + " kept from earlier";
    return report;
}

}  // namespace gsv
