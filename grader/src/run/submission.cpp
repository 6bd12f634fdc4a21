#include "grader/src/run/submission.h"

#include "common/app/kit_layout.h"
#include "common/core/error.h"
#include "common/io/folder_tree.h"

#include <fstream>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace gsv {
namespace {

// Plain content only, copied (never linked): a symlink or a hard link could lead to the reference solution, a
// device or FIFO could block the grader, a huge file fill its disk. Returns a line for each thing refused.
std::vector<std::string> copy_plain_tree(const fs::path& from, const fs::path& to) {
    std::vector<std::string> refused;
    fs::create_directories(to);
    std::uintmax_t entries = 0, bytes = 0;
    for (auto it = fs::recursive_directory_iterator(from); it != fs::recursive_directory_iterator(); ++it) {
        if (++entries > kMaxSubmissionEntries) {
            refused.push_back("labs/: more than " + std::to_string(kMaxSubmissionEntries) + " files and folders; the rest is not taken");
            break;
        }
        const fs::path relative = it->path().lexically_relative(from);  // fs::relative would follow a link
        const fs::path target = to / relative;
        const fs::file_status status = it->symlink_status();
        const std::string name = "labs/" + relative.generic_string();
        if (fs::is_symlink(status)) {
            refused.push_back(name + ": a symbolic link");
        } else if (fs::is_directory(status)) {
            fs::create_directories(target);
        } else if (!fs::is_regular_file(status)) {
            refused.push_back(name + ": not a plain file (a device, FIFO or socket)");
        } else if (fs::hard_link_count(it->path()) > 1) {
            refused.push_back(name + ": a hard link (" + std::to_string(fs::hard_link_count(it->path())) + " names)");
        } else if (fs::file_size(it->path()) > kMaxSubmissionFileBytes) {
            refused.push_back(name + ": " + std::to_string(fs::file_size(it->path())) + " bytes, over the " +
                              std::to_string(kMaxSubmissionFileBytes >> 20) + " MiB a file may have");
        } else if ((bytes += fs::file_size(it->path())) > kMaxSubmissionBytes) {
            refused.push_back(name + ": over the " + std::to_string(kMaxSubmissionBytes >> 20) + " MiB a submission's labs/ may hold in all");
        } else {
            fs::copy_file(it->path(), target, fs::copy_options::overwrite_existing);
        }
    }
    return refused;
}

std::string cmake_generator(const fs::path& kit_build) {
    std::ifstream cache(kit_build / "CMakeCache.txt");
    for (std::string line; std::getline(cache, line);)
        if (line.rfind("CMAKE_GENERATOR:INTERNAL=", 0) == 0) return line.substr(line.find('=') + 1);
    return "";
}

}  // namespace

SubmissionBuild build_submission(const fs::path& submission, const fs::path& kit_root, const fs::path& kit_build,
                                 const std::vector<std::string>& labs, const fs::path& work_dir,
                                 const ProcessLimits& limits) {
    const fs::path labs_dir = fs::is_directory(submission / "labs") ? submission / "labs" : submission;
    if (!fs::is_directory(labs_dir) || labs_dir.filename() != "labs")
        throw Error("submission '" + submission.string() + "' has no labs/ folder");
    if (!fs::exists(kit_build / "gsv-targets.cmake"))
        throw Error("'" + kit_build.string() + "' is not a configured kit build (no gsv-targets.cmake): build the kit first");
    SubmissionBuild result;
    result.root = work_dir / "kit";
    result.bin_dir = work_dir / "build" / "bin";
    remove_folder(work_dir);
    const std::vector<std::string> refused = copy_plain_tree(labs_dir, KitLayout{result.root}.labs());
    const KitLayout kit{fs::absolute(kit_root)}, copy{result.root};
    fs::create_directory_symlink(kit.shaders(), copy.shaders());
    fs::create_directory_symlink(kit.data(), copy.data());
    fs::create_directories(work_dir / "build");
    // Only the build folder becomes the sandbox user's: the copy of labs/ stays the grader's, read-only to builds and labs.
    if (limits.support && limits.sandbox) hand_over(work_dir / "build", *limits.sandbox, *limits.support);

    std::vector<std::string> configure{GSV_CMAKE_COMMAND, "-S", kit.submission_project().string(),
                                       "-B", (work_dir / "build").string(), "-DGSV_KIT_BUILD=" + fs::absolute(kit_build).string(),
                                       "-DGSV_LABS_ROOT=" + result.root.string()};
    if (const std::string generator = cmake_generator(kit_build); !generator.empty()) {
        configure.push_back("-G");
        configure.push_back(generator);
    }
    const ProcessResult configured = run_process(configure, work_dir / "build", limits);
    for (const auto& lab : labs) {
        LabBuild build;
        build.lab = lab;
        if (configured.exit_code != 0) {
            build.log = "configuring the submission's build failed:\n" + configured.output;
        } else {
            const ProcessResult made = run_process({GSV_CMAKE_COMMAND, "--build", (work_dir / "build").string(), "--target", lab},
                                                   work_dir / "build", limits);
            build.seconds = made.seconds;
            build.ok = made.exit_code == 0 && fs::exists(result.bin_dir / lab);
            build.log = made.output;
            if (made.timed_out) build.log += "\nthe build was killed after the time limit";
            if (!build.ok && made.output.find("unknown target") != std::string::npos)
                build.log = "the submission has no sources for " + lab + " (labs/<lab folder>/*.cpp)\n" + made.output;
        }
        for (const auto& line : refused) build.log += "\nnot taken from the submission: " + line;
        result.builds.push_back(std::move(build));
    }
    return result;
}

}  // namespace gsv
