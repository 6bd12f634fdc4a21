#include "common/app/known_mistake_pictures.h"

#include "common/app/kit_layout.h"
#include "common/core/error.h"
#include "common/core/fnv1a.h"
#include "common/io/json.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>

namespace fs = std::filesystem;

namespace gsv {
namespace {

constexpr const char* kPictureFile = "mistakes.png";

std::string file_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("cannot read '" + path.string() + "'");
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string trimmed(const std::string& line) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) return "";
    return line.substr(first, line.find_last_not_of(" \t\r") - first + 1);
}

// Every regular file under `folder` (relative name and bytes) into the fingerprint, in name order.
void add_folder(Fnv1a& f, const fs::path& folder, const std::set<std::string>& skip = {}) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) {
        f.add("(no " + folder.filename().string() + ")");
        return;
    }
    std::vector<fs::path> files;
    for (const auto& e : fs::recursive_directory_iterator(folder, ec))
        if (e.is_regular_file() && !skip.count(e.path().filename().string())) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) {
        f.add(fs::relative(file, folder).generic_string());
        f.add(file_bytes(file));
    }
}

Image crop(const Image& atlas, int x, int y, int w, int h) {
    Image out(w, h);
    for (int row = 0; row < h; ++row)
        std::copy_n(atlas.at(x, y + row), static_cast<std::size_t>(w) * 4, out.at(0, row));
    return out;
}

}  // namespace

fs::path known_mistakes_file(const fs::path& kit_root, const std::string& lab) {
    return KitLayout{kit_root}.golden_dir(lab) / "mistakes.json";
}

namespace {

// The atlas's pixels, fingerprinted: the index (mistakes.json) names the atlas it was written with, so that an index
// kept beside another atlas (one regenerated while the other was kept) is refused instead of naming the wrong pictures.
std::string atlas_fingerprint(const Image& atlas) {
    Fnv1a f;
    f.add(std::to_string(atlas.width) + "x" + std::to_string(atlas.height));
    f.add(reinterpret_cast<const char*>(atlas.rgba.data()), atlas.rgba.size());
    return f.hex();
}

}  // namespace

KnownMistakePictures read_known_mistake_pictures(const fs::path& kit_root, const std::string& lab) {
    KnownMistakePictures k;
    k.lab = lab;
    const fs::path file = known_mistakes_file(kit_root, lab);
    std::error_code ec;
    if (!fs::exists(file, ec)) return k;
    const Json j = read_json_file(file);
    if (j.string_at("lab") != lab) throw Error(file.string() + ": holds the mistakes of '" + j.string_at("lab") + "', not " + lab);
    k.lab_dir = j.string_at("lab_dir");
    k.block = j.int_at("block");
    k.inputs = j.string_or("inputs", "");
    for (const Json& m : j.array_at("mistakes").as_array()) {
        ShippedMistake s{m.string_at("id"), m.string_at("todo"), m.string_at("says"), m.string_at("sheet"),
                         m.bool_or("not_started", false), {}, {}};
        if (const Json* starter = m.find("starter"))
            for (const auto& [name, blocks] : starter->as_object())
                for (const Json& block : blocks.as_array()) {
                    s.starter[name].emplace_back();
                    for (const Json& line : block.as_array()) s.starter[name].back().push_back(line.as_string());
                }
        for (const Json& c : m.array_at("fails").as_array()) s.fails.insert(c.as_string());
        k.mistakes.push_back(std::move(s));
    }
    const Json& pictures = j.array_at("pictures");
    if (pictures.size() == 0) return k;
    const Image atlas = read_png(file.parent_path() / kPictureFile);
    if (atlas_fingerprint(atlas) != j.string_at("atlas"))
        throw Error(file.string() + ": indexes another " + kPictureFile + " than the one beside it (the two are written "
                    "together by gsv-grade --update-mistakes: keep or commit both)");
    const int bw = j.int_at("blocks_wide"), bh = j.int_at("blocks_high");
    for (const Json& p : pictures.as_array()) {
        const int row = p.int_at("row");
        const std::size_t mistake = static_cast<std::size_t>(p.int_at("mistake"));
        if (mistake >= k.mistakes.size() || row < 0 || (row + 1) * bh > atlas.height || 2 * bw > atlas.width)
            throw Error(file.string() + ": a picture of case '" + p.string_at("case") + "' points outside " + kPictureFile +
                        " or the mistakes (mistake " + std::to_string(mistake) + ", row " + std::to_string(row) + ")");
        PictureSignature s;
        s.block = k.block;
        s.colour = crop(atlas, 0, row * bh, bw, bh);
        s.texture = crop(atlas, bw, row * bh, bw, bh);
        k.cases[p.string_at("case")].push_back({mistake, std::move(s)});
    }
    return k;
}

