// gsv-make-starters: generates labs/ (the students' starters) from the annotated solutions/, or checks
// that the committed starters are what the solutions generate.
#include "common/core/error.h"
#include "common/core/version.h"
#include "tools/starter.h"

#include <cstdio>
#include <cstring>

namespace {

constexpr const char* kUsage =
    "usage: gsv-make-starters [--check|--write] [--root DIR]\n"
    "  --check      (default) exit 1 if a starter in labs/ differs from what its solution in solutions/ generates\n"
    "  --write      regenerate labs/ from solutions/ (the //@solution ... //@starter ... //@end blocks)\n"
    "  --root DIR   the kit to work on (default: the one this was built from)\n"
    "  --version    the kit's version\n";

}  // namespace

int main(int argc, char** argv) {
    bool write = false;
    const char* root = GSV_SOURCE_ROOT;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--write") == 0) write = true;
        else if (std::strcmp(argv[i], "--check") == 0) write = false;
        else if (std::strcmp(argv[i], "--root") == 0 && i + 1 < argc) root = argv[++i];
        else if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) {
            std::printf("%s", kUsage);
            return 0;
        } else if (std::strcmp(argv[i], "--version") == 0) {
            std::printf("%s\n", gsv::version_line("gsv-make-starters").c_str());
            return 0;
        } else {
            std::fprintf(stderr, "gsv-make-starters: unknown option '%s' (see --help)\n", argv[i]);
            return 2;
        }
    }
    try {
        int stale = 0;
        for (const auto& r : gsv::sync_starters(root, write)) {
            if (!r.up_to_date) {
                ++stale;
                std::printf("%s %s\n", write ? "wrote" : "STALE", r.starter.string().c_str());
            }
        }
        if (!write && stale > 0) {
            std::fprintf(stderr, "gsv-make-starters: %d starter file(s) differ from what solutions/ generates; "
                                 "run gsv-make-starters --write\n", stale);
            return 1;
        }
        if (!write) std::printf("starters match solutions\n");
        return 0;
    } catch (const gsv::Error& e) {
        std::fprintf(stderr, "gsv-make-starters: %s\n", e.what());
        return 1;
    }
}
