// Generated include files: text the C++ side writes (lab 06's rc_config.glsl) found by #include like a
// file, named "<generated NAME>" in messages and #line maps, and carried through programs and hot reload.
#include "catch.hpp"
#include "gl_fixture.h"
#include "test_support.h"

#include "common/core/error.h"
#include "common/gl/framebuffer.h"
#include "common/gl/gpu_mesh.h"
#include "common/scene/mesh_data.h"
#include "common/shader/shader_library.h"
#include "common/shader/compile_log.h"
#include "common/shader/shader_source.h"

#include <chrono>
#include <string>

namespace fs = std::filesystem;
using gsv::GeneratedFile;
using gsv::PreprocessOptions;
using gsv::test::TempDir;

namespace {

PreprocessOptions bare_options(std::vector<GeneratedFile> generated = {}) {
    PreprocessOptions options;
    options.with_prelude = false;
    options.generated = std::move(generated);
    return options;
}

std::string error_of(const fs::path& main_file, const PreprocessOptions& options) {
    return gsv::test::gsv_error_message([&] { gsv::preprocess_shader(main_file, options); });
}

using gsv::test::count_of;

}  // namespace

TEST_CASE("shader_source: a generated file is found by name before any folder and named as generated", "[unit]") {
    TempDir dir;
    dir.write("lab/rc_config.glsl", "// the file on disk\n");
    const fs::path main = dir.write("lab/main.frag", "// main\n#include \"rc_config.glsl\"\nvoid main() {}\n");
    const auto source =
        gsv::preprocess_shader(main, bare_options({{"rc_config.glsl", "// generated\nfloat g() { return 1.0; }\n"}}));
    CHECK(source.text == "#version 410 core\n"
                         "#line 100003 0\n"
                         "#define GSV_PROFILE_CORE 1\n"
                         "#define GSV_STAGE_FRAGMENT 1\n"
                         "#define GSV_GLSL_VERSION 410\n"
                         "#line 1 1\n"
                         "// main\n"
                         "#line 1 2\n"
                         "// generated\n"
                         "float g() { return 1.0; }\n"
                         "#line 3 1\n"
                         "void main() {}\n");
    REQUIRE(source.files.size() == 3);
    CHECK(source.files[2] == "<generated rc_config.glsl>");
    CHECK(source.files[2] == gsv::generated_file_label("rc_config.glsl"));
    CHECK(source.file_line_text(2, 2) == "float g() { return 1.0; }");
    // No timestamp to watch: only the main file is a dependency.
    CHECK(source.dependencies == std::vector<fs::path>{main.lexically_normal()});

    // Without it the file on disk is found again: nothing else changed.
    const auto plain = gsv::preprocess_shader(main, bare_options());
    CHECK(plain.text.find("// the file on disk") != std::string::npos);
    // A generated file nobody includes is not in the source at all.
    const auto unused = gsv::preprocess_shader(dir.write("lab/none.frag", "void main() {}\n"),
                                               bare_options({{"rc_config.glsl", "// generated\n"}}));
    CHECK(unused.files.size() == 2);
    CHECK(unused.text.find("// generated") == std::string::npos);
}

TEST_CASE("shader_source: a generated file's includes search the include dirs, never the working directory", "[unit]") {
    TempDir dir;
    dir.write("inc/raycast/module.glsl", "#pragma once\nfloat module_marker() { return 2.0; }\n");
    dir.write("cwd/beside.glsl", "// in the working directory\n");
    const fs::path main = dir.write("lab/main.frag", "#include \"config.glsl\"\nvoid main() {}\n");
    PreprocessOptions options = bare_options({{"config.glsl", "#include \"raycast/module.glsl\"\n"
                                                              "#include \"raycast/module.glsl\"\n"}});
    options.include_dirs = {dir.path("inc")};
    const auto source = gsv::preprocess_shader(main, options);
    CHECK(count_of(source.text, "float module_marker()") == 1);  // #pragma once holds across a generated file
    REQUIRE(source.files.size() == 4);
    CHECK(source.files[3] == dir.path("inc/raycast/module.glsl").string());
    const std::vector<fs::path> expected = {main.lexically_normal(), dir.path("inc/raycast/module.glsl")};
    CHECK(source.dependencies == expected);

    // A generated file has no folder: "." (the working directory) is not searched for it.
    const fs::path cwd = fs::current_path();
    fs::current_path(dir.path("cwd"));
    const std::string message = error_of(main, bare_options({{"config.glsl", "// one\n#include \"beside.glsl\"\n"}}));
    fs::current_path(cwd);
    CHECK(message == "<generated config.glsl>:2: cannot find include \"beside.glsl\" (searched: <generated config.glsl>)");
}

TEST_CASE("shader_source: a missing include lists the generated files before the folders searched", "[unit]") {
    TempDir dir;
    const fs::path main = dir.write("lab/main.frag", "#include \"rc_confg.glsl\"\n");
    PreprocessOptions options = bare_options({{"rc_config.glsl", ""}, {"extra.glsl", ""}});
    options.include_dirs = {dir.path("inc")};
    CHECK(error_of(main, options) == dir.path("lab/main.frag").string() +
                                         ":1: cannot find include \"rc_confg.glsl\" (searched: <generated rc_config.glsl>, "
                                         "<generated extra.glsl>, " +
                                         dir.path("lab").string() + ", " + dir.path("inc").string() + ")");
}

