#include "grader/src/run/reference_store.h"

#include "common/core/fnv1a.h"
#include "grader/src/core/kit_fingerprint.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace fs = std::filesystem;

namespace gsv {
namespace {

constexpr const char* kMagic = "gsv-reference 1\n";
// Bigger renders are rendered each time rather than filling the disk (lab 05's million particles are 32 MiB).
constexpr std::size_t kMaxEntryBytes = 64u << 20;

// The GL driver's files, by name, size and time: a driver update (Mesa's, a vendor's) renders the references anew.
std::string driver_stamp() {
    static const char* kLibraryDirs[] = {"/usr/lib/x86_64-linux-gnu", "/usr/lib/aarch64-linux-gnu", "/usr/lib64", "/usr/lib",
                                         "/usr/local/lib"};
    static const char* kDriverPrefixes[] = {"libEGL", "libGL", "libgallium", "libglapi", "libLLVM", "libnvidia-egl",
                                            "libnvidia-gl", "libnvidia-eglcore", "libnvidia-glcore", "libnvidia-tls"};
    std::vector<std::string> lines;
    const auto add = [&](const fs::directory_entry& e) {
        std::error_code ec;
        const auto size = e.file_size(ec);
        const auto time = e.last_write_time(ec).time_since_epoch().count();
        lines.push_back(e.path().string() + " " + std::to_string(size) + " " + std::to_string(time));
    };
    for (const char* dir : kLibraryDirs) {
        std::error_code ec;
        for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
            const std::string name = it->path().filename().string();
            if (std::any_of(std::begin(kDriverPrefixes), std::end(kDriverPrefixes), [&](const char* p) { return name.rfind(p, 0) == 0; }))
                add(*it);
        }
        std::error_code dri_ec;
        for (auto it = fs::directory_iterator(fs::path(dir) / "dri", dri_ec); !dri_ec && it != fs::directory_iterator(); it.increment(dri_ec))
            add(*it);
    }
    std::sort(lines.begin(), lines.end());
    std::string stamp;
    for (const auto& line : lines) stamp += line + "\n";
    return stamp;
}

// The environment that picks a driver or changes what it draws (GALLIUM_DRIVER=softpipe, LP_NUM_THREADS,
// MESA_GL_VERSION_OVERRIDE, the margin table's GSV_TEXEL_SNAP, ...), sorted.
std::string driver_environment() {
    static const char* kPrefixes[] = {"GALLIUM_", "LP_", "MESA_", "LIBGL_", "SOFTPIPE_", "EGL_", "__GLX_", "__EGL_", "GSV_",
                                      "DRI_", "vblank_mode"};
    std::vector<std::string> lines;
    for (char** e = environ; e && *e; ++e) {
        const std::string entry = *e;
        if (std::any_of(std::begin(kPrefixes), std::end(kPrefixes), [&](const char* p) { return entry.rfind(p, 0) == 0; }))
            lines.push_back(entry);
    }
    std::sort(lines.begin(), lines.end());
    std::string text;
    for (const auto& line : lines) text += line + "\n";
    return text;
}

// A little-endian byte writer and a reader that refuses to run past the end.
struct Writer {
    std::string bytes;
    void u32(std::uint32_t v) {
        for (int i = 0; i < 4; ++i) bytes.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
    }
    void text(const std::string& s) {
        u32(static_cast<std::uint32_t>(s.size()));
        bytes += s;
    }
    void raw(const void* data, std::size_t size) { bytes.append(static_cast<const char*>(data), size); }
};

struct Reader {
    const std::string& bytes;
    std::size_t at = 0;
    bool ok = true;
    bool take(std::size_t n) {
        if (!ok || bytes.size() - at < n) return ok = false;
        return true;
    }
    std::uint32_t u32() {
        if (!take(4)) return 0;
        std::uint32_t v = 0;
        for (int i = 0; i < 4; ++i) v |= std::uint32_t(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
        at += 4;
        return v;
    }
    std::string text() {
        const std::uint32_t n = u32();
        if (!take(n)) return {};
        std::string s = bytes.substr(at, n);
        at += n;
        return s;
    }
    void raw(void* data, std::size_t size) {
        if (!take(size)) return;
        std::memcpy(data, bytes.data() + at, size);
        at += size;
    }
};

std::string checksum(const std::string& bytes, std::size_t size) {
    Fnv1a hash;
    hash.add(bytes.data(), size);
    return hash.hex();
}

}  // namespace

std::string file_fingerprint(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return "";
    Fnv1a hash;
    std::vector<char> buffer(1 << 16);
    while (in.read(buffer.data(), static_cast<std::streamsize>(buffer.size())) || in.gcount() > 0)
        hash.add(buffer.data(), static_cast<std::size_t>(in.gcount()));
    return hash.hex();
}

std::string reference_context(const fs::path& kit_root) {
    return "kit " + kit_fingerprint(kit_root) + "\n" + "driver\n" + driver_stamp() + "environment\n" + driver_environment();
}

namespace {

// Why a user other than the grader and root could write `path` itself (a folder or a file); empty when none could.
std::string others_may_write(const fs::path& path, const struct stat& st) {
    if (st.st_uid != 0 && st.st_uid != geteuid()) return path.string() + " belongs to uid " + std::to_string(st.st_uid);
    if ((st.st_mode & (S_IWGRP | S_IWOTH)) && !(S_ISDIR(st.st_mode) && (st.st_mode & S_ISVTX)))
        return path.string() + " is writable by its group or by others";
    return "";
}

}  // namespace

std::string writable_by_others(const fs::path& folder) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(folder, ec);
    if (ec) return "cannot resolve " + folder.string();
    if (!fs::exists(absolute, ec)) {
        fs::create_directories(absolute, ec);
        if (ec) return "cannot make " + absolute.string() + ": " + ec.message();
        fs::permissions(absolute, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read |
                                      fs::perms::others_exec, ec);
    }
    // Every folder from the store up to /, as named and where it really is (links followed): whoever may write one of
    // them may put another folder, or another link, in the store's place.
    const fs::path real = fs::canonical(absolute, ec);
    if (ec) return "cannot resolve " + absolute.string() + ": " + ec.message();
    for (const fs::path& start : {absolute.lexically_normal(), real}) {
        for (fs::path p = start;; p = p.parent_path()) {
            struct stat st {};
            if (lstat(p.c_str(), &st) != 0) return "cannot look at " + p.string();
            // A link's own mode bits mean nothing; who owns it, and the folder holding it (next), do.
            if (S_ISLNK(st.st_mode) ? st.st_uid != 0 && st.st_uid != geteuid() : !others_may_write(p, st).empty())
                return S_ISLNK(st.st_mode) ? p.string() + " is a link of uid " + std::to_string(st.st_uid) : others_may_write(p, st);
            if (p == p.root_path() || p.parent_path() == p) break;
        }
    }
    return "";
}

