#include "grader/src/run/build_reuse.h"

#include "common/core/error.h"
#include "common/core/fnv1a.h"
#include "common/io/folder_tree.h"

#include <algorithm>
#include <array>
#include <fstream>
#include <iterator>
#include <random>
#include <regex>
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

}  // namespace

bool is_build_input(const fs::path& file) {
    static const std::array<const char*, 16> kReadAtRunTime = {
        ".glsl", ".vert", ".frag", ".comp", ".geom", ".tesc", ".tese", ".network",
        ".json", ".md", ".txt", ".png", ".jpg", ".obj", ".csv", ".pdf"};
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    return std::find_if(kReadAtRunTime.begin(), kReadAtRunTime.end(),
                        [&](const char* e) { return extension == e; }) == kReadAtRunTime.end();
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

BuildCache::BuildCache(fs::path folder, const fs::path& kit_build) : folder_(std::move(folder)), kit_stamp_(kit_build_stamp(kit_build)) {}

fs::path BuildCache::entry(const std::string& lab, const BuildInputs& inputs) const {
    Fnv1a key;
    key.add(kit_stamp_);
    key.add(lab);
    for (const auto& [name, bytes] : inputs) {
        key.add(name);
        key.add(std::to_string(bytes.size()));
        key.add(bytes.data(), bytes.size());
    }
    return folder_ / (lab + "-" + key.hex());
}

bool BuildCache::fetch(const std::string& lab, const BuildInputs& inputs, const fs::path& to, std::string& note) const {
    const fs::path at = entry(lab, inputs);
    std::error_code ec;
    if (!fs::is_directory(at, ec)) return false;
    try {
        // The key only finds the entry; the inputs it was built from must be these, byte for byte, and the binary
        // what was stored (its fingerprint written beside it).
        const bool same = read_build_inputs(at / "inputs") == inputs && read_bytes(at / "stamp") == kit_stamp_;
        const std::string binary = read_bytes(at / "binary");
        Fnv1a check;
        check.add(binary.data(), binary.size());
        if (!same || read_bytes(at / "binary.fnv") != check.hex()) {
            note += "\nbuild cache: the entry " + at.string() + " does not hold what its key says; removed, the lab is built";
            remove_folder(at);
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

void BuildCache::store(const std::string& lab, const BuildInputs& inputs, const fs::path& binary, std::string& note) const {
    const fs::path at = entry(lab, inputs);
    std::error_code ec;
    if (fs::is_directory(at, ec)) return;
    // Written under a name of its own, then renamed into place: a reader sees a whole entry or none.
    std::random_device random;
    const fs::path partial = folder_ / (".partial-" + std::to_string(random()) + std::to_string(random()));
    try {
        fs::create_directories(partial / "inputs");
        for (const auto& [name, bytes] : inputs) {
            fs::create_directories((partial / "inputs" / name).parent_path());
            if (!write_bytes(partial / "inputs" / name, bytes)) throw Error("cannot write '" + (partial / "inputs" / name).string() + "'");
        }
        const std::string built = read_bytes(binary);
        Fnv1a check;
        check.add(built.data(), built.size());
        if (!write_bytes(partial / "binary", built) || !write_bytes(partial / "binary.fnv", check.hex()) ||
            !write_bytes(partial / "stamp", kit_stamp_))
            throw Error("cannot write into '" + partial.string() + "' (is the disk full?)");
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
