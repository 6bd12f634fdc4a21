// Grades out to the LMS (issue 42, item 2; grader/src/lms/): each LMS's file byte for byte for a small class, against the
// rules grader/README.md cites (Canvas's RFC 4180 CSV and its "Name (id)" headings; Moodle's feedback only beside its
// grade, its case-sensitive e-mails, its grade limit; Blackboard's tab-separated, every-field-quoted file and its
// "[Total Pts: N Score] |id" headings), names with a comma, a quote and letters outside ASCII, and every student or
// submission that does not match named. The batch record is written by the code that writes a batch's.
#include "catch.hpp"
#include "lab_runner.h"
#include "test_support.h"

#include "grader/src/batch/batch_record.h"
#include "grader/src/batch/class_cases.h"
#include "grader/src/lms/export_command.h"
#include "grader/src/lms/lms_export.h"
#include "grader/src/lms/lms_roster.h"

#include <fstream>

namespace fs = std::filesystem;
using namespace gsv;

namespace {

BatchEntry graded(const std::string& name, double score, double max_score) {
    BatchEntry e;
    e.name = name;
    e.graded = true;
    e.score = score;
    e.max_score = max_score;
    return e;
}

BatchEntry not_graded(const std::string& name, const std::string& problem, bool kit_fault) {
    BatchEntry e;
    e.name = name;
    e.problem = problem;
    e.kit_fault = kit_fault;
    return e;
}

// ann lost L01-T2 and part of L01-T4 in lab01 and a timing check in lab02 (19 of 29); bo lost nothing (29 of 29).
std::vector<ClassCaseRow> class_cases() {
    return {{"ann", "lab01", "L01-T1", "diffuse", "image", "passed", 6, 6},   {"ann", "lab01", "L01-T2", "gooch", "image", "failed", 0, 6},
            {"ann", "lab01", "L01-T4", "stretched", "image", "failed", 1, 3}, {"ann", "lab02", "L02-T1", "gyre", "image", "passed", 10, 10},
            {"ann", "lab02", "L02-T1", "gyre", "timing", "failed", 2, 4},    {"bo", "lab01", "L01-T1", "diffuse", "image", "passed", 6, 6},
            {"bo", "lab01", "L01-T2", "gooch", "image", "passed", 6, 6},     {"bo", "lab01", "L01-T4", "stretched, \"thin\"", "image", "passed", 3, 3},
            {"bo", "lab02", "L02-T1", "gyre", "image", "passed", 10, 10},    {"bo", "lab02", "L02-T1", "gyre", "timing", "passed", 4, 4}};
}

// A batch's --out as gsv-grade --batch leaves it: class-cases.csv and batch.json (which keeps its rows).
BatchRecord write_batch(const fs::path& out, const std::vector<BatchEntry>& entries, const std::vector<ClassCaseRow>& cases) {
    fs::create_directories(out);
    std::ofstream(out / "class-cases.csv") << class_cases_csv(cases);
    BatchRecord record;
    record.seed = 7;
    record.kit = "0123456789abcdef";
    for (const BatchEntry& e : entries) {
        record.roster.push_back(e.name);
        record.entries.push_back(e);
    }
    write_batch_record(record, out, cases);
    return read_batch_record(out);
}

// One roster for all three LMSs: a name with a comma and quotes, names outside ASCII, e-mails in mixed case.
const char* const kRoster =
    "submission,student,sis_login_id,section,id,email,username,last_name,first_name\n"
    "ann,Zoë Ångström,zang,GSV-01,101,Zoe.Angstrom@Uni.example,zang,Ångström,Zoë\n"
    "bo,\"O'Brien, \"\"Bo\"\"\",bobr,\"GSV-01, lab B\",102,bo@uni.example,bobr,O'Brien,\"Bo \"\"the builder\"\"\"\n";

struct Class {
    test::TempDir dir;
    BatchRecord record;
    std::vector<ClassCaseRow> cases = class_cases();
    explicit Class(std::vector<BatchEntry> entries = {graded("ann", 19, 29), graded("bo", 29, 29)}) {
        record = write_batch(dir.path("out"), entries, cases);
        cases = *read_batch_cases(dir.path("out"));
    }
    Roster roster(const std::string& text = kRoster) const { return read_roster_csv(dir.write("roster.csv", text)); }
    LmsExport export_for(Lms lms, std::vector<std::string> columns, const std::string& roster_text = kRoster, bool partial = false) const {
        LmsExportOptions options;
        options.lms = lms;
        for (const std::string& c : columns) options.columns.push_back(parse_grade_column(c));
        options.allow_partial = partial;
        return export_grades(record, cases, roster(roster_text), options);
    }
};

}  // namespace

