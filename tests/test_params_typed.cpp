// One way to read a parameter (common/params/params.h): a choice declared from an enum's name table reads as the enum,
// its conditions name the enum's values, and a parameter whose uniform another setter has is refused where it is
// declared, or where a program declares that uniform as something its value cannot set. (That a misspelt choice does
// not compile is tests/check_misspelt_choice.cmake's.)
#include "catch.hpp"

#include "common/core/error.h"
#include "common/params/change_tracker.h"
#include "common/params/params.h"
#include "common/shader/param_uniforms.h"
#include "gl_fixture.h"
#include "support/flow/flow_field.h"
#include "support/particles/particle_motion.h"

#include <string>
#include <vector>

using namespace gsv;

namespace {

enum class Own { Swirl, File };
constexpr EnumName<Own> kOwn[] = {{Own::Swirl, "swirl"}, {Own::File, "file"}};
using Field = OneOf<FlowKind, Own>;

std::string refusal(const std::function<void()>& declare) {
    try {
        declare();
    } catch (const Error& e) {
        return e.what();
    }
    return "(not refused)";
}

}  // namespace

TEST_CASE("typed parameters: a choice from an enum's table reads as the enum, in the table's names and order", "[unit][params]") {
    Params p;
    const EnumParam<Integrator> integrator = p.add_enum("integrator", Integrator::Midpoint, kIntegratorNames, "the step");
    CHECK(integrator.get() == Integrator::Midpoint);
    CHECK(p.spec("integrator").choices == std::vector<std::string>{"euler", "midpoint", "rk4"});
    CHECK(p.get_text("integrator") == "midpoint");
    p.set("integrator", "rk4");
    CHECK(*integrator == Integrator::Rk4);
    CHECK(std::string(integrator.name_of(Integrator::Euler)) == "euler");

    SECTION("a read through the handle is noted, as a read by name is") {
        ChangeTracker tracker;
        CHECK(tracker.run_if_changed(p, [&] { (void)integrator.get(); }));
        CHECK_FALSE(tracker.run_if_changed(p, [&] { (void)integrator.get(); }));
        p.set("integrator", "euler");
        CHECK(tracker.run_if_changed(p, [&] { (void)integrator.get(); }));
    }
    SECTION("the refinements chain as a Param's") {
        const EnumParam<FlowKind> flow =
            p.add_enum("flow", FlowKind::Saddle, kFlowKindNames, "the flow").at_compile_time().series().without_uniform();
        CHECK(flow.param().spec().compile_time);
        CHECK(p.series()->name == "flow");
        CHECK(flow.get() == FlowKind::Saddle);
    }
}

TEST_CASE("typed parameters: one of two tables, support's then the lab's own, reads as OneOf", "[unit][params]") {
    Params p;
    const EnumParam<Field> field = p.add_enum("field", Own::Swirl, kFlowKindNames, kOwn, "the flow");
    CHECK(p.spec("field").choices ==
          std::vector<std::string>{"rotation", "saddle", "source", "double_gyre", "vortices", "swirl", "file"});
    CHECK(p.get_text("field") == "swirl");
    CHECK(field.get() == Own::Swirl);
    CHECK(field.get() != Own::File);
    CHECK_FALSE(field.get().as<FlowKind>());
    p.set("field", "double_gyre");
    CHECK(field.get() == FlowKind::DoubleGyre);
    CHECK(field.get() != Own::Swirl);
    CHECK(*field.get().as<FlowKind>() == FlowKind::DoubleGyre);
    CHECK_FALSE(field.get().as<Own>());
}

TEST_CASE("typed parameters: conditions name a declared parameter's values, typed or checked where declared", "[unit][params]") {
    Params p;
    const auto field = p.add_enum("field", FlowKind::Rotation, kFlowKindNames, kOwn, "the flow");
    const Param<bool> glow = p.add_bool("glow", false, "a switch");
    p.add_file("field_file", "a.flow", "the file").applies_when(field, {Own::File});
    p.add_float("time", 0, 0, 10, "time").applies_when(field, {FlowKind::DoubleGyre, Own::File});
    p.add_float("strength", 1, 0, 1, "glow strength").applies_when(glow, true);
    CHECK(p.spec("time").applies_when_all.at(0).values == std::vector<std::string>{"double_gyre", "file"});
    CHECK(p.inactive_reason("field_file") == "needs field=file (it is rotation)");
    CHECK(p.inactive_reason("strength") == "needs glow=on (it is off)");
    p.set("field", "double_gyre");
    CHECK(p.applies("time"));

    // By name, a misspelling no longer greys a parameter for ever: it is refused where it is declared.
    CHECK(refusal([&] { p.add_float("a", 0, 0, 1, "").applies_when("field", {"flie"}); }) ==
          "a condition on parameter 'field' names 'flie', which is not one of its values");
    CHECK(refusal([&] { p.add_float("b", 0, 0, 1, "").applies_when("glow", {"yes"}); }) ==
          "a condition on parameter 'glow' names 'yes', which is not one of its values");
    CHECK(refusal([&] { p.add_float("c", 0, 0, 1, "").applies_when("feild", {"file"}); }) ==
          "a condition names parameter 'feild', which is not declared (yet)");
}

