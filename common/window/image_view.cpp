#include "common/window/image_view.h"

#include "common/gl/gl.h"

#include <algorithm>
#include <cmath>

namespace gsv {

void ImageView::draw(const Image& image, int width, int height) {
    if (image.width <= 0 || image.height <= 0) return;
    // Making the source binds it: the target is the binding from before.
    GLint draw_binding = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_binding);
    if (source_.width() != image.width || source_.height() != image.height) {
        source_ = Framebuffer(image.width, image.height, ColorFormat::RGBA8, false);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(draw_binding));
    }
    glBindTexture(GL_TEXTURE_2D, source_.color().id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    const double scale = std::min(static_cast<double>(width) / image.width, static_cast<double>(height) / image.height);
    const int w = static_cast<int>(std::lround(image.width * scale)), h = static_cast<int>(std::lround(image.height * scale));
    const int x = (width - w) / 2, y = (height - h) / 2;
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, width, height);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, source_.id());
    // The image's row 0 is its top, GL's the bottom: the blit turns it over.
    glBlitFramebuffer(0, 0, image.width, image.height, x, y + h, x + w, y, GL_COLOR_BUFFER_BIT,
                      scale == std::floor(scale) ? GL_NEAREST : GL_LINEAR);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(draw_binding));
}

}  // namespace gsv