TEST_CASE("lms: Canvas's gradebook CSV, byte for byte: its five student columns, 'Name (id)' headings, RFC 4180 quoting",
          "[unit][lms]") {
    const Class c;
    // The case rows came back from batch.json as class-cases.csv had them, a check's name with a comma and quotes too.
    REQUIRE(c.cases.size() == class_cases().size());
    CHECK(c.cases[7].check == "stretched, \"thin\"");
    const LmsExport out = c.export_for(Lms::Canvas, {"total=GPU labs|4045949", "lab01=Lab 1: Gooch|4045950"});
    CHECK(out.problems.empty());
    CHECK(out.written());
    CHECK(out.rows == 2);
    // A field with a comma or a quote is quoted and its quotes doubled; "Zoë Ångström" goes as it is, in UTF-8.
    CHECK(out.text ==
          "Student,ID,SIS User ID,SIS Login ID,Section,GPU labs (4045949),Lab 1: Gooch (4045950)\r\n"
          "Zoë Ångström,101,,zang,GSV-01,19,7\r\n"
          "\"O'Brien, \"\"Bo\"\"\",102,,bobr,\"GSV-01, lab B\",29,15\r\n");
    // Canvas takes no comments in its gradebook import: no feedback column, whatever is asked.
    CHECK(out.text.find("Feedback") == std::string::npos);
    // A column without an id is matched by name or made anew: said, not refused.
    const LmsExport by_name = c.export_for(Lms::Canvas, {"lab02=Lab 2"});
    CHECK(by_name.text.rfind("Student,ID,SIS User ID,SIS Login ID,Section,Lab 2\r\n", 0) == 0);
    REQUIRE(by_name.notes.size() == 1);
    CHECK(by_name.notes[0].find("no assignment id") != std::string::npos);
    // A name that ends as an id would: Canvas would read it as one.
    CHECK(test::gsv_error_message([&] { c.export_for(Lms::Canvas, {"lab02=Lab (2)"}); }).find("would read its last '(...)'") !=
          std::string::npos);
}

