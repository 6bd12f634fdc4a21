#include "common/shader/shader_source.h"

#include "common/core/enum_names.h"
#include "common/core/error.h"
#include "common/core/not_done.h"
#include "common/core/trimmed.h"
#include "common/gl/gl_features.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <set>

namespace gsv {
namespace fs = std::filesystem;

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
bool is_identifier_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

bool is_blank_or_comment(const std::string& rest) {
    const std::string t = trimmed(rest);
    return t.empty() || t.rfind("//", 0) == 0 || t.rfind("/*", 0) == 0;
}

std::string stage_macro(ShaderStage stage) {
    switch (stage) {
    case ShaderStage::Vertex: return "GSV_STAGE_VERTEX";
    case ShaderStage::TessControl: return "GSV_STAGE_TESS_CONTROL";
    case ShaderStage::TessEval: return "GSV_STAGE_TESS_EVAL";
    case ShaderStage::Geometry: return "GSV_STAGE_GEOMETRY";
    case ShaderStage::Fragment: return "GSV_STAGE_FRAGMENT";
    case ShaderStage::Compute: return "GSV_STAGE_COMPUTE";
    }
    return "GSV_STAGE_UNKNOWN";
}

void check_define(const ShaderDefine& define) {
    const std::string& name = define.name;
    const std::string prefix = "shader define '" + name + "': ";
    if (name.empty() || !is_identifier_start(name[0]) ||
        !std::all_of(name.begin(), name.end(), is_identifier_char))
        throw Error(prefix + "not a GLSL identifier");
    if (name.rfind("GL_", 0) == 0 || name.rfind("gl_", 0) == 0)
        throw Error(prefix + "names starting with GL_ or gl_ are reserved by GLSL");
    if (name.find("__") != std::string::npos) throw Error(prefix + "names containing \"__\" are reserved by GLSL");
    if (define.value.find_first_of("\r\n") != std::string::npos)
        throw Error(prefix + "the value must fit on one line");
}

// Splits on '\n' so a CRLF file keeps its '\r' in `raw` (emitted unchanged) while `clean` drops it
// for directive matching and for quoting lines back in logs.
struct SplitText {
    std::vector<std::string> raw;
    std::vector<std::string> clean;
};

SplitText split_lines(std::string text) {
    // A UTF-8 byte-order mark would land in the middle of the concatenated source and break the compile.
    if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
    SplitText split;
    std::size_t begin = 0;
    while (begin < text.size()) {
        std::size_t end = text.find('\n', begin);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(begin, end - begin);
        std::string clean = line;
        if (!clean.empty() && clean.back() == '\r') clean.pop_back();
        split.raw.push_back(std::move(line));
        split.clean.push_back(std::move(clean));
        begin = end + 1;
    }
    return split;
}

std::optional<std::string> read_file(const fs::path& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) return std::nullopt;
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// "#  include rest" -> {"include", "rest"}; nullopt for lines that are not preprocessor directives.
struct Directive {
    std::string name;
    std::string rest;
};

std::optional<Directive> parse_directive(const std::string& line) {
    std::size_t i = 0;
    while (i < line.size() && is_space(line[i])) ++i;
    if (i == line.size() || line[i] != '#') return std::nullopt;
    ++i;
    while (i < line.size() && is_space(line[i])) ++i;
    const std::size_t name_begin = i;
    while (i < line.size() && is_identifier_char(line[i])) ++i;
    return Directive{line.substr(name_begin, i - name_begin), line.substr(i)};
}

// Updates whether a /* comment is still open at the end of `line`, so directives quoted inside
// block comments (commented-out includes, documentation) are left alone.
bool block_comment_open_after(const std::string& line, bool open) {
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        const char next = i + 1 < line.size() ? line[i + 1] : '\0';
        if (open && c == '*' && next == '/') {
            open = false;
            ++i;
        } else if (!open && c == '/' && next == '/') {
            break;
        } else if (!open && c == '/' && next == '*') {
            open = true;
            ++i;
        }
    }
    return open;
}

std::string join_paths(const std::vector<fs::path>& paths) {
    std::string joined;
    for (const auto& p : paths) joined += (joined.empty() ? "" : ", ") + p.string();
    return joined;
}

