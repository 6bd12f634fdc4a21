#pragma once
// Turns a lab's shader file into the one string handed to glShaderSource: the kit writes the #version
// line and its defines, splices in the profile prelude and every #include, and keeps a #line map so a
// driver's error log can be pointed back at the file and line the student actually wrote (compile_log.h).
#include <filesystem>
#include <string>
#include <vector>

#include "common/gl/gl_version.h"

namespace gsv {

struct ShaderDefine {
    std::string name;
    std::string value;
    friend bool operator==(const ShaderDefine& a, const ShaderDefine& b) { return a.name == b.name && a.value == b.value; }
    friend bool operator!=(const ShaderDefine& a, const ShaderDefine& b) { return !(a == b); }
};

// A file that exists only in memory: GLSL glue the C++ side writes for one configuration (lab 06's
// rc_config.glsl), so the compiled shader holds only what that configuration uses.
struct GeneratedFile {
    std::string name;  // exactly as #include names it: "rc_config.glsl"
    std::string text;
};

struct PreprocessOptions {
    Profile profile = Profile::Core;
    GlVersion version{4, 1};
    ShaderStage stage = ShaderStage::Fragment;
    std::vector<std::filesystem::path> include_dirs;  // searched in order AFTER the including file's own directory
    std::vector<ShaderDefine> defines;                // injected in order, after the built-in defines, before the prelude
    bool with_prelude = true;
    // Found by exact name BEFORE any folder. A generated file has no folder of its own, so its #includes
    // search the generated files and then include_dirs; and no timestamp, so it is not a dependency:
    // whoever changes its text rebuilds the program (ShaderLibrary::set_generated).
    std::vector<GeneratedFile> generated;
};

// Name of files[0]: the #version line and defines the kit writes are source string 0, so a driver
// complaint about them (an unsupported #version, a clashing define) is not blamed on the lab's file.
inline constexpr const char* kGeneratedHeaderName = "<generated header>";
// The header's lines after the #version line are numbered from this plus their line in the header (a
// #line directive says so). Mesa reports some errors (an assignment of the wrong type, for one) with source
// string 0 whatever #line said: a string-0 line below this, other than 1, is then not the header's, and
// translate_compile_log places it in the main file, saying the driver named no file.
inline constexpr int kGeneratedHeaderLineOffset = 100000;
// What messages, #line maps and translated logs call a generated file: "<generated rc_config.glsl>".
std::string generated_file_label(const std::string& name);

struct ShaderSource {
    std::string text;                                 // ready for glShaderSource
    std::vector<std::string> files;                   // index = GLSL source-string number used in #line
    std::vector<std::filesystem::path> dependencies;  // every file read (main, prelude, includes), for hot reload;
                                                      // generated files are not read, so not listed
    int main_file_index = 0;
    // lines[i] holds files[i]'s lines without their line endings; kept so logs can quote the source.
    std::vector<std::vector<std::string>> lines;

    std::string file_line_text(int source_string, int line) const;  // the original text of that line, "" if unknown
};

// Source string 0 is the generated header, 1 the main file, then the prelude and includes in the order
// they are first read. A file included twice keeps one source-string number.
// Limitation: #include is resolved before the GLSL preprocessor runs, so an #include inside a disabled
// #if branch must still name a file that exists.
ShaderSource preprocess_shader(const std::filesystem::path& main_file, const PreprocessOptions& options);

const char* stage_name(ShaderStage stage);                           // "vertex", "fragment", "tess_control", ...
ShaderStage stage_from_extension(const std::filesystem::path& file);  // .vert .frag .geom .comp .tesc .tese

}  // namespace gsv