ReferenceStore::ReferenceStore(fs::path folder) : folder_(std::move(folder)) {}

fs::path ReferenceStore::entry_path(const std::string& key) const {
    Fnv1a hash;
    hash.add(key);
    return folder_ / (hash.hex() + ".ref");
}

std::optional<LabRun> ReferenceStore::load(const std::string& key) {
    const fs::path file = entry_path(key);
    std::error_code ec;
    const auto status = fs::symlink_status(file, ec);
    if (ec || !fs::exists(status)) return std::nullopt;
    const auto damaged = [&](const std::string& why) -> std::optional<LabRun> {
        ++damaged_;
        std::error_code remove_ec;
        fs::remove(file, remove_ec);
        if (problem_.empty()) problem_ = "a stored reference " + file.string() + " " + why + ": removed, and the case rendered";
        return std::nullopt;
    };
    if (!fs::is_regular_file(status)) return damaged("is not a plain file");
    // An entry another user could have changed is not one the grader wrote (store() writes them 0644).
    struct stat st {};
    if (lstat(file.c_str(), &st) != 0 || !others_may_write(file, st).empty() || st.st_nlink != 1)
        return damaged("could have been changed by another user");
    const auto size = fs::file_size(file, ec);
    if (ec || size > kMaxEntryBytes + 4096) return damaged("is too big to be one");
    std::ifstream in(file, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t magic = std::strlen(kMagic);
    if (bytes.size() < magic + 16 || bytes.compare(0, magic, kMagic) != 0) return damaged("is not an entry");
    if (bytes.compare(bytes.size() - 16, 16, checksum(bytes, bytes.size() - 16)) != 0) return damaged("does not match its checksum");
    Reader r{bytes, magic};
    if (r.text() != key) return damaged("holds another case's key");
    LabRun run;
    run.status = CaseStatus::Passed;
    run.detail = r.text();
    run.renderer = r.text();
    Image image;
    image.width = static_cast<int>(r.u32());
    image.height = static_cast<int>(r.u32());
    const std::uint64_t pixels = std::uint64_t(image.width) * std::uint64_t(image.height);
    if (!r.ok || pixels * 4 > bytes.size()) return damaged("has an image of impossible size");
    image.rgba.resize(static_cast<std::size_t>(pixels * 4));
    r.raw(image.rgba.data(), image.rgba.size());
    run.image = std::move(image);
    const std::uint32_t arrays = r.u32();
    if (arrays > kMaxArrays) return damaged("has too many arrays");
    for (std::uint32_t i = 0; r.ok && i < arrays; ++i) {
        DataArray a;
        a.name = r.text();
        a.components = static_cast<int>(r.u32());
        const std::uint32_t floats = r.u32();
        if (!r.ok || std::uint64_t(floats) * 4 > bytes.size()) return damaged("has an array of impossible size");
        a.values.resize(floats);
        r.raw(a.values.data(), a.values.size() * sizeof(float));
        run.arrays.push_back(std::move(a));
    }
    if (!r.ok || r.at != bytes.size() - 16) return damaged("is cut short or too long");
    ++hits_;
    return run;
}

void ReferenceStore::store(const std::string& key, const LabRun& run) {
    if (run.status != CaseStatus::Passed || !run.image) return;
    Writer w;
    w.raw(kMagic, std::strlen(kMagic));
    w.text(key);
    w.text(run.detail);
    w.text(run.renderer);
    w.u32(static_cast<std::uint32_t>(run.image->width));
    w.u32(static_cast<std::uint32_t>(run.image->height));
    w.raw(run.image->rgba.data(), run.image->rgba.size());
    w.u32(static_cast<std::uint32_t>(run.arrays.size()));
    for (const DataArray& a : run.arrays) {
        w.text(a.name);
        w.u32(static_cast<std::uint32_t>(a.components));
        w.u32(static_cast<std::uint32_t>(a.values.size()));
        w.raw(a.values.data(), a.values.size() * sizeof(float));
    }
    if (w.bytes.size() > kMaxEntryBytes) return;
    w.bytes += checksum(w.bytes, w.bytes.size());
    // Written under a private name and renamed in: a reader sees a whole entry or none, and two graders storing the same
    // key at once each rename a whole one.
    const fs::path file = entry_path(key);
    std::random_device random;
    const fs::path part = folder_ / (file.filename().string() + ".part-" + std::to_string(random()));
    std::error_code ec;
    fs::create_directories(folder_, ec);
    std::ofstream out(part, std::ios::binary | std::ios::trunc);
    out.write(w.bytes.data(), static_cast<std::streamsize>(w.bytes.size()));
    out.close();
    // Whatever the umask: only the grader may change an entry, and load() reads no other.
    fs::permissions(part, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read, ec);
    if (!out || ec) {
        fs::remove(part, ec);
        if (problem_.empty())
            problem_ = "cannot store references in " + folder_.string() + " (unwritable or full): every live reference rendered";
        return;
    }
    fs::rename(part, file, ec);
    if (ec) {
        fs::remove(part, ec);
        if (problem_.empty()) problem_ = "cannot store references in " + folder_.string() + ": " + ec.message();
        return;
    }
    ++stored_;
}

}  // namespace gsv
