#include "grader/src/run/submission.h"

#include "grader/src/run/build_reuse.h"
#include "common/app/kit_layout.h"
#include "common/core/error.h"
#include "common/io/folder_tree.h"

#include <chrono>
#include <fstream>
#include <optional>
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

// A value from the kit build's CMakeCache.txt ("" where it has none): the generator, each lab's folder.

// The binary of a lab whose C++ is one already built (grader/submission.h): the kit's own, or the build cache's.
// Fills build.origin and returns true when `to` holds it; a lab that must be built returns false.
bool reuse_build(const std::string& lab, const fs::path& submission_lab, const fs::path& kit_root, const fs::path& kit_build,
                 const BuildCache* cache, const fs::path& to, LabBuild& build) {
    const std::string folder = cmake_cache_value(kit_build, "GSV_LAB_DIR_" + lab);
    if (folder.empty()) return false;
    const BuildInputs inputs = read_build_inputs(submission_lab);
    if (inputs.empty()) return false;  // no sources: the build says so
    const fs::path kit_lab = KitLayout{kit_root}.labs() / folder, kit_binary = kit_build / "bin" / lab;
    // The kit's binary was built from the kit build's own sources: those must be the kit graded with.
    const fs::path built_from = cmake_cache_value(kit_build, "CMAKE_HOME_DIRECTORY");
    std::error_code ec;
    const bool same_kit = !built_from.empty() && fs::equivalent(built_from, kit_root, ec);
    if (same_kit && fs::exists(kit_binary) && binary_is_newer(kit_binary, kit_lab) && read_build_inputs(kit_lab) == inputs) {
        fs::copy_file(kit_binary, to, fs::copy_options::overwrite_existing);
        build.origin = "unchanged C++: the kit's binary";
        return true;
    }
    if (cache && cache->fetch(lab, inputs, to, build.log)) {
        build.origin = "unchanged C++: an earlier build";
        return true;
    }
    return false;
}

}  // namespace

std::string cmake_cache_value(const fs::path& kit_build, const std::string& name) {
    std::ifstream cache(kit_build / "CMakeCache.txt");
    const std::string key = name + ":";
    for (std::string line; std::getline(cache, line);)
        if (line.rfind(key, 0) == 0 && line.find('=') != std::string::npos) return line.substr(line.find('=') + 1);
    return "";
}

SubmissionBuild build_submission(const fs::path& submission, const fs::path& kit_root, const fs::path& kit_build,
                                 const std::vector<std::string>& labs, const fs::path& work_dir,
                                 const ProcessLimits& limits, bool reuse, const fs::path& cache_dir) {
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
    if (const std::string generator = cmake_cache_value(kit_build, "CMAKE_GENERATOR"); !generator.empty()) {
        configure.push_back("-G");
        configure.push_back(generator);
    }
    // The binaries' folder, made here for those reused and handed over like the build folder for those built.
    fs::create_directories(result.bin_dir);
    if (limits.support && limits.sandbox) hand_over(result.bin_dir, *limits.sandbox, *limits.support);
    std::optional<BuildCache> cache;
    std::string cache_note;
    if (reuse) {
        try {
            cache.emplace(cache_dir.empty() ? fs::absolute(kit_build) / "grader-cache" / "builds" : fs::absolute(cache_dir),
                          kit_build);
        } catch (const std::exception& e) {
            cache_note = std::string("\nbuild cache: ") + e.what() + "; every lab is built";
        }
    }
    std::optional<ProcessResult> configured;  // configured for the first lab that needs building
    for (const auto& lab : labs) {
        LabBuild build;
        build.lab = lab;
        build.log = cache_note;
        const fs::path binary = result.bin_dir / lab;
        const std::string folder = cmake_cache_value(kit_build, "GSV_LAB_DIR_" + lab);
        const fs::path submission_lab = KitLayout{result.root}.labs() / folder;
        const auto started = std::chrono::steady_clock::now();
        if (reuse && !folder.empty() && reuse_build(lab, submission_lab, kit_root, kit_build, cache ? &*cache : nullptr, binary, build)) {
            build.ok = true;
            build.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
            for (const auto& line : refused) build.log += "\nnot taken from the submission: " + line;
            result.builds.push_back(std::move(build));
            continue;
        }
        if (!configured) configured = run_process(configure, work_dir / "build", limits);
        if (configured->exit_code != 0) {
            build.log = "configuring the submission's build failed:\n" + configured->output + build.log;
        } else {
            const ProcessResult made = run_process({GSV_CMAKE_COMMAND, "--build", (work_dir / "build").string(), "--target", lab},
                                                   work_dir / "build", limits);
            build.seconds = made.seconds;
            build.ok = made.exit_code == 0 && fs::exists(binary);
            build.log = made.output + build.log;
            if (reuse && build.ok && cache && !folder.empty()) cache->store(lab, read_build_inputs(submission_lab), binary, build.log);
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
