#include "common/app/assets.h"

#include "common/core/error.h"

#include <cstdlib>
#include <system_error>

#if defined(_WIN32)
#include <windows.h>
#elif defined(__APPLE__)
#include <mach-o/dyld.h>
#endif

#ifndef GSV_SOURCE_ROOT
#define GSV_SOURCE_ROOT "."
#endif

namespace fs = std::filesystem;

namespace gsv {

std::vector<fs::path> Assets::candidate_roots(const fs::path& executable) {
    std::vector<fs::path> roots;
    if (const char* env = std::getenv("GSV_ROOT"); env && *env) roots.emplace_back(env);
    if (!executable.empty()) roots.push_back(executable.parent_path() / "gsv-assets");
    roots.emplace_back(GSV_SOURCE_ROOT);
    return roots;
}

Assets::Assets(std::string lab_dir, const fs::path& executable) : lab_dir_(std::move(lab_dir)) {
    const auto roots = candidate_roots(executable);
    std::string searched;
    for (const auto& root : roots) {
        std::error_code ec;
        if (fs::is_directory(root / lab_dir_, ec) && fs::is_directory(KitLayout{root}.shaders(), ec)) {
            root_ = root.lexically_normal();
            return;
        }
        searched += (searched.empty() ? "" : ", ") + (root / lab_dir_).string();
    }
    throw Error("cannot find the kit's files for " + lab_dir_ + " (searched: " + searched +
                "); set GSV_ROOT to the kit's folder");
}

fs::path Assets::lab_file(const std::string& relative) const {
    const fs::path p = lab_dir() / relative;
    if (!fs::exists(p)) throw Error("cannot find '" + relative + "' in " + lab_dir().string());
    return p;
}

fs::path Assets::shader_file(const std::string& relative) const {
    std::error_code ec;
    if (fs::exists(lab_dir() / relative, ec)) return lab_dir() / relative;
    if (fs::exists(shaders_dir() / relative, ec)) return shaders_dir() / relative;
    throw Error("cannot find shader '" + relative + "' in " + lab_dir().string() + " or " + shaders_dir().string());
}

fs::path Assets::data_file(const std::string& relative) const {
    const fs::path p = layout().data() / relative;
    if (!fs::exists(p)) throw Error("cannot find data file '" + p.string() + "'");
    return p;
}

fs::path Assets::user_file(const std::string& typed) const {
    const fs::path path(typed);
    std::error_code ec;
    if (path.is_absolute() || fs::exists(path, ec)) return path;
    const fs::path in_data = layout().data() / path;
    if (fs::exists(in_data, ec)) return in_data;
    throw Error("cannot find file '" + typed + "' (looked in " + fs::current_path(ec).string() + " and " +
                layout().data().string() + ")");
}

fs::path Assets::executable_path(const char* argv0) {
    std::error_code ec;
#if defined(_WIN32)
    wchar_t buffer[MAX_PATH];
    if (GetModuleFileNameW(nullptr, buffer, MAX_PATH) > 0) return fs::path(buffer);
#elif defined(__APPLE__)
    char buffer[4096];
    uint32_t size = sizeof buffer;
    if (_NSGetExecutablePath(buffer, &size) == 0) return fs::weakly_canonical(fs::path(buffer), ec);
#else
    fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) return self;
#endif
    if (argv0) return fs::weakly_canonical(fs::path(argv0), ec);
    return {};
}

}  // namespace gsv
