// The framework's change tracking (common/params/change_tracker.h): what a build read is what decides a rebuild.
#include "catch.hpp"
#include "common/shader/param_uniforms.h"

#include "common/params/change_tracker.h"
#include "common/params/params.h"
#include "common/shader/shader_program.h"
#include "gl_fixture.h"

#include <stdexcept>

using namespace gsv;

namespace {

Params three_params() {
    Params p;
    p.add_choice("field", "rotation", {"rotation", "file"}, "the flow");
    p.add_file("field_file", "a.flow", "read when field=file");
    p.add_int("length", 10, 0, 100, "not read by the build");
    return p;
}

}  // namespace

TEST_CASE("change tracking: a build reruns when a parameter it read changes, not when another does", "[unit][app]") {
    Params p = three_params();
    Tracked<std::string> flow;
    int builds = 0;
    const auto make = [&] {
        ++builds;
        return p.get_choice("field") == "file" ? "file " + p.get_file("field_file") : std::string("rotation");
    };
    CHECK(flow.update(p, make));
    CHECK(*flow == "rotation");
    CHECK_FALSE(flow.update(p, make));
    p.set("length", "50");  // never read
    CHECK_FALSE(flow.update(p, make));
    // Not read while field=rotation: the file cannot change what was built.
    p.set("field_file", "b.flow");
    CHECK_FALSE(flow.update(p, make));
    p.set("field", "file");
    CHECK(flow.update(p, make));
    CHECK(*flow == "file b.flow");
    // Now it was read, so it counts.
    p.set("field_file", "c.flow");
    CHECK(flow.update(p, make));
    CHECK(*flow == "file c.flow");
    // Set back to the value the build saw: nothing to do.
    p.set("length", "10");
    CHECK_FALSE(flow.update(p, make));
    CHECK(builds == 3);
    CHECK(flow.version() == 3);
}

TEST_CASE("change tracking: keys, invalidation, a failed build and a nested tracker", "[unit][app]") {
    Params p = three_params();
    ChangeTracker outer, inner;
    int outer_builds = 0, inner_builds = 0;
    const auto build = [&](int width) {
        return outer.run_if_changed(p, [&] {
            ++outer_builds;
            inner.run_if_changed(p, [&] {
                ++inner_builds;
                (void)p.get_file("field_file");
            });
        }, width);
    };
    CHECK(build(64));
    CHECK_FALSE(build(64));
    CHECK(build(128));  // a key changed
    CHECK(inner_builds == 1);
    // What the inner tracker read counts for the outer one too, even when the inner had nothing to redo.
    p.set("field_file", "z.flow");
    CHECK(build(128));
    CHECK(inner_builds == 2);
    outer.invalidate();
    CHECK(build(128));
    CHECK(outer_builds == 4);

    // A build that throws leaves nothing built: the next call tries again.
    ChangeTracker failing;
    bool fail = true;
    const auto attempt = [&] {
        return failing.run_if_changed(p, [&] {
            (void)p.get_int("length");
            if (fail) throw std::runtime_error("broken file");
        });
    };
    CHECK_THROWS(attempt());
    fail = false;
    CHECK(attempt());
    CHECK_FALSE(attempt());
    // A copy of the parameters starts with no read log of its own, and assigning values keeps the log.
    Params copy = p;
    ChangeTracker on_copy;
    CHECK(on_copy.run_if_changed(copy, [&] { copy = p; (void)copy.get_int("length"); }));
    CHECK(on_copy.read_indices().size() == 1);
}

TEST_CASE("change tracking: a program in use counts its active uniforms and every compile-time parameter", "[gl]") {
    auto context = test::headless_context();
    Params p;
    p.add_float("shade", 0.5, 0, 1, "used by the shader");
    p.add_float("ignored", 0.5, 0, 1, "declared in the shader, dropped as unused");
    p.add_float("camera_yaw", 0, -360, 360, "no uniform of that name in the shader");
    p.add_effect("glow", false, "compiled in");
    const ShaderProgram program = test::test_program(*context, Profile::Core, {"quad.vert", "tracked.frag"}, param_defines(p));
    ChangeTracker drawn;
    int draws = 0;
    const auto draw = [&] {
        return drawn.run_if_changed(p, [&] {
            ++draws;
            program.use();
            apply_param_uniforms(p, program);
        });
    };
    CHECK(draw());
    CHECK_FALSE(draw());
    p.set("camera_yaw", "90");
    CHECK_FALSE(draw());
    p.set("ignored", "0.25");
    CHECK_FALSE(draw());
    p.set("shade", "0.25");
    CHECK(draw());
    p.set("glow", "on");
    CHECK(draw());
    CHECK(draws == 3);
}
