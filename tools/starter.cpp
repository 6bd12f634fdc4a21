#include "tools/starter.h"

#include "common/app/kit_layout.h"
#include "common/app/lab_sources.h"
#include "common/core/error.h"
#include "common/core/fnv1a.h"
#include "common/io/json.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <functional>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;

namespace gsv {
namespace {

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return "";
    return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("cannot read '" + path.string() + "'");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

namespace {

// `undone(id)`: whether a block of that TODO becomes the starter's.
StarterText convert(const std::string& text, const std::string& file, const std::function<bool(const std::string&)>& undone) {
    enum class State { Both, Solution, Starter } state = State::Both;
    static const std::regex id_pattern(R"(^L[0-9]{2}-T[0-9]+$)");
    StarterText out;
    std::istringstream in(text);
    std::string line;
    int number = 0, block_start = 0;
    bool converting = true;  // this block becomes the starter's
    auto fail = [&](const std::string& what) { throw Error(file + ":" + std::to_string(number) + ": " + what); };
    while (std::getline(in, line)) {
        ++number;
        const std::string t = trim(line);
        if (t.rfind("//@solution", 0) == 0) {
            if (state != State::Both) fail("//@solution inside another block (started at line " + std::to_string(block_start) + ")");
            const std::string id = trim(t.substr(11));
            if (!std::regex_match(id, id_pattern)) fail("//@solution needs a TODO id like L01-T2, got '" + id + "'");
            if (std::find(out.todo_ids.begin(), out.todo_ids.end(), id) == out.todo_ids.end()) out.todo_ids.push_back(id);
            converting = undone(id);
            state = State::Solution;
            block_start = number;
        } else if (t == "//@starter") {
            if (state != State::Solution) fail("//@starter without a //@solution before it");
            state = State::Starter;
        } else if (t == "//@end") {
            if (state != State::Starter) fail("//@end without //@solution and //@starter before it");
            state = State::Both;
        } else if (t.rfind("//@", 0) == 0) {
            fail("unknown marker '" + t + "' (expected //@solution ID, //@starter or //@end)");
        } else if (state == State::Both || (state == State::Solution && !converting)) {
            out.text += line + "\n";
        } else if (state == State::Starter) {
            const auto at = line.find("//");
            if (at == std::string::npos || trim(line.substr(0, at)) != "")
                fail("a starter line must be commented out with // in the solution");
            if (converting) out.text += line.substr(0, at) + line.substr(at + 2) + "\n";
        }
    }
    if (state != State::Both) {
        number = block_start;
        fail("block not closed with //@end");
    }
    if (!text.empty() && text.back() != '\n' && !out.text.empty()) out.text.pop_back();
    return out;
}

}  // namespace

StarterText make_starter(const std::string& text, const std::string& file, const std::string& only_todo) {
    return convert(text, file, [&](const std::string& id) { return only_todo.empty() || id == only_todo; });
}

StarterText make_partial_starter(const std::string& text, const std::string& file, const std::set<std::string>& done) {
    return convert(text, file, [&](const std::string& id) { return done.count(id) == 0; });
}

std::vector<StarterFileResult> sync_starters(const fs::path& root, bool write) {
    std::vector<StarterFileResult> results;
    const fs::path solutions = KitLayout{root}.solutions();
    if (!fs::is_directory(solutions)) throw Error("no solutions/ folder in '" + root.string() + "'");
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(solutions))
        if (entry.is_regular_file()) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    // grader/starters.json: each starter's C++ by the fingerprint of its bytes (common/app/lab_sources.h).
    Json manifest = Json::object();
    manifest["about"] = "Written by gsv-make-starters --write with labs/: each starter's C++ (the files a lab's build reads) by the "
                        "FNV-1a of its bytes. Where a lab's C++ is its starter's, the grader knows its cases come out alike whatever "
                        "ran before them in the same process.";
    Json labs = Json::object();
    for (const auto& file : files) {
        StarterFileResult r;
        r.solution = file;
        r.starter = KitLayout{root}.labs() / fs::relative(file, solutions);
        const std::string generated = make_starter(read_text(file), fs::relative(file, root).generic_string()).text;
        const fs::path in_labs = fs::relative(file, solutions);
        if (is_build_input(file) && in_labs.begin() != in_labs.end()) {
            Fnv1a hash;
            hash.add(generated.data(), generated.size());
            fs::path inside;
            for (auto part = std::next(in_labs.begin()); part != in_labs.end(); ++part) inside /= *part;
            labs[in_labs.begin()->string()][inside.generic_string()] = hash.hex();
        }
        std::string existing;
        if (fs::exists(r.starter)) existing = read_text(r.starter);
        r.up_to_date = fs::exists(r.starter) && existing == generated;
        if (write && !r.up_to_date) {
            fs::create_directories(r.starter.parent_path());
            std::ofstream out(r.starter, std::ios::binary);
            if (!out || !(out << generated)) throw Error("cannot write '" + r.starter.string() + "'");
        }
        results.push_back(r);
    }
    manifest["labs"] = labs;
    StarterFileResult m;
    m.solution = solutions;
    m.starter = starter_manifest(root);
    const std::string text = manifest.dump(2) + "\n";
    m.up_to_date = fs::exists(m.starter) && read_text(m.starter) == text;
    if (write && !m.up_to_date) {
        std::ofstream out(m.starter, std::ios::binary);
        if (!out || !(out << text)) throw Error("cannot write '" + m.starter.string() + "'");
    }
    results.push_back(m);
    return results;
}

}  // namespace gsv
