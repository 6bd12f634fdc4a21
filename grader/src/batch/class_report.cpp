#include "grader/src/batch/class_report.h"
#include "grader/src/batch/csv_field.h"

#include "common/core/error.h"
#include "common/image/image.h"
#include "common/io/json.h"
#include "grader/src/batch/batch_record.h"
#include "grader/src/diagnose/diagnosis.h"
#include "grader/src/judge/image_verdict.h"
#include "grader/src/report/report.h"
#include "grader/src/report/report_format.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>

namespace fs = std::filesystem;

namespace gsv {
namespace {

std::string html(std::string_view raw) { return escape_markup(raw, MarkupPlace::Text); }

std::string joined(const std::vector<std::string>& items, const char* separator) {
    std::string text;
    for (const auto& item : items) text += (text.empty() ? "" : separator) + item;
    return text;
}

std::optional<Image> picture_at(const fs::path& file) {
    try {
        return read_png(file);
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

// An <img> of a PNG in the batch's folder, shown small; a note where it cannot be read.
std::string thumbnail(const fs::path& out_dir, const std::string& relative, const std::string& alt) {
    if (relative.empty()) return "";
    std::ifstream in(out_dir / relative, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.empty()) return "<span class=\"note\">" + html(relative) + " is missing</span>";
    return "<img alt=\"" + escape_markup(alt, MarkupPlace::Attribute) + "\" src=\"data:image/png;base64," + base64(bytes) + "\">";
}

}  // namespace

ClassReport class_report(const fs::path& out_dir, const std::vector<BatchEntry>& entries, std::string* problems) {
    ClassReport report;
    std::map<std::pair<std::string, std::string>, ClassReport::Share> todos, cases;
    std::vector<std::pair<std::string, std::string>> todo_order, case_order;
    std::map<std::string, ClassMistake> mistakes;  // by lab and text
    std::vector<std::string> mistake_order;
    // Unexplained failures by lab and case: the student, the row's picture and its tolerance.
    struct Failure {
        std::string student, picture;
        ImageTolerance tolerance;
        std::string todo;
    };
    std::map<std::pair<std::string, std::string>, std::vector<Failure>> unexplained;
    for (const BatchEntry& e : entries) {
        if (!e.graded) continue;
        GradeReport graded;
        try {
            graded = read_report_json(out_dir / e.name / "report.json");
        } catch (const Error& error) {
            if (problems) *problems += std::string(problems->empty() ? "" : "\n") + error.what();
            continue;
        }
        ++report.students;
        std::map<std::pair<std::string, std::string>, bool> todo_passed;
        for (const CaseResult& r : graded.results) {
            if (r.kind != "image") continue;
            const auto case_key = std::make_pair(r.lab, r.name);
            if (!cases.count(case_key)) case_order.push_back(case_key);
            auto& share = cases[case_key];
            share.lab = r.lab;
            share.key = r.name;
            ++share.graded;
            share.passed += r.status == CaseStatus::Passed;
            // A failure a known mistake explains counts against the mistake's TODO (needs.h), one that needs another TODO
            // first against none: the case's own TODO has not failed for it.
            const auto own = std::make_pair(r.lab, r.todo);
            if (!todo_passed.count(own)) todo_passed[own] = true;
            if (r.status != CaseStatus::Passed && r.status != CaseStatus::NeedsFirst)
                todo_passed[std::make_pair(r.lab, r.mistake_todo.empty() ? r.todo : r.mistake_todo)] = false;
            if (r.status != CaseStatus::Passed && r.mistake_todo.empty() && is_diagnosable(r.status) && !r.actual_png.empty())
                unexplained[case_key].push_back({e.name, (fs::path(e.name) / r.actual_png).generic_string(), r.image.tolerance, r.todo});
        }
        for (const auto& [key, passed] : todo_passed) {
            if (!todos.count(key)) todo_order.push_back(key);
            auto& share = todos[key];
            share.lab = key.first;
            share.key = key.second;
            ++share.graded;
            share.passed += passed;
        }
        for (const LabDiagnosis& d : graded.diagnoses)
            for (const MistakeFound& f : d.found) {
                const std::string id = d.lab + "\n" + f.says;
                if (!mistakes.count(id)) {
                    mistake_order.push_back(id);
                    mistakes[id] = {d.lab, f.todo, f.says, f.names.empty() ? "" : f.names.front(), {}, ""};
                }
                ClassMistake& m = mistakes[id];
                if (std::find(m.students.begin(), m.students.end(), e.name) == m.students.end()) m.students.push_back(e.name);
                if (m.picture.empty())
                    for (const CaseResult& r : graded.results)
                        if (r.lab == d.lab && !f.cases.empty() && r.name == f.cases.front() && !r.mistake_png.empty())
                            m.picture = (fs::path(e.name) / r.mistake_png).generic_string();
            }
    }
    for (const auto& key : todo_order) report.todos.push_back(todos[key]);
    for (const auto& key : case_order) report.cases.push_back(cases[key]);
    for (const auto& id : mistake_order) report.mistakes.push_back(mistakes[id]);
    std::stable_sort(report.mistakes.begin(), report.mistakes.end(),
                     [](const ClassMistake& a, const ClassMistake& b) { return a.students.size() > b.students.size(); });
    // Clusters: each failure joins the first cluster of its case whose first picture it matches under the case's
    // tolerance, or starts one.
    for (const auto& key : case_order) {
        const auto it = unexplained.find(key);
        if (it == unexplained.end()) continue;
        std::vector<ClassCluster> clusters;
        std::vector<Image> firsts;
        for (const Failure& f : it->second) {
            const std::optional<Image> picture = picture_at(out_dir / f.picture);
            std::size_t joined_at = clusters.size();
            if (picture)
                for (std::size_t c = 0; c < clusters.size(); ++c)
                    if (image_passes(*picture, firsts[c], f.tolerance)) {
                        joined_at = c;
                        break;
                    }
            if (joined_at == clusters.size()) {
                clusters.push_back({"", key.first, key.second, f.todo, {}, f.picture});
                firsts.push_back(picture ? *picture : Image());
            }
            clusters[joined_at].students.push_back(f.student);
        }
        std::stable_sort(clusters.begin(), clusters.end(),
                         [](const ClassCluster& a, const ClassCluster& b) { return a.students.size() > b.students.size(); });
        for (std::size_t c = 0; c < clusters.size(); ++c) {
            clusters[c].id = key.first + "/" + key.second + "/" + std::to_string(c + 1);
            report.unexplained.push_back(clusters[c]);
        }
    }
    return report;
}

std::string class_mistakes_csv(const ClassReport& report) {
    std::ostringstream out;
    out << "kind,lab,todo,case,what,count,of,students,picture\n";
    const auto row = [&](const std::string& kind, const std::string& lab, const std::string& todo, const std::string& c,
                         const std::string& what, std::size_t count, int of, const std::vector<std::string>& students,
                         const std::string& picture) {
        out << kind << "," << csv_field(lab) << "," << csv_field(todo) << "," << csv_field(c) << "," << csv_field(what) << ","
            << count << "," << of << "," << csv_field(joined(students, " ")) << "," << csv_field(picture) << "\n";
    };
    for (const auto& s : report.todos) row("todo passed", s.lab, s.key, "", "", static_cast<std::size_t>(s.passed), s.graded, {}, "");
    for (const auto& s : report.cases) row("case passed", s.lab, "", s.key, "", static_cast<std::size_t>(s.passed), s.graded, {}, "");
    for (const auto& m : report.mistakes) row("known mistake", m.lab, m.todo, "", m.says, m.students.size(), report.students, m.students, m.picture);
    for (const auto& c : report.unexplained)
        row("unexplained", c.lab, c.todo, c.case_name, c.id, c.students.size(), report.students, c.students, c.picture);
    return out.str();
}

std::string class_report_html(const ClassReport& report, const fs::path& out_dir) {
    std::ostringstream out;
    out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
        << "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src data:; style-src 'unsafe-inline'\">\n"
        << "<title>The class by its mistakes</title>\n<style>body{font-family:sans-serif;margin:2em;max-width:80em}"
           "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:.3em .6em;text-align:left;vertical-align:top}"
           "img{width:128px;image-rendering:pixelated;border:1px solid #dadce0}.bar{background:#8ab4f8;height:.8em}"
           ".note{color:#a50e0e}</style>\n</head>\n<body>\n"
        << "<h1>The class by its mistakes</h1>\n<p>" << report.students << " submissions graded.</p>\n";
    const auto shares = [&](const char* title, const char* what, const std::vector<ClassReport::Share>& list) {
        out << "<h2>" << title << "</h2>\n<table>\n<tr><th>lab</th><th>" << what << "</th><th>passed</th><th></th></tr>\n";
        for (const auto& s : list) {
            const double share = s.graded > 0 ? double(s.passed) / s.graded : 0;
            out << "<tr><td>" << html(s.lab) << "</td><td>" << html(s.key) << "</td><td>" << s.passed << " of " << s.graded
                << "</td><td><div class=\"bar\" style=\"width:" << fixed(200 * share, 0) << "px\"></div></td></tr>\n";
        }
        out << "</table>\n";
    };
    out << "<h2>Known mistakes</h2>\n";
    if (report.mistakes.empty()) out << "<p>No known mistake explains any failure.</p>\n";
    else {
        out << "<table>\n<tr><th>lab</th><th>TODO</th><th>the mistake</th><th>students</th><th>its picture</th></tr>\n";
        for (const auto& m : report.mistakes)
            out << "<tr><td>" << html(m.lab) << "</td><td>" << html(m.todo) << "</td><td>" << html(m.says) << "<br><small>"
                << html(m.name) << "</small></td><td>" << m.students.size() << ": " << html(joined(m.students, ", ")) << "</td><td>"
                << thumbnail(out_dir, m.picture, m.says) << "</td></tr>\n";
        out << "</table>\n";
    }
    out << "<h2>Failures no known mistake explains</h2>\n<p>Students whose pictures of a case match each other are one cluster: "
           "a mistake the kit does not know yet. <code>gsv-grade mistake-skeleton OUT ID</code> writes an entry for "
           "<code>tests/mutants/&lt;lab&gt;.json</code> to fill in.</p>\n";
    if (report.unexplained.empty()) out << "<p>None.</p>\n";
    else {
        out << "<table>\n<tr><th>cluster</th><th>TODO</th><th>students</th><th>picture</th></tr>\n";
        for (const auto& c : report.unexplained)
            out << "<tr><td>" << html(c.id) << "</td><td>" << html(c.todo) << "</td><td>" << c.students.size() << ": "
                << html(joined(c.students, ", ")) << "</td><td>" << thumbnail(out_dir, c.picture, c.id) << "</td></tr>\n";
        out << "</table>\n";
    }
    shares("By TODO", "TODO", report.todos);
    shares("By case", "case", report.cases);
    out << "</body>\n</html>\n";
    return out.str();
}

void write_class_report(const fs::path& out_dir, const std::vector<BatchEntry>& entries) {
    std::string problems;
    const ClassReport report = class_report(out_dir, entries, &problems);
    for (const auto& [name, text] : {std::pair{"class-mistakes.csv", class_mistakes_csv(report)},
                                     std::pair{"class-report.html", class_report_html(report, out_dir)}}) {
        std::ofstream out(out_dir / name);
        out << text;
        if (!out) throw Error("cannot write '" + (out_dir / name).string() + "'");
    }
}

std::string mistake_skeleton(const fs::path& out_dir, const std::string& id) {
    const BatchRecord record = read_batch_record(out_dir);
    const ClassReport report = class_report(out_dir, record.entries);
    const auto c = std::find_if(report.unexplained.begin(), report.unexplained.end(), [&](const ClassCluster& x) { return x.id == id; });
    if (c == report.unexplained.end()) {
        std::string known;
        for (const auto& x : report.unexplained) known += (known.empty() ? "" : ", ") + x.id;
        throw Error("no cluster '" + id + "' in " + out_dir.string() + (known.empty() ? " (it has none)" : " (it has " + known + ")"));
    }
    Json entry = Json::object();
    entry["name"] = "TODO: the mistake, for the instructor (seen in " + std::to_string(c->students.size()) + ": " + joined(c->students, ", ") + ")";
    entry["todo"] = c->todo;
    entry["says"] = "TODO: the idea missed and what it does to the picture, for the student (never the code)";
    entry["sheet"] = "TODO table";
    entry["file"] = "TODO: the file of solutions/<lab_dir>/ the edit changes";
    entry["find"] = "TODO: the reference's text";
    entry["replace"] = "TODO: the text as these students wrote it";
    Json must = Json::array();
    must.push_back(c->case_name);
    entry["must_fail"] = must;
    entry["must_fail_hidden"] = Json::array();
    entry["hidden_why"] = "TODO: the hidden cases it must fail, or why none";
    return "// " + c->lab + ": a skeleton for tests/mutants/" + c->lab + ".json \"mutants\", from cluster " + c->id + " (" +
           (out_dir / c->picture).string() + ")\n" + entry.dump(2) + "\n";
}

}  // namespace gsv
