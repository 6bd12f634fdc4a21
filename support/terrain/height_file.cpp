// Reading the .height file format of support/terrain/height_field.h: load_height_field.
#include "support/terrain/height_field.h"

#include "common/core/error.h"
#include "common/io/data_file.h"
#include "common/io/little_endian.h"
#include "support/terrain/height_format.h"

#include <algorithm>
#include <cstddef>
#include <fstream>
#include <limits>
#include <string>
#include <system_error>
#include <vector>

namespace gsv {
namespace {

using namespace height_format;

const data_file::Format kFormat{"height", kMagic, kVersion, "GSVHEIGHT 1 <width> <height> <dx_m> <dy_m>", 128};

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) { data_file::fail(kFormat, path, what); }

double parse_metres(const std::filesystem::path& path, const char* name, const std::string& text) {
    const std::optional<double> value = parse_spacing(text);
    if (!value) fail(path, std::string(name) + " '" + data_file::printable(text) + "' is not a positive, finite number of metres");
    return *value;
}

// Opens the file and reads its header line, leaving `in` at the first height byte. Everything the header
// alone can show wrong is refused here, before any height is read or allocated.
HeightField read_header(const std::filesystem::path& path, std::ifstream& in) {
    std::string line;
    const std::vector<std::string> fields = data_file::open_with_header(kFormat, path, in, &line);
    if (fields.size() != 6)
        fail(path, "header '" + data_file::printable(line) + "' is not '" + kFormat.shape + "'");

    HeightField field;
    field.width = data_file::parse_count(kFormat, path, "width", fields[2], kMaxHeightSide);
    field.height = data_file::parse_count(kFormat, path, "height", fields[3], kMaxHeightSide);
    field.dx_m = parse_metres(path, "dx_m", fields[4]);
    field.dy_m = parse_metres(path, "dy_m", fields[5]);
    return field;
}

// Reads the heights chunk by chunk, so the vector grows only with bytes really in the file, then refuses
// anything after them.
void read_heights(const std::filesystem::path& path, std::ifstream& in, HeightField& field) {
    const std::size_t count = static_cast<std::size_t>(field.width) * static_cast<std::size_t>(field.height);
    const std::uint64_t expected = height_bytes(field.width, field.height);
    std::uint64_t found = 0;
    data_file::read_floats(
        kFormat, path, in, count, field.heights, found,
        [&](std::uint64_t read) {
            fail(path, "expected " + std::to_string(expected) + " bytes of heights, found " + std::to_string(read) + " (" +
                           std::to_string(field.width) + "x" + std::to_string(field.height) + " samples, 4 bytes each)");
        },
        [&](std::size_t i, float value) { fail(path, "height at " + sample_name(i, field.width) + " is " + non_finite_kind(value)); });
    data_file::refuse_trailing_bytes(kFormat, path, in, expected, "heights");
}

}  // namespace

HeightField load_height_field(const std::filesystem::path& path) {
    std::ifstream in;
    HeightField field = read_header(path, in);
    read_heights(path, in, field);
    return field;
}

}  // namespace gsv
