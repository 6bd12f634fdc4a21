#pragma once
// Internal to height_file.cpp (reading) and height_file_save.cpp (writing): the pieces of the .height format
// (described in height_field.h) that both sides must agree on.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <locale>
#include <optional>
#include <sstream>
#include <string>

namespace gsv::height_format {

inline constexpr const char* kMagic = "GSVHEIGHT";
inline constexpr const char* kVersion = "1";
// Heights are read and written this many bytes at a time (a multiple of 4), so a header that promises
// 256 MiB costs memory only for the bytes really there, and a save never copies a whole field into bytes.
inline constexpr std::size_t kChunkBytes = std::size_t(1) << 20;

inline std::string quoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

inline std::uint64_t height_bytes(int width, int height) {
    return std::uint64_t(width) * std::uint64_t(height) * sizeof(float);
}

// "sample (x, y)" for height `index`; y counts from the south row as everywhere in the kit.
inline std::string sample_name(std::size_t index, int width) {
    return "sample (" + std::to_string(index % width) + ", " + std::to_string(index / width) + ")";
}

inline const char* non_finite_kind(float value) { return std::isnan(value) ? "NaN" : "infinite"; }

// Spacings go through classic-locale streams: strtod and printf would read and write "74,573" in a German
// locale. (std::from_chars/to_chars would do, but Apple's libc++ lacks their floating-point forms.)
inline std::string printf_g(double value, int digits) {
    std::ostringstream out;
    out.imbue(std::locale::classic());
    out.precision(digits);
    out << value;
    return out.str();
}

// A positive finite number written as decimal text (the whole text); nullopt for anything else, "nan",
// "inf", overflow and trailing characters included.
inline std::optional<double> parse_spacing(const std::string& text) {
    std::istringstream in(text);
    in.imbue(std::locale::classic());
    double value = 0;
    in >> value;
    if (in.fail() || !in.eof() || !std::isfinite(value) || value <= 0) return std::nullopt;
    return value;
}

// The shortest "%.Ng" text that reads back as exactly `value`: the same algorithm as scripts/convert-dem.py,
// so either writer gives the same header for the same spacing.
inline std::string spacing_text(double value) {
    for (int digits = 1; digits < 17; ++digits) {
        const std::string text = printf_g(value, digits);
        if (parse_spacing(text) == value) return text;
    }
    return printf_g(value, 17);
}

}  // namespace gsv::height_format
