// The APNG writer and reader, and the framework's animate mode on a tiny test-only lab.
#include "catch.hpp"
#include "test_support.h"

#include "common/app/app_session.h"
#include "common/core/error.h"
#include "common/gl/gl.h"
#include "common/gl/gpu_mesh.h"
#include "common/image/animation.h"
#include "common/image/image.h"
#include "common/image/png_chunks.h"

#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace gsv;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Odd sizes, every channel varying, and alpha below 255, so a swapped row, channel or frame shows up.
std::vector<Image> three_frames(int w = 13, int h = 7) {
    std::vector<Image> frames;
    for (int k = 0; k < 3; ++k) {
        Image image(w, h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                std::uint8_t* p = image.at(x, y);
                p[0] = static_cast<std::uint8_t>(17 * x + 80 * k);
                p[1] = static_cast<std::uint8_t>(29 * y + 5 * k);
                p[2] = static_cast<std::uint8_t>(x * y + 100 * k);
                p[3] = static_cast<std::uint8_t>(255 - 40 * k - x);
            }
        frames.push_back(image);
    }
    return frames;
}

bool same_pixels(const Image& a, const Image& b) { return a.width == b.width && a.height == b.height && a.rgba == b.rgba; }

std::vector<std::uint8_t> read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const fs::path& path, const std::vector<std::uint8_t>& bytes) {
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                                static_cast<std::streamsize>(bytes.size()));
}

// Frame k through stb_image: the frame's data as a plain PNG of its own.
Image decode_frame(const ApngInfo& info, std::size_t k, const test::TempDir& dir) {
    const fs::path file = dir.path("frame" + std::to_string(k) + ".png");
    write_bytes(file, apng_frame_as_png(info, k));
    return read_png(file);
}

// Where chunk `type` number `nth` starts in a PNG (its length field), for corrupting files on purpose.
std::size_t chunk_offset(const std::vector<std::uint8_t>& bytes, const std::string& type, int nth = 0) {
    std::size_t pos = 8;
    while (pos + 8 <= bytes.size()) {
        if (std::memcmp(&bytes[pos + 4], type.data(), 4) == 0 && nth-- == 0) return pos;
        pos += 12 + png::get_u32(&bytes[pos]);
    }
    FAIL("no chunk " << type);
    return 0;
}

}  // namespace

TEST_CASE("apng: three frames round-trip with valid chunk order and sequence numbers and CRCs and every pixel", "[unit]") {
    test::TempDir dir;
    const auto frames = three_frames();
    const fs::path file = dir.path("out/anim.png");  // the folder is created
    write_apng(file, frames, 1, 20);
    CHECK_FALSE(fs::exists(dir.path("out/anim.png.partial")));

    const ApngInfo info = read_apng_info(file);  // checks every CRC and the chunk order
    CHECK(info.width == 13);
    CHECK(info.height == 7);
    CHECK(info.num_frames == 3);
    CHECK(info.num_plays == 0);
    REQUIRE(info.frames.size() == 3);
    std::vector<std::uint32_t> sequence;
    for (const auto& f : info.frames) {
        sequence.push_back(f.sequence);
        sequence.insert(sequence.end(), f.data_sequences.begin(), f.data_sequences.end());
        CHECK(f.width == 13);
        CHECK(f.height == 7);
        CHECK(f.x_offset == 0);
        CHECK(f.y_offset == 0);
        CHECK(f.delay.num == 1);
        CHECK(f.delay.den == 20);
        CHECK(f.dispose_op == 0);
        CHECK(f.blend_op == 0);
    }
    CHECK(info.frames[0].data_sequences.empty());  // frame 0 is the IDAT image
    CHECK_FALSE(info.frames[1].data_sequences.empty());
    for (std::size_t i = 0; i < sequence.size(); ++i) CHECK(sequence[i] == i);

    // A plain PNG reader sees frame 0; each frame's data decodes to exactly that frame.
    CHECK(same_pixels(read_png(file), frames[0]));
    for (std::size_t k = 0; k < frames.size(); ++k) {
        INFO("frame " << k);
        CHECK(same_pixels(decode_frame(info, k, dir), frames[k]));
    }
}

