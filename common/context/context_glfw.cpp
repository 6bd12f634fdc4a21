// The window backend: what students and lecturers see.
#include "common/context/context.h"
#include "common/core/error.h"

#include <GLFW/glfw3.h>

#include <string>

namespace gsv {
namespace {

std::string last_glfw_error() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "no description";
}

class GlfwContext final : public Context {
public:
    explicit GlfwContext(const ContextOptions& options) {
        if (!glfwInit())
            throw UnsupportedError("cannot open a window: " + last_glfw_error() +
                                   " (no display? headless runs use --backend egl)");
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, options.version.major);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, options.version.minor);
        if (options.profile == Profile::Es) {
            glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
        } else if (options.profile == Profile::Core) {
            glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
            glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);  // macOS refuses core contexts without it
        } else {
            glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_COMPAT_PROFILE);
        }
        glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
        glfwWindowHint(GLFW_SAMPLES, 0);
        glfwWindowHint(GLFW_DEPTH_BITS, 24);
        window_ = glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
        if (!window_ && options.profile == Profile::Es) {
            // GLX and WGL make ES contexts only through an extension; EGL is the other way in on Linux.
            glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
            window_ = glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
        }
        if (!window_) {
            const std::string why = last_glfw_error();
            glfwTerminate();
            throw UnsupportedError("cannot create a window with an " + api_name(options.profile, options.version) +
                                   " " + profile_name(options.profile) + " context: " + why +
                                   (options.profile == Profile::Es ? " (macOS has no OpenGL ES; render headless "
                                                                     "with --backend egl on Linux)"
                                                                   : ""));
        }
        glfwMakeContextCurrent(window_);
        glfwSwapInterval(options.vsync ? 1 : 0);
        try {
            load_gl(reinterpret_cast<void* (*)(const char*)>(glfwGetProcAddress), options);
        } catch (...) {
            glfwDestroyWindow(window_);
            glfwTerminate();
            throw;
        }
    }
    ~GlfwContext() override {
        glfwDestroyWindow(window_);
        glfwTerminate();
    }
    GLFWwindow* window() override { return window_; }
    void swap_buffers() override { glfwSwapBuffers(window_); }

private:
    GLFWwindow* window_ = nullptr;
};

}  // namespace

std::unique_ptr<Context> make_glfw_context(const ContextOptions& options) {
    return std::make_unique<GlfwContext>(options);
}

}  // namespace gsv
