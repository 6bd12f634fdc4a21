#include "grader/src/similarity/similarity_report.h"

#include "common/core/error.h"
#include "grader/src/batch/csv_field.h"
#include "grader/src/report/report_format.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace gsv {
namespace {

// The page lists this many pairs at most, and shows this many side by side (the most shared first): the CSV has all.
constexpr std::size_t kPairsListed = 500, kPairsSideBySide = 100;

std::string html(std::string_view raw) { return escape_markup(raw, MarkupPlace::Text); }

std::string percent(double share) { return fixed(100 * share, 0); }

// Every code pair of every lab, most shared first (the labs' own lists are ranked; this merges them).
std::vector<const CodePair*> ranked_pairs(const SimilarityFindings& findings) {
    std::vector<const CodePair*> pairs;
    for (const LabCode& lab : findings.code)
        for (const CodePair& p : lab.pairs) pairs.push_back(&p);
    std::stable_sort(pairs.begin(), pairs.end(), [](const CodePair* x, const CodePair* y) {
        return x->share != y->share ? x->share > y->share : x->shared_tokens > y->shared_tokens;
    });
    return pairs;
}

const LabCode& lab_of(const SimilarityFindings& findings, const CodePair& pair) {
    for (const LabCode& lab : findings.code)
        if (lab.lab == pair.lab) return lab;
    throw Error("no lab " + pair.lab + " in the findings");
}

std::vector<std::string> files_of(const CodePair& pair) {
    std::vector<std::string> files;
    for (const SharedRun& r : pair.runs)
        if (std::find(files.begin(), files.end(), r.file) == files.end()) files.push_back(r.file);
    return files;
}

std::string joined(const std::vector<std::string>& items, const char* separator) {
    std::string text;
    for (const auto& item : items) text += (text.empty() ? "" : separator) + item;
    return text;
}

std::string run_lines(const CodePair& pair, bool side_a) {
    std::vector<std::string> lines;
    for (const SharedRun& r : pair.runs)
        lines.push_back(r.file + ":" + std::to_string(side_a ? r.a_first : r.b_first) + "-" + std::to_string(side_a ? r.a_last : r.b_last));
    return joined(lines, " ");
}

// Lines shown around each shared run, so the page holds the runs rather than whole files.
constexpr int kContextLines = 4;

// One student's file where it shares runs, numbered, with the template's lines greyed, the class's common lines blue and
// the shared runs marked with their numbers; "..." where lines are left out.
std::string code_pane(const CodeFile& file, const std::vector<std::pair<int, std::pair<int, int>>>& runs) {
    const int count = static_cast<int>(file.lines.size());
    std::vector<bool> shown(file.lines.size(), false);
    for (const auto& [number, range] : runs)
        for (int line = std::max(1, range.first - kContextLines); line <= std::min(count, range.second + kContextLines); ++line)
            shown[static_cast<std::size_t>(line - 1)] = true;
    std::ostringstream out;
    out << "<pre class=\"code\">";
    bool gap = false;
    for (int line = 1; line <= count; ++line) {
        const auto i = static_cast<std::size_t>(line - 1);
        if (!shown[i]) {
            gap = true;
            continue;
        }
        if (gap) out << "<span class=\"gap\">...\n</span>";
        gap = false;
        std::string marks;
        bool shared = false;
        for (const auto& [number, range] : runs) {
            if (line >= range.first && line <= range.second) shared = true;
            if (line == range.first) marks += "<span class=\"run\">" + std::to_string(number) + "</span>";
        }
        const char* kind = file.kinds[i] == LineKind::Template ? "t" : file.kinds[i] == LineKind::Common ? "c" : shared ? "m" : "o";
        out << "<span class=\"" << kind << "\"><span class=\"n\">" << line << "</span>" << marks << html(file.lines[i]) << "\n</span>";
    }
    if (gap) out << "<span class=\"gap\">...\n</span>";
    out << "</pre>";
    return out.str();
}

std::string side_by_side(const LabCode& lab, const CodePair& pair) {
    std::ostringstream out;
    const auto a_files = lab.files.find(pair.a), b_files = lab.files.find(pair.b);
    if (a_files == lab.files.end() || b_files == lab.files.end()) return "";
    for (const std::string& name : files_of(pair)) {
        std::vector<std::pair<int, std::pair<int, int>>> a_runs, b_runs;
        for (std::size_t i = 0; i < pair.runs.size(); ++i) {
            const SharedRun& r = pair.runs[i];
            if (r.file != name) continue;
            a_runs.push_back({static_cast<int>(i) + 1, {r.a_first, r.a_last}});
            b_runs.push_back({static_cast<int>(i) + 1, {r.b_first, r.b_last}});
        }
        const auto a = a_files->second.find(name), b = b_files->second.find(name);
        if (a == a_files->second.end() || b == b_files->second.end()) continue;
        out << "<h4>" << html(name) << "</h4>\n<div class=\"sides\"><div><div class=\"who\">" << html(pair.a) << "</div>"
            << code_pane(a->second, a_runs) << "</div><div><div class=\"who\">" << html(pair.b) << "</div>" << code_pane(b->second, b_runs)
            << "</div></div>\n";
    }
    return out.str();
}

std::string thumbnail(const fs::path& out_dir, const std::string& relative, const std::string& alt) {
    std::ifstream in(out_dir / relative, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.empty()) return "<span class=\"note\">" + html(relative) + " is missing</span>";
    return "<img alt=\"" + escape_markup(alt, MarkupPlace::Attribute) + "\" src=\"data:image/png;base64," + base64(bytes) + "\">";
}

}  // namespace