TEST_CASE("shader_source: generated names #include cannot name, and a name given twice, are one-line errors", "[unit]") {
    TempDir dir;
    const fs::path main = dir.write("main.frag", "void main() {}\n");
    for (const std::string& bad : {std::string(), std::string("a\"b.glsl"), std::string("two\nlines.glsl")}) {
        const std::string message = error_of(main, bare_options({{bad, "// x\n"}}));
        INFO(message);
        CHECK(message.rfind("generated shader file '" + bad + "': the name must be", 0) == 0);
    }
    CHECK(error_of(main, bare_options({{"a.glsl", "1"}, {"a.glsl", "2"}})) == "generated shader file 'a.glsl': given twice");
}

TEST_CASE("shader_source: errors in and through a generated file name it and its line", "[unit]") {
    TempDir dir;
    const fs::path main = dir.write("main.frag", "#include \"rc_config.glsl\"\nvoid main() {}\n");
    // The kit's own checks.
    CHECK(error_of(main, bare_options({{"rc_config.glsl", "\n#version 410\n"}})) ==
          "<generated rc_config.glsl>:2: remove '#version': the kit writes it from --profile/--gl");
    CHECK(error_of(main, bare_options({{"rc_config.glsl", "#include \"rc_config.glsl\"\n"}})) ==
          "<generated rc_config.glsl>:1: include cycle: " + dir.path("main.frag").string() +
              " -> <generated rc_config.glsl> -> <generated rc_config.glsl>");
    // A driver's log.
    const auto source = gsv::preprocess_shader(
        main, bare_options({{"rc_config.glsl", "// generated for: dvr\n#define RC_SHADE(c) broken(c)\nvec3 x = RC_SHADE(1);\n"}}));
    REQUIRE(source.files[2] == "<generated rc_config.glsl>");
    CHECK(gsv::translate_compile_log("2:3(10): error: no function with name 'broken'\n", source) ==
          "<generated rc_config.glsl>:3: error: no function with name 'broken'\n    vec3 x = RC_SHADE(1);\n");
}

TEST_CASE("shader_library: generated files travel with the program and set_generated rebuilds with new text", "[gl]") {
    auto context = gsv::test::headless_context();
    TempDir dir;
    dir.write("g.vert", "void main() { gl_Position = vec4(aVertex.xy, 0.0, 1.0); }\n");
    const fs::path frag = dir.write("g.frag", "#include \"color.glsl\"\nout vec4 fColor;\nvoid main() { fColor = kColor; }\n");
    PreprocessOptions options;
    options.version = context->effective_version();
    options.include_dirs = {gsv::test::source_root() / "shaders"};
    gsv::ShaderLibrary library(options);
    gsv::ProgramSpec spec{"g", {dir.path("g.vert"), frag}, {}};
    spec.generated = {{"color.glsl", "const vec4 kColor = vec4(0.25);\n"}};
    const auto& entry = library.add(spec, {});
    CHECK(entry.program().compiled_sources()[1].find("const vec4 kColor = vec4(0.25);") != std::string::npos);

    gsv::GpuMesh quad(gsv::make_fullscreen_quad(), gsv::Profile::Core);
    gsv::Framebuffer target(1, 1, gsv::ColorFormat::RGBA32F, false);
    auto drawn = [&] {
        target.bind();
        entry.program().use();
        quad.draw();
        return target.read_rgba32f().at(0, 0)[0];
    };
    CHECK(drawn() == 0.25f);

    CHECK_FALSE(library.set_generated(entry, {{"color.glsl", "const vec4 kColor = vec4(0.75);\n"}}, {}).has_value());
    CHECK(drawn() == 0.75f);
    CHECK_FALSE(library.reload_changed({}).has_value());  // a generated file has no timestamp to go stale

    // A broken text: the error names it and its line, and the last good program keeps drawing.
    const auto error = library.set_generated(entry, {{"color.glsl", "// v2\nconst vec4 kColor = vec4(0.5) +;\n"}}, {});
    REQUIRE(error.has_value());
    INFO(*error);
    CHECK(error->find("<generated color.glsl>:2") != std::string::npos);
    CHECK(error->find("const vec4 kColor = vec4(0.5) +;") != std::string::npos);
    CHECK(drawn() == 0.75f);

    // Hot reload of a real file builds with the text last asked for, here still broken, then fixed.
    const auto before = fs::last_write_time(frag);
    dir.write("g.frag", "#include \"color.glsl\"\nout vec4 fColor;\nvoid main() { fColor = 2.0 * kColor; }\n");
    fs::last_write_time(frag, before + std::chrono::seconds(2));
    const auto reload_error = library.reload_changed({});
    REQUIRE(reload_error.has_value());
    CHECK(reload_error->find("<generated color.glsl>:2") != std::string::npos);
    CHECK_FALSE(library.set_generated(entry, {{"color.glsl", "const vec4 kColor = vec4(0.125);\n"}}, {}).has_value());
    CHECK(drawn() == 0.25f);

    gsv::ShaderLibrary other(options);
    CHECK_THROWS_WITH(other.set_generated(entry, {}, {}), "program 'g' does not belong to this shader library");
}
