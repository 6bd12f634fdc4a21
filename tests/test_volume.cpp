// Lab 06's data layer: Volume and its GL_LINEAR emulation, the NIfTI-1 reader and writer, the
// Marschner-Lobb signal with its exact gradient and ray hits, ray/box spans, the gradient modules' CPU
// reference (reference/volume/gradient.h), and the Sobel gradient volume of the precomputed module.
#include "catch.hpp"

#include "common/core/error.h"
#include "common/core/splitmix64.h"
#include "support/geometry/ray_box.h"
#include "reference/volume/gradient.h"
#include "support/volume/marschner_lobb.h"
#include "support/volume/nifti_file.h"
#include "support/volume/sobel_gradient.h"
#include "support/volume/volume.h"
#include "test_support.h"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

using gsv::MarschnerLobb;
using gsv::NiftiHeader;
using gsv::Volume;
using gsv::test::gsv_error_message;
using gsv::test::TempDir;
namespace fs = std::filesystem;

namespace {

constexpr double kPi = 3.14159265358979323846;
const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

bool finite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// A volume whose value names its voxel: 100 k + 10 j + i + 0.25, exact in float, so any mix-up of axes or
// any weight that is not exactly 0 or 1 shows.
Volume labelled_volume(int nx, int ny, int nz) {
    Volume volume;
    volume.nx = nx, volume.ny = ny, volume.nz = nz;
    volume.name = "labelled";
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) volume.values.push_back(float(100 * k + 10 * j + i) + 0.25f);
    volume.update_range();
    return volume;
}

Volume constant_volume(int nx, int ny, int nz, float value) {
    Volume volume;
    volume.nx = nx, volume.ny = ny, volume.nz = nz;
    volume.spacing = {0.7, 1.3, 2.9};
    volume.name = "constant";
    volume.values.assign(std::size_t(nx) * ny * nz, value);
    volume.update_range();
    return volume;
}

glm::dvec3 texel_centre(const Volume& volume, int i, int j, int k) {
    return {(i + 0.5) / volume.nx, (j + 0.5) / volume.ny, (k + 0.5) / volume.nz};
}

// ---------------------------------------------------------------------------------------------------------
// NIfTI-1 files built byte by byte, in either byte order, with every field the tests break settable: the
// header layout is the standard's nifti1.h, written out here independently of support/volume/nifti_format.h.

struct NiftiSpec {
    bool big_endian = false;
    std::int32_t sizeof_hdr = 348;
    int dim[8] = {3, 2, 3, 4, 1, 1, 1, 1};
    int datatype = 16, bitpix = 32;
    float pixdim[8] = {1, 1, 1, 1, 0, 0, 0, 0};
    float vox_offset = 352;
    float scl_slope = 0, scl_inter = 0;
    int xyzt_units = 2;
    std::string magic = std::string("n+1\0", 4);
    std::string voxels;  // the bytes after vox_offset, already in the file's byte order
};

void put(std::string& bytes, std::size_t at, std::uint64_t value, int size, bool big_endian) {
    for (int i = 0; i < size; ++i)
        bytes[at + (big_endian ? size - 1 - i : i)] = static_cast<char>((value >> (8 * i)) & 0xff);
}

void put_float(std::string& bytes, std::size_t at, float value, bool big_endian) {
    std::uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    put(bytes, at, bits, 4, big_endian);
}

std::string nifti_bytes(const NiftiSpec& spec) {
    const std::size_t offset = std::max<std::size_t>(352, static_cast<std::size_t>(spec.vox_offset));
    std::string bytes(offset, '\0');
    const bool be = spec.big_endian;
    put(bytes, 0, std::uint32_t(spec.sizeof_hdr), 4, be);
    for (int i = 0; i < 8; ++i) put(bytes, 40 + 2 * i, std::uint16_t(spec.dim[i]), 2, be);
    put(bytes, 70, std::uint16_t(spec.datatype), 2, be);
    put(bytes, 72, std::uint16_t(spec.bitpix), 2, be);
    for (int i = 0; i < 8; ++i) put_float(bytes, 76 + 4 * i, spec.pixdim[i], be);
    put_float(bytes, 108, spec.vox_offset, be);
    put_float(bytes, 112, spec.scl_slope, be);
    put_float(bytes, 116, spec.scl_inter, be);
    bytes[123] = static_cast<char>(spec.xyzt_units);
    bytes.replace(344, 4, spec.magic.substr(0, 4));
    return bytes + spec.voxels;
}

// One stored value of a datatype, in the given byte order.
std::string encode(double value, int datatype, bool big_endian) {
    std::string bytes;
    const auto integer = [&](std::int64_t v, int size) {
        bytes.assign(size, '\0');
        put(bytes, 0, std::uint64_t(v), size, big_endian);
    };
    switch (datatype) {
        case 2: case 256: integer(std::int64_t(value), 1); break;
        case 4: case 512: integer(std::int64_t(value), 2); break;
        case 8: integer(std::int64_t(value), 4); break;
        case 16: bytes.assign(4, '\0'); put_float(bytes, 0, float(value), big_endian); break;
        case 64: {
            std::uint64_t bits;
            std::memcpy(&bits, &value, sizeof bits);
            bytes.assign(8, '\0');
            put(bytes, 0, bits, 8, big_endian);
            break;
        }
        default: FAIL("no encoding for datatype " << datatype);
    }
    return bytes;
}

NiftiSpec float_spec(const std::vector<float>& values, int nx, int ny, int nz, bool big_endian = false) {
    NiftiSpec spec;
    spec.big_endian = big_endian;
    spec.dim[1] = nx, spec.dim[2] = ny, spec.dim[3] = nz;
    for (float v : values) spec.voxels += encode(v, 16, big_endian);
    return spec;
}

// The message of the gsv::Error that load_nifti throws for `path`, checked to be one line naming the file.
std::string load_error(const fs::path& path) {
    const std::string message = gsv_error_message([&] { gsv::load_nifti(path); });
    CHECK(contains(message, "'" + path.string() + "'"));
    CHECK_FALSE(contains(message, "\n"));
    return message;
}

// gzip's own format through zlib, as `gzip` writes it.
std::string gzipped(const std::string& bytes) {
    z_stream stream{};
    REQUIRE(deflateInit2(&stream, Z_BEST_COMPRESSION, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) == Z_OK);
    std::string out(deflateBound(&stream, static_cast<uLong>(bytes.size())) + 64, '\0');
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
    stream.avail_in = static_cast<uInt>(bytes.size());
    stream.next_out = reinterpret_cast<Bytef*>(out.data());
    stream.avail_out = static_cast<uInt>(out.size());
    REQUIRE(deflate(&stream, Z_FINISH) == Z_STREAM_END);
    out.resize(stream.total_out);
    deflateEnd(&stream);
    return out;
}

fs::path anatomical_path() { return fs::path(GSV_SOURCE_ROOT) / "data/volumes/anatomical.nii"; }

// The first t in [a, b] where rho - iso changes sign, by marching n equal steps: a bracket [t_k, t_k+1]
// that the hit must lie in, or nothing.
std::optional<std::pair<double, double>> dense_bracket(glm::dvec3 o, glm::dvec3 d, double a, double b, double iso,
                                                       int n) {
    double ta = a, ga = gsv::marschner_lobb(o + ta * d) - iso;
    for (int s = 1; s <= n; ++s) {
        const double tb = a + (b - a) * s / n, gb = gsv::marschner_lobb(o + tb * d) - iso;
        if (ga == 0) return std::pair{ta, ta};
        if ((ga < 0) != (gb < 0) || gb == 0) return std::pair{ta, tb};
        ta = tb, ga = gb;
    }
    return std::nullopt;
}

}  // namespace

// ---------------------------------------------------------------------------------------------------------
// Volume

