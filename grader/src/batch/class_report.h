#pragma once
// The class by its mistakes (issue 40): from every graded submission's report.json in a batch's --out, a class report
// (class-report.html, class-mistakes.csv): per TODO and per case the share of the class that passed; per known mistake
// how many students made it, who, and its picture; the failures no known mistake explains, clustered by picture (the
// students whose pictures of a case match each other under the case's tolerance), which is the instructor's queue of new
// mistakes; and a skeleton entry for tests/mutants/<lab>.json for any cluster.
#include "grader/src/batch/batch.h"

#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

struct ClassCluster {
    std::string id;                     // "lab01/gooch/1": lab, case and its number among that case's clusters
    std::string lab, case_name, todo;
    std::vector<std::string> students;  // in class order; the first one's picture stands for the cluster
    std::string picture;                // relative to the batch's --out
};

struct ClassMistake {
    std::string lab, todo, says, name;  // name: the kit's own (the instructor's)
    std::vector<std::string> students;
    std::string picture;                // one student's case it explained: the mistake's picture, relative to --out
};

struct ClassReport {
    int students = 0;  // graded submissions
    struct Share {
        std::string lab, key;  // a TODO id or a case name
        int passed = 0, graded = 0;
    };
    std::vector<Share> todos, cases;
    std::vector<ClassMistake> mistakes;
    std::vector<ClassCluster> unexplained;
};

// Reads the graded entries' reports under `out_dir`. A report that cannot be read is skipped, named in `problems`.
ClassReport class_report(const std::filesystem::path& out_dir, const std::vector<BatchEntry>& entries, std::string* problems = nullptr);
std::string class_mistakes_csv(const ClassReport& report);
std::string class_report_html(const ClassReport& report, const std::filesystem::path& out_dir);
// Writes class-report.html and class-mistakes.csv into `out_dir`.
void write_class_report(const std::filesystem::path& out_dir, const std::vector<BatchEntry>& entries);
// A skeleton entry of tests/mutants/<lab>.json for cluster `id` of the batch in `out_dir`, for the instructor to fill in
// (the edit, the text); throws gsv::Error naming the id where the batch has no such cluster.
std::string mistake_skeleton(const std::filesystem::path& out_dir, const std::string& id);

}  // namespace gsv
