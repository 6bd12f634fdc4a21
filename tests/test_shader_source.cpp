#include "catch.hpp"
#include "gl_fixture.h"
#include "test_support.h"

#include "common/core/error.h"
#include "common/shader/compile_log.h"
#include "common/shader/reference_compiler.h"
#include "common/shader/shader_source.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using gsv::GlVersion;
using gsv::PreprocessOptions;
using gsv::Profile;
using gsv::ShaderStage;

namespace {

using gsv::test::TempDir;


PreprocessOptions bare_options(GlVersion version = {4, 1}, Profile profile = Profile::Core) {
    PreprocessOptions options;
    options.version = version;
    options.profile = profile;
    options.with_prelude = false;
    return options;
}

std::string error_of(const fs::path& main_file, const PreprocessOptions& options) {
    return gsv::test::gsv_error_message([&] { gsv::preprocess_shader(main_file, options); });
}

using gsv::test::count_of;

fs::path kit_shaders_dir() {
#ifdef GSV_SOURCE_ROOT
    return fs::path(GSV_SOURCE_ROOT) / "shaders";
#else
    return fs::absolute(fs::path(__FILE__)).parent_path().parent_path() / "shaders";
#endif
}

bool glslang_available() {
    const char* path_env = std::getenv("PATH");
    if (!path_env) return false;
#ifdef _WIN32
    const char separator = ';';
    const char* exe = "glslangValidator.exe";
#else
    const char separator = ':';
    const char* exe = "glslangValidator";
#endif
    std::stringstream dirs(path_env);
    std::string dir;
    while (std::getline(dirs, dir, separator)) {
        std::error_code ec;
        if (!dir.empty() && fs::is_regular_file(fs::path(dir) / exe, ec)) return true;
    }
    return false;
}

struct ToolRun {
    int status;
    std::string output;
};

ToolRun run_glslang(const fs::path& shader, const std::string& stage, const TempDir& scratch) {
    const fs::path log = scratch.path("glslang.log");
    const std::string command =
        "glslangValidator -S " + stage + " \"" + shader.string() + "\" > \"" + log.string() + "\" 2>&1";
    const int status = std::system(command.c_str());
    std::ifstream in(log, std::ios::binary);
    return {status, std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>())};
}

}  // namespace

TEST_CASE("shader_source: version line and built-in defines follow profile, version and stage", "[unit]") {
    TempDir dir;
    const fs::path main = dir.write("main.frag", "void main() {}\n");

    struct Case {
        GlVersion version;
        Profile profile;
        std::string version_line;
        std::string profile_define;
        std::string glsl_define;
    };
    const Case cases[] = {
        {{4, 1}, Profile::Core, "#version 410 core\n", "#define GSV_PROFILE_CORE 1\n", "#define GSV_GLSL_VERSION 410\n"},
        {{4, 1}, Profile::Compat, "#version 410 compatibility\n", "#define GSV_PROFILE_COMPAT 1\n",
         "#define GSV_GLSL_VERSION 410\n"},
        {{4, 5}, Profile::Core, "#version 450 core\n", "#define GSV_PROFILE_CORE 1\n", "#define GSV_GLSL_VERSION 450\n"},
        {{4, 5}, Profile::Compat, "#version 450 compatibility\n", "#define GSV_PROFILE_COMPAT 1\n",
         "#define GSV_GLSL_VERSION 450\n"},
        {{3, 2}, Profile::Core, "#version 150 core\n", "#define GSV_PROFILE_CORE 1\n", "#define GSV_GLSL_VERSION 150\n"},
        // Before GLSL 1.50 there is no profile word to write.
        {{3, 1}, Profile::Compat, "#version 140\n", "#define GSV_PROFILE_COMPAT 1\n", "#define GSV_GLSL_VERSION 140\n"},
        {{3, 0}, Profile::Core, "#version 130\n", "#define GSV_PROFILE_CORE 1\n", "#define GSV_GLSL_VERSION 130\n"},
        // GLSL ES follows its API's number and says "es"; its #line numbers the next line N, as GLSL 3.30 does.
        {{3, 0}, Profile::Es, "#version 300 es\n", "#define GSV_PROFILE_ES 1\n", "#define GSV_GLSL_VERSION 300\n"},
        {{3, 1}, Profile::Es, "#version 310 es\n", "#define GSV_PROFILE_ES 1\n", "#define GSV_GLSL_VERSION 310\n"},
        {{3, 2}, Profile::Es, "#version 320 es\n", "#define GSV_PROFILE_ES 1\n", "#define GSV_GLSL_VERSION 320\n"},
    };
    for (const Case& c : cases) {
        INFO("GL " << c.version.str() << " " << gsv::profile_name(c.profile));
        const auto source = gsv::preprocess_shader(main, bare_options(c.version, c.profile));
        // Before GLSL 3.30, "#line N" numbers the line after it N + 1.
        const std::string header_lines =
            c.profile == Profile::Es || c.version.glsl() >= 330 ? "#line 100003 0\n" : "#line 100002 0\n";
        CHECK(source.text.rfind(c.version_line + header_lines + c.profile_define + "#define GSV_STAGE_FRAGMENT 1\n" + c.glsl_define, 0) ==
              0);
    }

    const std::pair<ShaderStage, std::string> stages[] = {
        {ShaderStage::Vertex, "GSV_STAGE_VERTEX"},         {ShaderStage::Fragment, "GSV_STAGE_FRAGMENT"},
        {ShaderStage::Geometry, "GSV_STAGE_GEOMETRY"},     {ShaderStage::Compute, "GSV_STAGE_COMPUTE"},
        {ShaderStage::TessControl, "GSV_STAGE_TESS_CONTROL"}, {ShaderStage::TessEval, "GSV_STAGE_TESS_EVAL"},
    };
    for (const auto& [stage, macro] : stages) {
        PreprocessOptions options = bare_options();
        options.stage = stage;
        const auto source = gsv::preprocess_shader(main, options);
        CHECK(source.text.find("\n#define " + macro + " 1\n") != std::string::npos);
        CHECK(count_of(source.text, "#define GSV_STAGE_") == 1);
    }
}