TEST_CASE("volume: index and at run x fastest, then y, then z, and throw outside the grid", "[unit][volume]") {
    const Volume volume = labelled_volume(5, 4, 3);
    CHECK(volume.index(0, 0, 0) == 0);
    CHECK(volume.index(1, 0, 0) == 1);
    CHECK(volume.index(0, 1, 0) == 5);
    CHECK(volume.index(0, 0, 1) == 20);
    CHECK(volume.index(4, 3, 2) == 59);
    CHECK(volume.at(3, 2, 1) == 123.25f);
    CHECK(volume.min == 0.25f);
    CHECK(volume.max == 234.25f);
    for (const glm::ivec3& v : {glm::ivec3(-1, 0, 0), glm::ivec3(5, 0, 0), glm::ivec3(0, 4, 0), glm::ivec3(0, 0, 3)}) {
        const std::string message = gsv_error_message([&] { volume.at(v.x, v.y, v.z); });
        CHECK(contains(message, "is outside the 5x4x3 grid of volume 'labelled'"));
    }
    Volume short_of_values = volume;
    short_of_values.values.pop_back();
    CHECK(contains(gsv_error_message([&] { short_of_values.at(0, 0, 0); }), "is 5x4x3 but holds 59 values"));
}

TEST_CASE("volume: extent is n times the anisotropic spacing", "[unit][volume]") {
    Volume volume = labelled_volume(5, 4, 3);
    volume.spacing = {0.5, 2.0, 3.25};
    CHECK(volume.extent() == glm::dvec3(2.5, 8.0, 9.75));
}

TEST_CASE("volume: sample at texel centres returns the voxel exactly, for odd and even sizes", "[unit][volume]") {
    // 41 and 7 are not powers of two: (i + 0.5) / n is rounded, and the lookup must still land on voxel i.
    for (const auto& [nx, ny, nz] : {std::tuple{4, 2, 8}, std::tuple{41, 7, 3}, std::tuple{1, 5, 2}}) {
        const Volume volume = labelled_volume(nx, ny, nz);
        for (int k = 0; k < nz; ++k)
            for (int j = 0; j < ny; ++j)
                for (int i = 0; i < nx; ++i) REQUIRE(volume.sample(texel_centre(volume, i, j, k)) == volume.at(i, j, k));
    }
}

TEST_CASE("volume: sample clamps to the edge voxel in the outer half texel and beyond 0..1", "[unit][volume]") {
    const Volume volume = labelled_volume(5, 4, 3);
    const glm::dvec3 middle = texel_centre(volume, 2, 1, 1);
    // x: the outer half texel, the edge itself, and far outside, on both sides.
    for (double s : {0.0, 0.05, -0.5, -1e300, -kInf}) CHECK(volume.sample({s, middle.y, middle.z}) == volume.at(0, 1, 1));
    for (double s : {1.0, 0.95, 1.5, 1e300, kInf}) CHECK(volume.sample({s, middle.y, middle.z}) == volume.at(4, 1, 1));
    // All three axes at once: the corners.
    CHECK(volume.sample({-1, -1, -1}) == volume.at(0, 0, 0));
    CHECK(volume.sample({2, 2, 2}) == volume.at(4, 3, 2));
    // A one-voxel volume is its value everywhere.
    Volume one = labelled_volume(1, 1, 1);
    for (double s : {-1.0, 0.0, 0.3, 1.0, 9.0}) CHECK(one.sample({s, s, s}) == 0.25);
}

TEST_CASE("volume: sample between centres is the trilinear mix, and a NaN coordinate gives NaN", "[unit][volume]") {
    const Volume volume = labelled_volume(5, 4, 3);
    // Halfway between the centres of voxels 1 and 2 along every axis: the mean of the 8 voxels around it,
    // exact here (quarters and halves of small integers).
    const glm::dvec3 halfway(2.0 / 5, 2.0 / 4, 2.0 / 3);
    double mean = 0;
    for (int k = 1; k <= 2; ++k)
        for (int j = 1; j <= 2; ++j)
            for (int i = 1; i <= 2; ++i) mean += volume.at(i, j, k) / 8.0;
    CHECK(volume.sample(halfway) == Approx(mean).epsilon(1e-15));
    // A quarter of the way from voxel 3 to voxel 4 along x: the value is linear in i, so 3.25 + 0.25.
    const glm::dvec3 centre = texel_centre(volume, 3, 2, 1);
    CHECK(volume.sample(centre + glm::dvec3(0.25 / 5, 0, 0)) == Approx(volume.at(3, 2, 1) + 0.25).epsilon(1e-14));
    CHECK(std::isnan(volume.sample({kNaN, 0.5, 0.5})));
    CHECK(std::isnan(volume.sample({0.5, 0.5, kNaN})));
}

TEST_CASE("volume: normalized maps min to 0 and max to 1, a constant volume to 0 with no NaN", "[unit][volume]") {
    Volume volume;
    volume.nx = 3, volume.ny = 1, volume.nz = 1;
    volume.values = {-2.0f, 0.0f, 6.0f};
    volume.update_range();
    const Volume unit = volume.normalized();
    CHECK(unit.values == std::vector<float>{0.0f, 0.25f, 1.0f});
    CHECK(unit.min == 0.0f);
    CHECK(unit.max == 1.0f);
    // A window narrower than the data saturates, as an 8-bit texture would.
    volume.min = 0, volume.max = 2;
    CHECK(volume.normalized().values == std::vector<float>{0.0f, 0.0f, 1.0f});

    const Volume flat = constant_volume(4, 3, 5, 7.3f).normalized();
    CHECK(std::all_of(flat.values.begin(), flat.values.end(), [](float v) { return v == 0.0f; }));
    CHECK(flat.min == 0.0f);
    CHECK(flat.max == 0.0f);

    volume.min = 3, volume.max = 1;
    CHECK(contains(gsv_error_message([&] { volume.normalized(); }), "not finite min <= max"));
    volume.min = 0, volume.max = std::numeric_limits<float>::infinity();
    CHECK(contains(gsv_error_message([&] { volume.normalized(); }), "not finite min <= max"));
}

TEST_CASE("volume: a percentile window leaves the outliers out of the range that normalized maps onto 0 to 1", "[unit][volume]") {
    Volume volume;
    volume.nx = 1000, volume.ny = 1, volume.nz = 1;
    for (int i = 0; i < 1000; ++i) volume.values.push_back(static_cast<float>(i));
    volume.values[999] = 1e6f;  // one outlier, like an MRI's brightest voxel
    volume.set_percentile_window(0.01, 0.99);
    CHECK(volume.min == 10.0f);
    CHECK(volume.max == 990.0f);
    const Volume unit = volume.normalized();
    CHECK(unit.values[500] == Approx(490.0 / 980.0));
    CHECK(unit.values[999] == 1.0f);  // saturated
    CHECK(unit.values[0] == 0.0f);
    volume.set_percentile_window(0.0, 1.0);
    CHECK(volume.min == 0.0f);
    CHECK(volume.max == 1e6f);
    CHECK(contains(gsv_error_message([&] { volume.set_percentile_window(0.5, 0.5); }), "0 <= low < high <= 1"));
    CHECK(contains(gsv_error_message([&] { Volume().set_percentile_window(0.0, 1.0); }), "has no values"));
}

TEST_CASE("volume: exchanging y and z moves voxel (i, j, k) to (i, k, j) and the spacing with it", "[unit][volume]") {
    Volume volume;
    volume.nx = 2, volume.ny = 3, volume.nz = 4;
    volume.spacing = {1.0, 2.0, 3.0};
    for (int v = 0; v < 24; ++v) volume.values.push_back(static_cast<float>(v));
    const Volume swapped = volume.with_y_and_z_exchanged();
    CHECK(swapped.nx == 2);
    CHECK(swapped.ny == 4);
    CHECK(swapped.nz == 3);
    CHECK(swapped.spacing == glm::dvec3(1.0, 3.0, 2.0));
    for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 2; ++i) CHECK(swapped.at(i, k, j) == volume.at(i, j, k));
    CHECK(swapped.with_y_and_z_exchanged().values == volume.values);
}

// ---------------------------------------------------------------------------------------------------------
// NIfTI-1

