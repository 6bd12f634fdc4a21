#pragma once
// What a lab hands the grader, and how. Under the grader a lab writes nothing it hands in to a file: its image, its
// arrays and its report travel as messages over a socket the grader made and holds the other end of (fd 3, named
// in $GSV_HANDIN_FD). The grader reads no path the student's process could have chosen or linked, and knows each
// message's size from its header before it reads the message.
//
// The same socket times frames: once the lab says it is warm, for each timed frame the grader sends a challenge
// (settings no one could know before, e.g. a camera angle drawn at random), the lab draws the frame with them and
// answers with the frame's pixels. The grader times request to answer and compares each answer with the reference's frame drawn with the
// same settings, so a frame is only fast if its work was done fast (grader/src/run/lab_run.cpp).
//
// A lab started with `render --serve` renders case after case in one process. It says DONE when it waits for its first
// case; the grader sends each case as a request (its size, warm-up, arrays and settings, what a one-case command line
// would say), the lab answers it with exactly the messages above (and the challenges of a timed case), and after the
// grader's END it says DONE again once everything of the case is gone (its lab, session and GL context): the case's
// time ends there, as a process's would at its exit. Another request follows only once the last is answered; an END
// while the lab waits for a case ends the process. Anything else the lab sends while no request is open is refused.
//
// A message: a 4-byte tag, a 4-byte little-endian payload size, the payload. Integers are little-endian.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gsv {

// The variable naming the hand-in socket's descriptor in a lab run by the grader.
inline constexpr const char* kHandinVariable = "GSV_HANDIN_FD";
inline constexpr int kHandinFd = 3;

using HandinTag = std::array<char, 4>;
// Lab to grader.
inline constexpr HandinTag kTagImage{'I', 'M', 'G', '1'};   // u32 width, u32 height, RGBA8 rows, top row first
inline constexpr HandinTag kTagArray{'A', 'R', 'R', '1'};   // u32 name bytes, name, u32 components, u32 count, floats
inline constexpr HandinTag kTagReport{'R', 'P', 'T', '1'};  // the JSON report; always last of the hand-in
inline constexpr HandinTag kTagReady{'R', 'D', 'Y', '1'};   // after the hand-in and the warm-up: ready for challenges
inline constexpr HandinTag kTagFrame{'F', 'R', 'M', '1'};   // u32 challenge number, then as an image
inline constexpr HandinTag kTagDone{'D', 'N', 'E', '1'};    // served: waiting for a case (at the start, after each)
// Grader to lab.
inline constexpr HandinTag kTagChallenge{'C', 'H', 'L', '1'};  // u32 number, then settings as "name=value" lines
inline constexpr HandinTag kTagEnd{'E', 'N', 'D', '1'};        // no more challenges: exit (served: the case is over)
inline constexpr HandinTag kTagCase{'C', 'A', 'S', '1'};       // served: the next case (HandinCase below)

inline constexpr std::uint32_t kHandinHeaderBytes = 8;
// The most a message may hold: an image of 4096 x 4096; a report of 1 MiB; a challenge of 4 KiB.
inline constexpr std::uint64_t kMaxHandinImagePixels = 4096ull * 4096ull;
inline constexpr std::uint32_t kMaxHandinReportBytes = 1u << 20;
inline constexpr std::uint32_t kMaxHandinChallengeBytes = 4096;
inline constexpr std::uint32_t kMaxHandinCaseBytes = 16384;

struct HandinMessage {
    HandinTag tag{};
    std::vector<std::uint8_t> payload;
};

std::string tag_name(const HandinTag& tag);  // "IMG1", or the bytes escaped when they are not printable

// The bytes of a whole message.
std::vector<std::uint8_t> encode_message(const HandinTag& tag, const std::vector<std::uint8_t>& payload);

// Payload builders and readers. A reader throws gsv::Error naming what is malformed ("an image message of 100
// bytes holds no 64 x 64 image").
struct HandinImage {
    std::uint32_t width = 0, height = 0;
    std::vector<std::uint8_t> rgba;
};
std::vector<std::uint8_t> image_payload(std::uint32_t width, std::uint32_t height, const std::vector<std::uint8_t>& rgba);
HandinImage read_image_payload(const std::vector<std::uint8_t>& payload, std::size_t offset = 0);

struct HandinFrame {
    std::uint32_t number = 0;
    HandinImage image;
};
std::vector<std::uint8_t> frame_payload(std::uint32_t number, std::uint32_t width, std::uint32_t height,
                                        const std::vector<std::uint8_t>& rgba);
HandinFrame read_frame_payload(const std::vector<std::uint8_t>& payload);

struct HandinArray {
    std::string name;
    std::uint32_t components = 0, count = 0;
    std::vector<float> values;
};
std::vector<std::uint8_t> array_payload(const std::string& name, std::uint32_t components, const std::vector<float>& values);
HandinArray read_array_payload(const std::vector<std::uint8_t>& payload);

struct HandinChallenge {
    std::uint32_t number = 0;
    std::vector<std::string> settings;  // name=value
};
std::vector<std::uint8_t> challenge_payload(const HandinChallenge& challenge);
HandinChallenge read_challenge_payload(const std::vector<std::uint8_t>& payload);

// A served lab's next case: u32 width, height, warm-up frames, flags (1: hand in the arrays), the GL version's
// major and minor (0.0: the lab's own), then its settings as "name=value" lines, applied over the declared defaults.
struct HandinCase {
    std::uint32_t width = 0, height = 0;
    std::uint32_t warmup = 0;  // untimed frames before a timed case's challenges (--warmup)
    bool arrays = false;       // --arrays
    std::uint32_t gl_major = 0, gl_minor = 0;  // --gl; 0.0: none given
    std::vector<std::string> settings;  // --set name=value, in order
};
std::vector<std::uint8_t> case_payload(const HandinCase& request);
HandinCase read_case_payload(const std::vector<std::uint8_t>& payload);

// A message's size as its header declares it, refused before anything is read when the tag is unknown or the size
// is over what that tag may carry (images: `max_pixels`). Throws gsv::Error naming the tag and the size.
std::uint32_t checked_payload_size(const HandinTag& tag, std::uint32_t declared, std::uint64_t max_pixels,
                                   std::uint64_t max_array_floats);

// The lab's end of the socket (blocking). Inactive outside the grader ($GSV_HANDIN_FD unset): then render mode
// writes files as usual.
class HandinChannel {
public:
    HandinChannel();  // reads $GSV_HANDIN_FD
    bool active() const { return fd_ >= 0; }
    // Throws gsv::Error when the grader's end is gone.
    void send(const HandinTag& tag, const std::vector<std::uint8_t>& payload) const;
    // The grader's next message; none when it closed its end.
    std::optional<HandinMessage> receive() const;

private:
    int fd_ = -1;
};

}  // namespace gsv
