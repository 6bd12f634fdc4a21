#include "grader/src/similarity/similarity_command.h"

#include "common/core/error.h"
#include "grader/src/grade/grade_exit.h"
#include "grader/src/similarity/similarity_report.h"

#include <chrono>
#include <cstdio>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace gsv {

const char* const kSimilarityUsage =
    "usage: gsv-grade similarity --batch DIR --out DIR [--labs lab01,lab02] [--kit DIR] [--min-run N]\n"
    "  --batch DIR       the class: one folder per student, each with its labs/ (what gsv-grade --batch grades)\n"
    "  --out DIR         the batch's --out: its report.json files and pictures give the same rare wrong pictures; the\n"
    "                    report goes there: similarity.html (opens offline) and similarity.csv. A folder without a\n"
    "                    batch.json (nothing graded yet) gets the code comparison only\n"
    "  --labs A,B        only these labs (default: every lab of the kit)\n"
    "  --kit DIR         the kit whose starters, reference answers and shared shaders are the template subtracted\n"
    "                    (default: the one gsv-grade was built from)\n"
    "  --min-run N       the shortest run of tokens that counts (default 20)\n"
    "needs Debian's similarity-tester: sudo apt-get install similarity-tester (scripts/setup.sh installs it)\n"
    "exit status: 0 written (whatever it found), 2 usage error, unreadable input or similarity-tester missing\n";

SimilarityCommand read_similarity_command(const std::vector<std::string>& args, const fs::path& default_kit) {
    SimilarityCommand command;
    command.kit_root = default_kit;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        const auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) throw Error("option " + a + " needs a value");
            return args[++i];
        };
        if (a == "--help" || a == "-h") {
            command.help = true;
            return command;
        } else if (a == "--batch") {
            command.submissions = value();
        } else if (a == "--out") {
            command.out_dir = value();
        } else if (a == "--kit") {
            command.kit_root = value();
        } else if (a == "--labs") {
            std::istringstream labs(value());
            for (std::string lab; std::getline(labs, lab, ',');)
                if (!lab.empty()) command.labs.push_back(lab);
            if (command.labs.empty()) throw Error("--labs needs lab names, e.g. lab01,lab02");
        } else if (a == "--min-run") {
            const std::string& text = value();
            std::size_t used = 0;
            int n = 0;
            try {
                n = std::stoi(text, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            if (used != text.size() || n < 4 || n > 1000) throw Error("--min-run needs a whole number of tokens from 4 to 1000, got '" + text + "'");
            command.min_run = n;
        } else {
            throw Error("unknown argument '" + a + "' (gsv-grade similarity --help lists the options)");
        }
    }
    if (command.submissions.empty()) throw Error("needs --batch DIR, the folder of submissions");
    if (command.out_dir.empty()) throw Error("needs --out DIR, the batch's output folder (where the report goes)");
    return command;
}

int run_similarity_command(const std::vector<std::string>& args, const fs::path& default_kit) {
    try {
        const SimilarityCommand command = read_similarity_command(args, default_kit);
        if (command.help) {
            std::printf("%s", kSimilarityUsage);
            return kGradeOk;
        }
        const auto start = std::chrono::steady_clock::now();
        SimilarityFindings findings;
        CopiedCodeOptions options;
        options.kit_root = command.kit_root;
        options.submissions = command.submissions;
        options.labs = command.labs;
        if (command.min_run > 0) options.min_run = command.min_run;
        findings.min_run = options.min_run;
        findings.code = find_copied_code(options);
        findings.pictures = find_copied_pictures(command.out_dir);
        findings.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        write_similarity_report(findings, command.out_dir);
        int pairs = 0, likely = 0;
        for (const LabCode& lab : findings.code)
            for (const CodePair& p : lab.pairs) {
                ++pairs;
                likely += p.likely_copied();
            }
        // A pair who drew the same wrong pictures is one pair however many cases show it.
        std::set<std::pair<std::string, std::string>> picture_pairs;
        for (const PicturePair& p : findings.pictures.pairs) picture_pairs.insert({p.a, p.b});
        std::printf("pairs sharing own code: %d (%d likely copied); pairs with the same rare wrong picture: %zu (%zu case%s)%s; %.1f s: %s, %s\n",
                    pairs, likely, picture_pairs.size(), findings.pictures.pairs.size(), findings.pictures.pairs.size() == 1 ? "" : "s",
                    findings.pictures.batch_found ? "" : " (no batch.json: not compared)",
                    findings.seconds, (command.out_dir / "similarity.html").c_str(), (command.out_dir / "similarity.csv").c_str());
        return kGradeOk;
    } catch (const Error& e) {
        std::fprintf(stderr, "gsv-grade similarity: %s\n", e.what());
        return kGradeNotGraded;
    } catch (const fs::filesystem_error& e) {
        std::fprintf(stderr, "gsv-grade similarity: %s\n", e.what());
        return kGradeNotGraded;
    }
}

}  // namespace gsv
