// The hand-in socket (common/io/handin.h) from the grader's side: what a lab process may send, in what order, and
// how each way of breaking the rules ends. The "labs" are small Python programs speaking the wire format.
#include "catch.hpp"
#include "test_support.h"

#include "common/io/handin.h"
#include "grader/src/run/lab_run.h"

#include <chrono>
#include <fstream>

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
    // `arrays`: the lab hands in arrays its cases check (lab 05's particles), as a case file with tolerance.arrays says.
    explicit Fixture(bool arrays = false) {
        lab.lab = "lab99";
        lab.width = lab.height = lab.timing_width = lab.timing_height = 4;
        if (arrays) lab.live_array_tolerance = ArrayTolerance{1e-4, 0};
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
         "handed in a timed frame before the grader asked for it"},
        {"frames before their challenge", "send(b'IMG1', image); send(b'RPT1', b'{}'); send(b'FRM1', struct.pack('<I', 0) + image); "
                                          "send(b'RDY1'); answer()", true, CaseStatus::Refused, "before the grader asked for it"},
        {"a frame for another challenge", "hand_in(); answer(1)", true, CaseStatus::Refused, "handed in timed frame 1 before"},
        {"fewer frames than asked", "hand_in(); read_message(); sys.exit(0)", true, CaseStatus::Refused, "answered 0 of the 2 timed frames"},
        {"an image larger than the case's", "os.write(fd, b'IMG1' + struct.pack('<I', 67108872)); time.sleep(30)", false, CaseStatus::Refused,
         "a IMG1 message of 67108872 bytes, over the 72 it may have"},
        {"an image of another size", "send(b'IMG1', struct.pack('<II', 2, 8) + bytes(64)); send(b'RPT1', b'{}')", false, CaseStatus::Passed, ""},
        {"a size no message may have", "send(b'IMG1', image); os.write(fd, b'RPT1' + struct.pack('<I', 0xfffffff0)); time.sleep(30)", false,
         CaseStatus::Refused, "over the"},
        {"a message no lab sends", "send(b'CHL1', struct.pack('<I', 0))", false, CaseStatus::Refused, "a CHL1 message, which a lab does not send"},
        {"a tag that is no message", "send(b'/etc', b'passwd')", false, CaseStatus::Refused, "which is no message of the hand-in"},
        {"a report before its image", "send(b'RPT1', b'{}'); send(b'IMG1', image)", false, CaseStatus::Refused, "before its image"},
        {"a report that is not JSON", "send(b'IMG1', image); send(b'RPT1', b'{not json')", false, CaseStatus::Refused, "the lab's report:1:"},
        {"two images", "send(b'IMG1', image); send(b'IMG1', image)", false, CaseStatus::Refused, "a second image"},
        {"an array where the case checks none", "a = struct.pack('<I', 1) + b'p' + struct.pack('<II', 1, 1) + bytes(4)\nsend(b'ARR1', a)",
         false, CaseStatus::Refused, "handed in an array, which this case does not ask for"},
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

TEST_CASE("hand-in: arrays are taken strictly, and their total is refused as announced", "[grader][process]") {
    Fixture f(true);
    const std::string array_p = "struct.pack('<I', 1) + b'p' + struct.pack('<II', 1, 1) + bytes(4)";
    const LabRun twice = f.run("a = " + array_p + "\nsend(b'ARR1', a); send(b'ARR1', a)", nullptr, 3);
    CHECK(twice.status == CaseStatus::Refused);
    CHECK(twice.detail.find("array 'p' twice") != std::string::npos);
    const LabRun after = f.run("send(b'IMG1', image); send(b'RPT1', b'{}'); send(b'ARR1', " + array_p + ")", nullptr, 3);
    CHECK(after.status == CaseStatus::Refused);
    // Seventeen arrays: the seventeenth is refused from its header.
    std::string many;
    for (int i = 0; i < 17; ++i)
        many += "send(b'ARR1', struct.pack('<I', 2) + b'a" + std::string(1, char('a' + i)) + "' + struct.pack('<II', 1, 1) + bytes(4))\n";
    const LabRun seventeen = f.run(many + "hand_in()", nullptr, 3);
    CHECK(seventeen.status == CaseStatus::Refused);
    CHECK(seventeen.detail.find("more than 16 arrays") != std::string::npos);
}

namespace {

// The grader's resident memory at its peak since `reset_peak_memory` (Linux: VmHWM, reset through clear_refs).
long peak_memory_kib() {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
    return -1;
}
void reset_peak_memory() { std::ofstream("/proc/self/clear_refs") << "5"; }
long memory_now_kib() {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
    return -1;
}

}  // namespace

// Issue 39: ten arrays of 25 Mi floats (1000 MiB) were taken and the case passed, the grader at 1.18 GB for one case.
TEST_CASE("hand-in: arrays over the 64 Mi floats a render may hand in are refused from the header, the grader's memory bounded",
          "[grader][process]") {
    Fixture f(true);
    const std::string floats_25mi = "struct.pack('<I', 1) + bytes([97 + i]) + struct.pack('<II', 1, 25 << 20) + bytes(100 << 20)";
    reset_peak_memory();
    const long before = memory_now_kib();
    const LabRun ten = f.run("for i in range(10): send(b'ARR1', " + floats_25mi + ")\nhand_in()", nullptr, 60);
    const long grown_ten = peak_memory_kib() - before;
    INFO(status_name(ten.status) << ": " << ten.detail << "; the grader's peak grew by " << grown_ten / 1024 << " MiB");
    CHECK(ten.status == CaseStatus::Refused);
    CHECK(ten.detail.find("announced arrays of") != std::string::npos);
    CHECK(ten.detail.find("67108864 floats") != std::string::npos);
    // The most a render may hand in, in one array: 64 Mi floats, taken; what the grader holds then is the bound.
    reset_peak_memory();
    const long before_one = memory_now_kib();
    const LabRun most = f.run("i = 0\nsend(b'ARR1', struct.pack('<I', 1) + b'a' + struct.pack('<II', 1, 64 << 20) + bytes(256 << 20))\n"
                              "hand_in()", nullptr, 60);
    const long grown_most = peak_memory_kib() - before_one;
    INFO(status_name(most.status) << ": " << most.detail << "; the grader's peak grew by " << grown_most / 1024 << " MiB");
    CHECK(most.status == CaseStatus::Passed);
    CHECK(most.arrays.size() == 1);
    // grader/README.md states the bound: the floats taken (256 MiB) and the one message being read (at most as much).
    CHECK(grown_ten < 600 * 1024);
    CHECK(grown_most < 600 * 1024);
    WARN("the grader's peak memory for one render: " << grown_ten / 1024 << " MiB refusing ten arrays of 25 Mi floats, "
         << grown_most / 1024 << " MiB taking one of 64 Mi floats (the most a render may hand in)");
}
