// The pace of work an interactive frame spreads over frames (common/timing/work_pacer.h): lab 05's catch-up steps,
// tested against made-up devices whose frames take fixed + per_unit * work, with a clock the test drives (no GL, no
// waiting).
#include "common/timing/work_pacer.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

using gsv::WorkPacer;

namespace {

struct Device {
    double fixed_s;   // a frame with no work: drawing
    double per_unit;  // seconds per unit of work
};

struct CatchUp {
    std::vector<long> steps;  // each frame's
    double total_s = 0, longest_s = 0;
};

CatchUp catch_up(WorkPacer& pacer, long total, double cost, long most, Device device, double& now) {
    CatchUp c;
    long done = 0;
    while (done < total) {
        const long steps = pacer.steps(total - done, cost, most, now);
        c.steps.push_back(steps);
        done += steps;
        pacer.done(done < total);
        const double frame = device.fixed_s + static_cast<double>(steps) * cost * device.per_unit;
        now += frame;
        c.total_s += frame;
        c.longest_s = std::max(c.longest_s, frame);
    }
    return c;
}

}  // namespace

TEST_CASE("work pacer: a frame takes the work that fills its target, within 1 and the most", "[unit]") {
    double now = 0;
    SECTION("a fast device: the most a frame") {
        WorkPacer pacer(32 * 65536.0, 0.25);
        const CatchUp c = catch_up(pacer, 200, 65536.0, 32, {0.001, 1e-10}, now);
        for (long t : c.steps) CHECK((t == 32 || t == 200 % 32));
    }
    SECTION("drawing takes little: frames settle at the target") {
        WorkPacer pacer(32 * 65536.0, 0.25);
        // 100,000 particles, 10 ms to draw, 10 million particle steps a second: 24 steps fill 0.25 s.
        const CatchUp c = catch_up(pacer, 600, 100000.0, 1000, {0.01, 1e-7}, now);
        REQUIRE(c.steps.size() > 10);
        for (std::size_t i = 6; i + 1 < c.steps.size(); ++i) CHECK((c.steps[i] >= 22 && c.steps[i] <= 25));
        CHECK(c.longest_s < 0.27);
    }
}

TEST_CASE("work pacer: where drawing alone is slow, a frame works as long as it draws, and no frame freezes the page",
          "[unit]") {
    // A million particles on llvmpipe in a browser, as measured: 0.7 s to draw them, 0.156 s a step. Fixed 32 steps
    // a frame took 5.7 s a frame; one step a frame would take 40 frames of 0.86 s (34 s) for 40 steps.
    double now = 0;
    WorkPacer pacer(32 * 65536.0, 0.25);
    const CatchUp c = catch_up(pacer, 40, 1048576.0, 32, {0.7, 0.156 / 1048576.0}, now);
    CHECK(c.longest_s < 1.6);                          // was 5.7 s a frame
    CHECK(c.total_s < 2.2 * (40 * 0.156 + 0.7));       // at most about twice the steps' own time and one drawing
    // Settled: a frame of twice a one-step frame's 0.856 s, so (1.71 - 0.7) / 0.156 = 6.5 steps a frame at most.
    for (std::size_t i = 5; i + 1 < c.steps.size(); ++i) CHECK((c.steps[i] >= 4 && c.steps[i] <= 6));
    // A long catch-up (time moved far ahead) keeps that pace.
    const CatchUp longer = catch_up(pacer, 2000, 1048576.0, 32, {0.7, 0.156 / 1048576.0}, now);
    for (std::size_t i = 0; i + 1 < longer.steps.size(); ++i) CHECK((longer.steps[i] >= 4 && longer.steps[i] <= 6));
    CHECK(longer.longest_s < 1.75);
}

TEST_CASE("work pacer: a first frame slowed by something else (a restart) does not leave it at one step a frame",
          "[unit]") {
    WorkPacer pacer(32 * 65536.0, 0.25);
    double now = 0;
    // The first frame's 2 steps also upload a million particles (3 s); then frames of 0.7 s drawing, 0.156 s a step.
    long done = pacer.steps(40, 1048576.0, 32, now);
    pacer.done(true);
    now += 3.0 + 0.7 + 0.156 * static_cast<double>(done);
    std::vector<long> steps;
    while (done < 40) {
        const long s = pacer.steps(40 - done, 1048576.0, 32, now);
        steps.push_back(s);
        done += s;
        pacer.done(done < 40);
        now += 0.7 + 0.156 * static_cast<double>(s);
    }
    REQUIRE(steps.size() > 5);
    for (std::size_t i = 5; i + 1 < steps.size(); ++i) CHECK((steps[i] >= 4 && steps[i] <= 6));
}

TEST_CASE("work pacer: the time between a finished frame and the next change is idle, not work", "[unit]") {
    WorkPacer pacer(32 * 65536.0, 0.25);
    double now = 0;
    catch_up(pacer, 64, 65536.0, 32, {0.001, 1e-9}, now);  // fast: 32 a frame
    const double before = pacer.budget();
    now += 30.0;  // half a minute with nothing changed, then a change
    CHECK(pacer.steps(64, 65536.0, 32, now) == 32);
    CHECK(pacer.budget() == before);
    // A gap after a frame with work left is learnt from: a frame that took 10 s cuts the budget.
    pacer.done(true);
    now += 10.0;
    pacer.steps(32, 65536.0, 32, now);
    CHECK(pacer.budget() < 0.5 * before);
}
