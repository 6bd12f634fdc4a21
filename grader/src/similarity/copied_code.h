#pragma once
// Copied code in a class, the template subtracted (issue 42 item 3). In this kit correct work converges: answers are
// a few lines, the reference's answer is the obvious one, and a later lab's starter holds an earlier lab's answer
// (lab 03's lic_time.frag holds lab 02's). So each student's files are first stripped of whatever SIM (sim_tool.h)
// finds of the template in them: the lab's starter, its reference answers, every lab's starter and the kit's shared
// shaders. What is left is the student's own code, less what much of the class shares (kCommonPartners); only that is
// compared between students, file by file of the same name, and a pair's share is how much of the smaller own code the
// other has too. Two students who both wrote the
// reference's answer have no own code in common; a copy has all of it.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace gsv {

// The shortest run of tokens that counts, both as the template's and as shared own code. The same length for both,
// so what is left of the template where a student edited inside it (each piece shorter than a run, or it would have
// been subtracted) never makes a shared run on its own. 20: on a made-up class of every lab's reference with the
// kit's correct variants (tests/mutants/), 12 to 24 all found exactly the planted copies; shorter runs take more of the
// students' own answers for the template's (every identifier is one token, so short shapes recur), longer ones leave
// more of the template in.
inline constexpr int kMinRun = 20;
// A pair whose shared own code is at least this share of the smaller own code is marked "likely copied".
inline constexpr double kLikelyCopiedShare = 0.5;
// Own code in runs with this many other students or more is the class's common code (an alternative many found, or
// a hint given in class), subtracted like the template: MOSS's default for a passage that appears too often (-m 10).
// Without it, a class of 200 made of the reference and the kit's variants at random gave 74,785 pairs.
inline constexpr int kCommonPartners = 10;

// The files compared: GLSL of every extension the kit uses or a GLSL tool knows (.glsl .vert .frag .geom .comp .tesc
// .tese), read as C; C++ (.cpp .h .hpp), read as C++. Lab 06's .network files and the READMEs are not code.
bool is_glsl_file(const std::string& name);
bool is_compared_file(const std::string& name);

// The kit's labs: (lab, folder) for each labs/labNN_* folder, in order.
std::vector<std::pair<std::string, std::string>> kit_labs(const std::filesystem::path& kit_root);
// The template a lab's files are stripped of: labs/<lab_dir> (the starter), solutions/<lab_dir> (the reference
// answers: SIM skips comments, so its //@starter lines are no tokens), every other lab's starter, and shaders/.
std::vector<std::filesystem::path> template_files(const std::filesystem::path& kit_root, const std::string& lab_dir);

// What a line of a student's file is to the comparison.
enum class LineKind {
    Own,       // the student's own code, compared
    Template,  // in a run the template holds too
    Common,    // own code kCommonPartners or more other students share
};

struct CodeFile {
    std::vector<std::string> lines;  // the student's text
    std::vector<LineKind> kinds;     // per line
    int own_tokens = 0;              // tokens left with the template's and the common lines blanked
};

// A run of own code two students share, in their files of the same name (lines 1-based, inclusive).
struct SharedRun {
    std::string file;
    int a_first = 0, a_last = 0, b_first = 0, b_last = 0;
    int tokens = 0;
};

struct CodePair {
    std::string lab, a, b;  // a before b in the class's order
    int shared_tokens = 0, own_a = 0, own_b = 0;
    double share = 0;       // shared_tokens over the smaller of own_a and own_b, at most 1
    std::vector<SharedRun> runs;
    // Every file the two changed from the template is the same, byte for byte, and no more than kCommonPartners others
    // changed theirs the same way: a copy even where the edits are too short for a run (a reference-like submission
    // with one slip, handed in twice). Share 1.
    bool identical_edits = false;
    bool likely_copied() const { return share >= kLikelyCopiedShare; }
};

struct LabCode {
    std::string lab, lab_dir;
    int students = 0;  // with a folder for the lab
    // student -> file name -> its text and template lines: the students of some pair only (for the side-by-side view).
    std::map<std::string, std::map<std::string, CodeFile>> files;
    std::map<std::string, int> own_tokens;  // every student's own tokens in the lab
    std::vector<CodePair> pairs;            // most shared first
    std::vector<std::string> notes;         // files left out, and why
};

struct CopiedCodeOptions {
    std::filesystem::path kit_root;
    std::filesystem::path submissions;  // one folder per student, each a copy of the kit with its labs/
    std::vector<std::string> labs;      // lab ids; empty: every lab of the kit
    int min_run = kMinRun;
};

// Throws gsv::Error (one line) for a folder that is not there, a lab the kit has not got, or SIM missing or failing.
std::vector<LabCode> find_copied_code(const CopiedCodeOptions& options);

}  // namespace gsv
