#pragma once
// The grader's end of a child's hand-in socket (common/io/handin.h): what arrives is cut into whole messages, each
// header checked (its tag, its declared size against the limits) before any of its payload is taken, so a message
// over its limit is refused from its header, and the grader's memory stays bounded whatever the child sends.
// Internal to grader/src/run/ (ChildProcess reads with it).
#include "common/io/handin.h"
#include "grader/src/run/process.h"

#include <cstddef>
#include <cstdint>
#include <functional>

namespace gsv {

class HandinReader {
public:
    explicit HandinReader(std::uint64_t max_bytes) : max_bytes_(max_bytes) {}

    // Everything readable now on `fd`, each chunk timed by `clock` as it is read and added to `total`; each whole
    // message goes to `conversation`. Throws gsv::Error to refuse (over max_bytes in all, or a message the
    // conversation or the header check refuses).
    void read_from(int fd, HandinConversation& conversation, const std::function<double()>& clock,
                   const HandinConversation::Reply& reply, std::uint64_t& total);
    bool closed() const { return closed_; }
    // A message begun and not finished when the process ended.
    bool partial() const { return header_got_ > 0 || payload_left_ > 0; }

private:
    void take(HandinConversation& conversation, const std::uint8_t* data, std::size_t n, double t,
              const HandinConversation::Reply& reply);

    std::uint64_t max_bytes_;
    std::uint8_t header_[kHandinHeaderBytes] = {};
    std::size_t header_got_ = 0;
    std::size_t payload_left_ = 0;
    HandinMessage message_;
    bool closed_ = false;
};

}  // namespace gsv
