// Writing the .height file format of support/terrain/height_field.h: save_height_field.
#include "support/terrain/height_field.h"

#include "common/core/error.h"
#include "common/io/little_endian.h"
#include "support/terrain/height_format.h"

#include <algorithm>
#include <cstddef>
#include <fstream>
#include <string>
#include <vector>

namespace gsv {
namespace {

using namespace height_format;

// Everything load_height_field would refuse, checked before the file is opened, so a refused save leaves
// no half-written file behind.
void check_savable(const std::filesystem::path& path, const HeightField& field) {
    const auto refuse = [&](const std::string& what) { throw Error("save_height_field " + quoted(path) + ": " + what); };
    const auto side_ok = [](int side) { return side >= 1 && side <= kMaxHeightSide; };
    if (!side_ok(field.width) || !side_ok(field.height))
        refuse("size " + std::to_string(field.width) + "x" + std::to_string(field.height) + " is not in 1.." +
               std::to_string(kMaxHeightSide) + " each way");
    // The text written is what the loader will parse, so the loader's own test decides.
    for (const auto& [name, value] : {std::pair{"dx_m", field.dx_m}, std::pair{"dy_m", field.dy_m}})
        if (!parse_spacing(spacing_text(value)))
            refuse(std::string(name) + " " + printf_g(value, 17) + " is not a positive, finite number of metres");
    const std::size_t count = static_cast<std::size_t>(field.width) * static_cast<std::size_t>(field.height);
    if (field.heights.size() != count)
        refuse(std::to_string(field.heights.size()) + " heights for " + std::to_string(field.width) + "x" +
               std::to_string(field.height) + " samples, which need " + std::to_string(count));
    for (std::size_t i = 0; i < count; ++i)
        if (!std::isfinite(field.heights[i]))
            refuse("height at " + sample_name(i, field.width) + " is " + non_finite_kind(field.heights[i]));
}

}  // namespace

void save_height_field(const std::filesystem::path& path, const HeightField& field) {
    check_savable(path, field);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw Error("cannot write height file " + quoted(path));
    const std::string header = std::string(kMagic) + " " + kVersion + " " + std::to_string(field.width) + " " +
                               std::to_string(field.height) + " " + spacing_text(field.dx_m) + " " +
                               spacing_text(field.dy_m) + "\n";
    out.write(header.data(), static_cast<std::streamsize>(header.size()));
    std::vector<unsigned char> chunk(kChunkBytes);
    for (std::size_t done = 0; done < field.heights.size();) {
        const std::size_t n = std::min(field.heights.size() - done, chunk.size() / sizeof(float));
        for (std::size_t i = 0; i < n; ++i) float_to_le_bytes(field.heights[done + i], chunk.data() + 4 * i);
        out.write(reinterpret_cast<const char*>(chunk.data()), static_cast<std::streamsize>(n * sizeof(float)));
        done += n;
    }
    out.close();
    if (!out) throw Error("cannot write height file " + quoted(path) + ": write error");
}

}  // namespace gsv