TEST_CASE("lms: Moodle's CSV, byte for byte: the e-mail as the roster has it, each feedback column right after its grade",
          "[unit][lms]") {
    const Class c;
    const LmsExport out = c.export_for(Lms::Moodle, {"total=Labs total", "lab02=Lab 2"});
    CHECK(out.written());
    CHECK(out.text ==
          "Email address,Labs total,Labs total (Feedback),Lab 2,Lab 2 (Feedback)\r\n"
          "Zoe.Angstrom@Uni.example,19,\"lab01 7/15 (L01-T2 0/6, L01-T4 1/3); lab02 12/14 (L02-T1 12/14)\",12,lab02 12/14 (L02-T1 12/14)\r\n"
          "bo@uni.example,29,lab01 15/15; lab02 14/14,14,lab02 14/14\r\n");
    // Moodle wipes an activity's grades where its feedback is imported without them: every feedback heading follows
    // its own grade's, with the default columns too.
    const LmsExport all = c.export_for(Lms::Moodle, {}, "submission,idnumber\nann,S-1\nbo,S-2\n");
    CHECK(all.text.rfind("ID number,total,total (Feedback),lab01,lab01 (Feedback),lab02,lab02 (Feedback)\r\n", 0) == 0);
    const std::string header = all.text.substr(0, all.text.find('\r'));
    std::vector<std::string> headings;
    for (std::size_t at = 0; at <= header.size();) {
        const auto comma = std::min(header.find(',', at), header.size());
        headings.push_back(header.substr(at, comma - at));
        at = comma + 1;
    }
    int feedback = 0;
    for (std::size_t i = 0; i < headings.size(); ++i)
        if (headings[i].size() > 11 && headings[i].substr(headings[i].size() - 11) == " (Feedback)") {
            ++feedback;
            CHECK(headings[i - 1] + " (Feedback)" == headings[i]);
        }
    CHECK(feedback == 3);
    // --no-feedback drops the feedback columns, never a grade column.
    LmsExportOptions plain;
    plain.lms = Lms::Moodle;
    plain.feedback = false;
    CHECK(export_grades(c.record, c.cases, c.roster(), plain).text.rfind("Email address,total,lab01,lab02\r\n", 0) == 0);
    // An id has no place in Moodle's file: its import form maps the columns.
    CHECK(test::gsv_error_message([&] { c.export_for(Lms::Moodle, {"total=Labs|12"}); }).find("takes no id") != std::string::npos);
}

TEST_CASE("lms: Moodle refuses a grade over its limit, so a total above 100 needs --percent or the site's limit", "[unit][lms]") {
    const Class c({graded("ann", 95, 145), graded("bo", 145, 145)});
    // The case rows are the small class's; the totals are what the record says.
    LmsExportOptions options;
    options.lms = Lms::Moodle;
    options.columns = {parse_grade_column("total=Labs")};
    CHECK(test::gsv_error_message([&] { export_grades(c.record, c.cases, c.roster(), options); })
              .find("goes up to 145, over Moodle's grade limit of 100") != std::string::npos);
    options.percent = true;
    const std::string text = export_grades(c.record, c.cases, c.roster(), options).text;
    CHECK(text.find("\r\nZoe.Angstrom@Uni.example,65.52,") != std::string::npos);
    CHECK(text.find("\r\nbo@uni.example,100,") != std::string::npos);
    options.percent = false;
    options.moodle_grade_limit = 200;
    CHECK(export_grades(c.record, c.cases, c.roster(), options).text.find("\r\nbo@uni.example,145,") != std::string::npos);
}

TEST_CASE("lms: Blackboard's Grade Center file, byte for byte: tab-separated, every field quoted, headings with points and column id",
          "[unit][lms]") {
    const Class c;
    const LmsExport out = c.export_for(Lms::Blackboard, {"total=Labs total|4045949", "lab02=Lab 2: LIC|4045951"});
    CHECK(out.written());
    CHECK(out.text ==
          "\"Last Name\"\t\"First Name\"\t\"Username\"\t\"Labs total [Total Pts: 29 Score] |4045949\"\t"
          "\"Lab 2: LIC [Total Pts: 14 Score] |4045951\"\r\n"
          "\"Ångström\"\t\"Zoë\"\t\"zang\"\t\"19\"\t\"12\"\r\n"
          "\"O'Brien\"\t\"Bo \"\"the builder\"\"\"\t\"bobr\"\t\"29\"\t\"14\"\r\n");
    // Without its column id Blackboard makes a new text column worth 0 points: refused, not written.
    CHECK(test::gsv_error_message([&] { c.export_for(Lms::Blackboard, {"total=Labs total"}); }).find("needs its Grade Center column id") !=
          std::string::npos);
}