TEST_CASE("shader_source: user defines come in order after the built-ins and before the prelude", "[unit]") {
    TempDir dir;
    dir.write("inc/gsv/prelude_core.glsl", "// prelude body\n");
    const fs::path main = dir.write("main.frag", "void main() {}\n");
    PreprocessOptions options;
    options.include_dirs = {dir.path("inc")};
    options.defines = {{"LIGHTS", "4"}, {"USE_FOG", ""}, {"TINT", "vec3(1.0, 0.5, 0.25)"}};
    const auto source = gsv::preprocess_shader(main, options);

    const std::string expected_start = "#version 410 core\n"
                                       "#line 100003 0\n"
                                       "#define GSV_PROFILE_CORE 1\n"
                                       "#define GSV_STAGE_FRAGMENT 1\n"
                                       "#define GSV_GLSL_VERSION 410\n"
                                       "#define LIGHTS 4\n"
                                       "#define USE_FOG\n"
                                       "#define TINT vec3(1.0, 0.5, 0.25)\n"
                                       "#line 1 2\n"
                                       "// prelude body\n"
                                       "#line 1 1\n"
                                       "void main() {}\n";
    CHECK(source.text == expected_start);
    REQUIRE(source.files.size() == 3);
    CHECK(source.files[0] == gsv::kGeneratedHeaderName);
    CHECK(source.files[1] == main.lexically_normal().string());
    CHECK(source.files[2] == dir.path("inc/gsv/prelude_core.glsl").string());
    CHECK(source.main_file_index == 1);
    CHECK(source.file_line_text(0, 6) == "#define LIGHTS 4");
}

