#include "grader/src/similarity/copied_code.h"

#include "common/core/error.h"
#include "common/io/temporary_folder.h"
#include "grader/src/similarity/sim_tool.h"
#include "tools/starter.h"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <set>

namespace fs = std::filesystem;

namespace gsv {
namespace {

// A file larger than this is no lab answer (a data file renamed, say): left out, said in the notes.
constexpr std::uintmax_t kLargestComparedFile = 512 * 1024;

bool ends_with(const std::string& text, const std::string& tail) {
    return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

SimLanguage language_of(const std::string& name) { return is_glsl_file(name) ? SimLanguage::C : SimLanguage::Cpp; }

// The file's text with CR LF read as LF and a newline at the end (SIM numbers an unterminated last line 0).
std::string normalised_text(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error("cannot read '" + file.string() + "'");
    std::string text;
    for (std::istreambuf_iterator<char> it(in), end; it != end; ++it)
        if (*it != '\r') text += *it;
    if (!text.empty() && text.back() != '\n') text += '\n';
    return text;
}

std::vector<std::string> split_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1) lines.push_back(text.substr(start, end - start));
    return lines;
}

void write_text(const fs::path& file, const std::string& text) {
    fs::create_directories(file.parent_path());
    std::ofstream out(file, std::ios::binary);
    out << text;
    if (!out) throw Error("cannot write '" + file.string() + "'");
}

// One lab's comparison in a staging folder of its own: every file under a plain name SIM's output cannot confuse
// (the students' own names may hold spaces).
class LabComparison {
public:
    LabComparison(const CopiedCodeOptions& options, const std::string& lab, const std::string& lab_dir, const fs::path& staging)
        : options_(options), staging_(staging) {
        result_.lab = lab;
        result_.lab_dir = lab_dir;
    }

    LabCode run(const std::vector<std::string>& students) {
        read_students(students);
        subtract_template();
        compare_own_code();
        find_identical_edits();
        keep_files_of_pairs();
        return std::move(result_);
    }

private:
    struct Staged {
        std::string student, name;
        std::string original, own;  // relative to the staging folder
    };

    void read_students(const std::vector<std::string>& students) {
        for (std::size_t i = 0; i < students.size(); ++i) {
            const fs::path folder = options_.submissions / students[i] / "labs" / result_.lab_dir;
            if (!fs::is_directory(folder)) continue;
            ++result_.students;
            result_.own_tokens[students[i]] = 0;
            std::vector<fs::path> files;
            for (const auto& e : fs::directory_iterator(folder)) {
                if (!is_compared_file(e.path().filename().string())) continue;
                // A link could point anywhere on the instructor's machine: not the student's text.
                if (e.is_symlink()) result_.notes.push_back(students[i] + "'s " + e.path().filename().string() + " left out: a link");
                else if (e.is_regular_file()) files.push_back(e.path());
            }
            std::sort(files.begin(), files.end());
            for (const fs::path& file : files) {
                const std::string name = file.filename().string();
                if (fs::file_size(file) > kLargestComparedFile) {
                    result_.notes.push_back(students[i] + "'s " + name + " left out: over " + std::to_string(kLargestComparedFile / 1024) + " KiB");
                    continue;
                }
                const std::string text = normalised_text(file);
                CodeFile& code = result_.files[students[i]][name];
                code.lines = split_lines(text);
                code.kinds.assign(code.lines.size(), LineKind::Own);
                const std::string tag = "s" + std::to_string(i) + "/f" + std::to_string(name_index(name));
                staged_.push_back({students[i], name, tag, "own-" + tag});
                write_text(staging_ / tag, text);
                texts_[tag] = text;
            }
        }
    }

    int name_index(const std::string& name) {
        const auto at = std::find(names_.begin(), names_.end(), name);
        if (at != names_.end()) return static_cast<int>(at - names_.begin());
        names_.push_back(name);
        return static_cast<int>(names_.size()) - 1;
    }

