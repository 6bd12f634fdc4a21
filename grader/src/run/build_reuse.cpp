#include "grader/src/run/build_reuse.h"

#include "common/core/error.h"
#include "common/core/fnv1a.h"
#include "common/io/folder_tree.h"
#include "grader/src/run/reference_store.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <system_error>

namespace fs = std::filesystem;

namespace gsv {
namespace {

std::string read_bytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error("cannot read '" + file.string() + "'");
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// What the kit build's libraries are: a rebuilt library makes every cached binary that linked the old one stale.
std::string kit_build_stamp(const fs::path& kit_build) {
    std::ostringstream stamp;
    for (const char* settings : {"gsv-targets.cmake", "gsv-build-settings.cmake"}) {
        const fs::path file = kit_build / settings;
        const std::string text = read_bytes(file);
        stamp << settings << '\n' << text << '\n';
        if (std::string(settings) != "gsv-targets.cmake") continue;
        static const std::regex location("IMPORTED_LOCATION[A-Z_]*\\s+\"([^\"]+)\"");
        for (auto it = std::sregex_iterator(text.begin(), text.end(), location); it != std::sregex_iterator(); ++it) {
            const fs::path library = (*it)[1].str();
            std::error_code ec;
            const auto size = fs::file_size(library, ec);
            const auto time = fs::last_write_time(library, ec).time_since_epoch().count();
            stamp << library.string() << ' ' << size << ' ' << time << '\n';
        }
    }
    return stamp.str();
}

bool write_bytes(const fs::path& file, const std::string& bytes) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    return static_cast<bool>(out);
}

// A path from a dependency record: relative ones are the build folder's.
fs::path absolute_in(const fs::path& build_dir, const std::string& text) {
    const fs::path p(text);
    return (p.is_absolute() ? p : build_dir / p).lexically_normal();
}

// Whether `path` is `folder` or lies in it (both normal).
bool lies_in(const fs::path& path, const fs::path& folder) {
    const fs::path relative = path.lexically_relative(folder);
    return !relative.empty() && *relative.begin() != "..";
}

// `ninja -t deps`: "OBJECT: #deps N, deps mtime T (VALID)" and the files indented below it; "OBJECT: deps not found".
void read_ninja_records(const std::string& text, const fs::path& build_dir, const std::string& prefix, BuildReads& reads,
                        std::set<fs::path>& files) {
    std::istringstream in(text);
    bool mine = false;
    int objects = 0;
    for (std::string line; std::getline(in, line);) {
        if (line.empty()) continue;
        if (line[0] != ' ' && line[0] != '\t') {
            const auto colon = line.find(": ");
            mine = colon != std::string::npos && line.compare(0, prefix.size(), prefix) == 0;
            if (!mine) continue;
            ++objects;
            if (line.find("(VALID)") == std::string::npos) {
                reads.why_not = "the dependency record of " + line.substr(0, colon) + " is " +
                                (line.find("STALE") != std::string::npos ? "stale" : "missing");
                return;
            }
            continue;
        }
        if (!mine) continue;
        const auto first = line.find_first_not_of(" \t");
        files.insert(absolute_in(build_dir, line.substr(first)));
    }
    if (objects == 0) {
        reads.why_not = "no dependency records for " + prefix;
        return;
    }
    reads.complete = true;
}

// The .o.d files CMake keeps beside a Makefile build's objects: "OBJECT: FILE FILE \\\n FILE ...".
void read_make_records(const fs::path& target_dir, const fs::path& build_dir, BuildReads& reads, std::set<fs::path>& files) {
    std::error_code ec;
    int objects = 0;
    for (auto it = fs::recursive_directory_iterator(target_dir, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (!it->is_regular_file(ec) || name.size() < 4 || name.compare(name.size() - 4, 4, ".o.d") != 0) continue;
        ++objects;
        std::string text = read_bytes(it->path());
        const auto colon = text.find(": ");
        if (colon == std::string::npos) {
            reads.why_not = "the dependency file " + it->path().string() + " holds no rule";
            return;
        }
        std::string token;
        const auto flush = [&] {
            if (!token.empty()) files.insert(absolute_in(build_dir, token));
            token.clear();
        };
        for (std::size_t i = colon + 2; i < text.size(); ++i) {
            const char c = text[i];
            if (c == '\\' && i + 1 < text.size() && (text[i + 1] == '\n' || text[i + 1] == '\r')) {
                flush();
                ++i;
            } else if (c == '\\' && i + 1 < text.size() && text[i + 1] == ' ') {
                token += ' ';
                ++i;
            } else if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
                flush();
            } else {
                token += c;
            }
        }
        flush();
    }
    if (ec || objects == 0) {
        reads.why_not = "no dependency files in " + target_dir.string();
        return;
    }
    reads.complete = true;
}

}  // namespace

std::string cmake_cache_value(const fs::path& build_dir, const std::string& name) {
    std::ifstream cache(build_dir / "CMakeCache.txt");
    const std::string key = name + ":";
    for (std::string line; std::getline(cache, line);)
        if (line.rfind(key, 0) == 0 && line.find('=') != std::string::npos) return line.substr(line.find('=') + 1);
    return "";
}