TEST_CASE("typed parameters: a uniform another setter has is refused where the parameter is declared", "[unit][params]") {
    Params p;
    p.reserve_uniform("uNormalMatrix", "the kit's transforms (apply_transforms)");
    p.add_choice("time_wrap", "repeat", {"repeat", "clamp"}, "wraps");

    SECTION("a uniform the kit sets") {
        CHECK(refusal([&] { p.add_vec3("normal_matrix", glm::vec3(0), 0, 1, ""); }) ==
              "parameter 'normal_matrix' would set the uniform uNormalMatrix, which the kit's transforms (apply_transforms) sets");
        CHECK(refusal([&] { p.add_float("tilt", 0, 0, 1, "").with_uniform("uNormalMatrix"); }) ==
              "parameter 'tilt' would set the uniform uNormalMatrix, which the kit's transforms (apply_transforms) sets");
    }
    SECTION("another parameter's uniform, its name spelt otherwise or named outright") {
        CHECK(refusal([&] { p.add_float("time-wrap", 0, 0, 1, ""); }) ==
              "parameter 'time-wrap' would set the uniform uTimeWrap, which parameter 'time_wrap' sets");
        CHECK(refusal([&] { p.add_float("period", 0, 0, 1, "").with_uniform("uTimeWrap"); }) ==
              "parameter 'period' would set the uniform uTimeWrap, which parameter 'time_wrap' sets");
        CHECK(refusal([&] { p.reserve_uniform("uTimeWrap", "a shader component"); }) ==
              "parameter 'time_wrap' would set the uniform uTimeWrap, which a shader component sets");
    }
    SECTION("none where it reaches no uniform: a file, a text, one declared without one") {
        CHECK_NOTHROW(p.add_file("time-wrap", "", "a file"));
        CHECK_NOTHROW(p.reserve_uniform("uTimeWrap2", "x"));
        Params q;
        q.add_choice("input", "noise", {"noise", "photo"}, "").without_uniform();
        CHECK_NOTHROW(q.reserve_uniform("uInput", "the texture's binding"));
        CHECK(q.describe().find("read by the lab") != std::string::npos);
        // Adopted (a processor's declarations made the lab's), it still has none.
        Params lab;
        lab.adopt("source", "VolumeSource 'source'", q);
        CHECK(lab.spec("input").uniform.empty());
    }
}

TEST_CASE("typed parameters: a parameter whose uniform a program declares as a sampler is refused, naming both",
          "[unit][params]") {
    Params p;
    p.add_choice("field", "rotation", {"rotation", "saddle"}, "the flow");
    p.add_float("shade", 0.5, 0, 1, "a float the shader reads");
    const std::vector<UniformDeclaration> uniforms{{"uShade", UniformKind::Float}, {"uField", UniformKind::Sampler}};
    CHECK(refusal([&] { check_param_uniforms(p, uniforms, "lic"); }) ==
          "parameter 'field' would set the uniform uField, which program 'lic' declares as a sampler: rename the parameter, "
          "or declare it without_uniform() if only the lab reads it");
    CHECK(refusal([&] { check_param_uniforms(p, {{"uShade", UniformKind::Vec3}}, "lic"); }) ==
          "parameter 'shade' would set the uniform uShade, which program 'lic' declares as a vec3: rename the parameter, "
          "or declare it without_uniform() if only the lab reads it");
    SECTION("its own uniform, of a type its value sets, is what it is for") {
        CHECK_NOTHROW(check_param_uniforms(p, {{"uShade", UniformKind::Float}, {"uField", UniformKind::Int}}, "lic"));
    }
    SECTION("a compile-time parameter, or one without a uniform, sets none") {
        Params q;
        q.add_choice("field", "rotation", {"rotation", "saddle"}, "").at_compile_time();
        q.add_choice("input", "noise", {"noise", "photo"}, "").without_uniform();
        CHECK_NOTHROW(check_param_uniforms(q, {{"uField", UniformKind::Sampler}, {"uInput", UniformKind::Sampler}}, "lic"));
    }
}

TEST_CASE("typed parameters: a program's sampler of a parameter's uniform is refused when made and when used", "[gl]") {
    auto context = test::headless_context();
    const ShaderProgram program = test::test_program(*context, Profile::Core, {"quad.vert", "samplers.frag"});
    const std::vector<UniformDeclaration> kinds = program.active_uniform_kinds();
    const auto kind_of = [&](const std::string& name) {
        for (const auto& u : kinds)
            if (u.name == name) return u.kind;
        return UniformKind::Other;
    };
    CHECK(kind_of("uVolume") == UniformKind::Sampler);
    CHECK(kind_of("uLayers") == UniformKind::Sampler);
    Params p;
    p.add_choice("volume", "marschner_lobb", {"marschner_lobb", "file"}, "what goes into the texture");
    CHECK_THROWS_WITH(check_param_uniforms(p, kinds, "samplers"),
                      Catch::Contains("parameter 'volume' would set the uniform uVolume, which program 'samplers' declares as a sampler"));
    program.use();
    CHECK_THROWS_WITH(apply_param_uniforms(p, program), Catch::Contains("which the program in use declares as a sampler"));
    Params fixed;
    fixed.add_choice("volume", "marschner_lobb", {"marschner_lobb", "file"}, "what goes into the texture").without_uniform();
    CHECK_NOTHROW(check_param_uniforms(fixed, kinds, "samplers"));
    CHECK_NOTHROW(apply_param_uniforms(fixed, program));
}