    // The template's runs in each student file, by SIM's old group (-S: compared with the template only). A file the
    // same as a template file is the template whole: SIM cannot see a file shorter than a run.
    void subtract_template() {
        std::map<std::string, std::vector<std::string>> template_by_name;  // normalised text of the template's files, by name
        std::map<SimLanguage, std::vector<std::string>> template_staged;
        int k = 0;
        for (const fs::path& file : template_files(options_.kit_root, result_.lab_dir)) {
            const std::string text = normalised_text(file);
            const std::string tag = "t/" + std::to_string(k++);
            write_text(staging_ / tag, text);
            template_staged[language_of(file.filename().string())].push_back(tag);
            template_by_name[file.filename().string()].push_back(text);
        }
        std::map<SimLanguage, std::vector<std::string>> students_staged;
        for (const Staged& s : staged_) {
            CodeFile& code = result_.files[s.student][s.name];
            const auto& same_name = template_by_name[s.name];
            if (std::find(same_name.begin(), same_name.end(), texts_[s.original]) != same_name.end())
                code.kinds.assign(code.lines.size(), LineKind::Template);
            else
                students_staged[language_of(s.name)].push_back(s.original);
        }
        std::map<std::string, const Staged*> by_tag;
        for (const Staged& s : staged_) by_tag[s.original] = &s;
        for (const auto& [language, files] : students_staged) {
            if (template_staged[language].empty()) continue;
            const SimOutput found = run_sim(language, {"-S", "-n", "-r", std::to_string(options_.min_run), "-w", "1000"}, files,
                                            template_staged[language], staging_);
            for (const SimRun& r : found.runs) {
                const auto s = by_tag.find(r.file_a);
                if (s == by_tag.end()) continue;
                CodeFile& code = result_.files[s->second->student][s->second->name];
                for (int line = std::max(1, r.a_first); line <= r.a_last && line <= static_cast<int>(code.lines.size()); ++line)
                    code.kinds[static_cast<std::size_t>(line - 1)] = LineKind::Template;
            }
        }
    }

    // The file with every line but its own code blanked (so the line numbers stay), for SIM.
    void write_own(const Staged& s) {
        const CodeFile& code = result_.files[s.student][s.name];
        std::string own;
        for (std::size_t i = 0; i < code.lines.size(); ++i) own += (code.kinds[i] == LineKind::Own ? code.lines[i] : "") + "\n";
        write_text(staging_ / s.own, own);
    }

    // Marks the own lines in runs with kCommonPartners or more other students Common; says whether there were any.
    bool mark_common_lines(const SimOutput& found, const std::map<std::string, const Staged*>& by_tag) {
        std::map<std::pair<const Staged*, int>, std::set<std::string>> partners;  // (file, line) -> other students
        for (const SimRun& r : found.runs) {
            const Staged* a = by_tag.at(r.file_a);
            const Staged* b = by_tag.at(r.file_b);
            for (int line = r.a_first; line <= r.a_last; ++line) partners[{a, line}].insert(b->student);
            for (int line = r.b_first; line <= r.b_last; ++line) partners[{b, line}].insert(a->student);
        }
        bool any = false;
        for (const auto& [at, others] : partners) {
            if (static_cast<int>(others.size()) < kCommonPartners) continue;
            CodeFile& code = result_.files[at.first->student][at.first->name];
            const auto line = static_cast<std::size_t>(at.second - 1);
            if (line < code.kinds.size() && code.kinds[line] == LineKind::Own) {
                code.kinds[line] = LineKind::Common;
                any = true;
            }
        }
        return any;
    }

    // Each file of one name, only its own code left, against the same file of every other student: SIM -e, each file
    // with each. Where much of the class shares some of it, again without that.
    void compare_own_code() {
        std::map<std::string, std::vector<const Staged*>> by_name;
        for (const Staged& s : staged_) {
            const CodeFile& code = result_.files[s.student][s.name];
            if (std::none_of(code.kinds.begin(), code.kinds.end(), [](LineKind k) { return k == LineKind::Own; })) continue;
            write_own(s);
            by_name[s.name].push_back(&s);
        }
        std::map<std::pair<std::string, std::string>, CodePair> pairs;
        for (const auto& [name, files] : by_name) {
            std::vector<std::string> tags;
            std::map<std::string, const Staged*> by_tag;
            for (const Staged* s : files) {
                tags.push_back(s->own);
                by_tag[s->own] = s;
            }
            const std::vector<std::string> options{"-e", "-s", "-n", "-r", std::to_string(options_.min_run), "-w", "1000"};
            SimOutput found = run_sim(language_of(name), options, tags, {}, staging_);
            if (mark_common_lines(found, by_tag)) {
                for (const Staged* s : files) write_own(*s);
                found = run_sim(language_of(name), options, tags, {}, staging_);
            }
            for (const auto& [tag, tokens] : found.tokens_of) {
                const auto s = by_tag.find(tag);
                if (s == by_tag.end()) continue;
                result_.files[s->second->student][name].own_tokens = tokens;
                result_.own_tokens[s->second->student] += tokens;
            }
            for (const SimRun& r : found.runs) {
                const auto a = by_tag.find(r.file_a), b = by_tag.find(r.file_b);
                if (a == by_tag.end() || b == by_tag.end() || a->second->student == b->second->student) continue;
                // The class's order: the staged files are in it.
                const bool in_order = a->second < b->second;
                const Staged& first = in_order ? *a->second : *b->second;
                const Staged& second = in_order ? *b->second : *a->second;
                CodePair& pair = pairs[{first.student, second.student}];
                pair.lab = result_.lab;
                pair.a = first.student;
                pair.b = second.student;
                pair.shared_tokens += r.tokens;
                SharedRun run{name, r.a_first, r.a_last, r.b_first, r.b_last, r.tokens};
                if (!in_order) {
                    std::swap(run.a_first, run.b_first);
                    std::swap(run.a_last, run.b_last);
                }
                pair.runs.push_back(run);
            }
        }
        for (auto& [names, pair] : pairs) {
            pair.own_a = result_.own_tokens[pair.a];
            pair.own_b = result_.own_tokens[pair.b];
            const int smaller = std::max(1, std::min(pair.own_a, pair.own_b));
            pair.share = std::min(1.0, static_cast<double>(pair.shared_tokens) / smaller);
            result_.pairs.push_back(pair);
        }
        std::stable_sort(result_.pairs.begin(), result_.pairs.end(), [](const CodePair& x, const CodePair& y) {
            return x.share != y.share ? x.share > y.share : x.shared_tokens > y.shared_tokens;
        });
    }

