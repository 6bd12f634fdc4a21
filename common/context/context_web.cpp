// The browser edition's backend: WebGL 2 (OpenGL ES 3.0, GLSL ES 3.00) on the page's canvas, through Emscripten's
// html5 API. Compiled only by cmake/web.cmake.
#include "common/context/context.h"
#include "common/core/error.h"

#include <emscripten/html5.h>
#include <emscripten/html5_webgl.h>

namespace gsv {
namespace {

constexpr const char* kCanvas = "#canvas";

class WebContext final : public Context {
public:
    explicit WebContext(const ContextOptions& options) {
        if (options.profile != Profile::Es)
            throw UnsupportedError("a browser offers WebGL 2, which is OpenGL ES 3.0: the page runs the es profile");
        EmscriptenWebGLContextAttributes attributes;
        emscripten_webgl_init_context_attributes(&attributes);
        attributes.majorVersion = 2;
        attributes.minorVersion = 0;
        attributes.alpha = false;
        attributes.depth = true;
        attributes.antialias = false;  // as the window (GLFW_SAMPLES 0): the picture is the one the grader compares
        // The canvas is read back after a frame (screenshots, the page's tests) as a window's front buffer is.
        attributes.preserveDrawingBuffer = true;
        emscripten_set_canvas_element_size(kCanvas, options.width, options.height);
        handle_ = emscripten_webgl_create_context(kCanvas, &attributes);
        if (handle_ <= 0)
            throw UnsupportedError("this browser gives the page no WebGL 2 context (error " + std::to_string(handle_) +
                                   "): WebGL 2 is OpenGL ES 3.0, which every lab needs");
        emscripten_webgl_make_context_current(handle_);
        load_gl(reinterpret_cast<void* (*)(const char*)>(emscripten_webgl_get_proc_address), options);
    }
    ~WebContext() override { emscripten_webgl_destroy_context(handle_); }

private:
    EMSCRIPTEN_WEBGL_CONTEXT_HANDLE handle_ = 0;
};

}  // namespace

std::unique_ptr<Context> make_web_context(const ContextOptions& options) { return std::make_unique<WebContext>(options); }

}  // namespace gsv
