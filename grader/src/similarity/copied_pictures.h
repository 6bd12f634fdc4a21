#pragma once
// Copied work by its pictures, which no token matcher sees: two students who hand in the same rare wrong picture. From
// a batch's --out: each failing case's picture (a wrong image no known mistake explains, as the diagnosis recorded it
// in report.json) grouped by its pixels; a picture exactly two students of the class drew, pixel for pixel, is listed
// as their pair. Pixels, not PNG bytes: the same pixels are the same picture whichever zlib of whichever shard's
// machine wrote them. Exactly two: a picture three or more drew is a mistake the class makes, which the class report
// clusters (class_report.h); a copy of a correct picture is no evidence (it is the golden's).
#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

struct PicturePair {
    std::string lab, case_name, todo, a, b;  // a before b in the class's order
    std::string picture;                     // a's, relative to the batch's --out
    std::string expected;                    // the picture a's failed against, likewise; empty where none was kept
    // Whether the diagnosis looked for known mistakes on this case in both reports (--diagnose all, or public and a
    // public case): where it did not, the picture may still be a known mistake's.
    bool mistakes_looked_for = true;
};

struct CopiedPictures {
    bool batch_found = false;  // the folder holds a batch's batch.json
    int students = 0;          // graded submissions whose report.json was read
    int wrong_pictures = 0;    // failing pictures no known mistake explains, all students
    std::vector<PicturePair> pairs;
    std::vector<std::string> notes;  // reports or pictures that could not be read
};

// Reads <out_dir>/batch.json and each graded student's report.json and pictures. A folder without a batch.json gives
// batch_found false and no pairs (the code can be compared before grading).
CopiedPictures find_copied_pictures(const std::filesystem::path& out_dir);

}  // namespace gsv
