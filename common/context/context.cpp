#include "common/context/context.h"

#include "common/core/enum_names.h"
#include "common/core/error.h"
#include "common/gl/gl.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <regex>

namespace gsv {

#if GSV_HAVE_EGL
namespace {
// GSV_TEST_WITHOUT_EGL=1: a Linux build acts as one without EGL (Windows, macOS), so that the tests of the fallback
// (tests/no_egl_xvfb.sh) run where CI runs. The processes a run starts (compare's reference) inherit it.
bool egl_left_out_for_test() {
    const char* value = std::getenv("GSV_TEST_WITHOUT_EGL");
    return value && *value && std::strcmp(value, "0") != 0;
}
}  // namespace
#endif

std::unique_ptr<Context> make_glfw_context(const ContextOptions& options);
#if GSV_HAVE_EGL
std::unique_ptr<Context> make_egl_context(const ContextOptions& options);
#endif
#if GSV_HAVE_OSMESA
std::unique_ptr<Context> make_osmesa_context(const ContextOptions& options);
#endif
#ifdef __EMSCRIPTEN__
std::unique_ptr<Context> make_web_context(const ContextOptions& options);
#endif

std::unique_ptr<Context> create_context(const ContextOptions& options) {
    switch (options.backend) {
#ifdef __EMSCRIPTEN__
    case Backend::Web: return make_web_context(options);
    default: throw UnsupportedError(std::string("the browser edition draws on the page's canvas (backend 'web'), not ") +
                                    backend_name(options.backend));
#else
    case Backend::Window: return make_glfw_context(options);
    case Backend::Egl:
#if GSV_HAVE_EGL
        if (!egl_left_out_for_test()) return make_egl_context(options);
#endif
        throw UnsupportedError("backend 'egl' is not compiled into this build (EGL was not found); use --backend window");
    case Backend::OSMesa:
#if GSV_HAVE_OSMESA
        return make_osmesa_context(options);
#else
        throw UnsupportedError("backend 'osmesa' is not compiled into this build (libOSMesa was not found)");
#endif
    case Backend::Web: throw UnsupportedError("backend 'web' is the browser edition's (scripts/kit web builds its pages)");
#endif
    }
    throw Error("unknown backend");
}

std::vector<Backend> compiled_backends() {
#ifdef __EMSCRIPTEN__
    return {Backend::Web};
#else
    std::vector<Backend> backends{Backend::Window};
#if GSV_HAVE_EGL
    if (!egl_left_out_for_test()) backends.push_back(Backend::Egl);
#endif
#if GSV_HAVE_OSMESA
    backends.push_back(Backend::OSMesa);
#endif
    return backends;
#endif
}

bool is_compiled(Backend backend) {
    for (Backend b : compiled_backends())
        if (b == backend) return true;
    return false;
}

namespace {
// "glfw" is an alias of "window": read, never printed.
constexpr EnumName<Backend> kBackendNames[] = {
    {Backend::Window, "window"}, {Backend::Egl, "egl"}, {Backend::OSMesa, "osmesa"}, {Backend::Web, "web"},
    {Backend::Window, "glfw"}};
constexpr EnumName<Profile> kProfileNames[] = {{Profile::Core, "core"},
                                               {Profile::Compat, "compat"},
                                               {Profile::Es, "es"},
                                               {Profile::Compat, "compatibility"},
                                               {Profile::Es, "gles"}};
}  // namespace

const char* backend_name(Backend backend) { return name_of(kBackendNames, backend); }

Backend parse_backend(const std::string& text) { return parse_enum(kBackendNames, "backend", text); }

Profile parse_profile(const std::string& text) { return parse_enum(kProfileNames, "profile", text); }

GlVersion parse_gl_version(const std::string& text, Profile profile) {
    std::smatch m;
    static const std::regex pattern(R"(^([0-9])\.([0-9])$)");
    if (!std::regex_match(text, m, pattern))
        throw Error("bad GL version '" + text + "' (expected MAJOR.MINOR, e.g. 4.1)");
    GlVersion v{std::stoi(m[1]), std::stoi(m[2])};
    const bool es = profile == Profile::Es;
    const GlVersion lowest = es ? GlVersion{3, 0} : GlVersion{3, 3};
    const GlVersion highest = es ? GlVersion{3, 2} : GlVersion{4, 6};
    if (v < lowest || highest < v) {
        std::string hint;
        if (es && !(v < GlVersion{3, 3})) hint = " (desktop versions go with --profile core)";
        if (!es && v < lowest && !(v < GlVersion{3, 0})) hint = " (OpenGL ES versions go with --profile es)";
        throw Error("GL version '" + text + "' is out of range [" + lowest.str() + ", " + highest.str() + "] for the " +
                    profile_name(profile) + " profile" + hint);
    }
    return v;
}

GlVersion Context::effective_version() const {
    return info_.obtained < info_.held_to ? info_.obtained : info_.held_to;
}

void Context::require(GlVersion needed, const std::string& what_for) const {
    const GlVersion have = effective_version();
    if (have < needed) {
        const Profile p = info_.profile;
        std::string why = "needs " + api_name(p, needed) + " (" + what_for + ") but this run has " + have.str();
        if (info_.obtained < info_.requested || info_.obtained < needed)
            why += " (the driver offers " + info_.obtained.str() + ": " + info_.renderer + ")";
        else
            why += " (asked for with --gl " + info_.requested.str() + ")";
        throw UnsupportedError(why);
    }
}

std::string Context::describe() const {
    // GL_VERSION of an ES context already begins "OpenGL ES".
    const std::string version = info_.version_string.rfind("OpenGL", 0) == 0 ? info_.version_string
                                                                            : "OpenGL " + info_.version_string;
    return info_.renderer + ", " + version + ", " + profile_name(info_.profile) + " profile, " +
           backend_name(info_.backend) + " backend";
}

static std::string gl_string(GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return s ? s : "";
}

void Context::load_gl(void* (*get_proc)(const char*), const ContextOptions& options) {
    // One set of entry points, loaded for the API the context speaks: an ES context has no glPolygonMode,
    // and glad's desktop loader would read "OpenGL ES 3.2" as desktop 3.2 and skip compute and storage.
    const bool es = options.profile == Profile::Es;
    const int loaded = es ? gladLoadGLES2(reinterpret_cast<GLADloadfunc>(get_proc))
                          : gladLoadGL(reinterpret_cast<GLADloadfunc>(get_proc));
    if (loaded == 0) throw Error(std::string("could not load ") + (es ? "OpenGL ES" : "OpenGL") +
                                 " functions through the " + backend_name(options.backend) + " backend");
    info_.backend = options.backend;
    info_.requested = options.version;
    info_.held_to = options.up_to && options.version < *options.up_to ? *options.up_to : options.version;
    info_.obtained = GlVersion{GLAD_VERSION_MAJOR(loaded), GLAD_VERSION_MINOR(loaded)};
    info_.renderer = gl_string(GL_RENDERER);
    info_.vendor = gl_string(GL_VENDOR);
    info_.version_string = gl_string(GL_VERSION);
    info_.glsl_version_string = gl_string(GL_SHADING_LANGUAGE_VERSION);
    if (info_.version_string.rfind("OpenGL ES", 0) == 0) {
        info_.profile = Profile::Es;
    } else {
        GLint mask = 0;
        glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
        info_.profile = (mask & GL_CONTEXT_CORE_PROFILE_BIT) ? Profile::Core : Profile::Compat;
    }
    if (info_.profile != options.profile)
        throw UnsupportedError(std::string("asked for a ") + profile_name(options.profile) +
                               " profile context but the driver gave " + profile_name(info_.profile) +
                               " (" + info_.version_string + ")" +
                               (options.profile == Profile::Es ? "" : "; macOS offers only core: use --profile core"));
    glGetError();  // some drivers leave an error from context creation
}

// Asked of the current context, not of glad's flags: a process that made an ES context and then a desktop one
// (the tests do) still has the ES flags set from the first.
bool gl_is_es() {
    const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    return version && std::strncmp(version, "OpenGL ES", 9) == 0;
}

bool gl_has_extension(const char* name) {
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i)
        if (const auto* e = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i))); e && std::strcmp(e, name) == 0)
            return true;
    return false;
}

void check_gl_error(const char* what) {
    const GLenum error = glGetError();
    if (error == GL_NO_ERROR) return;
    while (glGetError() != GL_NO_ERROR) {
    }
    throw Error(std::string("GL error ") + gl_error_name(error) + " after " + what);
}

const char* gl_error_name(unsigned error) {
    switch (error) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    default: return "GL_UNKNOWN_ERROR";
    }
}

}  // namespace gsv