std::string similarity_csv(const SimilarityFindings& findings) {
    std::ostringstream out;
    out << "rank,kind,lab,student_a,student_b,similarity_percent,shared_tokens,own_tokens_a,own_tokens_b,likely_copied,files,lines_a,"
           "lines_b,case,picture,note\n";
    int rank = 0;
    for (const CodePair* p : ranked_pairs(findings))
        out << ++rank << ",code," << csv_field(p->lab) << "," << csv_field(p->a) << "," << csv_field(p->b) << "," << percent(p->share) << ","
            << p->shared_tokens << "," << p->own_a << "," << p->own_b << "," << (p->likely_copied() ? "yes" : "no") << ","
            << csv_field(joined(files_of(*p), " ")) << "," << csv_field(run_lines(*p, true)) << "," << csv_field(run_lines(*p, false))
            << ",,," << (p->identical_edits ? "every changed file the same, byte for byte" : "") << "\n";
    for (const PicturePair& p : findings.pictures.pairs)
        out << ++rank << ",picture," << csv_field(p.lab) << "," << csv_field(p.a) << "," << csv_field(p.b) << ",,,,,yes,,,,"
            << csv_field(p.case_name) << "," << csv_field(p.picture) << ","
            << (p.mistakes_looked_for ? "" : "known mistakes were not looked for on this case") << "\n";
    return out.str();
}

