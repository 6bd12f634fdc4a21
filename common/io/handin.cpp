#include "common/io/handin.h"

#include "common/core/error.h"
#include "common/core/number_text.h"
#include "common/io/data_array.h"
#include "common/io/little_endian.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>

#if defined(__unix__) || defined(__APPLE__)
#include <sys/socket.h>
#include <unistd.h>
#endif

namespace gsv {
namespace {

void put_u32(std::vector<std::uint8_t>& out, std::uint32_t value) {
    unsigned char bytes[4];
    u32_to_le_bytes(value, bytes);
    out.insert(out.end(), bytes, bytes + 4);
}

// Reads little-endian values from a payload, refusing to read past its end.
class PayloadReader {
public:
    PayloadReader(const std::vector<std::uint8_t>& payload, std::size_t offset, const char* what)
        : p_(payload), at_(offset), what_(what) {}
    std::uint32_t u32() {
        need(4);
        const std::uint32_t v = u32_from_le_bytes(p_.data() + at_);
        at_ += 4;
        return v;
    }
    const std::uint8_t* bytes(std::uint64_t n) {
        need(n);
        const std::uint8_t* start = p_.data() + at_;
        at_ += static_cast<std::size_t>(n);
        return start;
    }
    std::size_t left() const { return p_.size() - at_; }
    void need(std::uint64_t n) const {
        if (n > left())
            throw Error(std::string(what_) + " message of " + std::to_string(p_.size()) + " bytes ends before its content does");
    }
    void done() const {
        if (left() != 0)
            throw Error(std::string(what_) + " message has " + std::to_string(left()) + " bytes after its content");
    }

private:
    const std::vector<std::uint8_t>& p_;
    std::size_t at_;
    const char* what_;
};

bool same(const HandinTag& a, const HandinTag& b) { return a == b; }

// Settings as "name=value" lines, the rest of a challenge's or a case's payload.
void put_settings(std::vector<std::uint8_t>& out, const std::vector<std::string>& settings, const char* what) {
    for (const auto& s : settings) {
        if (s.find('\n') != std::string::npos || s.find('=') == std::string::npos)
            throw Error(std::string(what) + " setting '" + s + "' is not name=value");
        out.insert(out.end(), s.begin(), s.end());
        out.push_back('\n');
    }
}

std::vector<std::string> read_settings(PayloadReader& in, const char* what) {
    const std::size_t n = in.left();
    const std::uint8_t* text = in.bytes(n);
    std::vector<std::string> settings;
    std::string line;
    for (const std::uint8_t* p = text; p != text + n; ++p) {
        if (*p != '\n') {
            line += static_cast<char>(*p);
            continue;
        }
        if (line.find('=') == std::string::npos) throw Error(std::string(what) + " setting '" + line + "' is not name=value");
        settings.push_back(line);
        line.clear();
    }
    if (!line.empty()) throw Error(std::string(what) + " ends inside a setting");
    return settings;
}

}  // namespace

std::string tag_name(const HandinTag& tag) {
    std::string name;
    for (char c : tag) {
        if (c >= 0x21 && c <= 0x7e) {
            name += c;
        } else {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02x", static_cast<unsigned char>(c));
            name += escaped;
        }
    }
    return name;
}

std::vector<std::uint8_t> encode_message(const HandinTag& tag, const std::vector<std::uint8_t>& payload) {
    if (payload.size() > 0xffffffffull) throw Error("a hand-in message over 4 GiB");
    std::vector<std::uint8_t> out(tag.begin(), tag.end());
    out.reserve(kHandinHeaderBytes + payload.size());
    put_u32(out, static_cast<std::uint32_t>(payload.size()));
    out.insert(out.end(), payload.begin(), payload.end());
    return out;
}

std::vector<std::uint8_t> image_payload(std::uint32_t width, std::uint32_t height, const std::vector<std::uint8_t>& rgba) {
    if (std::uint64_t(width) * height * 4 != rgba.size()) throw Error("an image's pixels do not match its size");
    std::vector<std::uint8_t> out;
    out.reserve(8 + rgba.size());
    put_u32(out, width);
    put_u32(out, height);
    out.insert(out.end(), rgba.begin(), rgba.end());
    return out;
}

HandinImage read_image_payload(const std::vector<std::uint8_t>& payload, std::size_t offset) {
    PayloadReader in(payload, offset, "an image");
    HandinImage image;
    image.width = in.u32();
    image.height = in.u32();
    const std::uint64_t pixels = std::uint64_t(image.width) * image.height;
    if (image.width == 0 || image.height == 0 || pixels > kMaxHandinImagePixels)
        throw Error("an image message declares " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                    " pixels (1 to 4096 x 4096 are taken)");
    if (in.left() != pixels * 4)
        throw Error("an image message of " + std::to_string(payload.size()) + " bytes holds no " +
                    std::to_string(image.width) + " x " + std::to_string(image.height) + " RGBA image");
    const std::uint8_t* rgba = in.bytes(pixels * 4);
    image.rgba.assign(rgba, rgba + pixels * 4);
    return image;
}

std::vector<std::uint8_t> frame_payload(std::uint32_t number, std::uint32_t width, std::uint32_t height,
                                        const std::vector<std::uint8_t>& rgba) {
    std::vector<std::uint8_t> out;
    put_u32(out, number);
    const std::vector<std::uint8_t> image = image_payload(width, height, rgba);
    out.insert(out.end(), image.begin(), image.end());
    return out;
}

HandinFrame read_frame_payload(const std::vector<std::uint8_t>& payload) {
    PayloadReader in(payload, 0, "a frame");
    HandinFrame frame;
    frame.number = in.u32();
    frame.image = read_image_payload(payload, 4);
    return frame;
}

std::vector<std::uint8_t> array_payload(const std::string& name, std::uint32_t components, const std::vector<float>& values) {
    if (components == 0 || values.size() % components != 0) throw Error("array '" + name + "' is not whole elements");
    std::vector<std::uint8_t> out;
    out.reserve(16 + name.size() + values.size() * 4);
    put_u32(out, static_cast<std::uint32_t>(name.size()));
    out.insert(out.end(), name.begin(), name.end());
    put_u32(out, components);
    put_u32(out, static_cast<std::uint32_t>(values.size() / components));
    const std::size_t at = out.size();
    out.resize(at + values.size() * 4);
    for (std::size_t i = 0; i < values.size(); ++i) float_to_le_bytes(values[i], out.data() + at + 4 * i);
    return out;
}

HandinArray read_array_payload(const std::vector<std::uint8_t>& payload) {
    PayloadReader in(payload, 0, "an array");
    HandinArray a;
    const std::uint32_t name_bytes = in.u32();
    if (name_bytes > kMaxArrayNameBytes) throw Error("an array message names an array of " + std::to_string(name_bytes) + " bytes");
    const std::uint8_t* name = in.bytes(name_bytes);
    a.name.assign(name, name + name_bytes);
    if (!valid_array_name(a.name))
        throw Error("an array message's name is not 1.." + std::to_string(kMaxArrayNameBytes) + " of a-z, 0-9, '_'");
    a.components = in.u32();
    a.count = in.u32();
    if (a.components < 1 || a.components > static_cast<std::uint32_t>(kMaxArrayComponents))
        throw Error("array '" + a.name + "' has " + std::to_string(a.components) + " components, not 1.." +
                    std::to_string(kMaxArrayComponents));
    const std::uint64_t floats = std::uint64_t(a.count) * a.components;
    if (floats > kMaxArrayFloats) throw Error("array '" + a.name + "' holds more than the " + std::to_string(kMaxArrayFloats) + " floats taken");
    if (in.left() != floats * 4)
        throw Error("array '" + a.name + "': " + std::to_string(a.count) + " x " + std::to_string(a.components) +
                    " floats declared, " + std::to_string(in.left()) + " bytes sent");
    const std::uint8_t* bytes = in.bytes(floats * 4);
    a.values.resize(static_cast<std::size_t>(floats));
    for (std::size_t i = 0; i < a.values.size(); ++i) a.values[i] = float_from_le_bytes(bytes + 4 * i);
    in.done();
    return a;
}

std::vector<std::uint8_t> challenge_payload(const HandinChallenge& challenge) {
    std::vector<std::uint8_t> out;
    out.reserve(kMaxHandinChallengeBytes);  // also keeps GCC 12 from a false -Wstringop-overflow on the first insert
    put_u32(out, challenge.number);
    put_settings(out, challenge.settings, "a challenge");
    if (out.size() > kMaxHandinChallengeBytes) throw Error("a challenge over " + std::to_string(kMaxHandinChallengeBytes) + " bytes");
    return out;
}

HandinChallenge read_challenge_payload(const std::vector<std::uint8_t>& payload) {
    PayloadReader in(payload, 0, "a challenge");
    HandinChallenge c;
    c.number = in.u32();
    c.settings = read_settings(in, "a challenge");
    return c;
}

std::vector<std::uint8_t> case_payload(const HandinCase& request) {
    std::vector<std::uint8_t> out;
    out.reserve(kMaxHandinCaseBytes);
    for (const std::uint32_t v : {request.width, request.height, request.warmup, request.arrays ? 1u : 0u, request.gl_major, request.gl_minor})
        put_u32(out, v);
    put_settings(out, request.settings, "a case");
    if (out.size() > kMaxHandinCaseBytes) throw Error("a case over " + std::to_string(kMaxHandinCaseBytes) + " bytes");
    return out;
}

HandinCase read_case_payload(const std::vector<std::uint8_t>& payload) {
    PayloadReader in(payload, 0, "a case");
    HandinCase c;
    c.width = in.u32();
    c.height = in.u32();
    c.warmup = in.u32();
    const std::uint32_t flags = in.u32();
    if (flags > 1) throw Error("a case message has flags " + std::to_string(flags) + " (1: arrays, the only one)");
    c.arrays = flags == 1;
    c.gl_major = in.u32();
    c.gl_minor = in.u32();
    c.settings = read_settings(in, "a case");
    return c;
}

std::uint32_t checked_payload_size(const HandinTag& tag, std::uint32_t declared, std::uint64_t max_pixels,
                                   std::uint64_t max_array_floats) {
    std::uint64_t most = 0;
    if (same(tag, kTagImage)) most = 8 + 4 * max_pixels;
    else if (same(tag, kTagFrame)) most = 12 + 4 * max_pixels;
    else if (same(tag, kTagArray)) most = 12 + kMaxArrayNameBytes + 4 * max_array_floats;
    else if (same(tag, kTagReport)) most = kMaxHandinReportBytes;
    else if (same(tag, kTagChallenge)) most = kMaxHandinChallengeBytes;
    else if (same(tag, kTagCase)) most = kMaxHandinCaseBytes;
    else if (same(tag, kTagEnd) || same(tag, kTagReady) || same(tag, kTagDone)) most = 0;
    else throw Error("a message tagged '" + tag_name(tag) + "', which is no message of the hand-in");
    if (declared > most)
        throw Error("a " + tag_name(tag) + " message of " + std::to_string(declared) + " bytes, over the " +
                    std::to_string(most) + " it may have");
    return declared;
}

HandinChannel::HandinChannel() {
#if defined(__unix__) || defined(__APPLE__)
    if (const char* text = std::getenv(kHandinVariable); text && *text)
        if (const auto fd = parse_finite_number(text); fd && *fd >= 3 && *fd < 1024 && *fd == static_cast<int>(*fd))
            fd_ = static_cast<int>(*fd);
#endif
}

void HandinChannel::send(const HandinTag& tag, const std::vector<std::uint8_t>& payload) const {
#if defined(__unix__) || defined(__APPLE__)
    const std::vector<std::uint8_t> message = encode_message(tag, payload);
    std::size_t sent = 0;
    while (sent < message.size()) {
        const ssize_t n = write(fd_, message.data() + sent, message.size() - sent);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw Error("the grader's hand-in socket closed (" + std::string(std::strerror(errno)) + ")");
        sent += static_cast<std::size_t>(n);
    }
#else
    (void)tag;
    (void)payload;
#endif
}

std::optional<HandinMessage> HandinChannel::receive() const {
#if defined(__unix__) || defined(__APPLE__)
    auto read_all = [&](std::uint8_t* into, std::size_t n) {
        std::size_t got = 0;
        while (got < n) {
            const ssize_t r = read(fd_, into + got, n - got);
            if (r < 0 && errno == EINTR) continue;
            if (r <= 0) return false;
            got += static_cast<std::size_t>(r);
        }
        return true;
    };
    std::uint8_t header[kHandinHeaderBytes];
    if (!read_all(header, sizeof header)) return std::nullopt;
    HandinMessage m;
    std::memcpy(m.tag.data(), header, 4);
    const std::uint32_t size = checked_payload_size(m.tag, u32_from_le_bytes(header + 4), 0, 0);
    m.payload.resize(size);
    if (!read_all(m.payload.data(), size)) throw Error("the grader's message ended early");
    return m;
#else
    return std::nullopt;
#endif
}

}  // namespace gsv
