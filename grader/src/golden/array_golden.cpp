#include "grader/src/golden/array_golden.h"

#include "common/app/kit_layout.h"
#include "common/core/error.h"
#include "common/io/little_endian.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <limits>
#include <system_error>

namespace fs = std::filesystem;

namespace gsv {
namespace {

constexpr char kMagic[8] = {'G', 'S', 'V', 'A', 'R', 'R', '1', '\0'};
constexpr std::size_t kHeaderBytes = 8 + 3 * 4;

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

[[noreturn]] void fail(const fs::path& path, const std::string& what) {
    throw Error("golden array " + quoted(path) + ": " + what);
}

void put_u32(std::vector<unsigned char>& bytes, std::uint32_t v) {
    unsigned char b[4];
    u32_to_le_bytes(v, b);
    bytes.insert(bytes.end(), b, b + 4);
}

}  // namespace

std::vector<std::uint32_t> golden_sample_indices(std::size_t count) {
    std::vector<std::uint32_t> indices;
    // The stride runs over the elements before the tail, so a large array's sample is always 4096 + 64.
    const std::size_t body = count > kGoldenStrided ? count - std::min(count, kGoldenTail) : count;
    if (body <= kGoldenStrided) {
        for (std::size_t i = 0; i < count; ++i) indices.push_back(static_cast<std::uint32_t>(i));
        return indices;
    }
    for (std::size_t i = 0; i < kGoldenStrided; ++i)
        indices.push_back(static_cast<std::uint32_t>(std::uint64_t(i) * body / kGoldenStrided));
    for (std::size_t i = body; i < count; ++i) indices.push_back(static_cast<std::uint32_t>(i));
    return indices;
}

ExpectedArray sample_array(const DataArray& array) {
    if (array.count() > std::numeric_limits<std::uint32_t>::max())
        throw Error("array '" + array.name + "': " + std::to_string(array.count()) +
                    " elements, more than a golden array's 32-bit indices can name");
    ExpectedArray sample;
    sample.name = array.name;
    sample.count = array.count();
    sample.components = array.components;
    sample.indices = golden_sample_indices(sample.count);
    const std::size_t k = static_cast<std::size_t>(array.components);
    sample.values.reserve(sample.indices.size() * k);
    for (const std::uint32_t i : sample.indices)
        sample.values.insert(sample.values.end(), array.values.begin() + std::ptrdiff_t(i * k),
                             array.values.begin() + std::ptrdiff_t((i + 1) * k));
    return sample;
}

void write_array_golden(const fs::path& path, const ExpectedArray& sample) {
    const std::size_t k = static_cast<std::size_t>(std::max(sample.components, 0));
    const std::size_t held = sample.held();
    if (sample.count > std::numeric_limits<std::uint32_t>::max() || k < 1 || sample.values.size() != held * k)
        throw Error("cannot write golden array " + quoted(path) + ": a malformed sample (" +
                    std::to_string(sample.values.size()) + " values for " + std::to_string(held) + " elements of " +
                    std::to_string(k) + " components)");
    std::vector<unsigned char> bytes(kMagic, kMagic + sizeof kMagic);
    put_u32(bytes, static_cast<std::uint32_t>(sample.count));
    put_u32(bytes, static_cast<std::uint32_t>(k));
    put_u32(bytes, static_cast<std::uint32_t>(held));
    for (std::size_t h = 0; h < held; ++h) put_u32(bytes, static_cast<std::uint32_t>(sample.element(h)));
    for (const float v : sample.values) {
        unsigned char b[4];
        float_to_le_bytes(v, b);
        bytes.insert(bytes.end(), b, b + 4);
    }
    std::error_code ec;
    if (path.has_parent_path()) fs::create_directories(path.parent_path(), ec);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw Error("cannot write golden array " + quoted(path) + ": cannot open it for writing");
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    out.close();
    // A full disk shows up only when the buffer is flushed, so check after close().
    if (!out) throw Error("cannot write golden array " + quoted(path) + ": write error (disk full?)");
}

ExpectedArray read_array_golden(const fs::path& path, const std::string& name) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) fail(path, fs::exists(path, ec) ? "not a plain file" : "no such file");
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) fail(path, "cannot read its size: " + ec.message());
    if (size < kHeaderBytes) fail(path, std::to_string(size) + " bytes, shorter than the " + std::to_string(kHeaderBytes) + "-byte header");
    std::ifstream in(path, std::ios::binary);
    unsigned char header[kHeaderBytes];
    if (!in.read(reinterpret_cast<char*>(header), sizeof header)) fail(path, "cannot read its header");
    if (std::memcmp(header, kMagic, sizeof kMagic) != 0) fail(path, "not a golden array (it must start with \"GSVARR1\")");
    ExpectedArray golden;
    golden.name = name;
    golden.count = u32_from_le_bytes(header + 8);
    const std::uint32_t components = u32_from_le_bytes(header + 12);
    const std::uint32_t samples = u32_from_le_bytes(header + 16);
    if (components < 1 || components > std::uint32_t(kMaxArrayComponents))
        fail(path, std::to_string(components) + " components, not 1.." + std::to_string(kMaxArrayComponents));
    golden.components = static_cast<int>(components);
    if (std::uint64_t(golden.count) * components > kMaxArrayFloats)
        fail(path, "an array of " + std::to_string(golden.count) + " x " + std::to_string(components) +
                       " floats, more than the " + std::to_string(kMaxArrayFloats) + " the grader reads");
    if (samples > golden.count)
        fail(path, std::to_string(samples) + " samples of an array of " + std::to_string(golden.count) + " elements");
    const std::uint64_t expected = kHeaderBytes + std::uint64_t(samples) * 4 * (1 + std::uint64_t(components));
    if (size != expected)
        fail(path, std::to_string(size) + " bytes, not the " + std::to_string(expected) + " its header promises (" +
                       std::to_string(samples) + " samples of " + std::to_string(components) + " components)");
    std::vector<unsigned char> body(static_cast<std::size_t>(expected - kHeaderBytes));
    if (!in.read(reinterpret_cast<char*>(body.data()), static_cast<std::streamsize>(body.size())))
        fail(path, "ends before the " + std::to_string(expected) + " bytes its header promises");
    golden.indices.resize(samples);
    for (std::size_t s = 0; s < samples; ++s) {
        golden.indices[s] = u32_from_le_bytes(body.data() + 4 * s);
        if (golden.indices[s] >= golden.count || (s > 0 && golden.indices[s] <= golden.indices[s - 1]))
            fail(path, "sample " + std::to_string(s) + " names element " + std::to_string(golden.indices[s]) +
                           ": indices must ascend and stay under the count " + std::to_string(golden.count));
    }
    const unsigned char* values = body.data() + 4 * std::size_t(samples);
    golden.values.resize(std::size_t(samples) * components);
    for (std::size_t i = 0; i < golden.values.size(); ++i) golden.values[i] = float_from_le_bytes(values + 4 * i);
    return golden;
}

fs::path array_golden_path(const fs::path& kit, const std::string& lab, const std::string& case_name,
                           const std::string& name) {
    return KitLayout{kit}.golden_dir(lab) / (case_name + "." + name + ".f32s");
}

std::vector<std::string> golden_array_names(const fs::path& kit, const std::string& lab, const std::string& case_name) {
    std::vector<std::string> names;
    const fs::path dir = KitLayout{kit}.golden_dir(lab);
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) return names;
    const std::string prefix = case_name + ".";
    for (const auto& e : fs::directory_iterator(dir, ec)) {
        const std::string file = e.path().filename().string();
        if (e.path().extension() != ".f32s" || file.rfind(prefix, 0) != 0) continue;
        const std::string name = file.substr(prefix.size(), file.size() - prefix.size() - 5);
        if (valid_array_name(name)) names.push_back(name);
    }
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace gsv
