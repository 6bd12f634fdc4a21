// gsv-make-starters: generates labs/ (the students' starters) from the annotated solutions/, or checks
// that the committed starters are what the solutions generate.
#include "common/core/error.h"
#include "grader/starter.h"

#include <cstdio>
#include <cstring>

int main(int argc, char** argv) {
    bool write = false;
    const char* root = GSV_SOURCE_ROOT;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--write") == 0) write = true;
        else if (std::strcmp(argv[i], "--check") == 0) write = false;
        else if (std::strcmp(argv[i], "--root") == 0 && i + 1 < argc) root = argv[++i];
        else {
            std::fprintf(stderr, "gsv-make-starters: unknown option '%s' (usage: gsv-make-starters [--check|--write] [--root DIR])\n", argv[i]);
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
