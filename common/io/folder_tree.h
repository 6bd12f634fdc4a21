#pragma once
// Folders a student's process wrote into, seen from outside: how much it left, and removing all of it whatever
// it made (deep trees, folders without permissions, links, FIFOs). Nothing here follows a link, and nothing
// walks by path: a tree deeper than PATH_MAX is removed as well as a flat one. (POSIX; elsewhere std::filesystem.)
#include <cstdint>
#include <filesystem>

namespace gsv {

struct FolderUse {
    std::uint64_t bytes = 0;  // allocated, as du counts
    std::uint64_t files = 0;  // entries of every kind, folders included
    bool too_deep = false;    // folders nested deeper than measure_folder looks (counted as far as it looked)
};

// Folders nested deeper than this are not looked into by measure_folder (each level holds a descriptor).
inline constexpr int kMeasuredDepth = 200;

// What `folder` holds now. Throws gsv::Error when it cannot be read.
FolderUse measure_folder(const std::filesystem::path& folder);

// Removes `folder` and everything in it, and returns what that was (the folder itself included); a missing folder
// is already removed. Throws
// gsv::Error naming what could not be removed and why: a folder left on the grader's disk is never silent.
FolderUse remove_folder(const std::filesystem::path& folder);

}  // namespace gsv