TEST_CASE("apng: one frame is a valid animation and a later write replaces the file whole", "[unit]") {
    test::TempDir dir;
    const fs::path file = dir.path("one.png");
    write_apng(file, three_frames(), 1, 20);
    write_apng(file, {three_frames(4, 4)[2]}, ApngDelay{1, 1});
    const ApngInfo info = read_apng_info(file);
    CHECK(info.num_frames == 1);
    REQUIRE(info.frames.size() == 1);
    CHECK(info.frames[0].delay.num == 1);
    CHECK(info.frames[0].delay.den == 1);
    CHECK(same_pixels(read_png(file), three_frames(4, 4)[2]));
}

TEST_CASE("apng: no frames or frames of different sizes or a bad delay are refused naming the frame", "[unit]") {
    test::TempDir dir;
    const fs::path file = dir.path("bad.png");
    const std::string none = test::gsv_error_message([&] { write_apng(file, {}, 1, 20); });
    CHECK(contains(none, "cannot write '" + file.string() + "'"));
    CHECK(contains(none, "at least one frame"));

    auto frames = three_frames(8, 8);
    frames.push_back(three_frames(4, 6)[0]);
    const std::string sizes = test::gsv_error_message([&] { write_apng(file, frames, 1, 20); });
    CHECK(contains(sizes, "frame 3 is 4x6 but frame 0 is 8x8"));
    CHECK(sizes.find('\n') == std::string::npos);

    CHECK(contains(test::gsv_error_message([&] { write_apng(file, three_frames(), 1, 70000); }), "16-bit"));
    CHECK(contains(test::gsv_error_message([&] { write_apng(file, {Image()}, 1, 20); }), "frame 0 is empty"));
    CHECK_FALSE(fs::exists(file));  // refused before anything was written
}

TEST_CASE("apng: a path that cannot be written is a one-line error and leaves no partial file", "[unit]") {
    test::TempDir dir;
    const fs::path blocker = dir.write("blocker", "a file where a folder should be");
    const fs::path file = blocker / "anim.png";
    const std::string message = test::gsv_error_message([&] { write_apng(file, three_frames(), 1, 20); });
    CHECK(contains(message, "cannot write '" + file.string() + "'"));
    CHECK(message.find('\n') == std::string::npos);
}

TEST_CASE("apng: the reader refuses a wrong CRC or a truncated file or a gap in the sequence or a plain PNG", "[unit]") {
    test::TempDir dir;
    const fs::path good = dir.path("good.png");
    write_apng(good, three_frames(), 1, 20);
    const auto bytes = read_bytes(good);

    auto bad_crc = bytes;
    const std::size_t fdat = chunk_offset(bad_crc, "fdAT");
    bad_crc[fdat + 12] ^= 0x40;  // a bit of the data: its CRC no longer matches
    CHECK(contains(test::gsv_error_message([&] { parse_apng(bad_crc, "x.png"); }),
                   "'x.png' is not a valid APNG: CRC mismatch in chunk fdAT"));

    const std::vector<std::uint8_t> truncated(bytes.begin(), bytes.end() - 20);
    CHECK(contains(test::gsv_error_message([&] { parse_apng(truncated, "x.png"); }), "is not a valid APNG"));

    // Frame 2's fcTL says 4 instead of 3, with a correct CRC: only the sequence check can catch it.
    auto gap = bytes;
    const std::size_t fctl = chunk_offset(gap, "fcTL", 2);
    REQUIRE(png::get_u32(&gap[fctl + 8]) == 3);
    gap[fctl + 11] = 4;
    const std::uint32_t crc = png::crc32(&gap[fctl + 4], 4 + 26);
    for (int i = 0; i < 4; ++i) gap[fctl + 34 + i] = static_cast<std::uint8_t>(crc >> (24 - 8 * i));
    CHECK(contains(test::gsv_error_message([&] { parse_apng(gap, "x.png"); }),
                   "fcTL has sequence number 4, expected 3"));

    const fs::path plain = dir.path("plain.png");
    write_png(plain, three_frames()[0]);
    CHECK(contains(test::gsv_error_message([&] { read_apng_info(plain); }), "a plain PNG, not an animation"));
    CHECK(contains(test::gsv_error_message([&] { read_apng_info(dir.path("missing.png")); }), "cannot read"));
}

