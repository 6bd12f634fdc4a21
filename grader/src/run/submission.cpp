#include "grader/src/run/submission.h"

#include "grader/src/run/build_reuse.h"
#include "grader/src/run/kit_fault.h"
#include "common/app/kit_layout.h"
#include "common/core/error.h"
#include "common/io/folder_tree.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iterator>
#include <optional>
#include <regex>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace gsv {
namespace {

// A folder or file of the copy as the sandbox's uid must read it, whatever the student's modes were: a submission
// unpacked under umask 077 (files 0600, folders 0700) is graded as its contents. Executable where the student's file
// had any execute bit (a script a lab reads keeps its meaning), never writable by anyone but the grader.
constexpr fs::perms kFolderMode = fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read |
                                  fs::perms::others_exec;
constexpr fs::perms kFileMode = fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read;
constexpr fs::perms kAnyExec = fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec;

// The file's bytes into `to` (a new file of the grader's, mode kFileMode or 0755): nothing of the student's copy but
// its contents (no owner, times, extended attributes or ACLs). False, with a reason, when it cannot be read.
bool copy_contents(const fs::path& from, const fs::path& to, bool executable, std::string& why) {
    std::ifstream in(from, std::ios::binary);
    if (!in) {
        why = "cannot be read by the grader";
        return false;
    }
    {
        std::ofstream out(to, std::ios::binary | std::ios::trunc);
        out << in.rdbuf();
        if (!in.good() && !in.eof()) {
            why = "cannot be read by the grader";
            return false;
        }
        out.close();
        if (!out) throw Error("cannot write the copy '" + to.string() + "'");
    }
    fs::permissions(to, executable ? kFolderMode : kFileMode, fs::perm_options::replace);
    return true;
}

// Plain content only, copied (never linked): a symlink or a hard link could lead to the reference solution, a
// device or FIFO could block the grader, a huge file fill its disk. Folders and files of the copy get the modes
// above, whatever the student's were. Returns a line for each thing refused.
std::vector<std::string> copy_plain_tree(const fs::path& from, const fs::path& to) {
    std::vector<std::string> refused;
    fs::create_directories(to);
    fs::permissions(to, kFolderMode, fs::perm_options::replace);
    std::uintmax_t entries = 0, bytes = 0;
    std::error_code ec;
    auto it = fs::recursive_directory_iterator(from, ec);
    if (ec) {
        refused.push_back("labs/: cannot be listed by the grader (" + ec.message() + ")");
        return refused;
    }
    for (; it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (ec) {
            refused.push_back("labs/: a folder cannot be listed by the grader (" + ec.message() + "); the rest is not taken");
            break;
        }
        if (++entries > kMaxSubmissionEntries) {
            refused.push_back("labs/: more than " + std::to_string(kMaxSubmissionEntries) + " files and folders; the rest is not taken");
            break;
        }
        const fs::path relative = it->path().lexically_relative(from);  // fs::relative would follow a link
        const fs::path target = to / relative;
        const fs::file_status status = it->symlink_status();
        const std::string name = "labs/" + relative.generic_string();
        std::string why;
        if (fs::is_symlink(status)) {
            refused.push_back(name + ": a symbolic link");
        } else if (fs::is_directory(status)) {
            fs::create_directories(target);
            fs::permissions(target, kFolderMode, fs::perm_options::replace);
            // A folder the grader cannot enter (a non-root grader, mode 0000) is named, not followed into an error.
            std::error_code open_ec;
            fs::directory_iterator probe(it->path(), open_ec);
            if (open_ec) {
                refused.push_back(name + "/: cannot be listed by the grader (" + open_ec.message() + ")");
                it.disable_recursion_pending();
            }
        } else if (!fs::is_regular_file(status)) {
            refused.push_back(name + ": not a plain file (a device, FIFO or socket)");
        } else if (fs::hard_link_count(it->path()) > 1) {
            refused.push_back(name + ": a hard link (" + std::to_string(fs::hard_link_count(it->path())) + " names)");
        } else if (fs::file_size(it->path()) > kMaxSubmissionFileBytes) {
            refused.push_back(name + ": " + std::to_string(fs::file_size(it->path())) + " bytes, over the " +
                              std::to_string(kMaxSubmissionFileBytes >> 20) + " MiB a file may have");
        } else if ((bytes += fs::file_size(it->path())) > kMaxSubmissionBytes) {
            refused.push_back(name + ": over the " + std::to_string(kMaxSubmissionBytes >> 20) + " MiB a submission's labs/ may hold in all");
        } else if (!copy_contents(it->path(), target, (status.permissions() & kAnyExec) != fs::perms::none, why)) {
            refused.push_back(name + ": " + why);
        }
    }
    return refused;
}

std::string file_bytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error("cannot read '" + file.string() + "'");
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// A command's output, run by the grader itself (on the kit's own build, which no student code has touched); none when
// it fails.
std::optional<std::string> run_directly(const std::vector<std::string>& command) {
    ProcessLimits limits;
    limits.timeout = std::chrono::seconds(60);
    limits.max_output_bytes = limits.flood_bytes = 64u << 20;
    const ProcessResult run = run_process(command, fs::current_path(), limits);
    if (run.exit_code != 0 || run.output_bytes > run.output.size()) return std::nullopt;
    return run.output;
}

// Whether the kit's own build of the lab read only what the submission has too: each file of the kit's lab folder it
// read is in the submission's, byte for byte (a text its C++ includes as much as a header), and every other file it
// read (the kit's headers, the system's) is older than the binary. The records name the lab's objects, so ninja
// answers for those alone.
bool kit_build_read_the_same(const std::string& lab, const fs::path& kit_lab, const fs::path& kit_build, const fs::path& kit_binary,
                             const fs::path& submission_lab) {
    std::vector<std::string> objects;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(kit_lab, ec))
        if (e.path().extension() == ".cpp")
            objects.push_back("CMakeFiles/" + lab + ".dir/labs/" + kit_lab.filename().string() + "/" + e.path().filename().string() + ".o");
    const BuildReads reads = build_reads(kit_build, lab, run_directly, objects);
    if (!reads.complete) return false;
    const auto built = fs::last_write_time(kit_binary, ec);
    if (ec) return false;
    const fs::path lab_folder = kit_lab.lexically_normal();
    for (const fs::path& file : reads.files) {
        const fs::path relative = file.lexically_relative(lab_folder);
        if (!relative.empty() && *relative.begin() != "..") {
            const fs::path theirs = submission_lab / relative;
            if (!fs::is_regular_file(fs::symlink_status(theirs, ec)) || file_bytes(theirs) != file_bytes(file)) return false;
        } else if (fs::last_write_time(file, ec) > built || ec) {
            return false;
        }
    }
    return true;
}

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
    if (same_kit && fs::exists(kit_binary) && binary_is_newer(kit_binary, kit_lab) && read_build_inputs(kit_lab) == inputs &&
        kit_build_read_the_same(lab, kit_lab, kit_build, kit_binary, submission_lab)) {
        fs::copy_file(kit_binary, to, fs::copy_options::overwrite_existing);
        build.origin = "unchanged C++: the kit's binary";
        return true;
    }
    if (cache && cache->fetch(lab, submission_lab, to, build.log)) {
        build.origin = "unchanged C++: an earlier build";
        return true;
    }
    return false;
}

