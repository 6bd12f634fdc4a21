#include "common/core/number_text.h"
#include "common/image/image.h"
#include "grader/src/report/report.h"
#include "grader/src/report/report_format.h"

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <system_error>

namespace fs = std::filesystem;

namespace gsv {
namespace {

// Larger files are left out so one huge render cannot make the report too big to open.
constexpr std::uintmax_t kMaxEmbeddedBytes = 16u << 20;

std::string html(std::string_view raw) { return escape_markup(raw, MarkupPlace::Text); }

const char* status_class(CaseStatus status) {
    if (status == CaseStatus::Passed) return "pass";
    if (is_kit_fault(status)) return "kit";
    if (status == CaseStatus::TooSlow) return "slow";
    if (status == CaseStatus::GpuMargin) return "margin";
    return "fail";
}

// The PNG bytes, or an empty string with `why` saying what is wrong. Never throws: a report with a
// note is better than no report.
std::string read_png_bytes(const fs::path& out_dir, const std::string& relative, std::string& why) {
    if (relative.empty()) {
        why = "no image was produced";
        return {};
    }
    try {
        const fs::path path = out_dir / relative;
        std::error_code ec;
        const auto size = fs::file_size(path, ec);
        if (ec) {
            why = relative + " is missing";
            return {};
        }
        if (size > kMaxEmbeddedBytes) {
            why = relative + " is too large to embed (" + std::to_string(size) + " bytes)";
            return {};
        }
        std::ifstream in(path, std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (!in.good() && !in.eof()) {
            why = relative + " cannot be read";
            return {};
        }
        // A passed case graded with --passed-pictures thumbnail keeps its picture as the grader's JPEG thumbnail.
        const bool jpeg_thumbnail = fs::path(relative).extension() == ".jpg" && bytes.compare(0, 3, "\xff\xd8\xff", 3) == 0;
        if (bytes.compare(0, 8, "\x89PNG\r\n\x1a\n", 8) != 0 && !jpeg_thumbnail) {
            why = relative + " is not a PNG file";
            return {};
        }
        return bytes;
    } catch (const std::exception& e) {
        why = relative + " cannot be read: " + e.what();
        return {};
    }
}

// A student's report embeds thumbnails up to this many bytes in all (base64 adds a third): past it, a line saying
// where to see them.
constexpr std::size_t kStudentPictureBytes = 1200u << 10;

// The picture as a student's report embeds it: a thumbnail, JPEG; empty with `why` where it cannot be read.
std::string thumbnail_bytes(const fs::path& png, std::string& why) {
    try {
        const Image full = read_png(png);
        const std::vector<std::uint8_t> jpeg = encode_jpeg(thumbnail(full, kThumbnailSide), kThumbnailQuality);
        return std::string(jpeg.begin(), jpeg.end());
    } catch (const std::exception& e) {
        why = std::string("the picture cannot be read: ") + e.what();
        return {};
    }
}

// The pictures a report embeds: who reads it, and for a student what is left of the bytes it may hold.
struct Pictures {
    ReportReader reader = ReportReader::Instructor;
    InstructorPictures instructor = InstructorPictures::Whole;
    std::size_t left = kStudentPictureBytes;
};

bool is_jpeg(const std::string& bytes) { return bytes.compare(0, 3, "\xff\xd8\xff", 3) == 0; }

// `thumbnail`: shown small whoever reads it (an instructor's passed case: its pictures match, and a class's reports
// stay small); a student's report shows every picture small, within its byte budget.
void figure(std::ostringstream& out, const fs::path& out_dir, const std::string& relative, const char* caption, Pictures& pictures,
            bool thumbnail) {
    std::string why;
    std::string bytes = read_png_bytes(out_dir, relative, why);
    const bool student = pictures.reader == ReportReader::Student;
    const bool linked = !student && pictures.instructor == InstructorPictures::LinkedThumbnails && !bytes.empty();
    const bool small = (student || thumbnail || linked) && !bytes.empty();
    if (small && !is_jpeg(bytes)) bytes = thumbnail_bytes(out_dir / relative, why);
    if (student && small && bytes.size() > pictures.left) {
        bytes.clear();
        why = "left out to keep this report small: `compare` draws it (the reproduce line above names the case)";
    }
    if (student && small) pictures.left -= bytes.size();
    out << "<figure>";
    if (bytes.empty())
        out << "<div class=\"note\">" << html(why) << "</div>";
    else if (linked)  // the whole picture lies beside the report, where the grader wrote it
        out << "<a href=\"" << escape_markup(relative, MarkupPlace::Attribute) << "\"><img alt=\"" << caption
            << "\" src=\"data:image/jpeg;base64," << base64(bytes) << "\"></a>";
    else
        out << "<img alt=\"" << caption << "\" src=\"data:image/" << (is_jpeg(bytes) ? "jpeg" : "png") << ";base64," << base64(bytes) << "\">";
    out << "<figcaption>" << caption << (linked ? " (click for the whole picture)" : "") << "</figcaption></figure>";
}

void figures(std::ostringstream& out, const fs::path& out_dir, const CaseResult& r, bool with_diff, Pictures& pictures,
             bool thumbnails = false) {
    out << "<div class=\"figures\">";
    figure(out, out_dir, r.actual_png, "actual (yours)", pictures, thumbnails);
    // A passed case kept as a thumbnail has no expected picture of its own: it matched.
    if (!r.expected_png.empty() || !thumbnails) figure(out, out_dir, r.expected_png, "expected", pictures, thumbnails);
    if (with_diff) figure(out, out_dir, r.diff_png, "difference", pictures, thumbnails);
    // The known mistake that explains it, drawn by the reference with that mistake made (grader/src/diagnose/).
    if (!r.mistake_png.empty()) figure(out, out_dir, r.mistake_png, "the known mistake's picture", pictures, thumbnails);
    out << "</div>\n";
    if (!r.mistake.empty())
        out << "<p class=\"mistake\">A known mistake in " << html(r.mistake_todo) << " explains this: " << html(r.mistake)
            << " (sheet: " << html(r.mistake_sheet) << ")</p>\n";
}

std::string percent(long part, long whole) {
    return whole > 0 ? fixed(100.0 * double(part) / double(whole), 3) + "%" : "-";
}

void image_numbers(std::ostringstream& out, const CaseResult& r) {
    const ImageCheck& im = r.image;
    if (!im.done) {
        out << "<p class=\"note\">The images were not compared.</p>\n";
        return;
    }
    const bool box = im.diff_x1 >= im.diff_x0;
    out << "<table class=\"numbers\">"
        << "<tr><th>max channel diff</th><td>" << im.max_channel_diff << " (allowed " << im.tolerance.max_channel_diff
        << ")</td></tr>"
        << "<tr><th>placement</th><td>"
        << (im.tolerance.neighbourhood > 0 ? html(neighbourhood_text(im.tolerance.neighbourhood)) +
                                                 " (each pixel against the best of its neighbours, both ways)"
                                           : std::string("each pixel at its own place"))
        << "</td></tr>"
        << "<tr><th>differing pixels</th><td>" << im.differing_pixels << " of " << im.total_pixels << " ("
        << percent(im.differing_pixels, im.total_pixels) << ", allowed "
        << fixed(100.0 * im.tolerance.max_differing_fraction, 3) << "%)</td></tr>"
        << "<tr><th>PSNR</th><td>" << (std::isfinite(im.psnr) ? fixed(im.psnr, 2) + " dB" : "identical (infinite)")
        << "</td></tr>"
        << "<tr><th>SSIM</th><td>" << fixed(im.ssim, 4) << "</td></tr>"
        << "<tr><th>differing region</th><td>";
    if (box)
        out << "x " << im.diff_x0 << "&ndash;" << im.diff_x1 << ", y " << im.diff_y0 << "&ndash;" << im.diff_y1
            << " (inclusive, y down from the top)";
    else
        out << "none";
    out << "</td></tr></table>\n";
}

// One row per array the case checks; a golden holds a sample, so "compared" can be fewer than the elements.
void data_numbers(std::ostringstream& out, const CaseResult& r) {
    const DataCheck& d = r.data;
    if (!d.done) return;
    out << "<table class=\"numbers data\"><tr><th>array</th><th>elements</th><th>compared</th><th>differing</th>"
        << "<th>max abs diff</th><th>result</th></tr>";
    for (const auto& a : d.arrays) {
        out << "<tr><td>" << html(a.name) << "</td>";
        if (!a.problem.empty()) {
            out << "<td colspan=\"4\"></td><td>" << html(a.problem) << "</td></tr>";
            continue;
        }
        out << "<td>" << with_commas(a.count) << " &times; " << a.components << "</td><td>" << with_commas(a.compared)
            << (d.reference == "golden" ? " (golden sample)" : "") << "</td><td>" << with_commas(a.differing) << " ("
            << percent(long(a.differing), long(a.compared)) << ", allowed " << fixed(100.0 * d.tolerance.max_differing_fraction, 3)
            << "%)</td><td>" << format_number(a.max_abs_diff) << " (allowed " << format_number(d.tolerance.max_abs)
            << ")</td><td>" << html(a.within() ? "ok" : a.summary()) << "</td></tr>";
    }
    out << "</table>\n";
}

void timing_numbers(std::ostringstream& out, const CaseResult& r) {
    const TimingCheck& t = r.timing;
    if (!t.done) {
        out << "<p class=\"note\">The frame time was not measured.</p>\n";
        return;
    }
    out << "<table class=\"numbers\">"
        << "<tr><th>your frame time</th><td>" << fixed(t.student_ms, 3) << " ms</td></tr>"
        << "<tr><th>reference frame time</th><td>" << fixed(t.reference_ms, 3) << " ms</td></tr>"
        << "<tr><th>ratio</th><td>" << fixed(t.ratio, 2) << "&times; (allowed " << fixed(t.max_ratio, 2)
        << "&times;)</td></tr>"
        << "<tr><th>rounds</th><td>" << t.rounds << (t.remeasured ? ", measured again near the limit" : "")
        << "</td></tr></table>\n";
}

void check_section(std::ostringstream& out, const fs::path& out_dir, const CaseResult& r, std::size_t index, Pictures& pictures) {
    const ReportReader reader = pictures.reader;
    const bool passed = r.status == CaseStatus::Passed;
    if (reader == ReportReader::Student && r.visibility != "public") {
        // A hidden case: what it is worth and how it went, nothing of what it draws or how.
        out << "<section id=\"check-" << index << "\" class=\"check " << status_class(r.status) << "\">\n<h3>" << html(check_title(r))
            << " <span class=\"badge\">" << html(status_name(r.status)) << "</span> " << format_points(r.points) << "/"
            << format_points(r.max_points) << "</h3>\n<p class=\"note\">a hidden case: its settings and pictures are the "
            << "instructor's</p>\n</section>\n";
        return;
    }
    const bool has_images = !r.actual_png.empty() || !r.expected_png.empty() || !r.diff_png.empty();
    out << "<section id=\"check-" << index << "\" class=\"check " << status_class(r.status) << "\">\n";
    out << "<h3>" << html(check_title(r)) << " <span class=\"badge\">" << html(status_name(r.status)) << "</span> "
        << format_points(r.points) << "/" << format_points(r.max_points) << "</h3>\n";
    if (!r.description.empty()) out << "<p>" << html(r.description) << "</p>\n";
    if (!r.detail.empty()) out << "<p class=\"detail\">" << html(r.detail) << "</p>\n";
    if (!passed && r.kind == "image" && !r.reproduce.empty())
        out << "<p class=\"reproduce\">reproduce: <code>" << html(r.reproduce) << "</code></p>\n";
    if (!r.settings.empty()) {
        out << "<p class=\"settings\">settings:";
        for (const auto& s : r.settings) out << " <code>" << html(s) << "</code>";
        out << "</p>\n";
    }
    if (r.kind == "timing") {
        timing_numbers(out, r);
    } else if (passed) {
        // A student's report shows the pictures of what failed only: it stays small.
        if (has_images && reader == ReportReader::Instructor) {
            out << "<details><summary>images</summary>";
            figures(out, out_dir, r, false, pictures, true);
            out << "</details>\n";
        }
    } else {
        // Wrong data has a passing image: no difference to show.
        if (has_images) figures(out, out_dir, r, r.status != CaseStatus::WrongData, pictures);
        if (r.image.done || has_images) image_numbers(out, r);
        data_numbers(out, r);
    }
    if (!r.output.empty()) out << "<pre>" << html(r.output) << "</pre>\n";
    out << "</section>\n";
}

constexpr const char* kStyle = R"(
body { font-family: system-ui, sans-serif; margin: 1.5em; color: #202124; }
table { border-collapse: collapse; }
th, td { border: 1px solid #dadce0; padding: 0.25em 0.6em; text-align: left; vertical-align: top; }
td.points { text-align: right; white-space: nowrap; }
tr.pass td.status, section.pass .badge { background: #ceead6; }
tr.fail td.status, section.fail .badge { background: #fad2cf; }
tr.slow td.status, section.slow .badge { background: #feefc3; }
tr.margin td.status, section.margin .badge { background: #feefc3; }
tr.kit td.status, section.kit .badge { background: #d2e3fc; }
.badge { padding: 0.1em 0.5em; border-radius: 0.4em; font-size: 0.85em; }
section.check { border-top: 1px solid #dadce0; margin-top: 1em; }
.figures { display: flex; flex-wrap: wrap; gap: 1em; }
figure { margin: 0; }
figure img { max-width: 420px; min-width: 128px; image-rendering: pixelated; border: 1px solid #dadce0; }
details figure img { max-width: 160px; min-width: 0; }
figcaption { font-size: 0.85em; color: #5f6368; }
.note { color: #5f6368; font-style: italic; padding: 1em; border: 1px dashed #dadce0; }
pre { background: #f8f9fa; padding: 0.6em; overflow-x: auto; max-height: 30em; white-space: pre-wrap; }
table.numbers th { font-weight: normal; color: #5f6368; }
)";

}  // namespace

std::string html_report(const GradeReport& report, const fs::path& out_dir, ReportReader reader, InstructorPictures instructor) {
    const bool student = reader == ReportReader::Student;
    std::ostringstream out;
    out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
        // Nothing in this file needs the network or scripts; saying so lets the browser refuse both.
        << "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src data:; "
           "style-src 'unsafe-inline'\">\n"
        << "<title>Grading report</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n";

    const double score = report.score(), max = report.max_score();
    out << "<h1>Grading report</h1>\n<table class=\"summary\">\n"
        << "<tr><th>score</th><td>" << format_points(score) << " / " << format_points(max);
    if (max > 0) out << " (" << fixed(100.0 * score / max, 0) << "%)";
    out << "</td></tr>\n";
    if (!report.submission.empty()) out << "<tr><th>submission</th><td>" << html(report.submission) << "</td></tr>\n";
    out << "<tr><th>mode</th><td>" << html(report.mode);
    if (report.hidden_included) out << ", hidden cases";
    if (report.timing_included) out << ", timing";
    out << "</td></tr>\n";
    out << "<tr><th>profile</th><td>" << html(report.profile) << "</td></tr>\n";
    if (!report.renderer.empty()) out << "<tr><th>renderer</th><td>" << html(report.renderer) << "</td></tr>\n";
    if (!report.golden_renderers.empty()) out << "<tr><th>goldens rendered on</th><td>" << html(golden_renderers_text(report)) << "</td></tr>\n";
    if (report.hidden_included && !student) {
        char seed[32];
        std::snprintf(seed, sizeof seed, "%" PRIu64, report.seed);
        out << "<tr><th>seed</th><td>" << seed << "</td></tr>\n";
    }
    out << "<tr><th>sandbox</th><td>" << html(report.sandbox) << "</td></tr>\n";
    if (!report.references.empty()) out << "<tr><th>references</th><td>" << html(report.references) << "</td></tr>\n";
    out << "<tr><th>time</th><td>" << fixed(std::isfinite(report.seconds) ? report.seconds : 0.0, 1) << " s</td></tr>\n"
        << "</table>\n";

    // What the failures come down to, before the checks (grader/src/diagnose/).
    if (!report.diagnoses.empty()) {
        out << "<h2>What went wrong</h2>\n<p>Your failing pictures compared with the kit's known mistakes' pictures.</p>\n";
        for (const auto& diagnosis : report.diagnoses) {
            // A student is told of public cases only (hidden ones are the instructor's).
            const LabDiagnosis d = student ? student_diagnosis(diagnosis, report) : diagnosis;
            out << "<h3>" << html(d.lab) << "</h3>\n<ul class=\"diagnosis\">\n";
            for (const auto& line : diagnosis_lines(d)) out << "<li>" << html(line) << "</li>\n";
            out << "</ul>\n";
        }
    }
    if (!report.diagnosis_note.empty()) out << "<p class=\"note\">diagnosis: " << html(report.diagnosis_note) << "</p>\n";

    bool any_failed_build = false;
    for (const auto& b : report.builds) {
        if (b.ok) continue;
        if (!any_failed_build) out << "<h2>Builds that failed</h2>\n";
        any_failed_build = true;
        out << "<h3>" << html(b.lab) << "</h3>\n<pre>" << html(b.log) << "</pre>\n";
    }

    out << "<h2>Checks</h2>\n<table class=\"checks\">\n<tr><th>lab</th><th>check</th><th>todo</th><th>visibility</th>"
           "<th>status</th><th>points</th><th>detail</th></tr>\n";
    for (std::size_t i = 0; i < report.results.size(); ++i) {
        const CaseResult& r = report.results[i];
        out << "<tr class=\"" << status_class(r.status) << "\"><td>" << html(r.lab) << "</td><td><a href=\"#check-" << i
            << "\">" << html(check_label(r)) << "</a></td><td>" << html(r.todo) << "</td><td>" << html(r.visibility)
            << "</td><td class=\"status\">" << html(status_name(r.status)) << "</td><td class=\"points\">"
            << format_points(r.points) << "/" << format_points(r.max_points) << "</td><td>"
            << html(student && r.visibility != "public" ? std::string("a hidden case") : one_line(r.detail, 160)) << "</td></tr>\n";
    }
    out << "</table>\n<h2>Details</h2>\n";
    Pictures pictures{reader, instructor};
    for (std::size_t i = 0; i < report.results.size(); ++i) check_section(out, out_dir, report.results[i], i, pictures);
    out << "</body>\n</html>\n";
    return out.str();
}

}  // namespace gsv
