#include "grader/src/core/safe_text.h"

#include <cstdint>

namespace gsv {
namespace {

void append_utf8(std::string& out, std::uint32_t cp) {
    if (cp < 0x80) {
        out += static_cast<char>(cp);
    } else if (cp < 0x800) {
        out += static_cast<char>(0xC0 | (cp >> 6));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += static_cast<char>(0xE0 | (cp >> 12));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (cp >> 18));
        out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    }
}

// Decodes one code point at text[pos]; returns false (and consumes one byte) on anything invalid.
bool decode(std::string_view text, std::size_t& pos, std::uint32_t& cp) {
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    const unsigned char lead = byte(pos);
    int extra = 0;
    std::uint32_t min = 0;
    if (lead < 0x80) { cp = lead; ++pos; return true; }
    if ((lead & 0xE0) == 0xC0) { extra = 1; cp = lead & 0x1F; min = 0x80; }
    else if ((lead & 0xF0) == 0xE0) { extra = 2; cp = lead & 0x0F; min = 0x800; }
    else if ((lead & 0xF8) == 0xF0) { extra = 3; cp = lead & 0x07; min = 0x10000; }
    else { ++pos; return false; }
    if (pos + extra >= text.size()) { ++pos; return false; }  // truncated at the end
    for (int i = 1; i <= extra; ++i) {
        if ((byte(pos + i) & 0xC0) != 0x80) { ++pos; return false; }
        cp = (cp << 6) | (byte(pos + i) & 0x3F);
    }
    if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) { ++pos; return false; }
    pos += extra + 1;
    return true;
}

// Calls emit(code point) for each character, U+FFFD for each invalid byte.
template <typename Emit>
void for_each_char(std::string_view text, Emit&& emit) {
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::uint32_t cp = 0;
        emit(decode(text, pos, cp) ? cp : 0xFFFD);
    }
}

bool xml_allowed(std::uint32_t cp) {
    if (cp < 0x20) return cp == '\t' || cp == '\n' || cp == '\r';
    return cp != 0xFFFE && cp != 0xFFFF;
}

}  // namespace

std::string valid_utf8(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for_each_char(text, [&](std::uint32_t cp) { append_utf8(out, cp); });
    return out;
}

std::string xml_safe_text(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for_each_char(text, [&](std::uint32_t cp) {
        if (xml_allowed(cp)) append_utf8(out, cp);
    });
    return out;
}

std::string escape_markup(std::string_view raw, MarkupPlace place) {
    const std::string text = xml_safe_text(raw);
    const bool attribute = place == MarkupPlace::Attribute;
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&#39;"; break;
        case '\r': out += "&#13;"; break;  // a bare CR would be read back as LF
        case '\t': out += attribute ? "&#9;" : "\t"; break;
        case '\n': out += attribute ? "&#10;" : "\n"; break;
        default: out += c;
        }
    }
    return out;
}

std::string one_line(std::string_view text, std::size_t max_bytes) {
    std::string flat;
    flat.reserve(text.size());
    for_each_char(text, [&](std::uint32_t cp) {
        if (cp < 0x20 || cp == 0x7F || (cp >= 0x80 && cp < 0xA0)) cp = ' ';
        append_utf8(flat, cp);
    });
    while (!flat.empty() && flat.back() == ' ') flat.pop_back();
    if (flat.size() <= max_bytes) return flat;
    const std::size_t keep = max_bytes > 3 ? max_bytes - 3 : 0;
    std::size_t cut = keep;
    // Back up over continuation bytes so the cut never splits a character.
    while (cut > 0 && (static_cast<unsigned char>(flat[cut]) & 0xC0) == 0x80) --cut;
    return flat.substr(0, cut) + "...";
}

}  // namespace gsv