// A lab's build sees its own folder and the kit's public files only: an #include of anything else fails to compile.
// Where the compiler could not find a file that is in the submission's labs/ outside the lab's folder, say why.
std::string include_outside_hint(const std::string& output, const fs::path& labs_copy, const std::string& folder) {
    static const std::regex missing("fatal error: ([^:\\n]+): No such file or directory");
    std::smatch m;
    if (!std::regex_search(output, m, missing)) return "";
    const fs::path wanted = fs::path(m[1].str()).filename();
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(labs_copy, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        const fs::path relative = it->path().lexically_relative(labs_copy);
        if (it->path().filename() != wanted || *relative.begin() == folder) continue;
        return "error: '" + m[1].str() + "' is labs/" + relative.generic_string() + ", outside this lab's folder: a lab's build sees only "
               "its own folder (labs/" + folder + "/) and the kit's public files (common/, support/, shaders/, data/); copy what it "
               "needs into labs/" + folder + "/\n";
    }
    return "";
}

// Whether the submission project configures with no lab in it at all: where it does not, a failed configure is the
// kit's fault (grader/src/grade/kit_fault.h), not the student's. Run in the build's own folder and walls.
bool configures_without_labs(std::vector<std::string> configure, const fs::path& build_dir, const ProcessLimits& limits,
                             const SandboxPolicy* policy, std::string& output) {
    const fs::path empty_kit = build_dir / "configure-without-labs";
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(build_dir, ec))
        if (e.path() != empty_kit) fs::remove_all(e.path(), ec);
    fs::create_directories(empty_kit / "labs");
    for (auto& argument : configure)
        if (argument.rfind("-DGSV_LABS_ROOT=", 0) == 0) argument = "-DGSV_LABS_ROOT=" + empty_kit.string();
    ProcessLimits probe = limits;
    probe.sandbox = policy;
    const ProcessResult run = run_process(configure, build_dir, probe);
    output = run.output;
    return run.exit_code == 0;
}

}  // namespace

