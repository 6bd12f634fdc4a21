#pragma once
// A lab's grading cases, declared as data in grader/cases/<lab>.json.
#include "common/image_compare.h"

#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

struct GradeCase {
    std::string name, todo, description, visibility = "public";
    double points = 1;
    std::vector<std::string> settings;  // name=value, as for --set
};

struct LabCases {
    std::string lab;
    int width = 256, height = 256;
    ImageTolerance live_tolerance;    // against the reference rendered in the same run, same machine
    ImageTolerance golden_tolerance;  // against committed golden images: another GPU and driver
    double timeout_s = 60;
    std::vector<GradeCase> cases;
};

// Throws gsv::Error naming the file, the member and what is wrong.
LabCases load_lab_cases(const std::filesystem::path& file);
std::vector<std::filesystem::path> case_files(const std::filesystem::path& kit_root);

}  // namespace gsv