fs::path display_path(const fs::path& p) {
    fs::path normal = p.lexically_normal();
    return normal.empty() ? fs::path(".") : normal;
}

// Two spellings of one file (./a.glsl, dir/../a.glsl, a symlink) must count as the same file for
// #pragma once and cycle detection.
fs::path identity_of(const fs::path& p) {
    std::error_code ec;
    fs::path canonical = fs::weakly_canonical(p, ec);
    return ec ? fs::absolute(p).lexically_normal() : canonical;
}

class Preprocessor {
public:
    Preprocessor(const PreprocessOptions& options, ShaderSource& out) : options_(options), out_(out) {}

    void run(const fs::path& main_file) {
        check_generated();
        write_header();
        const int main_index = load(main_file);
        if (main_index < 0) throw Error("cannot open shader file '" + main_file.string() + "'");
        out_.main_file_index = main_index;
        if (options_.with_prelude) include_prelude();
        expand(main_index);
    }

private:
    // GLSL 3.30 (and GLSL ES 3.00) changed '#line N' to number the line after it N; earlier versions number it N + 1.
    std::string line_directive(int next_line, int source_string) const {
        const bool next_is_n = options_.profile == Profile::Es || options_.version.glsl() >= 330;
        const int number = next_is_n ? next_line : next_line - 1;
        return "#line " + std::to_string(number) + " " + std::to_string(source_string) + "\n";
    }

    static const char* profile_macro(Profile profile) {
        switch (profile) {
        case Profile::Core: return "GSV_PROFILE_CORE";
        case Profile::Compat: return "GSV_PROFILE_COMPAT";
        case Profile::Es: return "GSV_PROFILE_ES";
        }
        return "GSV_PROFILE_UNKNOWN";
    }

    void write_header() {
        const int glsl = options_.version.glsl(options_.profile);
        std::string header = "#version " + std::to_string(glsl);
        // Profiles arrived with GLSL 1.50; older compilers reject the word.
        if (options_.profile == Profile::Es) header += " es";
        else if (glsl >= 150) header += options_.profile == Profile::Core ? " core" : " compatibility";
        header += "\n";
        // Line 3 of the header on is numbered kGeneratedHeaderLineOffset + 3 on: see the constant.
        header += line_directive(kGeneratedHeaderLineOffset + 3, 0);
        header += std::string("#define ") + profile_macro(options_.profile) + " 1\n";
        header += "#define " + stage_macro(options_.stage) + " 1\n";
        header += "#define GSV_GLSL_VERSION " + std::to_string(glsl) + "\n";
        for (const GlFeature* feature : gl_feature::kAll)
            if (feature->missing_define && !allows(*feature, options_.profile, options_.version))
                header += std::string("#define ") + feature->missing_define + " 1\n";
        for (const auto& define : options_.defines) {
            check_define(define);
            header += "#define " + define.name + (define.value.empty() ? "" : " " + define.value) + "\n";
        }
        out_.text = header;
        out_.files.push_back(kGeneratedHeaderName);
        out_.lines.push_back(split_lines(header).clean);
    }

    // A bad name would only surface later as a baffling "cannot find include"; say what is wrong with it.
    void check_generated() const {
        std::set<std::string> seen;
        for (const auto& file : options_.generated) {
            const std::string prefix = "generated shader file '" + file.name + "': ";
            if (file.name.empty() || file.name.find_first_of("\"\r\n") != std::string::npos)
                throw Error(prefix + "the name must be what #include \"...\" can name (not empty, no quote or line break)");
            if (!seen.insert(file.name).second) throw Error(prefix + "given twice");
        }
    }

    const GeneratedFile* find_generated(const std::string& name) const {
        for (const auto& file : options_.generated)
            if (file.name == name) return &file;
        // Files the kit writes for every shader, after the caller's own.
        static const GeneratedFile kKitFiles[] = {{kNotDoneInclude, not_done_glsl()}};
        for (const auto& file : kKitFiles)
            if (file.name == name) return &file;
        return nullptr;
    }