TEST_CASE("shader_source: define names that GLSL reserves or cannot parse are rejected by name", "[unit]") {
    TempDir dir;
    const fs::path main = dir.write("main.frag", "void main() {}\n");
    const std::pair<std::string, std::string> bad[] = {
        {"GL_FOO", "reserved by GLSL"}, {"gl_Foo", "reserved by GLSL"},  {"MY__NAME", "\"__\""},
        {"1ST", "not a GLSL identifier"}, {"HAS SPACE", "not a GLSL identifier"}, {"", "not a GLSL identifier"},
        {"DASH-ED", "not a GLSL identifier"},
    };
    for (const auto& [name, reason] : bad) {
        PreprocessOptions options = bare_options();
        options.defines = {{"GOOD", "1"}, {name, "1"}};
        const std::string message = error_of(main, options);
        INFO(message);
        CHECK(message.find("'" + name + "'") != std::string::npos);
        CHECK(message.find(reason) != std::string::npos);
        CHECK(message.find('\n') == std::string::npos);
    }
    PreprocessOptions multiline = bare_options();
    multiline.defines = {{"TWO_LINES", "1\n2"}};
    CHECK(error_of(main, multiline) == "shader define 'TWO_LINES': the value must fit on one line");

    PreprocessOptions fine = bare_options();
    fine.defines = {{"_private", "1"}, {"Gl_Mixed", "2"}, {"gsv_x1", "3"}};
    CHECK_NOTHROW(gsv::preprocess_shader(main, fine));
}

TEST_CASE("shader_source: include from the file's own folder and nested includes", "[unit]") {
    TempDir dir;
    dir.write("lab/lib/noise.glsl", "float noise(vec3 p) { return 0.5; }\n");
    dir.write("lab/shading.glsl", "#include \"lib/noise.glsl\"\nvec3 shade() { return vec3(noise(vec3(0))); }\n");
    const fs::path main = dir.write("lab/main.frag", "#include \"shading.glsl\"\nout vec4 color;\n"
                                                     "void main() { color = vec4(shade(), 1.0); }\n");
    const auto source = gsv::preprocess_shader(main, bare_options());
    CHECK(source.text.find("float noise(vec3 p) { return 0.5; }\n") != std::string::npos);
    CHECK(source.text.find("vec3 shade()") > source.text.find("float noise"));
    CHECK(source.text.find("out vec4 color;") > source.text.find("vec3 shade()"));
    CHECK(source.text.find("#include") == std::string::npos);

    REQUIRE(source.files.size() == 4);
    CHECK(source.files[2] == dir.path("lab/shading.glsl").string());
    CHECK(source.files[3] == dir.path("lab/lib/noise.glsl").string());
    const std::vector<fs::path> expected_dependencies = {main.lexically_normal(), dir.path("lab/shading.glsl"),
                                                         dir.path("lab/lib/noise.glsl")};
    CHECK(source.dependencies == expected_dependencies);
}

TEST_CASE("shader_source: include_dirs are searched in order after the including file's folder", "[unit]") {
    TempDir dir;
    dir.write("first/common.glsl", "// from first\n");
    dir.write("second/common.glsl", "// from second\n");
    dir.write("second/only_second.glsl", "// only in second\n");
    const fs::path main = dir.write("lab/main.frag", "#include \"common.glsl\"\n#include   \"only_second.glsl\"  // ok\n");
    PreprocessOptions options = bare_options();
    options.include_dirs = {dir.path("first"), dir.path("second")};
    auto source = gsv::preprocess_shader(main, options);
    CHECK(source.text.find("// from first") != std::string::npos);
    CHECK(source.text.find("// from second") == std::string::npos);
    CHECK(source.text.find("// only in second") != std::string::npos);

    dir.write("lab/common.glsl", "// next to the lab\n");
    source = gsv::preprocess_shader(main, options);
    CHECK(source.text.find("// next to the lab") != std::string::npos);
    CHECK(source.text.find("// from first") == std::string::npos);
}

TEST_CASE("shader_source: a missing include names the includer, the line and every folder searched", "[unit]") {
    TempDir dir;
    const fs::path main = dir.write("lab/main.frag", "// one\n// two\n#include \"x.glsl\"\n");
    PreprocessOptions options = bare_options();
    options.include_dirs = {dir.path("inc1"), dir.path("inc2")};
    CHECK(error_of(main, options) == dir.path("lab/main.frag").string() + ":3: cannot find include \"x.glsl\" (searched: " +
                                         dir.path("lab").string() + ", " + dir.path("inc1").string() + ", " +
                                         dir.path("inc2").string() + ")");

    // Relative paths stay relative in the message, the way the student typed them.
    const fs::path cwd = fs::current_path();
    fs::current_path(dir.path());
    const std::string relative = error_of("lab/main.frag", bare_options());
    fs::current_path(cwd);
    CHECK(relative == "lab/main.frag:3: cannot find include \"x.glsl\" (searched: lab)");
}

