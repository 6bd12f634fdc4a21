#pragma once
// The reports of one grading run, all written from the same GradeReport.
#include "grader/src/core/grade_result.h"

#include <filesystem>
#include <string>

namespace gsv {

// Terminal: one line per check, then per-lab and total scores.
std::string score_table(const GradeReport& report);
// Gradescope's results.json: score, tests[{name, score, max_score, status, output, visibility, tags}];
// hidden checks are "after_due_date".
std::string gradescope_json(const GradeReport& report);
// Everything the run measured, for tools.
std::string report_json(const GradeReport& report);
// JUnit XML: one testsuite per lab, one testcase per check.
std::string junit_xml(const GradeReport& report);
// Who reads report.html: the instructor (everything, full-size images: the seed, hidden cases' settings and output) or
// the student (public cases' descriptions, details and the diagnosis; a hidden case its status and points only; no
// seed; images as small JPEG thumbnails of the failing cases only, so the file stays well under 2 MB).
enum class ReportReader { Instructor, Student };
// A thumbnail, wherever the grader makes one (a student's report, a passed case's picture in a class's folders): this
// many pixels along its longer side, a JPEG of this quality.
inline constexpr int kThumbnailSide = 128;
inline constexpr int kThumbnailQuality = 80;

// How the instructor's report shows a failing case's pictures: embedded whole, or (a class's reports: --passed-pictures
// thumbnail) embedded as thumbnails, each a link to its whole PNG beside the report. A passed case's are thumbnails.
enum class InstructorPictures { Whole, LinkedThumbnails };

// One self-contained HTML file: the images embedded as data URIs, actual / expected / difference side by side.
std::string html_report(const GradeReport& report, const std::filesystem::path& out_dir,
                        ReportReader reader = ReportReader::Instructor, InstructorPictures pictures = InstructorPictures::Whole);

// report.json read back: an earlier run's report, whole. Throws gsv::Error naming the file and what is wrong.
GradeReport read_report_json(const std::filesystem::path& file);

// Writes results.json, report.json, junit.xml and report.html into out_dir: report.html the student's form in a
// self-check (what a student runs), else the instructor's, with student-report.html beside it to hand out.
void write_reports(const GradeReport& report, const std::filesystem::path& out_dir,
                   InstructorPictures pictures = InstructorPictures::Whole);

}  // namespace gsv
