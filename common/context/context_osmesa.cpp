// The fallback headless backend, for Mesa builds that still ship OSMesa (removed in Mesa 25.1).
#include "common/context/context.h"
#include "common/core/error.h"

#include <GL/osmesa.h>

#include <vector>

namespace gsv {
namespace {

class OSMesaContextHolder final : public Context {
public:
    explicit OSMesaContextHolder(const ContextOptions& options) {
        if (options.profile == Profile::Es)
            throw UnsupportedError("OSMesa makes desktop OpenGL contexts only: OpenGL ES runs headless on --backend egl");
        const int attributes[] = {
            OSMESA_FORMAT, OSMESA_RGBA,
            OSMESA_DEPTH_BITS, 24,
            OSMESA_PROFILE, options.profile == Profile::Core ? OSMESA_CORE_PROFILE : OSMESA_COMPAT_PROFILE,
            OSMESA_CONTEXT_MAJOR_VERSION, options.version.major,
            OSMESA_CONTEXT_MINOR_VERSION, options.version.minor,
            0};
        context_ = OSMesaCreateContextAttribs(attributes, nullptr);
        if (!context_)
            throw UnsupportedError(std::string("OSMesa cannot create an OpenGL ") + options.version.str() + " " +
                                   profile_name(options.profile) + " context");
        // OSMesa needs a colour buffer to be current; the kit itself renders into framebuffer objects.
        buffer_.resize(16 * 16 * 4);
        if (!OSMesaMakeCurrent(context_, buffer_.data(), 0x1401 /* GL_UNSIGNED_BYTE */, 16, 16)) {
            OSMesaDestroyContext(context_);
            throw UnsupportedError("OSMesa cannot make its context current");
        }
        try {
            load_gl(reinterpret_cast<void* (*)(const char*)>(OSMesaGetProcAddress), options);
        } catch (...) {
            OSMesaDestroyContext(context_);
            throw;
        }
    }
    ~OSMesaContextHolder() override { OSMesaDestroyContext(context_); }

private:
    OSMesaContext context_ = nullptr;
    std::vector<unsigned char> buffer_;
};

}  // namespace

std::unique_ptr<Context> make_osmesa_context(const ContextOptions& options) {
    return std::make_unique<OSMesaContextHolder>(options);
}

}  // namespace gsv