TEST_CASE("lms: every student or submission that does not match is a line, nothing is written unless asked, and then as said",
          "[unit][lms]") {
    const Class c({graded("ann", 19, 29), graded("bo", 29, 29), not_graded("cy", "nothing submitted (no folder 'cy')", false),
                   not_graded("Dan", "timed out", false), not_graded("fay", "not graded: the batch stopped: no GL", true),
                   graded("gus", 29, 29)});
    const std::string roster = std::string(kRoster) +
                               "cy,Cy Young,cyou,GSV-01,103,cy@uni.example,cyou,Young,Cy\n"
                               "dan,Dan Brown,dbro,GSV-01,104,dan@uni.example,dbro,Brown,Dan\n"
                               "fay,Fay Wray,fwra,GSV-01,105,fay@uni.example,fwra,Wray,Fay\n";
    const LmsExport out = c.export_for(Lms::Canvas, {"total=Labs"}, roster);
    INFO(out.text);
    REQUIRE(out.problems.size() == 5);
    CHECK(out.problems[0] == c.dir.path("roster.csv").string() + ":4: 'cy' submitted nothing: written as 0");
    CHECK(out.problems[1].find(":5: 'dan' is not in the batch (the batch has 'Dan': folder names are matched exactly): left out") !=
          std::string::npos);
    CHECK(out.problems[2].find(":6: 'fay' was not graded (not graded: the batch stopped: no GL), the kit's fault, not theirs: left out") !=
          std::string::npos);
    // A submission without a roster row cannot be given to anyone: said too, graded or not.
    CHECK(out.problems[3] == "'Dan' (timed out) is in the batch but not in " + c.dir.path("roster.csv").string() + ": left out");
    CHECK(out.problems[4] == "'gus' (29/29) is in the batch but not in " + c.dir.path("roster.csv").string() + ": left out");
    CHECK_FALSE(out.written());
    CHECK_FALSE(out.blocking);
    // With --allow-partial: written, cy as 0, the others left out, the problems all the same.
    const LmsExport partial = c.export_for(Lms::Canvas, {"total=Labs"}, roster, true);
    CHECK(partial.written());
    CHECK(partial.rows == 3);
    CHECK(partial.text.find("\r\nCy Young,103,,cyou,GSV-01,0\r\n") != std::string::npos);
    CHECK(partial.text.find("dbro") == std::string::npos);
    CHECK(partial.text.find("fwra") == std::string::npos);
}

TEST_CASE("lms: one student twice, or Moodle e-mails that differ only in case, write nothing even with --allow-partial",
          "[unit][lms]") {
    const Class c;
    const std::string cased = "submission,email\nann,Ann@uni.example\nbo,ann@uni.example\n";
    const LmsExport moodle = c.export_for(Lms::Moodle, {"total=Labs"}, cased, true);
    REQUIRE(moodle.problems.size() == 1);
    CHECK(moodle.problems[0].find(":3: 'bo' has e-mail 'ann@uni.example', 'ann' (") != std::string::npos);
    CHECK(moodle.problems[0].find("has 'Ann@uni.example': they differ only in case, and Moodle compares e-mails case-sensitively") !=
          std::string::npos);
    CHECK(moodle.blocking);
    CHECK_FALSE(moodle.written());
    const LmsExport same = c.export_for(Lms::Blackboard, {"total=Labs|1"}, "submission,username\nann,zang\nbo,zang\n", true);
    REQUIRE(same.problems.size() == 1);
    CHECK(same.problems[0].find("'bo' has Username 'zang', as 'ann' (") != std::string::npos);
    CHECK_FALSE(same.written());
    const LmsExport twice = c.export_for(Lms::Canvas, {"total=Labs"}, "submission,student,sis_login_id\nann,A,a\nann,B,b\n", true);
    REQUIRE(twice.problems.size() >= 1);
    CHECK(twice.problems[0].find(":3: 'ann' again (first at ") != std::string::npos);
    CHECK_FALSE(twice.written());
}

