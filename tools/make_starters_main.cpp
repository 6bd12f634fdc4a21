// gsv-make-starters: generates labs/ (the students' starters) from the annotated solutions/, or checks
// that the committed starters are what the solutions generate.
#include "common/core/error.h"
#include "common/core/version.h"
#include "common/io/json.h"
#include "tools/starter.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
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
    "  --done T1,T2 --to DIR    the reference's lab folder with every TODO but these left as the starter has it\n"
    "               (a student part way through: what a case that declares these as its needs must pass with)\n"
    "  --mistakes LAB --to DIR  the reference's lab folder with each C++ TODO block switched at run time between the\n"
    "               solution, the starter's and each known C++ mistake of tests/mutants/LAB.json (GSV_KNOWN_MISTAKE\n"
    "               names one): the sources of the lab's _mistakes build, whose pictures diagnose C++ mistakes\n"
    "  --version    the kit's version\n";

namespace fs = std::filesystem;

// solutions/labXX_*/ of the TODOs' lab, each file with only the blocks of the TODOs `undone` says turned into the starter's.
int write_partly_undone(const fs::path& root, const std::string& todo, const fs::path& to,
                        const std::function<std::string(const std::string&, const std::string&)>& convert, const std::string& what) {
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
            std::ofstream(to / name, std::ios::binary) << convert(text.str(), name);
            ++written;
        }
    }
    if (written == 0) throw gsv::Error("no solutions/" + lab + "_*/ folder for TODO '" + todo + "' in " + root.string());
    std::printf("wrote %d files of %s with %s into %s\n", written, lab.c_str(), what.c_str(), to.string().c_str());
    return 0;
}

int write_one_undone(const fs::path& root, const std::string& todo, const fs::path& to) {
    return write_partly_undone(root, todo, to, [&](const std::string& text, const std::string& name) {
        return gsv::make_starter(text, name, todo).text;
    }, todo + " undone");
}

// Every TODO but those listed (comma-separated, of one lab) left as the starter has it.
int write_only_done(const fs::path& root, const std::string& list, const fs::path& to) {
    std::set<std::string> done;
    std::stringstream in(list);
    for (std::string id; std::getline(in, id, ',');) {
        if (id.size() < 4 || id[0] != 'L' || (!done.empty() && id.substr(0, 3) != done.begin()->substr(0, 3)))
            throw gsv::Error("--done takes TODO ids of one lab, comma-separated (L02-T1,L02-T3), got '" + list + "'");
        done.insert(id);
    }
    if (done.empty()) throw gsv::Error("--done takes at least one TODO id");
    return write_partly_undone(root, *done.begin(), to, [&](const std::string& text, const std::string& name) {
        return gsv::make_partial_starter(text, name, done).text;
    }, "only " + list + " done");
}

}  // namespace

int main(int argc, char** argv) {
    bool write = false;
    const char* root = GSV_SOURCE_ROOT;
    std::string undone, done, mistakes, to;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--write") == 0) write = true;
        else if (std::strcmp(argv[i], "--check") == 0) write = false;
        else if (std::strcmp(argv[i], "--root") == 0 && i + 1 < argc) root = argv[++i];
        else if (std::strcmp(argv[i], "--undone") == 0 && i + 1 < argc) undone = argv[++i];
        else if (std::strcmp(argv[i], "--done") == 0 && i + 1 < argc) done = argv[++i];
        else if (std::strcmp(argv[i], "--mistakes") == 0 && i + 1 < argc) mistakes = argv[++i];
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
    if ((undone.empty() && done.empty() && mistakes.empty()) != to.empty() ||
        (!undone.empty() + !done.empty() + !mistakes.empty()) > 1) {
        std::fprintf(stderr, "gsv-make-starters: one of --undone TODO, --done T1,T2 or --mistakes LAB, and --to DIR, go together (see --help)\n");
        return 2;
    }
    try {
        if (!mistakes.empty()) {
            const std::string lab_dir = gsv::read_json_file(fs::path(root) / "tests" / "mutants" / (mistakes + ".json")).string_at("lab_dir");
            const int written = gsv::write_switched_lab(root, lab_dir, gsv::cpp_mistakes(root, mistakes), to);
            std::printf("%s: its C++ TODOs switched between the solution, the starter's and its known C++ mistakes, in %s (%d files)\n",
                        mistakes.c_str(), to.c_str(), written);
            return 0;
        }
        if (!undone.empty()) return write_one_undone(root, undone, to);
        if (!done.empty()) return write_only_done(root, done, to);
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
