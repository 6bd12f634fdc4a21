#pragma once
// A lab compiled only where its C++ is one already built (grader/submission.h says the rules): its build inputs read
// and compared byte for byte, the kit's own binary, and a cache of earlier builds that keeps the inputs it was built
// from beside each binary, so a hit is proved by comparing them, never by a hash alone. Either way the reuse is proved
// on every file the compiler read, as its dependency records say (ninja's deps log, or the .o.d files CMake keeps with
// a Makefile generator): a `.txt` or `.json` a C++ file includes is as much the build's input as a header.
#include "common/app/lab_sources.h"

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gsv {

// A value of a CMake build's CMakeCache.txt ("GSV_LAB_DIR_lab01" -> "lab01_gooch"); "" when it has none.
std::string cmake_cache_value(const std::filesystem::path& build_dir, const std::string& name);

// A lab folder's build inputs: each file's path relative to the folder, and its bytes.
using BuildInputs = std::map<std::string, std::string>;

// Which files are build inputs: common/app/lab_sources.h (is_build_input). A file of the other kinds that the compiler
// does read (an #include of a .txt) is found in the build's dependency records (BuildReads) and proved like the inputs.
// Throws gsv::Error naming a file it cannot read. Plain files only (the submission's copy holds nothing else).
BuildInputs read_build_inputs(const std::filesystem::path& lab_folder);
// The names of every file in the folder, whatever its kind: what `__has_include` can ask about.
std::vector<std::string> file_names(const std::filesystem::path& lab_folder);
// Whether `binary` was built after the newest of `lab_folder`'s build inputs was last written.
bool binary_is_newer(const std::filesystem::path& binary, const std::filesystem::path& lab_folder);

// Every file a target's compilation read, from the build folder's dependency records.
struct BuildReads {
    bool complete = false;                    // every object of the target has a record, and none is stale
    std::string why_not;                      // when not complete
    std::vector<std::filesystem::path> files;  // absolute and normal, each once
};
// Runs a command and gives its standard output, or none when it failed (a sandboxed process, for a student's build).
using CommandRunner = std::function<std::optional<std::string>(const std::vector<std::string>&)>;
// The records of `target`'s objects in `build_dir` (a CMake build: its generator and make program from its
// CMakeCache.txt). `objects`, when given, names the target's objects (ninja answers for those alone, quickly);
// otherwise every record is read and the target's kept.
BuildReads build_reads(const std::filesystem::path& build_dir, const std::string& target, const CommandRunner& run,
                       const std::vector<std::string>& objects = {});

// What a build read: the files in its lab folder by their path there (their bytes kept, since a student's file is
// proved by its bytes), the others (the kit's headers, the system's) by their absolute path and a fingerprint. Files
// under `ignored` (the build folder's own generated files) are left out.
struct ReadFiles {
    std::map<std::string, std::string> in_lab;     // relative path -> bytes
    std::map<std::string, std::string> elsewhere;  // absolute path -> fingerprint
};
ReadFiles read_files(const BuildReads& reads, const std::filesystem::path& lab_folder, const std::filesystem::path& ignored);

// Earlier builds by their inputs and the kit build they linked against. Every fault (a folder that cannot be made or
// written, a full disk, a damaged entry) is one line in `note` and a miss; a damaged entry is removed.
class BuildCache {
public:
    BuildCache(std::filesystem::path folder, const std::filesystem::path& kit_build);
    // Copies the binary built from exactly these inputs to `to`, where every file that build read is as it was then
    // (in `lab_folder` by its bytes, elsewhere by its fingerprint); false when there is none, or one of them changed.
    bool fetch(const std::string& lab, const std::filesystem::path& lab_folder, const std::filesystem::path& to,
               std::string& note) const;
    // Keeps `binary` as built from the lab folder's inputs, with what its build read (atomically: a half-written
    // entry is never seen; an entry whose reads changed is replaced).
    void store(const std::string& lab, const std::filesystem::path& lab_folder, const ReadFiles& reads,
               const std::filesystem::path& binary, std::string& note) const;

private:
    std::filesystem::path entry(const std::string& lab, const BuildInputs& inputs, const std::vector<std::string>& names) const;
    std::filesystem::path folder_;
    std::string kit_stamp_;  // the kit build's libraries (path, size, time) and its build settings
};

}  // namespace gsv