TEST_CASE("shader_source: malformed and angle-bracket includes are errors", "[unit]") {
    TempDir dir;
    CHECK(error_of(dir.write("a.frag", "#include <x.glsl>\n"), bare_options()) ==
          dir.path("a.frag").string() + ":1: write #include \"x.glsl\"; the kit only resolves the quoted form");
    CHECK(error_of(dir.write("b.frag", "\n#include x.glsl\n"), bare_options()) ==
          dir.path("b.frag").string() + ":2: malformed #include; write #include \"file.glsl\"");
    CHECK(error_of(dir.write("c.frag", "#include \"x.glsl\" junk\n"), bare_options()).find(":1: malformed #include") !=
          std::string::npos);
}

TEST_CASE("shader_source: an include cycle is reported with the whole chain", "[unit]") {
    TempDir dir;
    dir.write("a.glsl", "#include \"b.glsl\"\n");
    dir.write("b.glsl", "// b\n#include \"a.glsl\"\n");
    const fs::path main = dir.write("main.frag", "#include \"a.glsl\"\n");
    const std::string a = dir.path("a.glsl").string(), b = dir.path("b.glsl").string();
    const std::string message = error_of(main, bare_options());
    CHECK(message == b + ":2: include cycle: " + dir.path("main.frag").string() + " -> " + a + " -> " + b + " -> " + a);

    const fs::path self = dir.write("self.frag", "#include \"self.frag\"\n");
    CHECK(error_of(self, bare_options()).find("include cycle: " + dir.path("self.frag").string() + " -> " +
                                              dir.path("self.frag").string()) != std::string::npos);
}

TEST_CASE("shader_source: #pragma once includes a file once, and without it a repeated include is inserted again", "[unit]") {
    TempDir dir;
    dir.write("once.glsl", "#pragma once\nconst float ONCE_MARKER = 1.0;\n");
    dir.write("twice.glsl", "const float TWICE_MARKER = 1.0;\n");
    dir.write("uses_once.glsl", "#include \"once.glsl\"\n");
    const fs::path main = dir.write("main.frag", "#include \"once.glsl\"\n#include \"uses_once.glsl\"\n"
                                                 "#include \"once.glsl\"\n#include \"twice.glsl\"\n"
                                                 "#include \"twice.glsl\"\nvoid main() {}\n");
    const auto source = gsv::preprocess_shader(main, bare_options());
    CHECK(count_of(source.text, "ONCE_MARKER") == 1);
    CHECK(count_of(source.text, "TWICE_MARKER") == 2);
    CHECK(source.text.find("#pragma") == std::string::npos);
    // One file, one source-string number, however often it is inserted.
    CHECK(source.files.size() == 5);
    CHECK(source.dependencies.size() == 4);
    const std::string tail = "#line 6 1\nvoid main() {}\n";
    CHECK(source.text.compare(source.text.size() - tail.size(), tail.size(), tail) == 0);
}

TEST_CASE("shader_source: #line directives map every line back to its file", "[unit]") {
    TempDir dir;
    dir.write("lib.glsl", "float lib() { return 1.0; }\n");
    const fs::path main = dir.write("main.frag", "// main line 1\n#include \"lib.glsl\"\nvoid main() {}");

    SECTION("GLSL 3.30 and later: #line N numbers the next line N") {
        const auto source = gsv::preprocess_shader(main, bare_options({4, 1}));
        CHECK(source.text == "#version 410 core\n"
                             "#line 100003 0\n"
                             "#define GSV_PROFILE_CORE 1\n"
                             "#define GSV_STAGE_FRAGMENT 1\n"
                             "#define GSV_GLSL_VERSION 410\n"
                             "#line 1 1\n"
                             "// main line 1\n"
                             "#line 1 2\n"
                             "float lib() { return 1.0; }\n"
                             "#line 3 1\n"
                             "void main() {}\n");
    }
    SECTION("before GLSL 3.30: #line N numbers the next line N + 1") {
        const auto source = gsv::preprocess_shader(main, bare_options({3, 0}, Profile::Compat));
        CHECK(source.text == "#version 130\n"
                             "#line 100002 0\n"
                             "#define GSV_PROFILE_COMPAT 1\n"
                             "#define GSV_STAGE_FRAGMENT 1\n"
                             "#define GSV_GLSL_VERSION 130\n"
                             // GL 3.0 has neither (common/gl/gl_features.h): the stand-ins' defines.
                             "#define GSV_NO_BUFFER_TEXTURES 1\n"
                             "#define GSV_NO_PRIMITIVE_ID 1\n"
                             "#line 0 1\n"
                             "// main line 1\n"
                             "#line 0 2\n"
                             "float lib() { return 1.0; }\n"
                             "#line 2 1\n"
                             "void main() {}\n");
    }
    const auto source = gsv::preprocess_shader(main, bare_options());
    CHECK(source.file_line_text(1, 3) == "void main() {}");
    CHECK(source.file_line_text(2, 1) == "float lib() { return 1.0; }");
    CHECK(source.file_line_text(1, 4).empty());
    CHECK(source.file_line_text(7, 1).empty());
    CHECK(source.file_line_text(1, 0).empty());
}

