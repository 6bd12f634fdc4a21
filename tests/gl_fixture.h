#pragma once
// Helpers for tests that need a GL context: one headless context per test, programs from tests/shaders.
#include "common/context/context.h"
#include "common/shader/shader_program.h"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace gsv::test {

inline std::filesystem::path source_root() { return GSV_SOURCE_ROOT; }
inline std::filesystem::path test_shader(const std::string& name) { return source_root() / "tests" / "shaders" / name; }

inline std::unique_ptr<Context> headless_context(Profile profile = Profile::Core, GlVersion version = {4, 1},
                                                 Backend backend = Backend::Egl) {
    ContextOptions options;
    options.backend = backend;
    options.profile = profile;
    options.version = version;
    return create_context(options);
}

inline ShaderProgram test_program(const Context& context, Profile profile, const std::vector<std::string>& files,
                                  std::vector<ShaderDefine> defines = {}) {
    PreprocessOptions options;
    options.profile = profile;
    options.version = context.effective_version();
    options.include_dirs = {source_root() / "shaders"};
    ProgramSpec spec;
    spec.name = "test";
    for (const auto& f : files) spec.files.push_back(test_shader(f));
    spec.defines = std::move(defines);
    return ShaderProgram::build(spec, options);
}

// A fresh, empty temporary directory for one test.
inline std::filesystem::path temp_dir(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("gsv-test-" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace gsv::test
