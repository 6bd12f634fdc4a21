// When a parameter has an effect (common/params/params.h): another parameter's value decides it and is refused where
// it does not hold; a GL feature the context lacks greys it with the reason and refuses nothing.
#include "catch.hpp"

#include "common/core/error.h"
#include "common/params/params.h"

using namespace gsv;

namespace {

Params particle_params() {
    Params p;
    p.add_choice("field", "abc", {"abc", "gravity"}, "the flow");
    p.add_float("gravity", 2, 0, 20, "downward").applies_when("field", {"gravity"});
    p.add_int("local_size", 128, 1, 1024, "invocations per work group").acts_through("compute shaders");
    p.add_int("groups", 4, 1, 8, "both").acts_through("compute shaders").applies_when("field", {"abc"});
    return p;
}

}  // namespace

TEST_CASE("parameter effect: a missing GL feature greys its parameter with the reason and refuses no setting",
          "[unit][params]") {
    Params p = particle_params();
    CHECK(p.inactive_reason("local_size").empty());
    p.note_missing_feature("compute shaders", "compute shaders, which OpenGL ES 3.1 has; this context is OpenGL ES 3.0");
    CHECK(p.inactive_reason("local_size") ==
          "needs compute shaders, which OpenGL ES 3.1 has; this context is OpenGL ES 3.0");
    CHECK_FALSE(p.applies("local_size"));
    // Cases set it alike on every profile: not refused.
    p.set_assignment("local_size=64");
    CHECK_NOTHROW(p.check_applies({"local_size"}, "--set "));
    // Another feature's absence leaves it alone.
    p.note_missing_feature("buffer textures", "buffer textures, which OpenGL ES 3.2 has");
    CHECK(p.inactive_reason("local_size").rfind("needs compute shaders", 0) == 0);

    SECTION("assigning values (a lab's defaults, the last values that drew) keeps what the context lacks") {
        const Params defaults = particle_params();
        p = defaults;
        CHECK(p.get_int("local_size") == 128);
        CHECK_FALSE(p.applies("local_size"));
        Params copy = p;  // a copy is of the same context
        CHECK_FALSE(copy.applies("local_size"));
    }
    SECTION("a value condition still refuses, whatever the context") {
        p.set_assignment("field=gravity");
        CHECK_THROWS_WITH(p.check_applies({"groups"}, "--set "),
                          "--set groups=4 has no effect here: it needs field=abc (it is gravity)");
        CHECK_NOTHROW(p.check_applies({"gravity"}, "--set "));
    }
}

TEST_CASE("parameter effect: another parameter's value decides it, and a setting where it does not hold is refused",
          "[unit][params]") {
    Params p = particle_params();
    CHECK(p.inactive_reason("gravity") == "needs field=gravity (it is abc)");
    CHECK_THROWS_WITH(p.check_applies({"gravity"}, "case 'x': "),
                      "case 'x': gravity=2 has no effect here: it needs field=gravity (it is abc)");
    p.set_assignment("field=gravity");
    CHECK(p.applies("gravity"));
    CHECK_NOTHROW(p.check_applies({"gravity"}, "--set "));
}