TEST_CASE("nifti: the real big-endian anatomical.nii reads as 33x41x25 int16 voxels 2 mm apart", "[unit][volume]") {
    // The facts and voxel values below were read independently of this reader, with Python's struct module
    // on the committed file (header fields at their nifti1.h offsets, voxels as '>33825h' from byte 352,
    // voxel (i, j, k) at i + 33 (j + 41 k)), and agree with nibabel 5.0.0's own reading of it
    // (nib.load(...).dataobj, get_zooms(), header.endianness '>').
    const fs::path path = anatomical_path();
    const NiftiHeader header = gsv::read_nifti_header(path);
    CHECK(header.big_endian);
    CHECK(header.nx == 33);
    CHECK(header.ny == 41);
    CHECK(header.nz == 25);
    CHECK(header.datatype == 4);
    CHECK(std::string(gsv::nifti_datatype_name(header.datatype)) == "int16");
    CHECK(header.bits_per_voxel == 16);
    CHECK(header.spacing == glm::dvec3(2.0, 2.0, 2.0));
    CHECK(header.vox_offset == 352);
    // scl_slope 1 and scl_inter 0: scaling applies and changes nothing.
    CHECK(header.scaled);
    CHECK(header.scl_slope == 1.0);
    CHECK(header.scl_inter == 0.0);
    CHECK(header.description == "spm - 3D normalized");
    CHECK(fs::file_size(path) == 68002);  // 352 + 33 * 41 * 25 * 2

    const Volume volume = gsv::load_nifti(path);
    CHECK(volume.name == "anatomical");
    CHECK(volume.spacing == glm::dvec3(2.0, 2.0, 2.0));
    CHECK(volume.extent() == glm::dvec3(66.0, 82.0, 50.0));
    REQUIRE(volume.values.size() == 33825);
    CHECK(volume.at(0, 0, 0) == 10712.0f);
    CHECK(volume.at(16, 20, 12) == 11881.0f);
    CHECK(volume.at(20, 25, 10) == 7641.0f);
    CHECK(volume.at(32, 40, 24) == 2971.0f);
    // The extremes, each at one voxel only.
    CHECK(volume.min == -610.0f);
    CHECK(volume.at(24, 32, 14) == -610.0f);
    CHECK(volume.max == 30393.0f);
    CHECK(volume.at(17, 23, 0) == 30393.0f);
}

TEST_CASE("nifti: the real MRI gzipped (.nii.gz) reads as the same voxels as the .nii", "[unit][volume]") {
    TempDir dir;
    const fs::path gz = dir.write("anatomical.nii.gz", gzipped(gsv::test::read_text(anatomical_path())));
    CHECK(fs::file_size(gz) < fs::file_size(anatomical_path()));
    const NiftiHeader header = gsv::read_nifti_header(gz);
    CHECK(header.nx == 33);
    CHECK(header.big_endian);
    const gsv::Volume plain = gsv::load_nifti(anatomical_path()), unzipped = gsv::load_nifti(gz);
    REQUIRE(unzipped.values.size() == plain.values.size());
    CHECK(unzipped.values == plain.values);
    CHECK(unzipped.spacing == plain.spacing);
}

TEST_CASE("nifti: the real volume saved as little-endian float32 reads back identically", "[unit][volume]") {
    TempDir dir;
    const Volume volume = gsv::load_nifti(anatomical_path());
    const fs::path copy = dir.path("anatomical_le.nii");
    gsv::save_nifti(copy, volume);
    CHECK(fs::file_size(copy) == 352 + 33825 * 4);
    const NiftiHeader header = gsv::read_nifti_header(copy);
    CHECK_FALSE(header.big_endian);
    CHECK(header.datatype == 16);
    CHECK(header.description == "gsv anatomical");
    const Volume back = gsv::load_nifti(copy);
    CHECK(back.values == volume.values);
    CHECK(back.spacing == volume.spacing);
    CHECK(back.min == volume.min);
    CHECK(back.max == volume.max);
}

TEST_CASE("nifti: every datatype round-trips in both byte orders, with and without slope and intercept", "[unit][volume]") {
    struct Case {
        int datatype, bitpix;
        std::vector<double> stored;
    };
    const std::vector<Case> cases = {
        {2, 8, {0, 1, 127, 128, 254, 255}},
        {256, 8, {-128, -1, 0, 1, 126, 127}},
        {4, 16, {-32768, -1, 0, 1, 1000, 32767}},
        {512, 16, {0, 1, 2, 32768, 65534, 65535}},
        {8, 32, {-2147483648.0, -1, 0, 1, 16777217, 2147483647}},
        // Float values as float32 holds them (1e-40 is subnormal), and below half of float's largest so
        // that slope 2 keeps them finite.
        {16, 32, {-1.5, -0.0, 1e-40f, 0.1f, 1.0e38f, 7}},
        {64, 64, {-1.5, 0.1, 1e-300, 123456789.125, -1.0e38, 7}},
    };
    TempDir dir;
    for (const Case& c : cases)
        for (bool big : {false, true})
            for (const auto& [slope, inter] : {std::pair{0.0f, 5.0f}, std::pair{2.0f, -3.0f}, std::pair{0.5f, 0.25f}}) {
                CAPTURE(c.datatype, big, slope, inter);
                NiftiSpec spec;
                spec.big_endian = big;
                spec.datatype = c.datatype, spec.bitpix = c.bitpix;
                // dim[0] = 4 with dim[4] = 1 is one 3D volume too.
                spec.dim[0] = 4, spec.dim[1] = 3, spec.dim[2] = 2, spec.dim[3] = 1, spec.dim[4] = 1;
                spec.pixdim[1] = 0.5f, spec.pixdim[2] = 1.25f, spec.pixdim[3] = 3.0f;
                spec.scl_slope = slope, spec.scl_inter = inter;
                for (double v : c.stored) spec.voxels += encode(v, c.datatype, big);
                const fs::path path = dir.write("t.nii", nifti_bytes(spec));
                const Volume volume = gsv::load_nifti(path);
                REQUIRE(volume.values.size() == 6);
                CHECK(volume.spacing == glm::dvec3(0.5, 1.25, 3.0));
                // Slope 0 means unscaled, and then the intercept is ignored too (the standard's rule).
                for (std::size_t n = 0; n < 6; ++n) {
                    const double expected = slope != 0 ? double(slope) * c.stored[n] + double(inter) : c.stored[n];
                    CHECK(volume.at(int(n % 3), int(n / 3), 0) == static_cast<float>(expected));
                }
                const auto [lowest, highest] = std::minmax_element(volume.values.begin(), volume.values.end());
                CHECK(volume.min == *lowest);
                CHECK(volume.max == *highest);
            }
}

TEST_CASE("nifti: a NaN scl_slope means unscaled, and spatial units become millimetres", "[unit][volume]") {
    TempDir dir;
    NiftiSpec spec = float_spec({1, 2, 3, 4, 5, 6}, 3, 2, 1);
    spec.scl_slope = std::numeric_limits<float>::quiet_NaN(), spec.scl_inter = 100;
    spec.pixdim[1] = 0.002f, spec.pixdim[2] = 0.001f, spec.pixdim[3] = 0.004f;
    spec.xyzt_units = 1 | 8;  // metres, and seconds for time (which a volume ignores)
    const Volume metres = gsv::load_nifti(dir.write("m.nii", nifti_bytes(spec)));
    CHECK(metres.values == std::vector<float>{1, 2, 3, 4, 5, 6});
    CHECK(metres.spacing.x == Approx(2.0).epsilon(1e-7));
    CHECK(metres.spacing.y == Approx(1.0).epsilon(1e-7));
    CHECK(metres.spacing.z == Approx(4.0).epsilon(1e-7));
    spec.pixdim[1] = 500, spec.pixdim[2] = 250, spec.pixdim[3] = 1000;
    spec.xyzt_units = 3;  // microns
    CHECK(gsv::read_nifti_header(dir.write("u.nii", nifti_bytes(spec))).spacing == glm::dvec3(0.5, 0.25, 1.0));
    spec.xyzt_units = 0;  // unknown: taken as it is
    CHECK(gsv::read_nifti_header(dir.write("x.nii", nifti_bytes(spec))).spacing == glm::dvec3(500, 250, 1000));
}