BuildInputs read_build_inputs(const fs::path& lab_folder) {
    BuildInputs inputs;
    if (!fs::is_directory(lab_folder)) return inputs;
    for (auto it = fs::recursive_directory_iterator(lab_folder); it != fs::recursive_directory_iterator(); ++it) {
        if (!it->is_regular_file() || !is_build_input(it->path())) continue;
        inputs[it->path().lexically_relative(lab_folder).generic_string()] = read_bytes(it->path());
    }
    return inputs;
}

std::vector<std::string> file_names(const fs::path& lab_folder) {
    std::vector<std::string> names;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(lab_folder, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
        names.push_back(it->path().lexically_relative(lab_folder).generic_string() + (it->is_directory(ec) ? "/" : ""));
    std::sort(names.begin(), names.end());
    return names;
}

bool binary_is_newer(const fs::path& binary, const fs::path& lab_folder) {
    std::error_code ec;
    const auto built = fs::last_write_time(binary, ec);
    if (ec) return false;
    for (auto it = fs::recursive_directory_iterator(lab_folder, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec)) {
        if (!it->is_regular_file() || !is_build_input(it->path())) continue;
        if (fs::last_write_time(it->path(), ec) > built) return false;
    }
    return !ec;
}

BuildReads build_reads(const fs::path& build_dir, const std::string& target, const CommandRunner& run,
                       const std::vector<std::string>& objects) {
    BuildReads reads;
    std::set<fs::path> files;
    const std::string generator = cmake_cache_value(build_dir, "CMAKE_GENERATOR");
    const std::string prefix = "CMakeFiles/" + target + ".dir/";
    try {
        if (generator == "Ninja") {
            const std::string ninja = cmake_cache_value(build_dir, "CMAKE_MAKE_PROGRAM");
            std::vector<std::string> command{ninja.empty() ? "ninja" : ninja, "-C", build_dir.string(), "-t", "deps"};
            command.insert(command.end(), objects.begin(), objects.end());
            const std::optional<std::string> text = run(command);
            if (!text) {
                reads.why_not = "ninja could not list the dependency records of " + target;
                return reads;
            }
            read_ninja_records(*text, build_dir, prefix, reads, files);
        } else if (generator.find("Makefiles") != std::string::npos) {
            read_make_records(build_dir / "CMakeFiles" / (target + ".dir"), build_dir, reads, files);
        } else {
            reads.why_not = "a " + (generator.empty() ? std::string("build of unknown generator") : generator + " build") +
                            " keeps no dependency records the grader reads";
        }
    } catch (const std::exception& e) {
        reads.complete = false;
        reads.why_not = e.what();
    }
    if (reads.complete) reads.files.assign(files.begin(), files.end());
    return reads;
}

ReadFiles read_files(const BuildReads& reads, const fs::path& lab_folder, const fs::path& ignored) {
    ReadFiles read;
    const fs::path lab = lab_folder.lexically_normal(), skip = ignored.lexically_normal();
    for (const fs::path& file : reads.files) {
        if (!skip.empty() && lies_in(file, skip)) continue;
        if (lies_in(file, lab))
            read.in_lab[file.lexically_relative(lab).generic_string()] = read_bytes(file);
        else
            read.elsewhere[file.string()] = file_fingerprint(file);
    }
    return read;
}

BuildCache::BuildCache(fs::path folder, const fs::path& kit_build) : folder_(std::move(folder)), kit_stamp_(kit_build_stamp(kit_build)) {}

fs::path BuildCache::entry(const std::string& lab, const BuildInputs& inputs, const std::vector<std::string>& names) const {
    Fnv1a key;
    key.add(kit_stamp_);
    key.add(lab);
    for (const auto& [name, bytes] : inputs) {
        key.add(name);
        key.add(std::to_string(bytes.size()));
        key.add(bytes.data(), bytes.size());
    }
    key.add("names");
    for (const auto& name : names) key.add(name);
    return folder_ / (lab + "-" + key.hex());
}

namespace {

// The entry's record of what its build read outside its inputs: "lab PATH" (bytes under read/PATH) and
// "elsewhere FINGERPRINT PATH", one a line.
std::string reads_record(const ReadFiles& reads) {
    std::string text;
    for (const auto& [path, bytes] : reads.in_lab) text += "lab " + path + "\n";
    for (const auto& [path, fingerprint] : reads.elsewhere) text += "elsewhere " + fingerprint + " " + path + "\n";
    return text;
}

// "" when each file the entry's build read is as it was; else which one changed (a file of the lab's folder as the
// student names it: labs/<folder>/<path>).
std::string changed_since(const fs::path& at, const fs::path& lab_folder) {
    std::istringstream record(read_bytes(at / "reads"));
    for (std::string line; std::getline(record, line);) {
        if (line.rfind("lab ", 0) == 0) {
            const std::string path = line.substr(4);
            std::error_code ec;
            const fs::path now = lab_folder / path;
            if (!fs::is_regular_file(fs::symlink_status(now, ec)) || read_bytes(now) != read_bytes(at / "read" / path))
                return "labs/" + lab_folder.filename().string() + "/" + path;
        } else if (line.rfind("elsewhere ", 0) == 0) {
            const auto space = line.find(' ', 10);
            if (space == std::string::npos) throw Error("the entry " + at.string() + "'s record of what its build read is damaged");
            const std::string path = line.substr(space + 1);
            if (file_fingerprint(path) != line.substr(10, space - 10)) return path;
        } else if (!line.empty()) {
            throw Error("the entry " + at.string() + "'s record of what its build read is damaged");
        }
    }
    return "";
}

std::string names_record(const std::vector<std::string>& names) {
    std::string text;
    for (const auto& name : names) text += name + "\n";
    return text;
}

}  // namespace

bool BuildCache::fetch(const std::string& lab, const fs::path& lab_folder, const fs::path& to, std::string& note) const {
    const BuildInputs inputs = read_build_inputs(lab_folder);
    const std::vector<std::string> names = file_names(lab_folder);
    const fs::path at = entry(lab, inputs, names);
    std::error_code ec;
    if (!fs::is_directory(at, ec)) return false;
    try {
        // The key only finds the entry; the inputs it was built from must be these, byte for byte, and the binary
        // what was stored (its fingerprint written beside it).
        const bool same = read_build_inputs(at / "inputs") == inputs && read_bytes(at / "stamp") == kit_stamp_ &&
                          read_bytes(at / "names") == names_record(names);
        const std::string binary = read_bytes(at / "binary");
        Fnv1a check;
        check.add(binary.data(), binary.size());
        if (!same || read_bytes(at / "binary.fnv") != check.hex()) {
            note += "\nbuild cache: the entry " + at.string() + " does not hold what its key says; removed, the lab is built";
            remove_folder(at);
            return false;
        }
        // Every other file its build read must be as it was: a text the C++ includes, a header of the kit's.
        if (const std::string changed = changed_since(at, lab_folder); !changed.empty()) {
            note += "\nbuild cache: the earlier build of these sources read " + changed + ", which has changed since; the lab is built";
            return false;
        }
        fs::create_directories(to.parent_path());
        if (!write_bytes(to, binary)) throw Error("cannot write '" + to.string() + "'");
        fs::permissions(to, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read |
                                fs::perms::others_exec);
        return true;
    } catch (const std::exception& e) {
        note += std::string("\nbuild cache: ") + e.what() + "; the lab is built";
        return false;
    }
}

void BuildCache::store(const std::string& lab, const fs::path& lab_folder, const ReadFiles& reads, const fs::path& binary,
                       std::string& note) const {
    // Written under a name of its own, then renamed into place: a reader sees a whole entry or none.
    std::random_device random;
    const auto unique = [&] { return std::to_string(random()) + std::to_string(random()); };
    const fs::path partial = folder_ / (".partial-" + unique());
    try {
        const BuildInputs inputs = read_build_inputs(lab_folder);
        const std::vector<std::string> names = file_names(lab_folder);
        const fs::path at = entry(lab, inputs, names);
        fs::create_directories(partial / "inputs");
        const auto write_tree = [&](const fs::path& root, const std::map<std::string, std::string>& files) {
            for (const auto& [name, bytes] : files) {
                fs::create_directories((root / name).parent_path());
                if (!write_bytes(root / name, bytes)) throw Error("cannot write '" + (root / name).string() + "'");
            }
        };
        write_tree(partial / "inputs", inputs);
        fs::create_directories(partial / "read");
        write_tree(partial / "read", reads.in_lab);
        const std::string built = read_bytes(binary);
        Fnv1a check;
        check.add(built.data(), built.size());
        if (!write_bytes(partial / "binary", built) || !write_bytes(partial / "binary.fnv", check.hex()) ||
            !write_bytes(partial / "stamp", kit_stamp_) || !write_bytes(partial / "names", names_record(names)) ||
            !write_bytes(partial / "reads", reads_record(reads)))
            throw Error("cannot write into '" + partial.string() + "' (is the disk full?)");
        std::error_code ec;
        // An entry of the same inputs whose reads have changed since (a text it includes) makes way for this one.
        if (fs::is_directory(at, ec)) {
            const fs::path stale = folder_ / (".stale-" + unique());
            fs::rename(at, stale, ec);
            if (!ec) remove_folder(stale);
        }
        fs::rename(partial, at, ec);  // another grader may have stored the same build meanwhile: theirs is as good
        if (ec) remove_folder(partial);
    } catch (const std::exception& e) {
        note += std::string("\nbuild cache: ") + e.what() + "; this build is not kept";
        std::error_code ignored;
        if (fs::exists(partial, ignored)) {
            try {
                remove_folder(partial);
            } catch (const std::exception&) {
            }
        }
    }
}

}  // namespace gsv
