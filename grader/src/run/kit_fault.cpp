#include "grader/src/run/kit_fault.h"

#include "common/app/kit_layout.h"
#include "grader/src/run/build_reuse.h"

namespace fs = std::filesystem;

namespace gsv {

void check_kit_for_submissions(const fs::path& kit, const fs::path& kit_build) {
    if (!fs::exists(kit_build / "gsv-targets.cmake"))
        throw KitFault("'" + kit_build.string() + "' is not a configured kit build (no gsv-targets.cmake): build the kit first "
                       "(scripts/kit build), then grade with --bin <its build>/bin");
    const fs::path built_from = cmake_cache_value(kit_build, "CMAKE_HOME_DIRECTORY");
    std::error_code ec;
    if (built_from.empty() || !fs::equivalent(built_from, kit, ec))
        throw KitFault("--kit " + kit.string() + " is not the checkout the build in " + kit_build.string() + " was made from (" +
                       (built_from.empty() ? std::string("its CMakeCache.txt does not say") : built_from.string()) +
                       "): grade with --kit " + (built_from.empty() ? std::string("<that checkout>") : built_from.string()) +
                       ", or build " + kit.string() + " and pass its build's bin folder with --bin");
    const KitLayout layout{kit};
    for (const fs::path& needed : {kit / "cmake" / "dependencies.cmake", kit / "cmake" / "labs.cmake",
                                   layout.submission_project() / "CMakeLists.txt", kit_build / "gsv-build-settings.cmake"})
        if (!fs::is_regular_file(needed, ec))
            throw KitFault("the kit has no " + needed.string() + ", which every submission's build reads: restore it (git checkout) "
                           "or rebuild the kit");
}

}  // namespace gsv