TEST_CASE("nifti: save_nifti and load_nifti round-trip float32 bit for bit, anisotropic spacing too", "[unit][volume]") {
    TempDir dir;
    Volume volume;
    volume.nx = 3, volume.ny = 2, volume.nz = 2;
    volume.spacing = {0.5, 1.25, 3.0};
    volume.values = {-0.0f, 0.0f, 1e-40f, -3.4e38f, 3.4e38f, 0.1f, 1, 2, 3, 4, 5, 6};
    volume.name = "round_trip";
    volume.update_range();
    const fs::path path = dir.path("round_trip.nii");
    gsv::save_nifti(path, volume);
    const Volume back = gsv::load_nifti(path);
    CHECK(back.nx == 3);
    CHECK(back.ny == 2);
    CHECK(back.nz == 2);
    CHECK(back.spacing == volume.spacing);
    CHECK(back.name == "round_trip");
    REQUIRE(back.values.size() == volume.values.size());
    CHECK(std::memcmp(back.values.data(), volume.values.data(), volume.values.size() * sizeof(float)) == 0);
}

TEST_CASE("nifti: save_nifti refuses what load_nifti would, before creating the file", "[unit][volume]") {
    TempDir dir;
    const fs::path path = dir.path("refused.nii");
    Volume volume = labelled_volume(3, 2, 2);
    volume.values[7] = std::numeric_limits<float>::quiet_NaN();
    CHECK(contains(gsv_error_message([&] { gsv::save_nifti(path, volume); }), "voxel (1, 0, 1) is NaN"));
    volume = labelled_volume(3, 2, 2);
    volume.spacing.y = 0;
    CHECK(contains(gsv_error_message([&] { gsv::save_nifti(path, volume); }), "spacing along y"));
    volume.spacing.y = 1e-60;  // positive, but 0 in float32
    CHECK(contains(gsv_error_message([&] { gsv::save_nifti(path, volume); }), "spacing along y"));
    volume = labelled_volume(3, 2, 2);
    volume.values.pop_back();
    CHECK(contains(gsv_error_message([&] { gsv::save_nifti(path, volume); }), "11 values for 12 voxels"));
    CHECK_FALSE(fs::exists(path));
}

TEST_CASE("nifti: each broken file is refused with one line naming the file and the fault", "[unit][volume]") {
    TempDir dir;
    const NiftiSpec good = float_spec({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23},
                                      2, 3, 4);
    REQUIRE(gsv::load_nifti(dir.write("good.nii", nifti_bytes(good))).values.size() == 24);
    const auto refused = [&](const NiftiSpec& spec) { return load_error(dir.write("bad.nii", nifti_bytes(spec))); };

    SECTION("missing") {
        const std::string message = load_error(dir.path("missing.nii"));
        CHECK(contains(message, "cannot read NIfTI file"));
        CHECK(contains(message, "no such file"));
    }
    SECTION("a directory") {
        fs::create_directories(dir.path("folder.nii"));
        CHECK(contains(load_error(dir.path("folder.nii")), "is a directory"));
    }
    SECTION("empty and truncated headers") {
        CHECK(contains(load_error(dir.write("empty.nii", "")), "is 0 bytes, too short for the 348-byte NIfTI-1 header"));
        CHECK(contains(load_error(dir.write("short.nii", nifti_bytes(good).substr(0, 100))),
                       "is 100 bytes, too short for the 348-byte NIfTI-1 header"));
    }
    SECTION("gzip data that is corrupt or cut short") {
        const std::string gz = std::string("\x1f\x8b\x08\x00", 4) + std::string(400, 'x');
        CHECK(contains(load_error(dir.write("brain.nii.gz", gz)), "is gzip-compressed but its data is corrupt or cut short"));
        CHECK(contains(load_error(dir.write("tiny.nii.gz", std::string("\x1f\x8b", 2))), "corrupt or cut short"));
        const std::string whole = gzipped(gsv::test::read_text(anatomical_path()));
        CHECK(contains(load_error(dir.write("cut.nii.gz", whole.substr(0, whole.size() / 2))), "corrupt or cut short"));
        CHECK(contains(load_error(dir.write("twice.nii.gz", gzipped(whole))), "gzip-compressed twice"));
    }
    SECTION("not NIfTI-1: sizeof_hdr") {
        NiftiSpec spec = good;
        spec.sizeof_hdr = 349;
        CHECK(contains(refused(spec), "not a NIfTI-1 file: sizeof_hdr is 349"));
        spec.sizeof_hdr = 540;
        CHECK(contains(refused(spec), "NIfTI-2"));
        CHECK(contains(load_error(dir.write("text.nii", std::string(400, 'a'))), "not a NIfTI-1 file"));
        CHECK(contains(load_error(dir.write("scan.img", std::string(400, 'a'))), "the voxels of a .hdr/.img pair?"));
    }
    SECTION("wrong magic, and the magic of a .hdr/.img pair") {
        NiftiSpec spec = good;
        spec.magic = std::string("n+2\0", 4);
        CHECK(contains(refused(spec), "magic is 'n+2', not 'n+1'"));
        spec.magic = std::string(4, '\0');
        CHECK(contains(refused(spec), "magic is ''"));
        spec.magic = std::string("ni1\0", 4);
        CHECK(contains(refused(spec), ".hdr/.img pair"));
    }
    SECTION("unsupported datatypes, naming the code") {
        NiftiSpec spec = good;
        spec.datatype = 32, spec.bitpix = 64;
        CHECK(contains(refused(spec), "datatype 32 (complex64) is not supported"));
        spec.datatype = 128, spec.bitpix = 24;
        CHECK(contains(refused(spec), "datatype 128 (rgb24) is not supported"));
        spec.datatype = 1234;
        CHECK(contains(refused(spec), "datatype 1234 (unknown) is not supported"));
        spec.datatype = 16, spec.bitpix = 16;
        CHECK(contains(refused(spec), "bitpix 16 does not match datatype 16 (float32, 32 bits)"));
    }
    SECTION("dims that are not one 3D volume in range") {
        NiftiSpec spec = good;
        spec.dim[0] = 2;
        CHECK(contains(refused(spec), "dim[0] is 2"));
        spec.dim[0] = 4, spec.dim[4] = 10;
        CHECK(contains(refused(spec), "dim[4] is 10"));
        spec = good;
        spec.dim[2] = 0;
        CHECK(contains(refused(spec), "dim[2] is 0, not in 1..2048"));
        spec.dim[2] = -3;
        CHECK(contains(refused(spec), "dim[2] is -3, not in 1..2048"));
        spec.dim[2] = 4096;
        CHECK(contains(refused(spec), "dim[2] is 4096, not in 1..2048"));
    }
    SECTION("zero, negative and NaN spacing, naming the pixdim") {
        NiftiSpec spec = good;
        spec.pixdim[2] = 0;
        CHECK(contains(refused(spec), "pixdim[2] (the spacing along y) is 0, not a positive finite number"));
        spec.pixdim[2] = 1, spec.pixdim[1] = -2;
        CHECK(contains(refused(spec), "pixdim[1] (the spacing along x) is -2"));
        spec.pixdim[1] = 1, spec.pixdim[3] = std::numeric_limits<float>::quiet_NaN();
        CHECK(contains(refused(spec), "pixdim[3] (the spacing along z) is nan"));
    }
    SECTION("vox_offset inside the header, or not a whole byte") {
        NiftiSpec spec = good;
        spec.vox_offset = 348;
        CHECK(contains(refused(spec), "vox_offset 348 is not a whole number of bytes from 352"));
        spec.vox_offset = 352.5f;
        CHECK(contains(refused(spec), "vox_offset 352.5 is not"));
    }
    SECTION("a voxel block of another size: lying dims, a truncated file, trailing bytes") {
        NiftiSpec spec = good;
        spec.dim[1] = 64, spec.dim[2] = 64, spec.dim[3] = 64;
        CHECK(contains(refused(spec), "expected 1048576 bytes of voxels after offset 352, found 96 (64x64x64 float32)"));
        CHECK(contains(load_error(dir.write("cut.nii", nifti_bytes(good).substr(0, 352 + 95))),
                       "expected 96 bytes of voxels after offset 352, found 95"));
        CHECK(contains(load_error(dir.write("long.nii", nifti_bytes(good) + "junk")),
                       "expected 96 bytes of voxels after offset 352, found 100"));
        spec = good;
        spec.vox_offset = 1024;  // beyond the end of a file of 352 + 96 bytes
        std::string bytes = nifti_bytes(spec);
        bytes.resize(448);
        CHECK(contains(load_error(dir.write("offset.nii", bytes)), "after offset 1024, found 0"));
    }
    SECTION("a header that promises gigabytes is refused from the file's size, not allocated") {
        NiftiSpec spec = good;
        spec.dim[1] = 2048, spec.dim[2] = 2048, spec.dim[3] = 60, spec.datatype = 64, spec.bitpix = 64;
        CHECK(contains(refused(spec), "expected 2013265920 bytes of voxels after offset 352, found 96"));
        spec.dim[3] = 2048;
        CHECK(contains(refused(spec), "more than the 268435456 this kit loads"));
    }
    SECTION("NaN and infinite voxels, naming the voxel") {
        std::vector<float> values(24, 1.0f);
        values[4] = std::numeric_limits<float>::quiet_NaN();  // (0, 2, 0) of a 2x3x4 grid
        CHECK(contains(refused(float_spec(values, 2, 3, 4)), "voxel (0, 2, 0) is NaN"));
        values[4] = 1, values[23] = -std::numeric_limits<float>::infinity();
        CHECK(contains(refused(float_spec(values, 2, 3, 4, true)), "voxel (1, 2, 3) is infinite"));
        NiftiSpec spec = good;
        spec.datatype = 64, spec.bitpix = 64, spec.voxels.clear();
        for (int n = 0; n < 24; ++n) spec.voxels += encode(n == 13 ? 1e300 : 0.0, 64, false);
        CHECK(contains(refused(spec), "voxel (1, 0, 2) is 1e+300, beyond float32"));
        spec = good;
        spec.scl_slope = 1e38f;
        // Voxel n holds n: 3e38 still fits float32, 4e38 (voxel 4, at (0, 2, 0)) does not.
        const std::string message = refused(spec);
        CHECK(contains(message, "voxel (0, 2, 0) is 3.99"));
        CHECK(contains(message, "after scaling, beyond float32"));
        spec.scl_slope = 1, spec.scl_inter = std::numeric_limits<float>::infinity();
        CHECK(contains(refused(spec), "scl_inter is inf with scl_slope 1"));
    }
}