TEST_CASE("apng: the PNG CRC-32 and frame delays from a frame rate", "[unit]") {
    const char* check = "123456789";  // the CRC-32 check value every implementation must give
    CHECK(png::crc32(reinterpret_cast<const std::uint8_t*>(check), 9) == 0xCBF43926u);
    auto delay = [](double fps) {
        const ApngDelay d = apng_delay(fps);
        return std::to_string(d.num) + "/" + std::to_string(d.den);
    };
    CHECK(delay(20) == "1/20");
    CHECK(delay(12.5) == "10/125");
    CHECK(delay(29.97) == "100/2997");
    CHECK(delay(1.0 / 3) == "3000/1000");
    CHECK(contains(test::gsv_error_message([] { apng_delay(0); }), "out of range"));
}

// ---- animate mode, on a lab that exists only here ----

namespace {

// Paints (phase, tint, 0): each frame's colour says which value of the animated parameter drew it. With
// poison on, frames from phase 0.5 on are NaN, drawn by a shader as a real lab's bug would be.
class PulseLab : public Lab {
public:
    explicit PulseLab(bool animated = true, std::vector<double>* phases_seen = nullptr)
        : animated_(animated), phases_seen_(phases_seen) {}

    LabInfo info() const override {
        LabInfo info{"pulse", "animate mode test lab"};
        info.case_file = "tests/shaders/pulse_cases.json";
        return info;
    }
    void declare(Params& params) override {
        gsv::Param<float> phase = params.add_float("phase", 0.25, 0, 1, "the animated parameter");
        if (animated_) phase.animated();
        params.add_float("tint", 0, 0, 1, "green, set with --set or a case");
        params.add_bool("poison", false, "NaN from phase 0.5 on");
    }
    void setup(LabKit& kit) override {
        quad_ = std::make_unique<GpuMesh>(make_fullscreen_quad(), kit.profile());
        nan_ = &kit.program("nan", {"quad.vert", "nan.frag"});
    }
    void params_changed(LabKit& kit) override {
        if (phases_seen_) phases_seen_->push_back(kit.params().get_float("phase"));
    }
    void render(LabKit& kit, const Frame&) override {
        const Params& p = kit.params();
        if (p.get_bool("poison") && p.get_float("phase") >= 0.5f) {
            kit.use(*nan_).set("uZero", 0.0f);
            quad_->draw();
            return;
        }
        glClearColor(p.get_float("phase"), p.get_float("tint"), 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
    }

private:
    bool animated_;
    std::vector<double>* phases_seen_;  // outlives the lab, which run_lab owns
    std::unique_ptr<GpuMesh> quad_;
    const ShaderLibrary::Entry* nan_ = nullptr;
};

int run_pulse(std::vector<std::string> args, bool animated = true, std::vector<double>* phases_seen = nullptr) {
    args.insert(args.begin(), "pulse");
    std::vector<const char*> argv;
    for (const auto& a : args) argv.push_back(a.c_str());
    return run_lab([&] { return std::unique_ptr<Lab>(std::make_unique<PulseLab>(animated, phases_seen)); }, "tests/shaders", "solution",
                   static_cast<int>(argv.size()), argv.data());
}

// The usage error animate mode gives before any GL work, as run_lab would print it.
std::string usage_error(const std::vector<std::string>& args, bool animated = true) {
    Session s;
    s.lab = std::make_unique<PulseLab>(animated);
    s.info = s.lab->info();
    s.lab->declare(s.params);
    s.defaults = s.params;
    s.lab_dir = "tests/shaders";
    std::vector<const char*> argv{"pulse"};
    for (const auto& a : args) argv.push_back(a.c_str());
    return test::gsv_error_message([&] {
        s.options = parse_cli(static_cast<int>(argv.size()), argv.data());
        s.apply_command_line_settings();
        check_animate_command(s);
    });
}

int red(const Image& image) { return image.at(0, 0)[0]; }
int green(const Image& image) { return image.at(0, 0)[1]; }

}  // namespace

TEST_CASE("animate: steps the animated parameter from min to max into a PNG per frame and the APNG", "[lab]") {
    test::TempDir dir;
    const fs::path out = dir.path("anim");
    REQUIRE(run_pulse({"animate", "--case", "green", "--size", "16x8", "--count", "4", "--out-dir", out.string()}) ==
            kExitOk);
    CHECK_FALSE(fs::exists(out / "frame_0004.png"));
    const ApngInfo info = read_apng_info(out / "animation.png");
    REQUIRE(info.frames.size() == 4);
    CHECK(info.width == 16);
    CHECK(info.height == 8);
    CHECK(info.frames[0].delay.num == 1);
    CHECK(info.frames[0].delay.den == 20);
    const int expected_red[] = {0, 64, 128, 191};  // phase 0, 0.25, 0.5, 0.75: the end (1) is the next loop's 0
    for (std::size_t k = 0; k < 4; ++k) {
        INFO("frame " << k);
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04zu.png", k);
        const Image frame = read_png(out / name);
        CHECK(red(frame) == expected_red[k]);
        CHECK(green(frame) == 255);  // the case's tint held in every frame
        CHECK(same_pixels(decode_frame(info, k, dir), frame));
    }
}

TEST_CASE("animate: --from and --to and --fps with the lab told of every step through params_changed", "[lab]") {
    test::TempDir dir;
    const fs::path out = dir.path("anim");
    std::vector<double> phases;
    REQUIRE(run_pulse({"animate", "--size", "4x4", "--count", "2", "--from", "0.5", "--to", "1", "--fps", "12.5",
                       "--set", "tint=0.5", "--out-dir", out.string()},
                      true, &phases) == kExitOk);
    CHECK(phases == std::vector<double>{0.5, 0.75});
    const ApngInfo info = read_apng_info(out / "animation.png");
    REQUIRE(info.frames.size() == 2);
    CHECK(info.frames[1].delay.num == 10);
    CHECK(info.frames[1].delay.den == 125);
    CHECK(red(read_png(out / "frame_0001.png")) == 191);
    CHECK(green(read_png(out / "frame_0000.png")) == 128);
}

TEST_CASE("animate: NaN in any frame gives status 4 and every frame is still written", "[lab]") {
    test::TempDir dir;
    const fs::path out = dir.path("anim");
    CHECK(run_pulse({"animate", "--set", "poison=on", "--size", "4x4", "--count", "4", "--out-dir", out.string()}) ==
          kExitNonFinite);
    CHECK(fs::exists(out / "frame_0003.png"));
    CHECK(fs::exists(out / "animation.png"));
    const Image poisoned = read_png(out / "frame_0002.png");  // phase 0.5: NaN, painted magenta
    CHECK(red(poisoned) == 255);
    CHECK(poisoned.at(0, 0)[2] == 255);
}

TEST_CASE("animate: bad command lines and a lab without an animated parameter give one line and status 2", "[lab]") {
    struct Bad {
        std::vector<std::string> args;
        std::string says;
        bool animated = true;
    };
    const std::vector<Bad> bad = {
        {{"animate", "--from", "2"}, "option --from = 2 is out of range [0, 1] of parameter 'phase'"},
        {{"animate", "--to", "-0.5"}, "option --to = -0.5 is out of range [0, 1] of parameter 'phase'"},
        {{"animate", "--from", "0.5", "--to", "0.5"}, "options --from and --to are both 0.5: nothing to animate"},
        {{"animate", "--from", "abc"}, "option --from needs a number, got 'abc'"},
        {{"animate", "--count", "0"}, "option --count = 0 is out of range [1, 9999]"},
        {{"animate", "--fps", "0"}, "option --fps = 0 is out of range [0.1, 1000]"},
        {{"animate", "--fps", "fast"}, "option --fps needs a number, got 'fast'"},
        {{"animate", "--bogus"}, "unknown option '--bogus'"},
        {{"animate"}, "pulse has no animated parameter to step", false},
        {{"animat"}, "expected window, render, sweep, animate, compare or list"},
    };
    test::TempDir dir;
    for (const auto& b : bad) {
        INFO(b.says);
        const std::string message = usage_error(b.args, b.animated);
        CHECK(contains(message, b.says));
        CHECK(message.find('\n') == std::string::npos);
        std::vector<std::string> args = b.args;
        args.push_back("--out-dir");
        args.push_back(dir.path("anim").string());
        CHECK(run_pulse(args, b.animated) == kExitUsage);
    }
    CHECK_FALSE(fs::exists(dir.path("anim")));  // refused before anything was rendered or written
}