std::string similarity_html(const SimilarityFindings& findings, const fs::path& out_dir) {
    std::ostringstream out;
    const std::vector<const CodePair*> pairs = ranked_pairs(findings);
    const auto likely = std::count_if(pairs.begin(), pairs.end(), [](const CodePair* p) { return p->likely_copied(); });
    std::set<std::string> students;
    for (const LabCode& lab : findings.code)
        for (const auto& [name, tokens] : lab.own_tokens) students.insert(name);
    out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
        << "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src data:; style-src 'unsafe-inline'\">\n"
        << "<title>Copied work</title>\n<style>body{font-family:sans-serif;margin:2em;max-width:110em}"
           "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:.3em .6em;text-align:left;vertical-align:top}"
           "img{width:160px;image-rendering:pixelated;border:1px solid #dadce0}.note{color:#a50e0e}.likely{color:#a50e0e;font-weight:bold}"
           ".sides{display:grid;grid-template-columns:minmax(0,1fr) minmax(0,1fr);gap:1em}.gap{color:#9aa0a6}"
           "td.likely{white-space:nowrap}.who{font-weight:bold;margin:.3em 0}"
           "pre.code{margin:0;font-size:12px;line-height:1.35;overflow-x:auto;border:1px solid #ddd;max-height:40em;overflow-y:auto}"
           "pre.code>span{display:block;white-space:pre}.t{color:#9aa0a6}.c{color:#7baaf7}.m{background:#fde293}.n{display:inline-block;width:3.5em;"
           "color:#9aa0a6;text-align:right;margin-right:1em;user-select:none}.run{background:#e37400;color:#fff;border-radius:.6em;"
           "padding:0 .35em;margin-right:.4em;font-size:10px}details{margin:1em 0}summary{cursor:pointer}</style>\n</head>\n<body>\n"
        << "<h1>Copied work</h1>\n<p>" << students.size() << " submissions compared, lab by lab, file by file of the same name. "
        << "Each student's files were first stripped of the template: the lab's starter, its reference answers, every lab's "
           "starter and the kit's shared shaders; then of what "
        << kCommonPartners << " or more other students share. Only what is left, the student's own code, is compared: a pair's share is "
           "how much of the smaller own code the other has too, in runs of at least "
        << findings.min_run << " tokens (similarity-tester: an identifier is one token, so renamed variables match; GLSL read as C). "
        << "Marked likely copied from " << percent(kLikelyCopiedShare) << "%. " << fixed(findings.seconds, 1) << " s.</p>\n";
    out << "<h2>Code two students share</h2>\n";
    if (pairs.empty()) out << "<p>No two students share a run of own code.</p>\n";
    else {
        out << "<p>" << pairs.size() << " pairs, " << likely << " likely copied.</p>\n<table>\n<tr><th>rank</th><th>lab</th><th>students"
            << "</th><th>share</th><th>shared tokens</th><th>own tokens</th><th>files</th></tr>\n";
        for (std::size_t i = 0; i < pairs.size() && i < kPairsListed; ++i) {
            const CodePair& p = *pairs[i];
            out << "<tr><td>" << (i < kPairsSideBySide ? "<a href=\"#pair-" + std::to_string(i + 1) + "\">" + std::to_string(i + 1) + "</a>"
                                                       : std::to_string(i + 1)) << "</td><td>" << html(p.lab) << "</td><td>" << html(p.a)
                << ", " << html(p.b) << "</td><td" << (p.likely_copied() ? " class=\"likely\"" : "") << ">" << percent(p.share) << "%"
                << (p.likely_copied() ? " likely copied" : "") << (p.identical_edits ? " (every changed file the same, byte for byte)" : "")
                << "</td><td>" << p.shared_tokens << "</td><td>" << p.own_a << ", " << p.own_b
                << "</td><td>" << html(joined(files_of(p), ", ")) << "</td></tr>\n";
        }
        out << "</table>\n";
        if (pairs.size() > kPairsListed) out << "<p>" << pairs.size() - kPairsListed << " more in similarity.csv.</p>\n";
    }
    out << "<h2>The same rare wrong picture</h2>\n";
    if (!findings.pictures.batch_found)
        out << "<p>No batch here (no batch.json): grade the class with <code>gsv-grade --batch</code> into this folder to compare "
               "their failing pictures.</p>\n";
    else if (findings.pictures.pairs.empty())
        out << "<p>None: of " << findings.pictures.wrong_pictures << " wrong pictures no known mistake explains, no two students "
            << "alone drew the same one.</p>\n";
    else {
        out << "<p>A failing case's picture no known mistake explains, pixel for pixel the same for these two students and no "
               "one else in the class.</p>\n<table>\n<tr><th>lab</th><th>case</th><th>TODO</th><th>students</th><th>their picture</th>"
               "<th>expected</th></tr>\n";
        for (const PicturePair& p : findings.pictures.pairs)
            out << "<tr><td>" << html(p.lab) << "</td><td>" << html(p.case_name) << "</td><td>" << html(p.todo) << "</td><td>" << html(p.a)
                << ", " << html(p.b) << (p.mistakes_looked_for ? "" : "<br><span class=\"note\">known mistakes were not looked for here</span>")
                << "</td><td>" << thumbnail(out_dir, p.picture, p.lab + "/" + p.case_name) << "</td><td>"
                << (p.expected.empty() ? "" : thumbnail(out_dir, p.expected, "expected")) << "</td></tr>\n";
        out << "</table>\n";
    }
    for (const std::string& note : findings.pictures.notes) out << "<p class=\"note\">" << html(note) << "</p>\n";
    if (!pairs.empty())
        out << "<h2>Side by side</h2>\n<p>Grey: the template's lines. Blue: own code " << kCommonPartners << " or more other students "
            << "share (the class's). Yellow: own code the two share, each run numbered alike on both sides.</p>\n";
    for (std::size_t i = 0; i < pairs.size() && i < kPairsSideBySide; ++i) {
        const CodePair& p = *pairs[i];
        out << "<details id=\"pair-" << i + 1 << "\"" << (p.likely_copied() ? " open" : "") << "><summary>" << i + 1 << ". " << html(p.lab)
            << ": " << html(p.a) << " and " << html(p.b) << ", " << percent(p.share) << "% (" << p.shared_tokens << " tokens)</summary>\n"
            << side_by_side(lab_of(findings, p), p) << "</details>\n";
    }
    for (const LabCode& lab : findings.code)
        for (const std::string& note : lab.notes) out << "<p class=\"note\">" << html(lab.lab) << ": " << html(note) << "</p>\n";
    out << "</body>\n</html>\n";
    return out.str();
}

void write_similarity_report(const SimilarityFindings& findings, const fs::path& out_dir) {
    fs::create_directories(out_dir);
    for (const auto& [name, text] : {std::pair{"similarity.csv", similarity_csv(findings)},
                                     std::pair{"similarity.html", similarity_html(findings, out_dir)}}) {
        std::ofstream out(out_dir / name);
        out << text;
        if (!out) throw Error("cannot write '" + (out_dir / name).string() + "'");
    }
}

}  // namespace gsv