// ---------------------------------------------------------------------------------------------------------
// ray_box_span

TEST_CASE("ray_box: spans through the box, along axes, on faces and touching an edge", "[unit][volume]") {
    const glm::dvec3 lo(-1.0), hi(1.0);
    const auto span = [&](glm::dvec3 o, glm::dvec3 d) { return gsv::ray_box_span(o, d, lo, hi); };
    // A diagonal ray through the centre: enters at the corner (-1,-1,-1), leaves at (1,1,1).
    auto s = span({-2, -2, -2}, {1, 1, 1});
    REQUIRE(s);
    CHECK(s->entry == 1.0);
    CHECK(s->exit == 3.0);
    // Axis-aligned: two direction components are exactly 0 (1/0 = inf in the textbook slab method).
    s = span({0.25, -0.5, 5}, {0, 0, -2});
    REQUIRE(s);
    CHECK(s->entry == 2.0);
    CHECK(s->exit == 3.0);
    // Along a face: origin on the plane x = 1 with d.x = 0, where (1 - o.x) * (1 / 0) = 0 * inf = NaN.
    s = span({1, 0, -3}, {0, 0, 1});
    REQUIRE(s);
    CHECK(s->entry == 2.0);
    CHECK(s->exit == 4.0);
    s = span({-1, -1, -3}, {0, 0, 1});  // along an edge
    REQUIRE(s);
    CHECK(s->entry == 2.0);
    // Just outside a face, parallel to it: a miss.
    CHECK_FALSE(span({std::nextafter(1.0, 2.0), 0, -3}, {0, 0, 1}));
    // Touching the edge x = 1, y = 1 at one point: entry == exit.
    s = span({0, 2, 0}, {1, -1, 0});
    REQUIRE(s);
    CHECK(s->entry == 1.0);
    CHECK(s->exit == 1.0);
    // Missing, pointing away (the line still crosses: entry and exit are negative), and starting inside.
    CHECK_FALSE(span({0, 2, 0}, {1, 0, 0}));
    s = span({0, 0, 3}, {0, 0, 1});
    REQUIRE(s);
    CHECK(s->entry == -4.0);
    CHECK(s->exit == -2.0);
    s = span({0, 0, 0}, {0.5, 0, 0});
    REQUIRE(s);
    CHECK(s->entry == -2.0);
    CHECK(s->exit == 2.0);
    CHECK(contains(gsv_error_message([&] { span({0, 0, 0}, {0, 0, 0}); }), "non-zero direction"));
    CHECK(contains(gsv_error_message([&] { span({kNaN, 0, 0}, {1, 0, 0}); }), "finite origin"));
}

// ---------------------------------------------------------------------------------------------------------
// Marschner-Lobb

TEST_CASE("marschner_lobb: exact values at the centre, on the axis, on a ring and at the corners", "[unit][volume]") {
    // f_M = 6, alpha = 0.25, so 2 (1 + alpha) = 2.5 and rho = (1 - sin(pi z / 2) + 0.25 (1 + rho_r)) / 2.5.
    // Centre: r = 0, rho_r = cos(12 pi cos 0) = cos(12 pi) = 1, sin 0 = 0: (1 + 0.5) / 2.5 = 0.6.
    CHECK(gsv::marschner_lobb({0, 0, 0}) == Approx(0.6).epsilon(1e-15));
    // Top and bottom of the axis: sin(+-pi / 2) = +-1: (1 - 1 + 0.5) / 2.5 = 0.2 and (1 + 1 + 0.5) / 2.5 = 1,
    // the largest value.
    CHECK(gsv::marschner_lobb({0, 0, 1}) == Approx(0.2).epsilon(1e-15));
    CHECK(gsv::marschner_lobb({0, 0, -1}) == Approx(1.0).epsilon(1e-15));
    // r = 1 (x = 1 or y = 1): cos(pi / 2) = 0, rho_r = cos 0 = 1, so 0.6 again at z = 0; r = 2/3:
    // cos(pi / 3) = 1/2, 12 pi / 2 = 6 pi, rho_r = 1.
    CHECK(gsv::marschner_lobb({1, 0, 0}) == Approx(0.6).epsilon(1e-14));
    CHECK(gsv::marschner_lobb({0, -1, 0}) == Approx(0.6).epsilon(1e-14));
    CHECK(gsv::marschner_lobb({0.4, 0.8 * 2 / 3, 0}) == Approx(0.6).epsilon(1e-14));  // r = 2/3 (0.4^2 + 0.5333^2 = 0.4444)
    // A ring's trough: 12 pi cos(pi r / 2) = pi, i.e. r = (2 / pi) acos(1 / 12) = 0.946887, rho_r = -1:
    // (1 + 0) / 2.5 = 0.4.
    CHECK(gsv::marschner_lobb({2 / kPi * std::acos(1.0 / 12), 0, 0}) == Approx(0.4).epsilon(1e-14));
    // Corners: r = sqrt 2, cos(pi / sqrt 2) = cos(2.221441) = -0.6056999, times 12 pi = -22.834347; adding
    // 8 pi = 25.132741 gives 2.298394 rad, whose cosine is rho_r = -0.6650777. At z = 1:
    // 0.25 (1 - 0.6650777) / 2.5 = 0.03349223; at z = -1, 0.8 more: 0.83349223. (Python's math module agrees:
    // 0.03349222933682191 and 0.833492229336822.)
    for (double x : {-1.0, 1.0})
        for (double y : {-1.0, 1.0}) {
            CHECK(gsv::marschner_lobb({x, y, 1}) == Approx(0.03349223).margin(5e-9));
            CHECK(gsv::marschner_lobb({x, y, -1}) == Approx(0.83349223).margin(5e-9));
        }
    // Other parameters: alpha = 0 leaves only the z term, (1 - sin(pi z / 2)) / 2.
    CHECK(gsv::marschner_lobb({0.3, 0.7, 1.0 / 3}, MarschnerLobb{6, 0}) == Approx(0.25).epsilon(1e-15));
    CHECK(contains(gsv_error_message([] { gsv::marschner_lobb({0, 0, kNaN}); }), "must be finite"));
    CHECK(contains(gsv_error_message([] { gsv::marschner_lobb({0, 0, 0}, MarschnerLobb{6, -1}); }), "alpha"));
}

