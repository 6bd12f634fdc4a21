#include "grader/src/report/report.h"

#include "common/core/error.h"

#include <fstream>
#include <system_error>

namespace fs = std::filesystem;

namespace gsv {
namespace {

void write_text(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw Error("cannot write report '" + path.string() + "': cannot open it for writing");
    out << text;
    out.close();
    // A full disk shows up only when the buffer is flushed, so check after close().
    if (!out) throw Error("cannot write report '" + path.string() + "': the write failed");
}

}  // namespace

void write_reports(const GradeReport& report, const fs::path& out_dir, InstructorPictures pictures) {
    std::error_code ec;
    fs::create_directories(out_dir, ec);
    if (ec) throw Error("cannot create report folder '" + out_dir.string() + "': " + ec.message());
    write_text(out_dir / "results.json", gradescope_json(report));
    write_text(out_dir / "report.json", report_json(report));
    write_text(out_dir / "junit.xml", junit_xml(report));
    const bool student_run = report.mode == "self-check";
    write_text(out_dir / "report.html", html_report(report, out_dir, student_run ? ReportReader::Student : ReportReader::Instructor, pictures));
    if (!student_run) write_text(out_dir / "student-report.html", html_report(report, out_dir, ReportReader::Student));
    else fs::remove(out_dir / "student-report.html", ec);  // an earlier instructor run's, in the same folder
}

}  // namespace gsv