TEST_CASE("lms: a roster is refused in one line naming the file and line: unknown column, short row, not UTF-8, tab, no file",
          "[unit][lms]") {
    test::TempDir dir;
    const auto refusal = [&](const std::string& text) {
        const fs::path file = dir.write("roster.csv", text);
        const std::string e = test::gsv_error_message([&] { read_roster_csv(file); });
        CHECK(e.find('\n') == std::string::npos);
        return e;
    };
    const std::string file = dir.path("roster.csv").string();
    CHECK(refusal("submission,mail\nann,a@x\n").rfind(file + ":1: unknown column 'mail' (a roster's columns: submission, student,", 0) == 0);
    CHECK(refusal("student,email\n") == file + ":1: no 'submission' column (the folder of each student's work in the batch)");
    CHECK(refusal("submission,email\n# a comment\n\nann\n") == file + ":4: 1 fields, the header has 2");
    CHECK(refusal("submission,email\nann,\"a@x\n") == file + ":2: a quote is left open (a value cannot hold a line break)");
    CHECK(refusal("submission,student\nann,Zo\xEB\n").rfind(file + ":2: not UTF-8", 0) == 0);
    CHECK(refusal("submission,student\nann,Zoe\tA\n").rfind(file + ":2: a tab", 0) == 0);
    CHECK(refusal("") == file + ": empty: a roster needs a header row (submission,...) and a row a student");
    CHECK(test::gsv_error_message([&] { read_roster_csv(dir.path("none.csv")); }) ==
          "cannot read the roster '" + dir.path("none.csv").string() + "'");
    // A byte-order mark (Excel's CSV UTF-8), CRLF lines and spaces around values are read through.
    const Roster r = read_roster_csv(dir.write("bom.csv", "\xEF\xBB\xBFsubmission, email\r\nann , a@x\r\n"));
    REQUIRE(r.students.size() == 1);
    CHECK(r.students[0].submission == "ann");
    CHECK(r.students[0].value("email") == "a@x");
    // What an LMS needs and the roster has not got is named with the roster's file.
    const Class c;
    CHECK(test::gsv_error_message([&] { c.export_for(Lms::Blackboard, {"total=Labs|1"}, "submission,email\nann,a@x\n"); }) ==
          c.dir.path("roster.csv").string() + ":1: --lms blackboard needs the column 'username' (Blackboard's Username, the key of "
          "every Grade Center row)");
}

TEST_CASE("lms: columns are checked against the batch: an unknown lab, a column twice, a bad id, a shard's record",
          "[unit][lms]") {
    CHECK(parse_grade_column("total=GPU labs|4045949").id == "4045949");
    CHECK(parse_grade_column("total=GPU labs|4045949").name == "GPU labs");
    // Only digits at the end are an id: a '|' elsewhere is the name's.
    CHECK(parse_grade_column("lab01=Lab 1 | Gooch").name == "Lab 1 | Gooch");
    CHECK(parse_grade_column("lab01=Lab 1 | Gooch").id.empty());
    CHECK(test::gsv_error_message([] { parse_grade_column("lab01"); }).find("needs WHAT=NAME") != std::string::npos);
    const Class c;
    CHECK(test::gsv_error_message([&] { c.export_for(Lms::Canvas, {"lab09=Lab 9"}); }) ==
          "--column lab09: the batch graded no lab 'lab09' (its labs: lab01, lab02; or 'total')");
    CHECK(test::gsv_error_message([&] { c.export_for(Lms::Canvas, {"lab01=A", "lab01=B"}); }) == "--column lab01 given twice");
    BatchRecord shard = c.record;
    shard.shard = 2;
    shard.shard_count = 3;
    CHECK(test::gsv_error_message([&] { export_grades(shard, c.cases, c.roster(), {}); }).find("shard 2/3 of a class: join the shards") !=
          std::string::npos);
    CHECK(feedback_text(c.cases, "ann", "lab01") == "lab01 7/15 (L01-T2 0/6, L01-T4 1/3)");
}