    // Students whose changed files (those with a line the template does not hold) are the same, file for file and byte
    // for byte, with a line no template file holds: SIM needs a run of kMinRun tokens, and a one-line slip in a reference-like file is shorter, so a whole
    // submission handed in twice would otherwise pass unseen. A version shared by more than kCommonPartners others is the
    // class's common edit, not a copy.
    void find_identical_edits() {
        std::map<std::string, std::map<std::string, std::string>> changed;  // student -> file -> text
        for (const Staged& s : staged_) {
            const CodeFile& code = result_.files[s.student][s.name];
            if (std::any_of(code.kinds.begin(), code.kinds.end(), [](LineKind k) { return k != LineKind::Template; }))
                changed[s.student][s.name] = texts_[s.original];
        }
        // A line of the template (starter, reference, other starters) is no sign of a copy: two students who both wrote
        // the reference's answer hand in the same file. A version counts only with a line of its own.
        std::map<std::string, std::set<std::string>> template_lines;  // file name -> its lines, trimmed
        const auto trimmed = [](const std::string& line) {
            const auto first = line.find_first_not_of(" \t\r"), last = line.find_last_not_of(" \t\r");
            return first == std::string::npos ? std::string() : line.substr(first, last - first + 1);
        };
        for (const fs::path& file : template_files(options_.kit_root, result_.lab_dir))
            for (const std::string& line : split_lines(normalised_text(file))) template_lines[file.filename().string()].insert(trimmed(line));
        const auto has_own_line = [&](const std::map<std::string, std::string>& files) {
            for (const auto& [name, text] : files)
                for (const std::string& line : split_lines(text))
                    if (!trimmed(line).empty() && !template_lines[name].count(trimmed(line))) return true;
            return false;
        };
        std::map<std::map<std::string, std::string>, std::vector<std::string>> by_version;
        for (const auto& [student, files] : changed) by_version[files].push_back(student);
        for (const auto& [files, students] : by_version) {
            if (students.size() < 2 || static_cast<int>(students.size()) > kCommonPartners + 1 || !has_own_line(files)) continue;
            for (std::size_t i = 0; i < students.size(); ++i)
                for (std::size_t j = i + 1; j < students.size(); ++j) {
                    // The class's order: the staged files are in it, and so are the names here (a map's order is the
                    // same sort).
                    const std::string &a = students[i], &b = students[j];
                    const auto existing = std::find_if(result_.pairs.begin(), result_.pairs.end(),
                                                       [&](const CodePair& p) { return p.a == a && p.b == b; });
                    CodePair& pair = existing != result_.pairs.end() ? *existing : result_.pairs.emplace_back();
                    pair.lab = result_.lab;
                    pair.a = a;
                    pair.b = b;
                    pair.own_a = result_.own_tokens[a];
                    pair.own_b = result_.own_tokens[b];
                    pair.share = 1.0;
                    pair.identical_edits = true;
                    if (!pair.runs.empty()) continue;
                    // The side-by-side view shows each changed file's own lines.
                    for (const auto& [name, text] : files) {
                        const CodeFile& code = result_.files[a][name];
                        int first = 0, last = 0;
                        for (std::size_t line = 0; line < code.kinds.size(); ++line)
                            if (code.kinds[line] != LineKind::Template) {
                                if (!first) first = static_cast<int>(line) + 1;
                                last = static_cast<int>(line) + 1;
                            }
                        if (first) pair.runs.push_back({name, first, last, first, last, 0});
                    }
                }
        }
        std::stable_sort(result_.pairs.begin(), result_.pairs.end(), [](const CodePair& x, const CodePair& y) {
            return x.share != y.share ? x.share > y.share : x.shared_tokens > y.shared_tokens;
        });
    }