    // Its identity is its label, never an absolute path, so it cannot collide with a real file.
    int load_generated(const GeneratedFile& file) {
        const fs::path identity = generated_file_label(file.name);
        if (auto it = index_of_.find(identity); it != index_of_.end()) return it->second;
        SplitText split = split_lines(file.text);
        const int index = static_cast<int>(out_.files.size());
        out_.files.push_back(identity.string());
        out_.lines.push_back(std::move(split.clean));
        raw_lines_.emplace(index, std::move(split.raw));
        identities_.emplace(index, identity);
        index_of_.emplace(identity, index);
        generated_.insert(index);
        return index;
    }

    // Returns the file's source-string number, reading it on first sight; -1 when it cannot be read.
    int load(const fs::path& path) {
        const fs::path identity = identity_of(path);
        if (auto it = index_of_.find(identity); it != index_of_.end()) return it->second;
        std::optional<std::string> text = read_file(path);
        if (!text) return -1;
        SplitText split = split_lines(std::move(*text));
        const int index = static_cast<int>(out_.files.size());
        const fs::path shown = display_path(path);
        out_.files.push_back(shown.string());
        out_.lines.push_back(std::move(split.clean));
        out_.dependencies.push_back(shown);
        raw_lines_.emplace(index, std::move(split.raw));
        identities_.emplace(index, identity);
        index_of_.emplace(identity, index);
        return index;
    }

    void include_prelude() {
        const fs::path name = options_.profile == Profile::Core     ? "gsv/prelude_core.glsl"
                              : options_.profile == Profile::Compat ? "gsv/prelude_compat.glsl"
                                                                    : "gsv/prelude_es.glsl";
        for (const auto& dir : options_.include_dirs) {
            if (const int index = load(dir / name); index >= 0) {
                expand(index);
                return;
            }
        }
        throw Error("cannot find the kit prelude \"" + name.generic_string() + "\" (searched: " +
                    join_paths(options_.include_dirs) + "); add the kit's shaders/ folder to the include dirs");
    }

    void expand(int index) {
        stack_.push_back(index);
        out_.text += line_directive(1, index);
        // raw_lines_ is a map, so this reference survives nested loads; out_.lines is a vector that
        // nested includes grow, so its lines are copied instead.
        const std::vector<std::string>& raw = raw_lines_.at(index);
        const std::vector<std::string> clean = out_.lines[static_cast<std::size_t>(index)];
        bool in_block_comment = false;
        for (std::size_t i = 0; i < raw.size(); ++i) {
            const int line_number = static_cast<int>(i) + 1;
            const std::optional<Directive> directive =
                in_block_comment ? std::nullopt : parse_directive(clean[i]);
            in_block_comment = block_comment_open_after(clean[i], in_block_comment);
            if (!directive) {
                out_.text += raw[i] + "\n";
                continue;
            }
            if (directive->name == "version") {
                throw Error(where(index, line_number) +
                            ": remove '#version': the kit writes it from --profile/--gl");
            }
            if (directive->name == "pragma" && trimmed(directive->rest) == "once") {
                once_.insert(identities_.at(index));
                out_.text += "\n";  // keeps the following lines on their own numbers
                continue;
            }
            if (directive->name == "include") {
                include(index, line_number, directive->rest);
                continue;
            }
            out_.text += raw[i] + "\n";
        }
        stack_.pop_back();
    }

