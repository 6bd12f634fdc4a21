#pragma once
// Kits and submissions made from the reference solution with edits (tests/mutants/<lab>.json), and
// grading them the way an instructor would.
#include "catch.hpp"
#include "gl_fixture.h"
#include "lab_runner.h"
#include "test_support.h"

#include "common/io/json.h"
#include "grader/src/grade/grade.h"

#include <algorithm>
#include <functional>
#include <fstream>
#include <map>

namespace gsv::test {

// Labs with a tests/mutants/<lab>.json, in order.
inline std::vector<std::string> labs_with_mutants() {
    std::vector<std::string> labs;
    for (const auto& e : std::filesystem::directory_iterator(source_root() / "tests" / "mutants"))
        if (e.path().extension() == ".json") labs.push_back(e.path().stem().string());
    std::sort(labs.begin(), labs.end());
    return labs;
}

inline Json mutant_spec(const std::string& lab) { return read_json_file(source_root() / "tests" / "mutants" / (lab + ".json")); }

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
inline void apply_edits(const std::filesystem::path& lab_folder, const Json& edit) {
    const std::filesystem::path file = lab_folder / edit.string_at("file");
    std::string text = read_text(file);
    auto one = [&](const Json& e) {
        const std::string find = e.string_at("find");
        const auto at = text.find(find);
        if (at == std::string::npos) FAIL("'" << find << "' not found in " << file);
        std::string replace = e.string_at("replace");
        for (auto kit = replace.find("@KIT@"); kit != std::string::npos; kit = replace.find("@KIT@"))
            replace.replace(kit, 5, source_root().string());
        text.replace(at, find.size(), replace);
    };
    if (const Json* edits = edit.find("edits")) {
        for (const Json& e : edits->as_array()) one(e);
    } else {
        one(edit);
    }
    std::ofstream(file, std::ios::binary) << text;
}

inline GradeOptions instructor_options(const std::string& lab, const std::filesystem::path& out) {
    GradeOptions options;
    options.kit_root = source_root();
    options.bin_dir = bin_dir();
    options.out_dir = out;
    options.labs = {lab};
    options.seed = 20261122;
    // These tests check grading, not the walls (test_grader_attacks.cpp does): they run where unshare is refused.
    options.allow_readable_kit = true;
    return options;
}

// A kit whose solutions/<lab_dir> has edits, and a copy of the built <lab>_solution to run it as the
// student's <lab>: so shader edits need no build, and labs with C++ TODOs run the solution's C++. The
// reference reads the untouched solution in the source tree.
class EditedKit {
public:
    EditedKit(const std::string& lab, const std::string& lab_dir, const Json& edit) : EditedKit(lab, lab_dir, [&](const std::filesystem::path& folder) {
        // Only shader edits: the solution's binary is copied, not rebuilt, so a C++ edit would change nothing
        // and its mutant would "pass". C++ faults go through a Submission, which the grader builds.
        const std::string file = edit.string_or("file", "");
        if (file.size() > 4 && (file.substr(file.size() - 4) == ".cpp" || file.substr(file.size() - 2) == ".h"))
            throw Error("mutant '" + edit.string_at("name") + "' edits " + file +
                        ": C++ is not rebuilt for mutants; plant C++ faults in a submission");
        apply_edits(folder, edit);
    }) {}
    // `edit` changes the copy of solutions/<lab_dir> (shaders only: the binary is the solution's).
    EditedKit(const std::string& lab, const std::string& lab_dir, const std::function<void(const std::filesystem::path&)>& edit)
        : lab_(lab) {
        const auto root = dir_.path("kit");
        std::filesystem::create_directories(root / "solutions");
        // The public files are the kit's own, linked (the sandbox binds what they lead to).
        std::filesystem::create_directory_symlink(source_root() / "shaders", root / "shaders");
        std::filesystem::create_directory_symlink(source_root() / "data", root / "data");
        std::filesystem::copy(source_root() / "solutions" / lab_dir, root / "solutions" / lab_dir, std::filesystem::copy_options::recursive);
        edit(root / "solutions" / lab_dir);
        std::filesystem::create_directories(dir_.path("bin"));
        std::filesystem::copy_file(bin_dir() / (lab + "_solution"), dir_.path("bin") / lab);
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

inline std::map<std::string, CaseResult> by_name(const GradeReport& report, const std::string& kind = "image") {
    std::map<std::string, CaseResult> results;
    for (const auto& r : report.results)
        if (r.kind == kind) results[r.name] = r;
    return results;
}

}  // namespace gsv::test
