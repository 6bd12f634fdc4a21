#pragma once
// The programs of one lab, kept rebuildable: when a shader file changes (hot reload) or a compile-time
// parameter changes (an effect switched on), every program is rebuilt; a build that fails keeps the
// last good program running and reports the error instead.
#include "common/shader/shader_program.h"

#include <deque>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gsv {

class ShaderLibrary {
public:
    class Entry {
    public:
        const ShaderProgram& program() const { return program_; }
        const ProgramSpec& spec() const { return spec_; }
        // Why the last rebuild failed (hot reload, new defines, new generated files), while the last good
        // program keeps running; empty when the program is up to date. Lets a lab show the error on what
        // owns the program (lab 06: the processor) rather than only in the window's status line.
        const std::string& error() const { return error_; }

    private:
        friend class ShaderLibrary;
        ProgramSpec spec_;
        ShaderProgram program_;
        std::string error_;
        std::vector<std::pair<std::filesystem::path, std::filesystem::file_time_type>> stamps_;
    };

    explicit ShaderLibrary(PreprocessOptions base) : base_(std::move(base)) {}

    // Builds now (throws on error: a lab cannot start with a broken shader). The reference stays valid.
    Entry& add(ProgramSpec spec, const std::vector<ShaderDefine>& defines);
    // Rebuilds every program with new defines; on failure keeps the old ones and returns the error.
    std::optional<std::string> rebuild_all(const std::vector<ShaderDefine>& defines);
    // Rebuilds programs whose files changed on disk; returns the error of a failed rebuild, if any.
    std::optional<std::string> reload_changed(const std::vector<ShaderDefine>& defines);
    // Replaces one program's generated include files (its configuration changed) and rebuilds it. A
    // generated file has no timestamp for reload_changed to see, so this is how its change arrives. On
    // failure the last good program keeps running and the error is returned; the new text is kept, so the
    // next hot reload builds what was asked for. Throws gsv::Error for an entry of another library.
    std::optional<std::string> set_generated(const Entry& entry, std::vector<GeneratedFile> generated,
                                             const std::vector<ShaderDefine>& defines);
    const PreprocessOptions& options() const { return base_; }

private:
    static void build(Entry& entry, const PreprocessOptions& options, const std::vector<ShaderDefine>& defines);
    PreprocessOptions base_;
    std::deque<Entry> entries_;
};

}  // namespace gsv
