#pragma once
// Output folders checked before long work starts: a sweep, an animation or a class's grading that can
// not write its results should say so in its first second, not after its last frame.
#include <filesystem>
#include <string>

namespace gsv {

// Creates `folder` where it is missing and proves it writable by creating and removing a file in it.
// Throws gsv::Error, one line naming `option` (what the user typed it as: "--out-dir") and the folder.
void prepare_output_folder(const std::filesystem::path& folder, const std::string& option);
// The same for the folder a file will be written into (the current folder for a bare name).
void prepare_output_file(const std::filesystem::path& file, const std::string& option);

}  // namespace gsv