TEST_CASE("gsv-grade export: the file from a batch folder, the problems and exit 1, bad input one line and exit 2", "[grader][lms]") {
    const Class c;
    const fs::path grader = test::bin_dir() / "gsv-grade";
    ProcessLimits limits;
    limits.timeout = std::chrono::seconds(60);
    const auto run = [&](std::vector<std::string> args) {
        args.insert(args.begin(), {grader.string(), "export"});
        return run_process(args, c.dir.path(), limits);
    };
    const std::string out = c.dir.path("out").string();
    const std::string roster = c.dir.write("roster.csv", kRoster).string();
    const ProcessResult canvas = run({"--lms", "canvas", "--roster", roster, "--column", "total=GPU labs|4045949", out});
    INFO(canvas.output);
    CHECK(canvas.exit_code == 0);
    CHECK(test::read_text(c.dir.path("out/canvas-grades.csv")) ==
          "Student,ID,SIS User ID,SIS Login ID,Section,GPU labs (4045949)\r\n"
          "Zoë Ångström,101,,zang,GSV-01,19\r\n"
          "\"O'Brien, \"\"Bo\"\"\",102,,bobr,\"GSV-01, lab B\",29\r\n");
    CHECK(canvas.output.find("canvas-grades.csv: 2 students for canvas (total as 'GPU labs')") != std::string::npos);

    // A roster missing bo: one line for him, exit 1, and no file.
    const std::string short_roster = c.dir.write("short.csv", "submission,email\nann,zoe@uni.example\n").string();
    const ProcessResult missing = run({"--lms", "moodle", "--roster", short_roster, "--to", c.dir.path("m.csv").string(), out});
    INFO(missing.output);
    CHECK(missing.exit_code == 1);
    CHECK(missing.output.find("gsv-grade export: 'bo' (29/29) is in the batch but not in " + short_roster + ": left out\n") !=
          std::string::npos);
    CHECK(missing.output.find("1 problem: nothing written to " + c.dir.path("m.csv").string() + "; --allow-partial writes it") !=
          std::string::npos);
    CHECK_FALSE(fs::exists(c.dir.path("m.csv")));
    const ProcessResult partial =
        run({"--lms", "moodle", "--roster", short_roster, "--to", c.dir.path("m.csv").string(), "--allow-partial", out});
    CHECK(partial.exit_code == 0);
    CHECK(test::read_text(c.dir.path("m.csv")).rfind("Email address,total,total (Feedback),lab01,", 0) == 0);

    // Bad input: one line naming the option, file or value, exit 2.
    const auto refused = [&](const std::vector<std::string>& args, const std::string& line) {
        const ProcessResult r = run(args);
        INFO(r.output);
        CHECK(r.exit_code == 2);
        CHECK(r.output == "gsv-grade export: " + line + "\n");
    };
    refused({"--lms", "sakai", "--roster", roster, out}, "--lms takes canvas, moodle or blackboard, got 'sakai'");
    refused({"--lms", "canvas", "--roster", roster, "--colour", out}, "unknown option '--colour' (gsv-grade export --help lists them)");
    refused({"--lms", "canvas", out}, "needs --roster FILE (submission -> the LMS's student; gsv-grade export --help)");
    refused({"--lms", "canvas", "--roster", roster, c.dir.path("nowhere").string()},
            "'" + c.dir.path("nowhere").string() + "' holds no batch.json: not the --out of a gsv-grade --batch");
    c.dir.write("broken/batch.json", "{\"format\": \"gsv-batch 1\", \"seed\": ");
    const ProcessResult broken = run({"--lms", "canvas", "--roster", roster, c.dir.path("broken").string()});
    CHECK(broken.exit_code == 2);
    CHECK(broken.output.find(c.dir.path("broken/batch.json").string()) != std::string::npos);
    CHECK(test::count_of(broken.output, "\n") == 1);
    const ProcessResult help = run({"--help"});
    CHECK(help.exit_code == 0);
    CHECK(help.output.rfind("usage: gsv-grade export --lms canvas|moodle|blackboard --roster FILE", 0) == 0);
}