TEST_CASE("marschner_lobb: the exact gradient matches central differences of rho at second order", "[unit][volume]") {
    const glm::dvec3 points[] = {{0.3, -0.2, 0.1}, {-0.71, 0.05, 0.6}, {0.02, 0.01, -0.4}, {0.9, 0.4, -0.95}};
    const auto central = [](glm::dvec3 p, double h) {
        glm::dvec3 g;
        for (int axis = 0; axis < 3; ++axis) {
            glm::dvec3 e(0.0);
            e[axis] = h;
            g[axis] = (gsv::marschner_lobb(p + e) - gsv::marschner_lobb(p - e)) / (2 * h);
        }
        return g;
    };
    for (const glm::dvec3& p : points) {
        CAPTURE(p.x, p.y, p.z);
        const glm::dvec3 exact = gsv::marschner_lobb_gradient(p);
        // Halving h quarters the error: the O(h^2) term of the central difference dominates.
        const double e1 = glm::length(central(p, 4e-3) - exact), e2 = glm::length(central(p, 2e-3) - exact);
        CHECK(e1 / e2 == Approx(4.0).margin(0.1));
        // And at a small step they agree closely (h^2 f''' / 6 is about 3e-9 here; rounding adds ~1e-10).
        CHECK(glm::length(central(p, 1e-6) - exact) < 1e-8 * glm::length(exact) + 1e-8);
    }
}

TEST_CASE("marschner_lobb: the gradient on the z axis, r = 0, is finite and continuous, no NaN", "[unit][volume]") {
    // On the axis the x and y parts are exactly 0 and the z part is the z term's: -(pi / 2) cos(pi z / 2) / 2.5.
    for (double z : {-1.0, -0.3, 0.0, 0.7, 1.0}) {
        const glm::dvec3 g = gsv::marschner_lobb_gradient({0, 0, z});
        CHECK(g.x == 0.0);
        CHECK(g.y == 0.0);
        CHECK(g.z == Approx(-(kPi / 2) * std::cos(kPi * z / 2) / 2.5).epsilon(1e-15));
    }
    // f_M = 6.25 puts a ring's flank on the axis (sin(2 pi f_M) = sin(12.5 pi) = 1), so d rho / dx grows
    // like c x near it, c = alpha / (2 (1 + alpha)) 2 pi f_M (pi / 2)^2 = 0.1 * 12.5 pi * pi^2 / 4 =
    // 3.125 pi^3 / 10 = 9.6894: the chain rule's x / r must become this limit, not 0 / 0.
    const MarschnerLobb flank{6.25, 0.25};
    const double c = 3.125 * kPi * kPi * kPi / 10;
    for (double x : {1e-3, 1e-6, 1e-9, 1e-150, 1e-300, 5e-324, 0.0}) {
        const glm::dvec3 g = gsv::marschner_lobb_gradient({x, 0, 0.2}, flank);
        CAPTURE(x);
        REQUIRE(finite(g));
        if (x > 1e-300) CHECK(g.x / x == Approx(c).epsilon(x > 1e-4 ? 1e-3 : 1e-9));
        CHECK(g.y == 0.0);
        const glm::dvec3 diagonal = gsv::marschner_lobb_gradient({x, x, 0.2}, flank);
        REQUIRE(finite(diagonal));
        CHECK(diagonal.x == diagonal.y);
    }
    CHECK(gsv::marschner_lobb_gradient({0, 0, 0.2}, flank).x == 0.0);
}

TEST_CASE("marschner_lobb: the volume holds rho at its texel centres and Volume::sample reads it there", "[unit][volume]") {
    const Volume volume = gsv::make_marschner_lobb_volume();
    CHECK(volume.nx == 41);
    CHECK(volume.ny == 41);
    CHECK(volume.nz == 41);
    CHECK(volume.spacing == glm::dvec3(2.0 / 41));
    CHECK(volume.extent().x == Approx(2.0).epsilon(1e-15));
    CHECK(volume.name == "marschner_lobb");
    // Voxel (20, 20, 20) is the centre, p = -1 + 41 / 41 = 0: rho = 0.6.
    CHECK(volume.at(20, 20, 20) == static_cast<float>(0.6));
    CHECK(volume.min >= 0.0f);
    CHECK(volume.max <= 1.0f);
    for (const auto& [i, j, k] : {std::tuple{0, 0, 0}, std::tuple{40, 3, 17}, std::tuple{7, 40, 40}, std::tuple{13, 29, 2}}) {
        const glm::dvec3 p(-1 + (2.0 * i + 1) / 41, -1 + (2.0 * j + 1) / 41, -1 + (2.0 * k + 1) / 41);
        CHECK(volume.at(i, j, k) == static_cast<float>(gsv::marschner_lobb(p)));
        CHECK(volume.sample(gsv::marschner_lobb_texcoord(p)) == volume.at(i, j, k));
        CHECK(gsv::marschner_lobb_point(gsv::marschner_lobb_texcoord(p)).x == Approx(p.x).margin(1e-15));
    }
    CHECK(contains(gsv_error_message([] { gsv::make_marschner_lobb_volume(1); }), "side 1 is not in 2..2048"));
    CHECK(contains(gsv_error_message([] { gsv::make_marschner_lobb_volume(1000); }), "side 1000"));
}

TEST_CASE("marschner_lobb: ray hits agree with a dense march and are exact to adjacent doubles", "[unit][volume]") {
    std::uint64_t state = 0x6a09e667f3bcc908ull;
    const auto uniform = [&](double lo, double hi) {
        return lo + (hi - lo) * double(gsv::splitmix64_next(state) >> 11) * 0x1.0p-53;
    };
    int hits = 0, misses = 0;
    for (int ray = 0; ray < 40; ++ray) {
        // From outside the box toward a point inside it, or past it, with a direction of any length.
        const glm::dvec3 origin(uniform(-3, 3), uniform(-3, 3), uniform(-3, 3));
        const glm::dvec3 target(uniform(-1.5, 1.5), uniform(-1.5, 1.5), uniform(-1.5, 1.5));
        const glm::dvec3 direction = (target - origin) * uniform(0.3, 3.0);
        const double iso = ray % 3 == 0 ? 0.5 : ray % 3 == 1 ? 0.3 : 0.8;
        CAPTURE(ray, origin.x, origin.y, origin.z, direction.x, direction.y, direction.z, iso);
        const std::optional<double> hit = gsv::marschner_lobb_ray_hit(origin, direction, 0, 10, iso);
        const std::optional<gsv::RaySpan> span = gsv::ray_box_span(origin, direction, glm::dvec3(-1), glm::dvec3(1));
        std::optional<std::pair<double, double>> bracket;
        if (span && span->exit >= 0)
            bracket = dense_bracket(origin, direction, std::max(0.0, span->entry), std::min(10.0, span->exit), iso, 100000);
        REQUIRE(hit.has_value() == bracket.has_value());
        if (!hit) {
            ++misses;
            continue;
        }
        ++hits;
        CHECK(*hit >= bracket->first);
        CHECK(*hit <= bracket->second);
        // Exact: rho - iso changes sign between the hit and the next double (or is 0 at the hit).
        const double here = gsv::marschner_lobb(origin + *hit * direction) - iso;
        const double next = gsv::marschner_lobb(origin + std::nextafter(*hit, kInf) * direction) - iso;
        CHECK((here == 0 || (here < 0) != (next < 0)));
    }
    // The rays were drawn so that both outcomes occur.
    CHECK(hits >= 10);
    CHECK(misses >= 3);
}

