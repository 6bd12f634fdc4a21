// The hand-in socket (common/io/handin.h) from the grader's side: what a lab process may send, in what order, and
// how each way of breaking the rules ends. The "labs" are small Python programs speaking the wire format.
#include "catch.hpp"
#include "test_support.h"

#include "common/io/handin.h"
#include "grader/src/run/lab_run.h"

#include <chrono>

using namespace gsv;
namespace fs = std::filesystem;

namespace {

// A lab whose behaviour is the Python statements `body`, after helpers send(tag, payload) and read_message().
// `image` is a valid 4x4 image payload; `challenge` loops over the grader's challenges answering each with it.
fs::path python_lab(const test::TempDir& dir, const std::string& name, const std::string& body) {
    const fs::path script = dir.path("bin") / name;
    fs::create_directories(script.parent_path());
    std::ofstream(script) << "#!/usr/bin/env python3\n"
                             "import os, struct, sys, time\n"
                             "fd = int(os.environ['GSV_HANDIN_FD'])\n"
                             "def send(tag, payload=b''):\n"
                             "    data = tag + struct.pack('<I', len(payload)) + payload\n"
                             "    while data: data = data[os.write(fd, data):]\n"
                             "def read_message():\n"
                             "    def read(n):\n"
                             "        data = b''\n"
                             "        while len(data) < n:\n"
                             "            more = os.read(fd, n - len(data))\n"
                             "            if not more: sys.exit(0)\n"
                             "            data += more\n"
                             "        return data\n"
                             "    tag, size = read(4), struct.unpack('<I', read(4))[0]\n"
                             "    return tag, read(size)\n"
                             "image = struct.pack('<II', 4, 4) + bytes(range(64))\n"
                             "def hand_in():\n"
                             "    send(b'IMG1', image)\n"
                             "    send(b'RPT1', b'{}')\n"
                             "    send(b'RDY1')\n"
                             "def answer(number_offset=0):\n"
                             "    while True:\n"
                             "        tag, payload = read_message()\n"
                             "        if tag == b'END1': sys.exit(0)\n"
                             "        number = struct.unpack('<I', payload[:4])[0] + number_offset\n"
                             "        send(b'FRM1', struct.pack('<I', number) + image)\n"
                          << body << "\n";
    fs::permissions(script, fs::perms::owner_all);
    return script;
}

struct Fixture {
    test::TempDir dir;
    LabCases lab;
    GradeCase c;
    Fixture() {
        lab.lab = "lab99";
        lab.width = lab.height = lab.timing_width = lab.timing_height = 4;
        c.name = "case";
    }
    LabRun run(const std::string& body, const std::vector<std::vector<std::string>>* challenges = nullptr, double timeout_s = 20) {
        python_lab(dir, "lab99", body);
        ProcessLimits limits;
        limits.timeout = std::chrono::milliseconds(static_cast<long>(timeout_s * 1000));
        return LabRunner{dir.path("bin"), {}, false, Profile::Core}.render("lab99", lab, c, limits, challenges);
    }
};

}  // namespace

TEST_CASE("hand-in: a lab that keeps the rules hands in its image and answers each challenge with a frame", "[grader][process]") {
    Fixture f;
    const LabRun plain = f.run("hand_in(); answer()");
    INFO(plain.detail << plain.process.output);
    CHECK(plain.status == CaseStatus::Passed);
    REQUIRE(plain.image);
    CHECK(plain.image->width == 4);
    CHECK(plain.image->rgba[5] == 5);
    const std::vector<std::vector<std::string>> challenges{{"a=1"}, {"a=2"}, {"a=3"}};
    const LabRun timed = f.run("hand_in(); answer()", &challenges);
    INFO(timed.detail << timed.process.output);
    CHECK(timed.status == CaseStatus::Passed);
    CHECK(timed.frames.size() == 3);
    CHECK(timed.frame_ms.size() == 3);
    CHECK(timed.challenges == challenges);
    // A frame is timed from its challenge: a lab that waits 200 ms before each answer takes 200 ms a frame.
    const LabRun slow = f.run("hand_in()\nwhile True:\n    tag, payload = read_message()\n    if tag == b'END1': sys.exit(0)\n"
                              "    time.sleep(0.2)\n    send(b'FRM1', payload[:4] + image)", &challenges);
    CHECK(slow.status == CaseStatus::Passed);
    CHECK(slow.median_ms >= 200);
    CHECK(slow.median_ms < 1000);
}

