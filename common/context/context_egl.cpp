// The headless default: an EGL context on Mesa's surfaceless platform (or the first EGL device),
// which needs no display server. Surfaceless contexts have no default framebuffer: the kit renders
// into framebuffer objects.
#include "common/context/context.h"
#include "common/core/error.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <string>

namespace gsv {
namespace {

bool in_extension_list(const char* list, const char* name) {
    if (!list) return false;
    const std::size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

std::string egl_error_name(EGLint error) {
    switch (error) {
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    default: return "EGL error 0x" + [&] { char b[16]; std::snprintf(b, sizeof b, "%x", error); return std::string(b); }();
    }
}

EGLDisplay open_headless_display() {
    const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto get_platform_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_platform_display) throw UnsupportedError("EGL has no eglGetPlatformDisplayEXT: cannot render headless");
    // eglGetDisplay(EGL_DEFAULT_DISPLAY) would try X11 and fail without a display, so ask for a platform.
    if (in_extension_list(client_extensions, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
    }
    if (in_extension_list(client_extensions, "EGL_EXT_platform_device")) {
        auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
        EGLDeviceEXT devices[8];
        EGLint count = 0;
        if (query_devices && query_devices(8, devices, &count) && count > 0) {
            EGLDisplay display = get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[0], nullptr);
            if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
        }
    }
    throw UnsupportedError("no headless EGL display (neither EGL_MESA_platform_surfaceless nor EGL_EXT_platform_device works)");
}

class EglContext final : public Context {
public:
    explicit EglContext(const ContextOptions& options) : keep_display_(options.keep_display) {
        display_ = open_headless_display();
        const char* extensions = eglQueryString(display_, EGL_EXTENSIONS);
        if (!in_extension_list(extensions, "EGL_KHR_surfaceless_context")) {
            eglTerminate(display_);
            throw UnsupportedError("EGL display lacks EGL_KHR_surfaceless_context");
        }
        const bool es = options.profile == Profile::Es;
        if (!eglBindAPI(es ? EGL_OPENGL_ES_API : EGL_OPENGL_API)) {
            eglTerminate(display_);
            throw UnsupportedError(std::string("EGL cannot bind the ") + (es ? "OpenGL ES" : "desktop OpenGL") + " API");
        }
        EGLConfig config = EGL_NO_CONFIG_KHR;
        if (!in_extension_list(extensions, "EGL_KHR_no_config_context")) {
            const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, es ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_BIT, EGL_NONE};
            EGLint count = 0;
            if (!eglChooseConfig(display_, config_attributes, &config, 1, &count) || count == 0) {
                eglTerminate(display_);
                throw UnsupportedError(std::string("EGL has no config for ") + (es ? "OpenGL ES 3" : "desktop OpenGL"));
            }
        }
        // ES has no profiles: its attribute list stops after the version.
        const EGLint profile_bit = options.profile == Profile::Core ? EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT
                                                                    : EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT;
        const EGLint context_attributes[] = {
            EGL_CONTEXT_MAJOR_VERSION, options.version.major,
            EGL_CONTEXT_MINOR_VERSION, options.version.minor,
            es ? EGL_NONE : EGL_CONTEXT_OPENGL_PROFILE_MASK, profile_bit,
            EGL_NONE};
        context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, context_attributes);
        if (context_ == EGL_NO_CONTEXT) {
            const EGLint error = eglGetError();
            eglTerminate(display_);
            throw UnsupportedError("EGL cannot create an " + api_name(options.profile, options.version) + " " +
                                   profile_name(options.profile) + " context (" + egl_error_name(error) + ")");
        }
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
            release();
            throw UnsupportedError("EGL cannot make the surfaceless context current");
        }
        try {
            load_gl(reinterpret_cast<void* (*)(const char*)>(eglGetProcAddress), options);
        } catch (...) {
            release();
            throw;
        }
    }
    ~EglContext() override { release(); }

private:
    void release() {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
        if (!keep_display_) eglTerminate(display_);
        context_ = EGL_NO_CONTEXT;
    }
    bool keep_display_ = false;
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<Context> make_egl_context(const ContextOptions& options) {
    return std::make_unique<EglContext>(options);
}

}  // namespace gsv