TEST_CASE("marschner_lobb: axis-aligned rays, with direction components of exactly 0, hit where the formula says",
          "[unit][volume]") {
    // Along the z axis rho = (1.5 - sin(pi z / 2)) / 2.5, which is 0.5 where sin(pi z / 2) = 0.25:
    // z* = (2 / pi) asin(0.25) = 0.1608612. Upward from z = -2, rho falls from 1 and crosses at t = 2 + z*.
    const double z_star = 2 / kPi * std::asin(0.25);
    std::optional<double> t = gsv::marschner_lobb_ray_hit({0, 0, -2}, {0, 0, 1}, 0, 10, 0.5);
    REQUIRE(t);
    CHECK(*t == Approx(2 + z_star).epsilon(1e-15));
    // Downward from z = 2, starting at rho = 0.2 on the top face: the same crossing, t = 2 - z*.
    t = gsv::marschner_lobb_ray_hit({0, 0, 2}, {0, 0, -1}, 0, 10, 0.5);
    REQUIRE(t);
    CHECK(*t == Approx(2 - z_star).epsilon(1e-15));
    // On the face x = 1 (d.x = 0 there: the slab method's 0 * inf): cos(pi / 2) = 0, so rho_r = 1 as on the
    // axis, and the crossing is at the same z.
    t = gsv::marschner_lobb_ray_hit({1, 0, -2}, {0, 0, 1}, 0, 10, 0.5);
    REQUIRE(t);
    CHECK(*t == Approx(2 + z_star).epsilon(1e-12));
    // Along x at y = z = 0: rho = (1 + 0.25 (1 + cos(12 pi cos(pi x / 2)))) / 2.5, 0.6 at x = -1, first 0.5
    // where 12 pi cos(pi x / 2) = pi / 2, x* = -(2 / pi) acos(1 / 24) = -0.9734665.
    t = gsv::marschner_lobb_ray_hit({-3, 0, 0}, {1, 0, 0}, 0, 10, 0.5);
    REQUIRE(t);
    CHECK(*t == Approx(3 - 2 / kPi * std::acos(1.0 / 24)).epsilon(1e-15));
    // A direction of any length gives the same point.
    t = gsv::marschner_lobb_ray_hit({-3, 0, 0}, {0.25, 0, 0}, 0, 40, 0.5);
    REQUIRE(t);
    CHECK(*t * 0.25 == Approx(3 - 2 / kPi * std::acos(1.0 / 24)).epsilon(1e-15));
    // [t0, t1] is honoured: starting past the first crossing finds the next one, further on.
    const std::optional<double> later = gsv::marschner_lobb_ray_hit({-3, 0, 0}, {1, 0, 0}, 2.1, 10, 0.5);
    REQUIRE(later);
    CHECK(*later > 2.1);
    // Misses: parallel to the box outside it, pointing away, a level rho never reaches, t1 before the box.
    CHECK_FALSE(gsv::marschner_lobb_ray_hit({0, 2, 0}, {1, 0, 0}, -10, 10, 0.5));
    CHECK_FALSE(gsv::marschner_lobb_ray_hit({0, 0, 2}, {0, 0, 1}, 0, 10, 0.5));
    CHECK_FALSE(gsv::marschner_lobb_ray_hit({0, 0, -2}, {0, 0, 1}, 0, 10, 1.5));
    CHECK_FALSE(gsv::marschner_lobb_ray_hit({0, 0, -2}, {0, 0, 1}, 0, 0.5, 0.5));
    // Entry == exit: touching the edge x = y = 1 at (1, 1, 0) only, at t = 1.
    const double at_edge = gsv::marschner_lobb({1, 1, 0});
    t = gsv::marschner_lobb_ray_hit({0, 2, 0}, {1, -1, 0}, 0, 10, at_edge);
    REQUIRE(t);
    CHECK(*t == 1.0);
    CHECK_FALSE(gsv::marschner_lobb_ray_hit({0, 2, 0}, {1, -1, 0}, 0, 10, at_edge + 0.01));
    CHECK(contains(gsv_error_message([] { gsv::marschner_lobb_ray_hit({0, 0, 0}, {0, 0, 0}, 0, 1, 0.5); }),
                   "non-zero direction"));
    CHECK(contains(gsv_error_message([] { gsv::marschner_lobb_ray_hit({0, 0, 0}, {0, 0, 1}, 1, 0, 0.5); }), "t0 <= t1"));
    CHECK(contains(gsv_error_message([] { gsv::marschner_lobb_ray_hit({0, 0, 0}, {0, 0, 1}, 0, 1, 0.5, {}, 1e-12); }),
                   "steps"));
}

// ---------------------------------------------------------------------------------------------------------
// Gradients

TEST_CASE("gradient: a linear volume's differences are its slope in physical units, anisotropic spacing too",
          "[unit][volume]") {
    // f = 3 x - y + 8 z at the physical centres ((i + 0.5) sx, ...), with spacings whose products are exact
    // in float, so every interior difference is exactly the slope.
    Volume volume;
    volume.nx = 5, volume.ny = 4, volume.nz = 6;
    volume.spacing = {0.5, 2.0, 0.25};
    volume.name = "linear";
    for (int k = 0; k < volume.nz; ++k)
        for (int j = 0; j < volume.ny; ++j)
            for (int i = 0; i < volume.nx; ++i)
                volume.values.push_back(float(3 * (i + 0.5) * 0.5 - (j + 0.5) * 2.0 + 8 * (k + 0.5) * 0.25));
    const glm::dvec3 slope(3, -1, 8);
    CHECK(gsv::central_difference(volume, 2, 1, 3) == slope);
    CHECK(gsv::forward_difference(volume, 2, 1, 3) == slope);
    // At the borders the clamped neighbour is the voxel itself: half the slope centrally, 0 forward at the end.
    CHECK(gsv::central_difference(volume, 0, 1, 3) == glm::dvec3(1.5, -1, 8));
    CHECK(gsv::central_difference(volume, 4, 3, 5) == glm::dvec3(1.5, -0.5, 4));
    CHECK(gsv::forward_difference(volume, 4, 3, 5) == glm::dvec3(0, 0, 0));
    // Through Volume::sample: at texel centres the same as at the voxels, borders included; between them,
    // trilinear interpolation of a linear function is the function, so the slope again.
    for (const auto& [i, j, k] : {std::tuple{2, 1, 3}, std::tuple{0, 0, 0}, std::tuple{4, 3, 5}, std::tuple{1, 2, 4}}) {
        CAPTURE(i, j, k);
        const glm::dvec3 s = texel_centre(volume, i, j, k);
        CHECK(gsv::central_difference(volume, s) == gsv::central_difference(volume, i, j, k));
        CHECK(gsv::forward_difference(volume, s) == gsv::forward_difference(volume, i, j, k));
    }
    for (const glm::dvec3& s : {glm::dvec3(0.37, 0.41, 0.52), glm::dvec3(0.55, 0.3, 0.33)}) {
        const glm::dvec3 c = gsv::central_difference(volume, s, 0.5), f = gsv::forward_difference(volume, s, 0.25);
        for (int axis = 0; axis < 3; ++axis) {
            CHECK(c[axis] == Approx(slope[axis]).epsilon(1e-12));
            CHECK(f[axis] == Approx(slope[axis]).epsilon(1e-12));
        }
    }
    CHECK(contains(gsv_error_message([&] { gsv::central_difference(volume, 5, 0, 0); }), "outside the 5x4x6 grid"));
    CHECK(contains(gsv_error_message([&] { gsv::central_difference(volume, glm::dvec3(0.5), 0.0); }), "step 0"));
    volume.spacing.z = 0;
    CHECK(contains(gsv_error_message([&] { gsv::forward_difference(volume, 1, 1, 1); }), "not positive and finite"));
}