TEST_CASE("hand-in: every way of breaking the rules is refused in one line, or its own status, and never hangs the grader",
          "[grader][process]") {
    Fixture f;
    const std::vector<std::vector<std::string>> challenges{{"a=1"}, {"a=2"}};
    struct Broken {
        const char* what;
        std::string body;
        bool timed;
        CaseStatus status;
        std::string says;
    };
    const std::vector<Broken> broken{
        {"frames before the hand-in", "send(b'FRM1', struct.pack('<I', 0) + image); hand_in(); answer()", true, CaseStatus::Refused,
         "handed in timed frame 0 before the grader asked for it"},
        {"frames before their challenge", "send(b'IMG1', image); send(b'RPT1', b'{}'); send(b'FRM1', struct.pack('<I', 0) + image); "
                                          "send(b'RDY1'); answer()", true, CaseStatus::Refused, "before the grader asked for it"},
        {"a frame for another challenge", "hand_in(); answer(1)", true, CaseStatus::Refused, "handed in timed frame 1 before"},
        {"fewer frames than asked", "hand_in(); read_message(); sys.exit(0)", true, CaseStatus::Refused, "answered 0 of the 2 timed frames"},
        {"an image larger than the case's", "os.write(fd, b'IMG1' + struct.pack('<I', 67108872)); time.sleep(30)", false, CaseStatus::Refused,
         "a IMG1 message of 67108872 bytes, over the 72 it may have"},
        {"an image of another size", "send(b'IMG1', struct.pack('<II', 2, 8) + bytes(64)); send(b'RPT1', b'{}')", false, CaseStatus::Passed, ""},
        {"a size no message may have", "os.write(fd, b'ARR1' + struct.pack('<I', 0xfffffff0)); time.sleep(30)", false,
         CaseStatus::Refused, "over the"},
        {"a message no lab sends", "send(b'CHL1', struct.pack('<I', 0))", false, CaseStatus::Refused, "a CHL1 message, which a lab does not send"},
        {"a tag that is no message", "send(b'/etc', b'passwd')", false, CaseStatus::Refused, "which is no message of the hand-in"},
        {"a report before its image", "send(b'RPT1', b'{}'); send(b'IMG1', image)", false, CaseStatus::Refused, "before its image"},
        {"a report that is not JSON", "send(b'IMG1', image); send(b'RPT1', b'{not json')", false, CaseStatus::Refused, "the lab's report:1:"},
        {"two images", "send(b'IMG1', image); send(b'IMG1', image)", false, CaseStatus::Refused, "a second image"},
        {"an array twice", "a = struct.pack('<I', 1) + b'p' + struct.pack('<II', 1, 1) + bytes(4)\nsend(b'ARR1', a); send(b'ARR1', a)", false,
         CaseStatus::Refused, "array 'p' twice"},
        {"half a message, then exit 0", "os.write(fd, b'IMG1' + struct.pack('<I', 72) + bytes(10)); sys.exit(0)", false, CaseStatus::Refused,
         "ended in the middle of a message"},
        {"no hand-in at all", "sys.exit(0)", false, CaseStatus::MissingOutput, "handed in no image and report"},
        {"an image, no report", "send(b'IMG1', image); sys.exit(0)", false, CaseStatus::MissingOutput, "handed in no image and report"},
        {"nothing, ever", "time.sleep(60)", false, CaseStatus::Timeout, "killed after the time limit"},
    };
    for (const auto& b : broken) {
        const auto start = std::chrono::steady_clock::now();
        const LabRun run = f.run(b.body, b.timed ? &challenges : nullptr, 3);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        INFO(b.what << ": " << status_name(run.status) << ": " << run.detail << "\n" << run.process.output);
        CHECK(run.status == b.status);
        CHECK(run.detail.find(b.says) != std::string::npos);
        CHECK(run.detail.find('\n') == std::string::npos);
        CHECK(seconds < 5);  // killed on the spot, or at the 3 s limit, never waited on
    }
}