TEST_CASE("shader_source: a #version line in a file is an error pointing at it", "[unit]") {
    TempDir dir;
    const fs::path main = dir.write("main.frag", "// header\n  #  version 330 core\nvoid main() {}\n");
    CHECK(error_of(main, bare_options()) ==
          dir.path("main.frag").string() + ":2: remove '#version': the kit writes it from --profile/--gl");
    dir.write("inc.glsl", "#version 410\n");
    const fs::path includer = dir.write("includer.frag", "#include \"inc.glsl\"\n");
    CHECK(error_of(includer, bare_options()).rfind(dir.path("inc.glsl").string() + ":1: remove '#version'", 0) == 0);
}

TEST_CASE("shader_source: directives inside block comments are left alone", "[unit]") {
    TempDir dir;
    const fs::path main = dir.write("main.frag", "/* usage:\n#include \"nowhere.glsl\"\n#version 100\n*/\n"
                                                 "// #include \"nowhere.glsl\"\nvoid main() {}\n");
    const auto source = gsv::preprocess_shader(main, bare_options());
    CHECK(source.text.find("#include \"nowhere.glsl\"\n#version 100\n") != std::string::npos);
}

TEST_CASE("shader_source: a missing main file is reported by path", "[unit]") {
    TempDir dir;
    CHECK(error_of(dir.path("absent.frag"), bare_options()) ==
          "cannot open shader file '" + dir.path("absent.frag").string() + "'");
    CHECK(error_of(dir.path(), bare_options()) == "cannot open shader file '" + dir.path().string() + "'");
}

TEST_CASE("shader_source: the prelude must be found when it is asked for", "[unit]") {
    TempDir dir;
    const fs::path main = dir.write("main.frag", "void main() {}\n");
    PreprocessOptions options;
    options.profile = Profile::Compat;
    options.include_dirs = {dir.path("nothing_here")};
    CHECK(error_of(main, options) == "cannot find the kit prelude \"gsv/prelude_compat.glsl\" (searched: " +
                                         dir.path("nothing_here").string() +
                                         "); add the kit's shaders/ folder to the include dirs");
}

TEST_CASE("shader_source: CRLF files work and keep their bytes", "[unit]") {
    TempDir dir;
    dir.write("lib.glsl", "#pragma once\r\nfloat lib() { return 1.0; }\r\n");
    const fs::path main = dir.write("main.frag", "// crlf\r\n#include \"lib.glsl\"\r\nvoid main() {}\r\n");
    const auto source = gsv::preprocess_shader(main, bare_options());
    CHECK(source.text.find("#line 1 1\n// crlf\r\n#line 1 2\n\nfloat lib() { return 1.0; }\r\n#line 3 1\n"
                           "void main() {}\r\n") != std::string::npos);
    CHECK(source.file_line_text(1, 1) == "// crlf");
    CHECK(source.file_line_text(2, 2) == "float lib() { return 1.0; }");

    const fs::path versioned = dir.write("versioned.frag", "#version 410\r\n");
    CHECK(error_of(versioned, bare_options()).find(":1: remove '#version'") != std::string::npos);
}

