#pragma once
// Where things are in a copy of the kit: the one place its folder names are spelled. The framework finds shaders,
// data and case files by it; the grader its golden images, hidden cases and what student code must not see.
#include <filesystem>
#include <string>

namespace gsv {

struct KitLayout {
    std::filesystem::path root;

    std::filesystem::path shaders() const { return root / "shaders"; }
    std::filesystem::path data() const { return root / "data"; }
    std::filesystem::path labs() const { return root / "labs"; }
    std::filesystem::path solutions() const { return root / "solutions"; }
    // Beside a lab's code, what the kit's lists need to know of it (cmake/lab_list.cmake): read by the build and the
    // scripts, never by the lab.
    static constexpr const char* kLabDescription = "lab.json";
    std::filesystem::path tests() const { return root / "tests"; }
    // Public cases (shipped to students): a lab's named cases, graded ones and demos.
    std::filesystem::path case_dir() const { return root / "grader" / "cases"; }
    std::filesystem::path case_file(const std::string& lab) const { return case_dir() / (lab + ".json"); }
    // Hidden cases (instructors only), drawn from the seed at grading time.
    std::filesystem::path hidden_dir() const { return root / "grader" / "hidden"; }
    std::filesystem::path hidden_case_file(const std::string& lab) const { return hidden_dir() / (lab + ".json"); }
    // Golden images and arrays: what the solutions render, committed.
    std::filesystem::path golden_dir() const { return root / "grader" / "golden"; }
    std::filesystem::path golden_dir(const std::string& lab) const { return golden_dir() / lab; }
    std::filesystem::path golden_image(const std::string& lab, const std::string& case_name) const {
        return golden_dir(lab) / (case_name + ".png");
    }
    // Which GL renderer (GL_RENDERER) each lab's goldens were rendered on, written with them.
    std::filesystem::path golden_renderers() const { return golden_dir() / "renderer.json"; }
    // The CMake project the grader builds a submission's labs with.
    std::filesystem::path submission_project() const { return root / "grader" / "submission"; }
};

}  // namespace gsv
