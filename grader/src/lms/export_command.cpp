#include "grader/src/lms/export_command.h"

#include "common/core/error.h"
#include "grader/src/grade/grade_exit.h"
#include "grader/src/lms/lms_dialect.h"

#include <cstdio>
#include <fstream>

namespace fs = std::filesystem;

namespace gsv {

const char* const kExportUsage =
    "usage: gsv-grade export --lms canvas|moodle|blackboard --roster FILE [--column WHAT=NAME[|ID]]... [--percent]\n"
    "                        [--no-feedback] [--gradepointmax N] [--allow-partial] [--to FILE] OUT\n"
    "  OUT               a batch's --out (or a merge's OUT): its batch.json is read, so shards must be merged first\n"
    "  --lms L           canvas: gradebook import CSV (Student, ID, SIS User ID, SIS Login ID, Section, a column each);\n"
    "                    moodle: CSV grade import (Email address and/or ID number, a grade and its feedback a column\n"
    "                    each); blackboard: Grade Center upload (Last Name, First Name, Username, a column each; tab-\n"
    "                    separated, every field quoted)\n"
    "  --roster FILE     CSV with a header row: submission (the batch's folder, a GitHub Classroom login) and what the\n"
    "                    LMS knows the student by: student, sis_login_id, section, id, sis_user_id (Canvas); email,\n"
    "                    idnumber (Moodle); username, last_name, first_name (Blackboard)\n"
    "  --column WHAT=NAME[|ID]  write WHAT (total, or a lab: lab01) into the LMS's assignment NAME, with its id where\n"
    "                    the LMS has one (Canvas's assignment id, Blackboard's column id: needed there); repeat for\n"
    "                    more columns, in that order. Default: total and every lab, named so (not for Blackboard)\n"
    "  --percent         grades as percentages of their maximum rather than points\n"
    "  --no-feedback     no Moodle feedback columns (Canvas's and Blackboard's imports take none)\n"
    "  --gradepointmax N Moodle's grade limit on your site (default 100): a grade column that goes higher is refused\n"
    "  --allow-partial   write the students that match even where some do not (each problem still listed, exit 0):\n"
    "                    a student who submitted nothing gets 0, one not graded or not matched is left out\n"
    "  --to FILE         where to write (default OUT/<lms>-grades.csv, OUT/blackboard-grades.txt)\n"
    "exit status: 0 written, 1 problems listed (a roster student not in the batch, a submission not in the roster, one\n"
    "                    not graded, one student twice) and nothing written, 2 usage error or unreadable input\n";

ExportCommand read_export_command(const std::vector<std::string>& args) {
    ExportCommand command;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        const auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) throw Error("option " + a + " needs a value");
            return args[++i];
        };
        if (a == "--help" || a == "-h") {
            command.help = true;
            return command;
        } else if (a == "--lms") {
            command.options.lms = parse_lms(value());
            command.lms_given = true;
        } else if (a == "--roster") {
            command.roster = value();
        } else if (a == "--column") {
            command.options.columns.push_back(parse_grade_column(value()));
        } else if (a == "--percent") {
            command.options.percent = true;
        } else if (a == "--no-feedback") {
            command.options.feedback = false;
        } else if (a == "--gradepointmax") {
            const std::string& text = value();
            std::size_t used = 0;
            double limit = 0;
            try {
                limit = std::stod(text, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            if (used != text.size() || !(limit > 0)) throw Error("--gradepointmax needs a number above 0, got '" + text + "'");
            command.options.moodle_grade_limit = limit;
        } else if (a == "--allow-partial") {
            command.options.allow_partial = true;
        } else if (a == "--to") {
            command.to = value();
        } else if (!a.empty() && a[0] == '-') {
            throw Error("unknown option '" + a + "' (gsv-grade export --help lists them)");
        } else if (command.batch_out.empty()) {
            command.batch_out = a;
        } else {
            throw Error("one batch folder only, got '" + command.batch_out.string() + "' and '" + a + "'");
        }
    }
    if (!command.lms_given) throw Error("needs --lms canvas, moodle or blackboard");
    if (command.roster.empty()) throw Error("needs --roster FILE (submission -> the LMS's student; gsv-grade export --help)");
    if (command.batch_out.empty()) throw Error("needs the batch's --out folder (gsv-grade export ... OUT)");
    if (command.options.lms != Lms::Moodle && !command.options.feedback)
        throw Error("--no-feedback is Moodle's: --lms " + std::string(lms_name(command.options.lms)) + " writes no feedback anyway");
    if (command.options.lms != Lms::Moodle && command.options.moodle_grade_limit != 100)
        throw Error("--gradepointmax is Moodle's grade limit: --lms " + std::string(lms_name(command.options.lms)) + " has none");
    if (command.options.lms == Lms::Blackboard && command.options.columns.empty())
        throw Error("--lms blackboard needs --column WHAT=NAME|ID for each column: Blackboard fills an existing column by its id only");
    return command;
}

int run_export_command(const std::vector<std::string>& args) {
    try {
        const ExportCommand command = read_export_command(args);
        if (command.help) {
            std::printf("%s", kExportUsage);
            return kGradeOk;
        }
        const BatchRecord record = read_batch_record(command.batch_out);
        const auto cases = read_batch_cases(command.batch_out);
        if (!cases) throw Error((command.batch_out / "batch.json").string() + " holds no case rows (a batch graded before it kept "
                                "them): grade the batch again with this gsv-grade");
        const Roster roster = read_roster_csv(command.roster);
        const LmsExport result = export_grades(record, *cases, roster, command.options);
        const fs::path to = command.to.empty() ? command.batch_out / default_file_name(command.options.lms) : command.to;
        for (const std::string& note : result.notes) std::fprintf(stderr, "gsv-grade export: note: %s\n", note.c_str());
        for (const std::string& problem : result.problems) std::fprintf(stderr, "gsv-grade export: %s\n", problem.c_str());
        if (!result.written()) {
            std::fprintf(stderr, "gsv-grade export: %zu problem%s: nothing written to %s%s\n", result.problems.size(),
                         result.problems.size() == 1 ? "" : "s", to.string().c_str(),
                         result.blocking ? " (fix the roster: a student or submission in it twice)"
                                         : "; --allow-partial writes it, each student as the lines above say");
            return kGradeFailed;
        }
        // Written beside and renamed into place: a file that fails half-way is never taken for a class's grades.
        const fs::path partial = to.string() + ".partial";
        {
            std::ofstream out(partial, std::ios::binary);
            out << result.text;
            if (!out) throw Error("cannot write '" + partial.string() + "'");
        }
        std::error_code renamed;
        fs::rename(partial, to, renamed);
        if (renamed) throw Error("cannot write '" + to.string() + "': " + renamed.message());
        std::string columns;
        for (const GradeColumn& c : result.columns) columns += (columns.empty() ? "" : ", ") + c.what + " as '" + c.name + "'";
        std::printf("%s: %zu students for %s (%s)%s\n", to.string().c_str(), result.rows, lms_name(command.options.lms), columns.c_str(),
                    result.problems.empty() ? "" : ", with the problems listed");
        return kGradeOk;
    } catch (const Error& e) {
        std::fprintf(stderr, "gsv-grade export: %s\n", e.what());
        return kGradeNotGraded;
    } catch (const fs::filesystem_error& e) {
        std::fprintf(stderr, "gsv-grade export: %s\n", e.what());
        return kGradeNotGraded;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "gsv-grade export: internal error: %s\n", e.what());
        return kGradeNotGraded;
    }
}

}  // namespace gsv