TEST_CASE("shader_source: translate_compile_log understands Mesa, NVIDIA and glslang logs", "[unit]") {
    TempDir dir;
    dir.write("labs/lab01/lighting.glsl", "vec3 light() {\n    vec3 c = undefined_thing;\n    return c;\n}\n");
    const fs::path main = dir.write("labs/lab01/gooch.frag", "#include \"lighting.glsl\"\nvoid main() {}\n");
    const auto source = gsv::preprocess_shader(main, bare_options());
    const std::string lib = dir.path("labs/lab01/lighting.glsl").string();
    const std::string gooch = dir.path("labs/lab01/gooch.frag").string();
    REQUIRE(source.files[2] == lib);

    SECTION("Mesa") {
        CHECK(gsv::translate_compile_log("2:2(14): error: `undefined_thing' undeclared\n", source) ==
              lib + ":2: error: `undefined_thing' undeclared\n    vec3 c = undefined_thing;\n");
    }
    SECTION("NVIDIA") {
        CHECK(gsv::translate_compile_log("2(2) : error C1008: undefined variable \"undefined_thing\"", source) ==
              lib + ":2: error C1008: undefined variable \"undefined_thing\"\n    vec3 c = undefined_thing;");
    }
    SECTION("glslang, AMD and Apple ERROR") {
        CHECK(gsv::translate_compile_log("ERROR: 2:2: 'undefined_thing' : undeclared identifier", source) ==
              lib + ":2: error: 'undefined_thing' : undeclared identifier\n    vec3 c = undefined_thing;");
    }
    SECTION("glslang, AMD and Apple WARNING") {
        CHECK(gsv::translate_compile_log("WARNING: 1:2: 'main' : something odd", source) ==
              gooch + ":2: warning: 'main' : something odd\n    void main() {}");
    }
    SECTION("several lines, and lines it cannot place pass through") {
        const std::string log = "ERROR: 2:3: 'return' : bad\r\n"
                                "ERROR: 9:1: unknown source string\r\n"
                                "ERROR: 2 compilation errors.  No code generated.\r\n"
                                "0:100007(1): error: past the end of the header";
        CHECK(gsv::translate_compile_log(log, source) == lib + ":3: error: 'return' : bad\n    return c;\n"
                                                               "ERROR: 9:1: unknown source string\n"
                                                               "ERROR: 2 compilation errors.  No code generated.\n" +
                                                               gsv::kGeneratedHeaderName +
                                                               ":7: error: past the end of the header");
    }
    SECTION("Mesa's string 0 for a line it lost the file of: placed by glslangValidator, else the main file's, said so") {
        const std::string log = "0:2(1): error: value of type vec4 cannot be assigned to variable of type vec2";
        if (gsv::reference_compiler_log("void main() {}", gsv::ShaderStage::Fragment))
            CHECK(gsv::translate_compile_log(log, source) ==
                  lib + ":2: error: value of type vec4 cannot be assigned to variable of type vec2 (placed by glslangValidator: "
                        "the driver named no file)\n    vec3 c = undefined_thing;");
        else
            CHECK(gsv::translate_compile_log(log, source) ==
                  gooch + ":2: error: value of type vec4 cannot be assigned to variable of type vec2 (the driver named no file: "
                          "the main file's line)\n    void main() {}");
        CHECK(gsv::translate_compile_log("0:100004(3): error: bad define", source) ==
              std::string(gsv::kGeneratedHeaderName) + ":4: error: bad define\n    #define GSV_STAGE_FRAGMENT 1");
    }
    SECTION("the generated header is quoted too") {
        CHECK(gsv::translate_compile_log("0:1(10): error: GLSL 4.10 is not supported", source) ==
              std::string(gsv::kGeneratedHeaderName) + ":1: error: GLSL 4.10 is not supported\n    #version 410 core");
    }
    CHECK(gsv::translate_compile_log("", source).empty());
}

