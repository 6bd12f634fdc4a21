#pragma once
// FNV-1a, 64 bits: a fingerprint to tell things apart (kits, cache entries), not a defence against someone forging
// one; whoever trusts a match on it compares the bytes themselves.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace gsv {

struct Fnv1a {
    std::uint64_t state = 0xcbf29ce484222325ull;
    void add(const char* data, std::size_t size) {
        for (std::size_t i = 0; i < size; ++i) {
            state ^= static_cast<unsigned char>(data[i]);
            state *= 0x100000001b3ull;
        }
    }
    void add(const std::string& text) { add(text.data(), text.size() + 1); }  // with its terminator: "ab","c" != "a","bc"
    std::string hex() const {
        char text[17];
        std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(state));
        return text;
    }
};

}  // namespace gsv
