#pragma once
// Kits and submissions made from the reference solution with edits (tests/mutants/<lab>.json), and
// grading them the way an instructor would.
#include "catch.hpp"
#include "gl_fixture.h"
#include "lab_runner.h"
#include "test_support.h"

#include "common/io/json.h"
#include "grader/src/grade/grade.h"
#include "grader/src/diagnose/mutant_kit.h"
#include "tools/starter.h"

#include <algorithm>
#include <functional>
#include <fstream>
#include <map>
#include <sstream>

namespace gsv::test {

// Labs with a tests/mutants/<lab>.json, in order.
inline std::vector<std::string> labs_with_mutants() { return gsv::labs_with_mutants(source_root()); }

inline Json mutant_spec(const std::string& lab) { return read_mutant_spec(source_root(), lab); }

// A submission (in a fresh temp folder named after `name`) whose labs/ hold the lab's reference solution, for the
// grader to build like any student's.
inline std::filesystem::path solution_submission(const std::string& lab, const std::string& name) {
    const std::string lab_dir = mutant_spec(lab).string_at("lab_dir");
    const auto submission = temp_dir(name);
    std::filesystem::create_directories(submission / "labs");
    std::filesystem::copy(source_root() / "solutions" / lab_dir, submission / "labs" / lab_dir, std::filesystem::copy_options::recursive);
    return submission;
}

// Applies one {find, replace} edit (or each of "edits") to the file named by `edit`'s "file".
// Every TODO id of a lab's reference (solutions/<lab_dir>), with the files that hold its blocks.
inline std::map<std::string, std::vector<std::string>> todo_files(const std::string& lab_dir) {
    std::map<std::string, std::vector<std::string>> files;
    for (const auto& e : std::filesystem::directory_iterator(source_root() / "solutions" / lab_dir)) {
        const std::string name = e.path().filename().string();
        for (const auto& id : make_starter(read_text(e.path()), name).todo_ids) files[id].push_back(name);
    }
    return files;
}

inline void apply_edits(const std::filesystem::path& lab_folder, const Json& edit) { apply_mutant_edits(lab_folder, edit, source_root()); }

inline GradeOptions instructor_options(const std::string& lab, const std::filesystem::path& out) {
    GradeOptions options;
    options.kit_root = source_root();
    options.bin_dir = bin_dir();
    options.out_dir = out;
    options.labs = {lab};
    options.seed = 20261122;
    // These tests check grading, not the walls (test_grader_attacks.cpp does): they run where unshare is refused.
    options.allow_readable_kit = true;
    // Nor the diagnosis, which has tests of its own (test_grader_diagnosis*.cpp, the mutation and held-out tests turn it
    // on): each failing case would render every known mistake of its lab.
    options.diagnose = DiagnoseCases::Off;
    return options;
}

// A kit whose solutions/<lab_dir> has edits, and a copy of the built <lab>_solution to run it as the
// student's <lab>: so shader edits need no build, and labs with C++ TODOs run the solution's C++. The
// reference reads the untouched solution in the source tree.
class EditedKit {
public:
    EditedKit(const std::string& lab, const std::string& lab_dir, const Json& edit) : lab_(lab) {
        make_edited_kit(dir_.path(), source_root(), bin_dir(), lab, lab_dir, edit);
    }
    // `edit` changes the copy of solutions/<lab_dir> (shaders only: the binary is the solution's).
    EditedKit(const std::string& lab, const std::string& lab_dir, const std::function<void(const std::filesystem::path&)>& edit)
        : lab_(lab) {
        make_edited_kit(dir_.path(), source_root(), bin_dir(), lab, lab_dir, edit);
    }
    std::filesystem::path out() const { return dir_.path("out"); }

    GradeOptions options() const {
        GradeOptions options = instructor_options(lab_, out());
        options.student_bin_dir = dir_.path("bin");
        options.student_root = dir_.path("kit");
        return options;
    }

private:
    std::string lab_;
    TempDir dir_;
};

// A submission: a folder whose labs/<lab_dir> is the solution with edits, and extra files copied in.
class Submission {
public:
    Submission(const std::string& lab_dir, const Json* edit) {
        const auto folder = dir_.path("submission/labs") / lab_dir;
        std::filesystem::create_directories(folder.parent_path());
        std::filesystem::copy(source_root() / "solutions" / lab_dir, folder, std::filesystem::copy_options::recursive);
        if (!edit) return;
        apply_edits(folder, *edit);
        if (const Json* files = edit->find("copy_files"))
            for (const auto& [name, from] : files->as_object())
                std::filesystem::copy_file(source_root() / from.as_string(), folder / name);
    }
    std::filesystem::path path() const { return dir_.path("submission"); }
    std::filesystem::path out() const { return dir_.path("out"); }

private:
    TempDir dir_;
};

// A submission at `submission` whose labs/<lab_dir> is the reference with every C++ TODO block switched at run time
// (gsv::write_switched_lab, tools/starter.h), for the grader to build once: the build graded as it is is the solution,
// and with GSV_KNOWN_MISTAKE set (the grader passes GSV_ variables on to student processes), each of the lab's C++
// mistakes and stateful variants.
inline void write_switched_cpp_submission(const std::filesystem::path& submission, const std::string& lab, const std::string& lab_dir) {
    write_switched_lab(source_root(), lab_dir, cpp_mistakes(source_root(), lab, true), submission / "labs" / lab_dir);
}

inline std::map<std::string, CaseResult> by_name(const GradeReport& report, const std::string& kind = "image") {
    std::map<std::string, CaseResult> results;
    for (const auto& r : report.results)
        if (r.kind == kind) results[r.name] = r;
    return results;
}

}  // namespace gsv::test