TEST_CASE("shader_source: stage names and extensions", "[unit]") {
    CHECK(std::string(gsv::stage_name(ShaderStage::Vertex)) == "vertex");
    CHECK(std::string(gsv::stage_name(ShaderStage::Fragment)) == "fragment");
    CHECK(std::string(gsv::stage_name(ShaderStage::Geometry)) == "geometry");
    CHECK(std::string(gsv::stage_name(ShaderStage::Compute)) == "compute");
    CHECK(std::string(gsv::stage_name(ShaderStage::TessControl)) == "tess_control");
    CHECK(std::string(gsv::stage_name(ShaderStage::TessEval)) == "tess_eval");

    CHECK(gsv::stage_from_extension("labs/lab01/gooch.vert") == ShaderStage::Vertex);
    CHECK(gsv::stage_from_extension("gooch.frag") == ShaderStage::Fragment);
    CHECK(gsv::stage_from_extension("a.geom") == ShaderStage::Geometry);
    CHECK(gsv::stage_from_extension("a.comp") == ShaderStage::Compute);
    CHECK(gsv::stage_from_extension("a.tesc") == ShaderStage::TessControl);
    CHECK(gsv::stage_from_extension("a.tese") == ShaderStage::TessEval);
    CHECK_THROWS_AS(gsv::stage_from_extension("shading.glsl"), gsv::Error);
    CHECK_THROWS_WITH(gsv::stage_from_extension("noext"),
                      "noext: cannot tell the shader stage from '' (use .vert, .frag, .geom, .comp, .tesc or .tese)");
}

TEST_CASE("shader_source: glslangValidator reports an error in an include at the file and line we map to", "[unit]") {
    if (!glslang_available()) {
        WARN("glslangValidator is not on PATH; skipping the compiler round-trip");
        SUCCEED();
        return;
    }
    TempDir dir;
    dir.write("lib/helpers.glsl", "// helpers\nfloat helper() {\n    return undefined_x;\n}\n");
    const fs::path main = dir.write("main.frag", "// main\n#include \"lib/helpers.glsl\"\nout vec4 color;\n"
                                                 "void main() {\n    color = vec4(helper());\n}\n");
    // 3.0 exercises the pre-3.30 #line rule, 4.1 and 4.5 the current one.
    for (const GlVersion version : {GlVersion{3, 0}, GlVersion{4, 1}, GlVersion{4, 5}}) {
        INFO("GL " << version.str());
        const auto source = gsv::preprocess_shader(main, bare_options(version));
        const fs::path generated = dir.write("generated.frag", source.text);
        const ToolRun run = run_glslang(generated, "frag", dir);
        INFO(run.output);
        CHECK(run.status != 0);
        const std::string translated = gsv::translate_compile_log(run.output, source);
        INFO(translated);
        CHECK(translated.find(dir.path("lib/helpers.glsl").string() + ":3: error: 'undefined_x' : undeclared identifier\n"
                                                                      "    return undefined_x;") != std::string::npos);
    }

    // An error after the include returns must land on the main file's own numbering.
    const fs::path after = dir.write("after.frag", "#include \"lib/ok.glsl\"\n\nvoid main() {\n    float y = missing_y;\n}\n");
    dir.write("lib/ok.glsl", "float ok() { return 1.0; }\n// two\n// three\n");
    const auto source = gsv::preprocess_shader(after, bare_options());
    const ToolRun run = run_glslang(dir.write("generated_after.frag", source.text), "frag", dir);
    const std::string translated = gsv::translate_compile_log(run.output, source);
    INFO(translated);
    CHECK(translated.find(dir.path("after.frag").string() + ":4: error: 'missing_y' : undeclared identifier\n"
                                                            "    float y = missing_y;") != std::string::npos);
}

