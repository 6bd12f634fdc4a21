#include "common/image/png_chunks.h"

#include "common/core/error.h"

#include <algorithm>
#include <cctype>
#include <cstddef>

namespace gsv::png {

std::uint32_t crc32(const std::uint8_t* data, std::size_t size) {
    // Built on first use rather than spelled out: 256 magic numbers are harder to review than 6 lines.
    static const std::array<std::uint32_t, 256> table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t n = 0; n < 256; ++n) {
            std::uint32_t c = n;
            for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
            t[n] = c;
        }
        return t;
    }();
    std::uint32_t c = 0xFFFFFFFFu;
    for (std::size_t i = 0; i < size; ++i) c = table[(c ^ data[i]) & 0xFF] ^ (c >> 8);
    return c ^ 0xFFFFFFFFu;
}

void put_u32(Bytes& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(v >> shift));
}

void put_u16(Bytes& out, std::uint32_t v) {
    out.push_back(static_cast<std::uint8_t>(v >> 8));
    out.push_back(static_cast<std::uint8_t>(v));
}

std::uint32_t get_u32(const std::uint8_t* p) {
    return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) | p[3];
}

int get_u16(const std::uint8_t* p) { return (p[0] << 8) | p[1]; }

void put_chunk(Bytes& out, const char* type, const Bytes& data) {
    put_u32(out, static_cast<std::uint32_t>(data.size()));
    const std::size_t start = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data.begin(), data.end());
    put_u32(out, crc32(out.data() + start, out.size() - start));
}

std::vector<Chunk> read_chunks(const Bytes& bytes) {
    if (bytes.size() < kSignature.size() || !std::equal(kSignature.begin(), kSignature.end(), bytes.begin()))
        throw Error("no PNG signature");
    std::vector<Chunk> chunks;
    std::size_t pos = kSignature.size();
    while (chunks.empty() || chunks.back().type != "IEND") {
        if (bytes.size() - pos < 12) throw Error("truncated at byte " + std::to_string(pos) + " (no IEND chunk)");
        const std::uint32_t length = get_u32(&bytes[pos]);
        Chunk chunk;
        chunk.type.assign(reinterpret_cast<const char*>(&bytes[pos + 4]), 4);
        for (char c : chunk.type)
            if (!std::isalpha(static_cast<unsigned char>(c)))
                throw Error("bad chunk type at byte " + std::to_string(pos));
        if (length > 0x7FFFFFFFu || bytes.size() - pos - 12 < length)
            throw Error("chunk " + chunk.type + " at byte " + std::to_string(pos) + " runs past the end of the file");
        if (crc32(&bytes[pos + 4], 4 + std::size_t(length)) != get_u32(&bytes[pos + 8 + length]))
            throw Error("CRC mismatch in chunk " + chunk.type + " at byte " + std::to_string(pos));
        const auto data = bytes.begin() + static_cast<std::ptrdiff_t>(pos + 8);
        chunk.data.assign(data, data + static_cast<std::ptrdiff_t>(length));
        chunks.push_back(std::move(chunk));
        pos += 12 + std::size_t(length);
    }
    if (pos != bytes.size()) throw Error(std::to_string(bytes.size() - pos) + " bytes after the IEND chunk");
    return chunks;
}

}  // namespace gsv::png