    void keep_files_of_pairs() {
        std::set<std::string> in_pairs;
        for (const CodePair& p : result_.pairs) in_pairs.insert({p.a, p.b});
        for (auto it = result_.files.begin(); it != result_.files.end();) it = in_pairs.count(it->first) ? std::next(it) : result_.files.erase(it);
    }

    const CopiedCodeOptions& options_;
    fs::path staging_;
    LabCode result_;
    std::vector<Staged> staged_;  // in the class's order, then the files' names
    std::vector<std::string> names_;
    std::map<std::string, std::string> texts_;  // staged tag -> text
};

}  // namespace

bool is_glsl_file(const std::string& name) {
    for (const char* tail : {".glsl", ".vert", ".frag", ".geom", ".comp", ".tesc", ".tese"})
        if (ends_with(name, tail)) return true;
    return false;
}

bool is_compared_file(const std::string& name) { return is_glsl_file(name) || is_cpp_file(name) || ends_with(name, ".hpp"); }

std::vector<std::pair<std::string, std::string>> kit_labs(const fs::path& kit_root) {
    std::vector<std::pair<std::string, std::string>> labs;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(kit_root / "labs", ec)) {
        const std::string dir = e.path().filename().string();
        const auto underscore = dir.find('_');
        if (e.is_directory() && dir.rfind("lab", 0) == 0 && underscore != std::string::npos) labs.push_back({dir.substr(0, underscore), dir});
    }
    if (ec) throw Error("no labs/ in the kit '" + kit_root.string() + "'");
    std::sort(labs.begin(), labs.end());
    return labs;
}

std::vector<fs::path> template_files(const fs::path& kit_root, const std::string& lab_dir) {
    std::vector<fs::path> files;
    const auto add_folder = [&](const fs::path& folder) {
        std::vector<fs::path> found;
        std::error_code ec;
        for (auto it = fs::recursive_directory_iterator(folder, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
            if (it->is_regular_file() && is_compared_file(it->path().filename().string())) found.push_back(it->path());
        std::sort(found.begin(), found.end());
        files.insert(files.end(), found.begin(), found.end());
    };
    add_folder(kit_root / "labs" / lab_dir);
    add_folder(kit_root / "solutions" / lab_dir);
    for (const auto& [lab, dir] : kit_labs(kit_root))
        if (dir != lab_dir) add_folder(kit_root / "labs" / dir);
    add_folder(kit_root / "shaders");
    return files;
}

std::vector<LabCode> find_copied_code(const CopiedCodeOptions& options) {
    if (!fs::is_directory(options.submissions)) throw Error("no folder of submissions '" + options.submissions.string() + "'");
    const auto labs = kit_labs(options.kit_root);
    std::vector<std::pair<std::string, std::string>> chosen;
    for (const std::string& lab : options.labs) {
        const auto at = std::find_if(labs.begin(), labs.end(), [&](const auto& l) { return l.first == lab; });
        if (at == labs.end()) throw Error("--labs: the kit has no lab '" + lab + "' (no labs/" + lab + "_* folder)");
        chosen.push_back(*at);
    }
    if (options.labs.empty()) chosen = labs;
    std::vector<std::string> students;
    for (const auto& e : fs::directory_iterator(options.submissions))
        if (e.is_directory() && e.path().filename().string()[0] != '.') students.push_back(e.path().filename().string());
    std::sort(students.begin(), students.end());
    if (students.empty()) throw Error("'" + options.submissions.string() + "' holds no submission folders");
    find_sim(SimLanguage::C);  // the install line before any work
    find_sim(SimLanguage::Cpp);
    TemporaryFolder staging("gsv-similarity-");
    std::vector<LabCode> result;
    for (const auto& [lab, lab_dir] : chosen)
        result.push_back(LabComparison(options, lab, lab_dir, staging.path() / lab).run(students));
    return result;
}

}  // namespace gsv