TEST_CASE("shader_source: one vertex/fragment pair builds against both preludes with glslangValidator", "[unit]") {
    if (!glslang_available()) {
        WARN("glslangValidator is not on PATH; skipping the prelude compile check");
        SUCCEED();
        return;
    }
    TempDir dir;
    const fs::path vert = dir.write("pair.vert", "out vec3 vNormal;\n"
                                                 "out vec2 vTexCoord;\n"
                                                 "out vec3 vEyePosition;\n"
                                                 "void main() {\n"
                                                 "    vNormal = normalize(uNormalMatrix * aNormal);\n"
                                                 "    vTexCoord = aTexCoord0.st;\n"
                                                 "    vEyePosition = (uModelViewMatrix * aVertex).xyz;\n"
                                                 "    gl_Position = uModelViewProjectionMatrix * aVertex;\n"
                                                 "}\n");
    const fs::path frag = dir.write("pair.frag", "in vec3 vNormal;\n"
                                                 "in vec2 vTexCoord;\n"
                                                 "in vec3 vEyePosition;\n"
                                                 "out vec4 fragColor;\n"
                                                 "void main() {\n"
                                                 "    vec4 clip = uProjectionMatrix * vec4(vEyePosition, 1.0);\n"
                                                 "    float shade = max(dot(normalize(vNormal), vec3(0.0, 0.0, 1.0)), 0.0);\n"
                                                 "    fragColor = vec4(vec3(shade), 1.0) + 0.0 * clip + vec4(vTexCoord, 0.0, 0.0);\n"
                                                 "}\n");
    for (const Profile profile : {Profile::Core, Profile::Compat}) {
        for (const fs::path& file : {vert, frag}) {
            PreprocessOptions options;
            options.profile = profile;
            options.version = {4, 1};
            options.stage = gsv::stage_from_extension(file);
            options.include_dirs = {kit_shaders_dir()};
            const auto source = gsv::preprocess_shader(file, options);
            const std::string stage = file.extension().string().substr(1);
            const ToolRun run = run_glslang(dir.write("built." + stage, source.text), stage, dir);
            INFO(gsv::profile_name(profile) << " " << stage << "\n" << source.text << "\n" << run.output);
            CHECK(run.status == 0);
            CHECK(run.output.find("ERROR") == std::string::npos);
            // The file, its prelude, and what the prelude includes, off unless asked: the margin table's texel-snap
            // stand-in and the instrumented build that counts texture fetches.
            CHECK(source.dependencies.size() == 4);
        }
    }
}

// The kit's own ES prelude, as a lab shader gets it: precision for every type GLSL ES leaves without a default in
// some stage, the shared names as uniforms and attributes, and the defines that name what ES 3.0 and 3.1 lack.
TEST_CASE("shader_source: on OpenGL ES the kit's prelude brings the precision statements and names what 3.0 lacks", "[unit]") {
    TempDir dir;
    const fs::path main = dir.write("main.frag", "out vec4 fColor;\nvoid main() { fColor = vec4(1.0); }\n");
    const auto with_kit_prelude = [&](GlVersion version, ShaderStage stage) {
        PreprocessOptions options = bare_options(version, Profile::Es);
        options.stage = stage;
        options.with_prelude = true;
        options.include_dirs = {gsv::test::source_root() / "shaders"};
        return gsv::preprocess_shader(main, options);
    };
    const auto es30 = with_kit_prelude({3, 0}, ShaderStage::Fragment);
    INFO(es30.text);
    CHECK(es30.text.rfind("#version 300 es\n", 0) == 0);
    CHECK(std::find(es30.files.begin(), es30.files.end(), (gsv::test::source_root() / "shaders/gsv/prelude_es.glsl").lexically_normal().string()) !=
          es30.files.end());
    for (const char* statement : {"precision highp float;", "precision highp int;", "precision highp sampler3D;",
                                  "precision highp sampler2DArray;"})
        CHECK(es30.text.find(statement) != std::string::npos);
    CHECK(es30.text.find("uniform mat4 uModelViewProjectionMatrix;") != std::string::npos);
    // The stand-ins a version needs are defined in the header, from the feature table; ES 3.2 and desktop need none.
    CHECK(es30.text.find("#define GSV_NO_BUFFER_TEXTURES 1") != std::string::npos);
    CHECK(es30.text.find("#define GSV_NO_PRIMITIVE_ID 1") != std::string::npos);
    const auto es32 = with_kit_prelude({3, 2}, ShaderStage::Fragment);
    CHECK(es32.text.rfind("#version 320 es\n", 0) == 0);
    CHECK(es32.text.find("#define GSV_NO_") == std::string::npos);
    CHECK(es32.text.find("precision highp samplerBuffer;") != std::string::npos);
    CHECK(gsv::preprocess_shader(main, bare_options({4, 1}, Profile::Core)).text.find("#define GSV_NO_") == std::string::npos);
    // Attributes only where they can be: the vertex stage.
    CHECK(es30.text.find("in vec4 aVertex;") < es30.text.find("#endif", es30.text.find("in vec4 aVertex;")));
    // A shader that writes #version itself is refused in every profile, ES included.
    const fs::path versioned = dir.write("versioned.frag", "#version 300 es\nvoid main() {}\n");
    CHECK_THROWS_WITH(gsv::preprocess_shader(versioned, bare_options({3, 0}, Profile::Es)),
                      Catch::Matchers::Contains("remove '#version'"));
}
