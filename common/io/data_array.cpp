#include "common/io/data_array.h"

#include "common/core/error.h"
#include "common/io/little_endian.h"

#include <algorithm>
#include <fstream>
#include <set>
#include <system_error>

namespace fs = std::filesystem;

namespace gsv {
namespace {

// Files are read and written this many bytes at a time, so neither side holds a second copy as bytes.
constexpr std::size_t kChunkBytes = std::size_t(1) << 20;

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

}  // namespace

bool valid_array_name(const std::string& name) {
    return !name.empty() && name.size() <= kMaxArrayNameBytes &&
           std::all_of(name.begin(), name.end(), [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'; });
}

void check_data_arrays(const std::vector<DataArray>& arrays) {
    if (arrays.size() > kMaxArrays)
        throw Error(std::to_string(arrays.size()) + " readback arrays, more than the " +
                    std::to_string(kMaxArrays) + " the grader reads");
    std::set<std::string> seen;
    std::uint64_t floats = 0;
    for (const auto& a : arrays) {
        const std::string what = "readback array '" + a.name + "'";
        if (!valid_array_name(a.name))
            throw Error(what + ": a name must be 1.." + std::to_string(kMaxArrayNameBytes) +
                        " of a-z, 0-9 and '_' (it names a file)");
        if (!seen.insert(a.name).second) throw Error(what + " is handed in twice");
        if (a.components < 1 || a.components > kMaxArrayComponents)
            throw Error(what + " has " + std::to_string(a.components) + " components, not 1.." +
                        std::to_string(kMaxArrayComponents));
        if (a.values.size() % static_cast<std::size_t>(a.components) != 0)
            throw Error(what + " has " + std::to_string(a.values.size()) + " values, not a whole number of " +
                        std::to_string(a.components) + "-component elements");
        floats += a.values.size();
        if (floats > kMaxArrayFloats)
            throw Error(what + ": the arrays hold more than the " + std::to_string(kMaxArrayFloats) +
                        " values in all that the grader reads");
    }
}

fs::path data_array_path(const fs::path& png, const std::string& name) {
    return png.parent_path() / (png.stem().string() + "." + name + ".f32");
}

void write_f32_file(const fs::path& path, const std::vector<float>& values) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw Error("cannot write array file " + quoted(path) + ": cannot open it for writing");
    std::vector<unsigned char> chunk(std::min(kChunkBytes, values.size() * sizeof(float)));
    for (std::size_t done = 0; done < values.size();) {
        const std::size_t n = std::min(values.size() - done, chunk.size() / sizeof(float));
        for (std::size_t i = 0; i < n; ++i) float_to_le_bytes(values[done + i], chunk.data() + 4 * i);
        out.write(reinterpret_cast<const char*>(chunk.data()), static_cast<std::streamsize>(n * sizeof(float)));
        done += n;
    }
    out.close();
    // A full disk shows up only when the buffer is flushed, so check after close().
    if (!out) throw Error("cannot write array file " + quoted(path) + ": write error (disk full?)");
}

std::vector<float> read_f32_file(const fs::path& path, std::uint64_t floats) {
    std::error_code ec;
    const fs::file_status status = fs::symlink_status(path, ec);
    if (ec || !fs::exists(status)) throw Error("array file " + quoted(path) + ": no such file");
    // A link could point anywhere the reader may read; only the plain file the lab wrote counts.
    if (!fs::is_regular_file(status)) throw Error("array file " + quoted(path) + ": not a plain file");
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) throw Error("array file " + quoted(path) + ": cannot read its size: " + ec.message());
    if (floats > UINT64_MAX / 4 || size != floats * 4)
        throw Error("array file " + quoted(path) + ": " + std::to_string(size) + " bytes, not the " +
                    std::to_string(floats) + " float32 values (" + std::to_string(floats * 4) + " bytes) listed");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("array file " + quoted(path) + ": cannot open it");
    std::vector<float> values(static_cast<std::size_t>(floats));
    std::vector<unsigned char> chunk(std::min<std::size_t>(kChunkBytes, values.size() * sizeof(float)));
    for (std::size_t done = 0; done < values.size();) {
        const std::size_t n = std::min(values.size() - done, chunk.size() / sizeof(float));
        in.read(reinterpret_cast<char*>(chunk.data()), static_cast<std::streamsize>(n * sizeof(float)));
        // The file may have changed since its size was taken.
        if (static_cast<std::size_t>(in.gcount()) != n * sizeof(float))
            throw Error("array file " + quoted(path) + ": ends after " +
                        std::to_string(done * 4 + static_cast<std::size_t>(in.gcount())) + " bytes");
        for (std::size_t i = 0; i < n; ++i) values[done + i] = float_from_le_bytes(chunk.data() + 4 * i);
        done += n;
    }
    if (in.peek() != std::char_traits<char>::eof()) throw Error("array file " + quoted(path) + ": longer than its listed size");
    return values;
}

}  // namespace gsv
