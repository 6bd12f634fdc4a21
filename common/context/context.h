#pragma once
// One interface over the ways the kit gets an OpenGL context: a GLFW window (students, lectures), EGL surfaceless
// (the headless default: CI and grading), OSMesa (a fallback, compiled in where found) and, in the browser edition,
// WebGL 2 on the page's canvas.
#include "common/gl/gl_version.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

struct GLFWwindow;

namespace gsv {

enum class Backend { Window, Egl, OSMesa, Web };

struct ContextOptions {
    Backend backend = Backend::Egl;
    Profile profile = Profile::Core;
    GlVersion version{4, 1};
    // The highest version the kit holds itself to where the driver gives more than `version`; none: `version`. A lab
    // that takes 4.3's features where offered asks for 4.1 (macOS's) and holds to at most 4.3.
    std::optional<GlVersion> up_to{};
    int width = 800, height = 600;  // window size; headless runs render into framebuffers of their own size
    std::string title = "gsv";
    bool visible = true;
    bool vsync = false;
    // EGL: leave the display initialized when the context goes, so that a process making context after context
    // (render --serve: a fresh one per case) starts the driver once. The process's end releases it.
    bool keep_display = false;
};

struct ContextInfo {
    Backend backend = Backend::Egl;
    Profile profile = Profile::Core;
    GlVersion requested;
    GlVersion held_to{};  // ContextOptions::up_to, or the version requested
    GlVersion obtained;  // what the driver reports; drivers may give more than was asked for
    std::string renderer, vendor, version_string, glsl_version_string;
};

class Context {
public:
    virtual ~Context() = default;
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    const ContextInfo& info() const { return info_; }
    // The version the kit holds itself to: the lower of what was asked for (or up_to) and what the driver gave,
    // so `--gl 4.1` on a 4.5 driver still compiles `#version 410` shaders, as a Mac would.
    GlVersion effective_version() const;
    // Stops the run with one line when the context cannot do what a lab needs.
    void require(GlVersion needed, const std::string& what_for) const;
    std::string describe() const;  // "llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6, core profile, egl backend"

    virtual GLFWwindow* window() { return nullptr; }
    virtual void swap_buffers() {}

protected:
    Context() = default;
    // Loads GL entry points through the backend's getter and fills info_; throws on failure.
    void load_gl(void* (*get_proc)(const char*), const ContextOptions& options);

    ContextInfo info_;
};

std::unique_ptr<Context> create_context(const ContextOptions& options);

std::vector<Backend> compiled_backends();
bool is_compiled(Backend backend);
const char* backend_name(Backend backend);
Backend parse_backend(const std::string& text);   // "window" | "egl" | "osmesa" | "web"; throws naming the value
Profile parse_profile(const std::string& text);   // "core" | "compat" | "es"
// "4.1", "4.5": 3.3..4.6 for the desktop profiles; "3.0".."3.2" for ES. Throws naming the value and the range.
GlVersion parse_gl_version(const std::string& text, Profile profile = Profile::Core);

}  // namespace gsv
