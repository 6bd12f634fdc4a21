#include "common/shader/shader_library.h"

#include "common/core/error.h"

#include <system_error>

namespace gsv {
namespace {

std::filesystem::file_time_type stamp_of(const std::filesystem::path& p) {
    std::error_code ec;
    auto t = std::filesystem::last_write_time(p, ec);
    return ec ? std::filesystem::file_time_type::min() : t;
}

}  // namespace

void ShaderLibrary::build(Entry& entry, const PreprocessOptions& base, const std::vector<ShaderDefine>& defines) {
    PreprocessOptions options = base;
    options.defines.insert(options.defines.end(), defines.begin(), defines.end());
    ShaderProgram program;
    try {
        program = ShaderProgram::build(entry.spec_, options);
    } catch (const Error& e) {
        entry.error_ = e.what();
        throw;
    }
    entry.error_.clear();
    entry.stamps_.clear();
    for (const auto& dependency : program.dependencies()) entry.stamps_.emplace_back(dependency, stamp_of(dependency));
    entry.program_ = std::move(program);
}

ShaderLibrary::Entry& ShaderLibrary::add(ProgramSpec spec, const std::vector<ShaderDefine>& defines) {
    Entry entry;
    entry.spec_ = std::move(spec);
    build(entry, base_, defines);
    entries_.push_back(std::move(entry));
    return entries_.back();
}

std::optional<std::string> ShaderLibrary::rebuild_all(const std::vector<ShaderDefine>& defines) {
    std::optional<std::string> first_error;
    for (auto& entry : entries_) {
        try {
            build(entry, base_, defines);
        } catch (const Error& e) {
            if (!first_error) first_error = e.what();
        }
    }
    return first_error;
}

std::optional<std::string> ShaderLibrary::set_generated(const Entry& target, std::vector<GeneratedFile> generated,
                                                       const std::vector<ShaderDefine>& defines) {
    for (auto& entry : entries_) {
        if (&entry != &target) continue;
        entry.spec_.generated = std::move(generated);
        try {
            build(entry, base_, defines);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::nullopt;
    }
    throw Error("program '" + target.spec().name + "' does not belong to this shader library");
}

std::optional<std::string> ShaderLibrary::reload_changed(const std::vector<ShaderDefine>& defines) {
    std::optional<std::string> first_error;
    for (auto& entry : entries_) {
        bool changed = false;
        for (auto& [path, stamp] : entry.stamps_)
            if (stamp_of(path) != stamp) changed = true;
        if (!changed) continue;
        try {
            build(entry, base_, defines);
        } catch (const Error& e) {
            // Remember the new stamps so a broken file is reported once, not every frame.
            for (auto& [path, stamp] : entry.stamps_) stamp = stamp_of(path);
            if (!first_error) first_error = e.what();
        }
    }
    return first_error;
}

}  // namespace gsv
