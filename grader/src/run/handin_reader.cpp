#include "grader/src/run/handin_reader.h"

#include "common/core/error.h"
#include "common/io/data_array.h"
#include "common/io/little_endian.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string>
#include <unistd.h>

namespace gsv {

void HandinReader::read_from(int fd, HandinConversation& conversation, const std::function<double()>& clock,
                             const HandinConversation::Reply& reply, std::uint64_t& total) {
    std::uint8_t chunk[65536];
    while (true) {
        const ssize_t n = read(fd, chunk, sizeof chunk);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            if (n == 0) closed_ = true;
            return;
        }
        total += static_cast<std::uint64_t>(n);
        if (total > max_bytes_)
            throw Error("sent more than " + std::to_string(max_bytes_ >> 20) + " MiB on the hand-in socket");
        take(conversation, chunk, static_cast<std::size_t>(n), clock(), reply);
    }
}

void HandinReader::take(HandinConversation& conversation, const std::uint8_t* data, std::size_t n, double t,
                        const HandinConversation::Reply& reply) {
    while (n > 0) {
        if (header_got_ < kHandinHeaderBytes) {
            const std::size_t k = std::min<std::size_t>(n, kHandinHeaderBytes - header_got_);
            std::memcpy(header_ + header_got_, data, k);
            header_got_ += k;
            data += k;
            n -= k;
            if (header_got_ < kHandinHeaderBytes) return;
            std::memcpy(message_.tag.data(), header_, 4);
            conversation.announced(message_.tag, u32_from_le_bytes(header_ + 4));
            payload_left_ = checked_payload_size(message_.tag, u32_from_le_bytes(header_ + 4),
                                                 conversation.max_image_pixels(), kMaxArrayFloats);
            message_.payload.clear();
            message_.payload.reserve(payload_left_);
        }
        const std::size_t k = std::min<std::size_t>(n, payload_left_);
        message_.payload.insert(message_.payload.end(), data, data + k);
        data += k;
        n -= k;
        payload_left_ -= k;
        if (payload_left_ == 0) {
            HandinMessage done = std::move(message_);
            message_ = HandinMessage{};
            header_got_ = 0;
            conversation.received(std::move(done), t, reply);
        }
    }
}

}  // namespace gsv