TEST_CASE("gradient: a constant volume's gradient is exactly 0 and its safe normalisation is 0, not NaN",
          "[unit][volume]") {
    // 0.1 is not a dyadic fraction: (1 - f) 0.1 + f 0.1 is not always 0.1 in floating point, which is why
    // Volume::sample mixes equal values exactly.
    const Volume volume = constant_volume(7, 5, 3, 0.1f);
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 5; ++j)
            for (int i = 0; i < 7; ++i) {
                REQUIRE(gsv::central_difference(volume, i, j, k) == glm::dvec3(0.0));
                REQUIRE(gsv::forward_difference(volume, i, j, k) == glm::dvec3(0.0));
            }
    std::uint64_t state = 42;
    for (int n = 0; n < 200; ++n) {
        const glm::dvec3 s(double(gsv::splitmix64_next(state) >> 11) * 0x1.0p-53,
                           double(gsv::splitmix64_next(state) >> 11) * 0x1.0p-53,
                           double(gsv::splitmix64_next(state) >> 11) * 0x1.0p-53);
        REQUIRE(gsv::central_difference(volume, s, 0.37) == glm::dvec3(0.0));
        REQUIRE(gsv::forward_difference(volume, s) == glm::dvec3(0.0));
    }
    const glm::dvec3 g = gsv::central_difference(volume, glm::dvec3(0.5));
    CHECK(gsv::safe_normalize(g) == glm::dvec3(0.0));
    // What the safe version is for: glm::normalize divides by the length 0.
    CHECK(std::isnan(glm::normalize(g).x));
}

TEST_CASE("gradient: safe_normalize gives unit vectors for tiny and huge gradients, NaN for NaN", "[unit][volume]") {
    CHECK(gsv::safe_normalize({3, 0, -4}) == glm::dvec3(0.6, 0, -0.8));
    // |g|^2 underflows to 0 (1e-200 squared) or overflows to inf (1e200 squared): still a unit vector.
    for (double scale : {1e-200, 5e-324, 1e200, 1.7e308}) {
        CAPTURE(scale);
        const glm::dvec3 n = gsv::safe_normalize(glm::dvec3(scale, scale, 0));
        CHECK(n.x == Approx(std::sqrt(0.5)).epsilon(1e-15));
        CHECK(n.y == n.x);
        CHECK(n.z == 0.0);
    }
    CHECK(gsv::safe_normalize({0, 0, 0}) == glm::dvec3(0.0));
    CHECK(gsv::safe_normalize({-0.0, 0, -0.0}) == glm::dvec3(0.0));
    CHECK(std::isnan(gsv::safe_normalize({kNaN, 0, 0}).x));
    CHECK(std::isnan(gsv::safe_normalize({kInf, 0, 0}).y));
}

TEST_CASE("gradient: central differences of a sampled smooth Marschner-Lobb volume converge at second order",
          "[unit][volume]") {
    // alpha = 0 leaves the smooth z term (1 - sin(pi z / 2)) / 2: its texel-centre central differences in
    // physical units (spacing 2 / n, the units of p) approach the exact gradient with error ~ h^2, so doubling
    // n divides the error by about 4. (With the rings, 41^3 is meant to be too coarse; see the header.)
    const MarschnerLobb smooth{6, 0};
    double previous = 0;
    for (int n : {21, 41, 81}) {
        const Volume volume = gsv::make_marschner_lobb_volume(n, smooth);
        double worst = 0;
        for (int k = 1; k < n - 1; ++k) {
            const int i = n / 3, j = n / 2;
            const glm::dvec3 p(-1 + (2.0 * i + 1) / n, -1 + (2.0 * j + 1) / n, -1 + (2.0 * k + 1) / n);
            worst = std::max(worst, glm::length(gsv::central_difference(volume, i, j, k) -
                                                gsv::marschner_lobb_gradient(p, smooth)));
        }
        CAPTURE(n, worst, previous);
        // (pi/2)^3 / 2 h^2 / 6 bounds the truncation error; float rounding of the values adds ~1e-7 / h.
        const double h = 2.0 / n;
        CHECK(worst < 0.33 * h * h + 1e-7 / h);
        if (previous > 0) CHECK(previous / worst == Approx(4.0).margin(0.4));
        previous = worst;
    }
}

TEST_CASE("sobel gradient: a linear volume's gradient is its slope inside, anisotropic spacing too, a constant one's is 0",
          "[unit][volume]") {
    // The same linear field as the differences' test above: every interior 3x3x3 neighbourhood sees the slope.
    Volume volume;
    volume.nx = 5, volume.ny = 4, volume.nz = 6;
    volume.spacing = {0.5, 2.0, 0.25};
    volume.name = "linear";
    for (int k = 0; k < volume.nz; ++k)
        for (int j = 0; j < volume.ny; ++j)
            for (int i = 0; i < volume.nx; ++i)
                volume.values.push_back(float(3 * (i + 0.5) * 0.5 - (j + 0.5) * 2.0 + 8 * (k + 0.5) * 0.25));
    const glm::dvec3 slope(3, -1, 8);
    CHECK(gsv::sobel_gradient(volume, 2, 1, 3) == slope);
    CHECK(gsv::sobel_gradient(volume, 1, 2, 2) == slope);
    // At a border the clamped neighbour is the voxel itself, as with central differences: half the slope across it.
    CHECK(gsv::sobel_gradient(volume, 0, 1, 3) == glm::dvec3(1.5, -1, 8));
    const Volume flat = constant_volume(7, 5, 3, 0.1f);
    for (float g : gsv::sobel_gradient_volume(flat)) REQUIRE(g == 0.0f);
    CHECK(contains(gsv_error_message([&] { gsv::sobel_gradient(volume, 5, 0, 0); }), "outside the 5x4x6 grid"));
    volume.spacing.y = -1;
    CHECK(contains(gsv_error_message([&] { gsv::sobel_gradient_volume(volume); }), "not positive and finite"));
}

TEST_CASE("sobel gradient: the whole volume, axis by axis, equals the 27-voxel operator at every voxel", "[unit][volume]") {
    Volume volume;
    volume.nx = 6, volume.ny = 5, volume.nz = 4;
    volume.spacing = {1.0, 0.7, 2.5};
    volume.name = "noise";
    std::uint64_t state = 7;
    for (int v = 0; v < volume.nx * volume.ny * volume.nz; ++v)
        volume.values.push_back(float(double(gsv::splitmix64_next(state) >> 11) * 0x1.0p-53));
    const std::vector<float> all = gsv::sobel_gradient_volume(volume);
    REQUIRE(all.size() == 3 * volume.values.size());
    std::size_t at = 0;
    for (int k = 0; k < volume.nz; ++k)
        for (int j = 0; j < volume.ny; ++j)
            for (int i = 0; i < volume.nx; ++i, at += 3) {
                const glm::dvec3 one = gsv::sobel_gradient(volume, i, j, k);
                CAPTURE(i, j, k);
                for (int axis = 0; axis < 3; ++axis)
                    REQUIRE(all[at + static_cast<std::size_t>(axis)] == Approx(one[axis]).margin(1e-6));
            }
}

TEST_CASE("sobel gradient: on a smooth Marschner-Lobb volume it converges to the exact gradient at second order",
          "[unit][volume]") {
    // The smoothing across the axis adds its own h^2 error to the central difference's, so a smooth field's
    // gradient still comes out within a constant times h^2: doubling n divides the error by about 4.
    const MarschnerLobb smooth{6, 0};
    double previous = 0;
    for (int n : {21, 41, 81}) {
        const Volume volume = gsv::make_marschner_lobb_volume(n, smooth);
        double worst = 0;
        for (int k = 1; k < n - 1; ++k) {
            const int i = n / 3, j = n / 2;
            const glm::dvec3 p(-1 + (2.0 * i + 1) / n, -1 + (2.0 * j + 1) / n, -1 + (2.0 * k + 1) / n);
            worst = std::max(worst, glm::length(gsv::sobel_gradient(volume, i, j, k) - gsv::marschner_lobb_gradient(p, smooth)));
        }
        CAPTURE(n, worst, previous);
        if (previous > 0) CHECK(previous / worst == Approx(4.0).margin(0.5));
        previous = worst;
    }
}
