#pragma once
// PNG's chunk framing (length, type, data, CRC-32), shared by the APNG writer and reader. Internal to the
// framework: image.h is where PNG files are read and written.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace gsv::png {

using Bytes = std::vector<std::uint8_t>;

inline const std::array<std::uint8_t, 8> kSignature{137, 80, 78, 71, 13, 10, 26, 10};

// The CRC-32 of ISO 3309 that follows every chunk, over its type and data.
std::uint32_t crc32(const std::uint8_t* data, std::size_t size);

void put_u32(Bytes& out, std::uint32_t v);
void put_u16(Bytes& out, std::uint32_t v);
std::uint32_t get_u32(const std::uint8_t* p);
int get_u16(const std::uint8_t* p);

// Appends length, type, data and CRC.
void put_chunk(Bytes& out, const char* type, const Bytes& data);

struct Chunk {
    std::string type;
    Bytes data;
};

// A PNG's chunks up to IEND, with the signature, framing and every CRC checked. Throws gsv::Error with
// the reason alone ("CRC mismatch in chunk fdAT at byte 912"): the caller names the file.
std::vector<Chunk> read_chunks(const Bytes& bytes);

}  // namespace gsv::png