SubmissionBuild build_submission(const fs::path& submission, const fs::path& kit_root, const fs::path& kit_build,
                                 const std::vector<std::string>& labs, const fs::path& work_dir,
                                 const ProcessLimits& limits, bool reuse, const fs::path& cache_dir) {
    const fs::path labs_dir = fs::is_directory(submission / "labs") ? submission / "labs" : submission;
    if (!fs::is_directory(labs_dir) || labs_dir.filename() != "labs")
        throw Error("submission '" + submission.string() + "' has no labs/ folder");
    // The kit's own faults before any build: every submission would fail them alike (kit_fault.h).
    check_kit_for_submissions(kit_root, kit_build);
    SubmissionBuild result;
    result.root = work_dir / "kit";
    result.bin_dir = work_dir / "build" / "bin";
    remove_folder(work_dir);
    const std::vector<std::string> refused = copy_plain_tree(labs_dir, KitLayout{result.root}.labs());
    const KitLayout kit{fs::absolute(kit_root)}, copy{result.root};
    fs::create_directory_symlink(kit.shaders(), copy.shaders());
    fs::create_directory_symlink(kit.data(), copy.data());
    const fs::path build_dir = work_dir / "build";
    fs::create_directories(build_dir);
    // Only the build folder becomes the sandbox user's: the copy of labs/ stays the grader's, read-only to builds and labs.
    if (limits.support && limits.sandbox) hand_over(build_dir, *limits.sandbox, *limits.support);
    // What a build may read of the submission: configuring globs every lab's sources (labs/, read-only); compiling and
    // linking a lab sees that lab's folder alone, so what it includes from elsewhere fails to compile, and what it
    // read is proved in its folder (the build cache's key and dependency records).
    std::optional<SandboxPolicy> configure_policy;
    if (limits.sandbox) {
        configure_policy = *limits.sandbox;
        configure_policy->read_only.push_back(copy.labs());
    }
    const auto lab_policy = [&](const std::string& folder) {
        SandboxPolicy policy = *limits.sandbox;
        policy.read_only.push_back(copy.labs() / folder);
        return policy;
    };

    std::vector<std::string> configure{GSV_CMAKE_COMMAND, "-S", kit.submission_project().string(),
                                       "-B", build_dir.string(), "-DGSV_KIT_BUILD=" + fs::absolute(kit_build).string(),
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
    bool kit_fault = false;                   // the project does not configure even without the submission's labs
    for (const auto& lab : labs) {
        LabBuild build;
        build.lab = lab;
        build.log = cache_note;
        const fs::path binary = result.bin_dir / lab;
        const std::string folder = cmake_cache_value(kit_build, "GSV_LAB_DIR_" + lab);
        const fs::path submission_lab = copy.labs() / folder;
        const auto started = std::chrono::steady_clock::now();
        if (reuse && !folder.empty() && reuse_build(lab, submission_lab, kit_root, kit_build, cache ? &*cache : nullptr, binary, build)) {
            build.ok = true;
            build.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
            for (const auto& line : refused) build.log += "\nnot taken from the submission: " + line;
            result.builds.push_back(std::move(build));
            continue;
        }
        if (!configured) {
            ProcessLimits configuring = limits;
            if (configure_policy) configuring.sandbox = &*configure_policy;
            configured = run_process(configure, build_dir, configuring);
            std::string without;
            if (configured->exit_code != 0 && !configures_without_labs(configure, build_dir, limits, configuring.sandbox, without)) {
                kit_fault = true;
                configured->output = "the kit's fault: the submission project does not configure even without the submission's "
                                     "labs (check the kit build and its cmake/ files):\n" + without;
            }
        }
        if (configured->exit_code != 0) {
            build.kit_fault = kit_fault;
            build.log = (kit_fault ? "" : "configuring the submission's build failed:\n") + configured->output + build.log;
        } else {
            const std::optional<SandboxPolicy> policy = limits.sandbox && !folder.empty() ? std::optional<SandboxPolicy>(lab_policy(folder))
                                                                                          : std::nullopt;
            ProcessLimits building = limits;
            if (policy) building.sandbox = &*policy;
            const ProcessResult made = run_process({GSV_CMAKE_COMMAND, "--build", build_dir.string(), "--target", lab}, build_dir, building);
            build.seconds = made.seconds;
            build.ok = made.exit_code == 0 && fs::exists(binary);
            build.log = made.output + build.log;
            if (!build.ok && !folder.empty()) build.log = include_outside_hint(made.output, copy.labs(), folder) + build.log;
            if (reuse && build.ok && cache && !folder.empty()) {
                // What the compiler read, from the build's own records (read inside the same walls): kept beside the
                // binary, so a later hit is proved on each of those files, not only on the lab's C++.
                ProcessLimits asking = building;
                asking.max_output_bytes = asking.flood_bytes = 64u << 20;
                const CommandRunner in_walls = [&](const std::vector<std::string>& command) -> std::optional<std::string> {
                    const ProcessResult run = run_process(command, build_dir, asking);
                    if (run.exit_code != 0 || run.output_bytes > run.output.size()) return std::nullopt;
                    return run.output;
                };
                const BuildReads reads = build_reads(build_dir, lab, in_walls);
                if (reads.complete)
                    cache->store(lab, submission_lab, read_files(reads, submission_lab, build_dir), binary, build.log);
                else
                    build.log += "\nbuild cache: " + reads.why_not + "; this build is not kept";
            }
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
