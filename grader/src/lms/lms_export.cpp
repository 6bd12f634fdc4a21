#include "grader/src/lms/lms_export.h"

#include "common/core/error.h"
#include "grader/src/lms/lms_dialect.h"
#include "grader/src/report/report_format.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <regex>
#include <set>

namespace gsv {
namespace {

std::string joined(const std::vector<std::string>& items) {
    std::string text;
    for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
    return text.empty() ? "none" : text;
}

// A name the LMS file can carry: UTF-8 without control characters (a tab or line break would split a row).
void check_text(const std::string& text, const std::string& what) {
    if (valid_utf8(text) != text) throw Error(what + " is not UTF-8");
    for (const char c : text)
        if (static_cast<unsigned char>(c) < 0x20) throw Error(what + " holds a tab, line break or other control character");
}

bool nothing_submitted(const BatchEntry& e) { return !e.graded && !e.kit_fault && e.problem.rfind("nothing submitted", 0) == 0; }

// Points per (submission, lab) summed from the case rows, with their maximum.
struct LabPoints {
    std::map<std::pair<std::string, std::string>, std::pair<double, double>> sums;
    std::set<std::string> submissions;  // those with any case row
    std::vector<std::string> labs;      // sorted
};

LabPoints lab_points(const std::vector<ClassCaseRow>& cases) {
    LabPoints points;
    std::set<std::string> labs;
    for (const ClassCaseRow& r : cases) {
        auto& sum = points.sums[{r.submission, r.lab}];
        sum.first += r.points;
        sum.second += r.max_points;
        points.submissions.insert(r.submission);
        labs.insert(r.lab);
    }
    points.labs.assign(labs.begin(), labs.end());
    return points;
}

}  // namespace

Lms parse_lms(const std::string& text) {
    if (text == "canvas") return Lms::Canvas;
    if (text == "moodle") return Lms::Moodle;
    if (text == "blackboard") return Lms::Blackboard;
    throw Error("--lms takes canvas, moodle or blackboard, got '" + text + "'");
}

const char* lms_name(Lms lms) {
    switch (lms) {
    case Lms::Canvas: return "canvas";
    case Lms::Moodle: return "moodle";
    case Lms::Blackboard: return "blackboard";
    }
    return "?";
}

GradeColumn parse_grade_column(const std::string& text) {
    const std::string where = "--column '" + text + "'";
    const auto equals = text.find('=');
    if (equals == std::string::npos || equals == 0)
        throw Error(where + ": needs WHAT=NAME or WHAT=NAME|ID (WHAT: total or a lab such as lab01)");
    GradeColumn column;
    column.what = text.substr(0, equals);
    column.name = text.substr(equals + 1);
    // "|digits" at the end is the id, as in Blackboard's own headings; a '|' elsewhere is part of the name.
    std::smatch id;
    if (std::regex_match(column.name, id, std::regex("(.*)\\|([0-9]+)"))) {
        column.id = id[2];
        column.name = id[1];
    }
    if (column.name.empty()) throw Error(where + ": no name for the LMS's assignment");
    check_text(column.name, where);
    return column;
}

std::string feedback_text(const std::vector<ClassCaseRow>& cases, const std::string& submission, const std::string& lab) {
    // In the case rows' order, which is the report's: labs, then each lab's TODOs as it names them.
    std::vector<std::string> labs;
    std::map<std::string, std::pair<double, double>> lab_sums;
    std::map<std::string, std::vector<std::string>> todo_order;
    std::map<std::pair<std::string, std::string>, std::pair<double, double>> todo_sums;
    for (const ClassCaseRow& r : cases) {
        if (r.submission != submission || (!lab.empty() && r.lab != lab)) continue;
        if (!lab_sums.count(r.lab)) labs.push_back(r.lab);
        lab_sums[r.lab].first += r.points;
        lab_sums[r.lab].second += r.max_points;
        const std::string todo = r.todo.empty() ? "(demo)" : r.todo;
        if (!todo_sums.count({r.lab, todo})) todo_order[r.lab].push_back(todo);
        todo_sums[{r.lab, todo}].first += r.points;
        todo_sums[{r.lab, todo}].second += r.max_points;
    }
    std::string text;
    for (const std::string& l : labs) {
        text += (text.empty() ? "" : "; ") + l + " " + format_points(lab_sums[l].first) + "/" + format_points(lab_sums[l].second);
        std::vector<std::string> lost;
        for (const std::string& todo : todo_order[l]) {
            const auto [points, max_points] = todo_sums[{l, todo}];
            if (points < max_points) lost.push_back(todo + " " + format_points(points) + "/" + format_points(max_points));
        }
        if (!lost.empty()) text += " (" + joined(lost) + ")";
    }
    return text;
}

LmsExport export_grades(const BatchRecord& record, const std::vector<ClassCaseRow>& cases, const Roster& roster,
                        const LmsExportOptions& options) {
    const Lms lms = options.lms;
    if (record.shard_count != 1)
        throw Error("this is shard " + std::to_string(record.shard) + "/" + std::to_string(record.shard_count) +
                    " of a class: join the shards with gsv-grade merge and export the merged folder");
    check_roster_for(lms, roster);
    const LabPoints points = lab_points(cases);

    LmsExport out;
    out.allow_partial = options.allow_partial;
    out.columns = options.columns;
    if (out.columns.empty()) {
        out.columns.push_back({"total", "total", ""});
        for (const std::string& lab : points.labs) out.columns.push_back({lab, lab, ""});
    }
    std::set<std::string> whats, names;
    bool lab_columns = false;
    for (const GradeColumn& c : out.columns) {
        if (c.what != "total" && std::find(points.labs.begin(), points.labs.end(), c.what) == points.labs.end())
            throw Error("--column " + c.what + ": the batch graded no lab '" + c.what + "' (its labs: " + joined(points.labs) +
                        "; or 'total')");
        if (!whats.insert(c.what).second) throw Error("--column " + c.what + " given twice");
        if (!names.insert(c.name).second) throw Error("--column: two columns named '" + c.name + "'");
        check_column_for(lms, c, out.notes);
        lab_columns = lab_columns || c.what != "total";
    }

    // A column's maximum: the most any graded submission could have got (one kit and its options grade all alike).
    const auto max_of = [&](const std::string& submission, const std::string& what, const BatchEntry& e) {
        if (what == "total") return std::pair{e.score, e.max_score};
        const auto at = points.sums.find({submission, what});
        return at == points.sums.end() ? std::pair{0.0, 0.0} : at->second;
    };
    std::vector<double> column_max(out.columns.size(), 0);
    for (const BatchEntry& e : record.entries)
        if (e.graded)
            for (std::size_t i = 0; i < out.columns.size(); ++i)
                column_max[i] = std::max(column_max[i], max_of(e.name, out.columns[i].what, e).second);
    for (std::size_t i = 0; i < out.columns.size(); ++i) {
        const double top = options.percent ? 100 : column_max[i];
        if (lms == Lms::Moodle && top > options.moodle_grade_limit)
            throw Error("column '" + out.columns[i].what + "' goes up to " + format_points(top) + ", over Moodle's grade limit of " +
                        format_points(options.moodle_grade_limit) + " (gradepointmax; Moodle refuses the whole file for one grade "
                        "over it): give --percent, or --gradepointmax N where the site allows more");
    }
    const auto cell = [&](double value, double max_points) {
        return format_points(options.percent ? (max_points > 0 ? 100 * value / max_points : 0) : value);
    };
    const bool feedback = options.feedback && takes_feedback(lms);

    std::vector<std::vector<std::string>> rows(1, identity_header(lms, roster));
    for (std::size_t i = 0; i < out.columns.size(); ++i) {
        rows[0].push_back(grade_heading(lms, out.columns[i], options.percent ? 100 : column_max[i]));
        // Moodle wipes an activity's grades where its feedback comes without them: a feedback column only ever
        // stands right after its own grade column.
        if (feedback) rows[0].push_back(feedback_heading(out.columns[i]));
    }

    std::map<std::string, const BatchEntry*> entries;
    for (const BatchEntry& e : record.entries) entries[e.name] = &e;
    std::map<std::string, const RosterStudent*> by_submission;
    std::map<std::pair<std::string, std::string>, const RosterStudent*> by_identity;
    const auto problem = [&](const RosterStudent& s, const std::string& text) {
        out.problems.push_back(roster.where(s) + ": '" + s.submission + "' " + text);
    };
    for (const RosterStudent& s : roster.students) {
        if (const auto [at, fresh] = by_submission.emplace(s.submission, &s); !fresh) {
            problem(s, "again (first at " + roster.where(*at->second) + "): one submission, two students");
            out.blocking = true;
            continue;
        }
        bool twice = false;
        for (const IdentityKey& k : identity_keys(lms, s)) {
            const auto [at, fresh] = by_identity.emplace(std::pair{k.what, k.key}, &s);
            if (fresh) continue;
            std::string first_value;  // the earlier row's, as written: Moodle's e-mails are keyed without case
            for (const IdentityKey& o : identity_keys(lms, *at->second))
                if (o.what == k.what) first_value = o.value;
            const std::string other = "'" + at->second->submission + "' (" + roster.where(*at->second) + ")";
            problem(s, first_value == k.value
                           ? "has " + k.what + " '" + k.value + "', as " + other + " has: two submissions, one student"
                           : "has e-mail '" + k.value + "', " + other + " has '" + first_value + "': they differ only in case, and "
                                 "Moodle compares e-mails case-sensitively, so one is not the e-mail Moodle holds (the roster must "
                                 "carry each exactly as Moodle does)");
            out.blocking = twice = true;
        }
        if (twice) continue;

        const auto entry = entries.find(s.submission);
        if (entry == entries.end()) {
            std::string hint;
            for (const auto& [name, e] : entries)
                if (name != s.submission && std::equal(name.begin(), name.end(), s.submission.begin(), s.submission.end(),
                                                       [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) ==
                                                                                   std::tolower(static_cast<unsigned char>(b)); }))
                    hint = " (the batch has '" + name + "': folder names are matched exactly)";
            problem(s, "is not in the batch" + hint + ": left out, the LMS keeps what it has");
            continue;
        }
        const BatchEntry& e = *entry->second;
        std::vector<std::string> row = identity_cells(lms, roster, s);
        if (nothing_submitted(e)) {
            problem(s, "submitted nothing: written as 0");
            for (std::size_t i = 0; i < out.columns.size(); ++i) {
                row.push_back("0");
                if (feedback) row.push_back("nothing submitted");
            }
        } else if (!e.graded) {
            problem(s, "was not graded (" + e.problem + ")" + (e.kit_fault ? ", the kit's fault, not theirs" : "") +
                           ": left out, the LMS keeps what it has; grade it again");
            continue;
        } else if (lab_columns && !points.submissions.count(e.name)) {
            problem(s, "was graded, but the batch has no case rows for it (its report.json was missing), so its labs' points are "
                       "unknown: left out");
            continue;
        } else {
            for (std::size_t i = 0; i < out.columns.size(); ++i) {
                const auto [value, max_points] = max_of(e.name, out.columns[i].what, e);
                row.push_back(cell(value, max_points));
                if (feedback)
                    row.push_back(feedback_text(cases, e.name, out.columns[i].what == "total" ? "" : out.columns[i].what));
            }
        }
        rows.push_back(row);
    }
    for (const BatchEntry& e : record.entries)
        if (!by_submission.count(e.name))
            out.problems.push_back("'" + e.name + "' (" + (e.graded ? format_points(e.score) + "/" + format_points(e.max_score) : e.problem) +
                                   ") is in the batch but not in " + roster.file.string() + ": left out");
    out.rows = rows.size() - 1;
    out.text = table_text(lms, rows);
    return out;
}

}  // namespace gsv