void write_known_mistake_pictures(const fs::path& kit_root, const KnownMistakePictures& k) {
    Json j = Json::object();
    j["lab"] = k.lab;
    j["lab_dir"] = k.lab_dir;
    j["block"] = k.block;
    j["inputs"] = k.inputs;
    Json mistakes = Json::array();
    for (const ShippedMistake& m : k.mistakes) {
        Json e = Json::object();
        e["id"] = m.id;
        e["todo"] = m.todo;
        e["says"] = m.says;
        e["sheet"] = m.sheet;
        if (m.not_started) {
            e["not_started"] = true;
            Json starter = Json::object();
            for (const auto& [name, blocks] : m.starter) {
                Json list = Json::array();
                for (const auto& block : blocks) {
                    Json lines = Json::array();
                    for (const std::string& line : block) lines.push_back(line);
                    list.push_back(std::move(lines));
                }
                starter[name] = std::move(list);
            }
            e["starter"] = std::move(starter);
        }
        Json fails = Json::array();
        for (const std::string& c : m.fails) fails.push_back(c);
        e["fails"] = std::move(fails);
        mistakes.push_back(std::move(e));
    }
    j["mistakes"] = std::move(mistakes);
    // One atlas: a row of blocks per distinct signature, its colour then its texture.
    std::vector<const PictureSignature*> rows;
    Json pictures = Json::array();
    int bw = 0, bh = 0;
    for (const auto& [name, list] : k.cases)
        for (const ShippedPicture& p : list) {
            bw = p.signature.colour.width;
            bh = p.signature.colour.height;
            const auto same = std::find_if(rows.begin(), rows.end(), [&](const PictureSignature* r) {
                return r->colour.rgba == p.signature.colour.rgba && r->texture.rgba == p.signature.texture.rgba;
            });
            Json e = Json::object();
            e["case"] = name;
            e["mistake"] = p.mistake;
            e["row"] = static_cast<int>(same - rows.begin());
            if (same == rows.end()) rows.push_back(&p.signature);
            pictures.push_back(std::move(e));
        }
    j["blocks_wide"] = bw;
    j["blocks_high"] = bh;
    j["pictures"] = std::move(pictures);
    const fs::path file = known_mistakes_file(kit_root, k.lab);
    if (!rows.empty()) {
        Image atlas(2 * bw, bh * static_cast<int>(rows.size()));
        for (std::size_t r = 0; r < rows.size(); ++r)
            for (int y = 0; y < bh; ++y) {
                std::copy_n(rows[r]->colour.at(0, y), static_cast<std::size_t>(bw) * 4, atlas.at(0, static_cast<int>(r) * bh + y));
                std::copy_n(rows[r]->texture.at(0, y), static_cast<std::size_t>(bw) * 4, atlas.at(bw, static_cast<int>(r) * bh + y));
            }
        write_png(file.parent_path() / kPictureFile, atlas);
        j["atlas"] = atlas_fingerprint(atlas);
    } else {
        fs::remove(file.parent_path() / kPictureFile);
    }
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out << j.dump(1) << "\n";
    if (!out) throw Error("cannot write '" + file.string() + "'");
}

std::string mistake_pictures_inputs(const fs::path& kit_root, const std::string& lab, const std::string& lab_dir) {
    const KitLayout kit{kit_root};
    Fnv1a f;
    f.add(file_bytes(kit.tests() / "mutants" / (lab + ".json")));
    f.add(file_bytes(kit.case_file(lab)));
    add_folder(f, kit.golden_dir(lab), {"mistakes.json", kPictureFile});
    add_folder(f, kit.solutions() / lab_dir, {KitLayout::kLabDescription});  // no picture comes from the description
    return f.hex();
}

std::vector<std::size_t> matching_mistakes(const KnownMistakePictures& k, const std::string& case_name, const Image& picture,
                                           const Image& golden) {
    const auto it = k.cases.find(case_name);
    if (it == k.cases.end() || picture.width != golden.width || picture.height != golden.height) return {};
    const PictureSignature yours = picture_signature(picture, k.block), expected = picture_signature(golden, k.block);
    if (yours.colour.width != it->second.front().signature.colour.width ||
        yours.colour.height != it->second.front().signature.colour.height)
        return {};
    std::vector<std::pair<double, std::size_t>> near;
    for (const ShippedPicture& p : it->second)
        if (signature_matches(yours, p.signature, expected)) near.push_back({signature_distance(yours, p.signature), p.mistake});
    std::stable_sort(near.begin(), near.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::size_t> out;
    for (const auto& n : near) out.push_back(n.second);
    return out;
}

std::optional<MistakePanel> known_mistake_panel(const KnownMistakePictures& k, const std::string& case_name, const Image& picture,
                                                const Image& golden) {
    const std::vector<std::size_t> matches = matching_mistakes(k, case_name, picture, golden);
    if (matches.empty()) return std::nullopt;
    const ShippedMistake& m = k.mistakes[matches.front()];
    for (const ShippedPicture& p : k.cases.at(case_name))
        if (p.mistake == matches.front())
            return MistakePanel{signature_picture(p.signature, picture.width, picture.height),
                                (m.not_started ? m.todo + " looks not started: its part draws as the starter's"
                                               : "looks like a known mistake in " + m.todo + ": " + m.says) +
                                    " (its picture, reduced)"};
    return std::nullopt;
}

bool holds_starter(const fs::path& student_folder, const std::string& todo, const StarterBlocks& blocks) {
    const std::string marker = "TODO(" + todo + ")";
    for (const auto& [file, list] : blocks) {
        std::error_code ec;
        if (list.empty() || !fs::is_regular_file(student_folder / file, ec)) continue;
        std::vector<std::string> student;
        std::istringstream in(file_bytes(student_folder / file));
        for (std::string line; std::getline(in, line);)
            if (!trimmed(line).empty()) student.push_back(trimmed(line));
        // Right after each comment that names the TODO (and the comment lines with it): a block's lines and the line
        // after it, in a row. The block may open with comment lines of its own (lab 05's "Until then, zeros"), so it
        // may start on any line of that comment, not only after it.
        for (std::size_t i = 0; i < student.size(); ++i) {
            if (student[i].find(marker) == std::string::npos) continue;
            std::size_t last = i + 1;
            while (last < student.size() && student[last].rfind("//", 0) == 0) ++last;
            for (auto block : list) {
                block.erase(std::remove(block.begin(), block.end(), std::string()), block.end());
                for (std::size_t at = i + 1; at <= last && !block.empty() && at + block.size() <= student.size(); ++at)
                    if (std::equal(block.begin(), block.end(), student.begin() + static_cast<long>(at))) return true;
            }
        }
    }
    return false;
}

}  // namespace gsv
