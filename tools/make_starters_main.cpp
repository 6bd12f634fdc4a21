// gsv-make-starters: generates labs/ (the students' starters) from the annotated solutions/, or checks
// that the committed starters are what the solutions generate.
#include "common/core/error.h"
#include "common/core/version.h"
#include "tools/starter.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

constexpr const char* kUsage =
    "usage: gsv-make-starters [--check|--write] [--root DIR]\n"
    "  --check      (default) exit 1 if a starter in labs/ differs from what its solution in solutions/ generates\n"
    "  --write      regenerate labs/ from solutions/ (the //@solution ... //@starter ... //@end blocks)\n"
    "  --root DIR   the kit to work on (default: the one this was built from)\n"
    "  --undone TODO --to DIR   the reference's lab folder with that one TODO left as the starter has it, into DIR\n"
    "               (what the tests hand a lab to see that exactly that TODO's cases fail)\n"
    "  --version    the kit's version\n";

namespace fs = std::filesystem;

// solutions/labXX_*/ of the TODO's lab, each file with only that TODO's blocks turned into the starter's.
int write_one_undone(const fs::path& root, const std::string& todo, const fs::path& to) {
    const std::string lab = "lab" + todo.substr(1, 2);
    fs::create_directories(to);
    int written = 0;
    for (const auto& dir : fs::directory_iterator(root / "solutions")) {
        if (dir.path().filename().string().rfind(lab + "_", 0) != 0) continue;
        for (const auto& file : fs::directory_iterator(dir.path())) {
            std::ifstream in(file.path(), std::ios::binary);
            std::stringstream text;
            text << in.rdbuf();
            const std::string name = file.path().filename().string();
            std::ofstream(to / name, std::ios::binary) << gsv::make_starter(text.str(), name, todo).text;
            ++written;
        }
    }
    if (written == 0) throw gsv::Error("no solutions/" + lab + "_*/ folder for TODO '" + todo + "' in " + root.string());
    std::printf("wrote %d files of %s with %s undone into %s\n", written, lab.c_str(), todo.c_str(), to.string().c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    bool write = false;
    const char* root = GSV_SOURCE_ROOT;
    std::string undone, to;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--write") == 0) write = true;
        else if (std::strcmp(argv[i], "--check") == 0) write = false;
        else if (std::strcmp(argv[i], "--root") == 0 && i + 1 < argc) root = argv[++i];
        else if (std::strcmp(argv[i], "--undone") == 0 && i + 1 < argc) undone = argv[++i];
        else if (std::strcmp(argv[i], "--to") == 0 && i + 1 < argc) to = argv[++i];
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
    if (undone.empty() != to.empty()) {
        std::fprintf(stderr, "gsv-make-starters: --undone TODO and --to DIR go together (see --help)\n");
        return 2;
    }
    try {
        if (!undone.empty()) return write_one_undone(root, undone, to);
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