    void include(int includer, int line_number, const std::string& rest) {
        const std::string at = where(includer, line_number);
        const std::string argument = trimmed(rest);
        if (!argument.empty() && argument[0] == '<')
            throw Error(at + ": write #include \"" + argument.substr(1, argument.find('>') - 1) +
                        "\"; the kit only resolves the quoted form");
        const std::size_t close = argument.find('"', 1);
        if (argument.empty() || argument[0] != '"' || close == std::string::npos || close == 1 ||
            !is_blank_or_comment(argument.substr(close + 1)))
            throw Error(at + ": malformed #include; write #include \"file.glsl\"");
        const std::string name = argument.substr(1, close - 1);

        const GeneratedFile* generated = find_generated(name);
        fs::path found;
        if (!generated) {
            std::vector<fs::path> searched;
            // A generated includer has no folder; "." would search the working directory, which the kit never does.
            if (!generated_.count(includer))
                searched.push_back(display_path(fs::path(out_.files[static_cast<std::size_t>(includer)]).parent_path()));
            searched.insert(searched.end(), options_.include_dirs.begin(), options_.include_dirs.end());
            for (const auto& dir : searched) {
                std::error_code ec;
                if (fs::is_regular_file(dir / name, ec)) {
                    found = dir / name;
                    break;
                }
            }
            if (found.empty()) {
                std::vector<fs::path> shown;
                for (const auto& file : options_.generated) shown.push_back(generated_file_label(file.name));
                shown.insert(shown.end(), searched.begin(), searched.end());
                throw Error(at + ": cannot find include \"" + name + "\" (searched: " + join_paths(shown) + ")");
            }
        }

        const fs::path identity = generated ? fs::path(generated_file_label(name)) : identity_of(found);
        if (once_.count(identity)) {
            out_.text += "\n";  // stands in for the #include line
            return;
        }
        if (auto it = index_of_.find(identity); it != index_of_.end() &&
            std::find(stack_.begin(), stack_.end(), it->second) != stack_.end()) {
            std::string chain;
            for (int open : stack_) chain += out_.files[static_cast<std::size_t>(open)] + " -> ";
            throw Error(at + ": include cycle: " + chain + out_.files[static_cast<std::size_t>(it->second)]);
        }
        const int child = generated ? load_generated(*generated) : load(found);
        if (child < 0) throw Error(at + ": cannot open include file '" + found.string() + "'");
        expand(child);
        out_.text += line_directive(line_number + 1, includer);
    }

    std::string where(int index, int line_number) const {
        return out_.files[static_cast<std::size_t>(index)] + ":" + std::to_string(line_number);
    }

    const PreprocessOptions& options_;
    ShaderSource& out_;
    std::map<fs::path, int> index_of_;
    std::map<int, fs::path> identities_;
    std::map<int, std::vector<std::string>> raw_lines_;
    std::set<fs::path> once_;
    std::set<int> generated_;  // source-string numbers of generated files
    std::vector<int> stack_;
};

}  // namespace

std::string generated_file_label(const std::string& name) { return "<generated " + name + ">"; }

std::string ShaderSource::file_line_text(int source_string, int line) const {
    if (source_string < 0 || static_cast<std::size_t>(source_string) >= lines.size()) return "";
    const auto& file_lines = lines[static_cast<std::size_t>(source_string)];
    if (line < 1 || static_cast<std::size_t>(line) > file_lines.size()) return "";
    return file_lines[static_cast<std::size_t>(line) - 1];
}

ShaderSource preprocess_shader(const fs::path& main_file, const PreprocessOptions& options) {
    ShaderSource source;
    Preprocessor(options, source).run(main_file);
    return source;
}

namespace {
constexpr EnumName<ShaderStage> kStageNames[] = {
    {ShaderStage::Vertex, "vertex"},     {ShaderStage::TessControl, "tess_control"}, {ShaderStage::TessEval, "tess_eval"},
    {ShaderStage::Geometry, "geometry"}, {ShaderStage::Fragment, "fragment"},        {ShaderStage::Compute, "compute"}};
constexpr EnumName<ShaderStage> kStageExtensions[] = {
    {ShaderStage::Vertex, ".vert"},   {ShaderStage::Fragment, ".frag"},    {ShaderStage::Geometry, ".geom"},
    {ShaderStage::Compute, ".comp"}, {ShaderStage::TessControl, ".tesc"}, {ShaderStage::TessEval, ".tese"}};
}  // namespace

const char* stage_name(ShaderStage stage) { return name_of(kStageNames, stage); }

ShaderStage stage_from_extension(const fs::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    try {
        return parse_enum(kStageExtensions, "shader extension", ext);
    } catch (const Error&) {
        throw Error(file.string() + ": cannot tell the shader stage from '" + file.extension().string() +
                    "' (use .vert, .frag, .geom, .comp, .tesc or .tese)");
    }
}

}  // namespace gsv
