#pragma once
// A CPU image shown in the window's picture area in place of the lab's render: a port being inspected, the
// reference, a difference. Scaled to fit, aspect kept, centred.
#include "common/gl/framebuffer.h"
#include "common/image/image.h"

namespace gsv {

class ImageView {
public:
    // Draws `image` into the bound draw framebuffer's rectangle (0, 0, width, height), which it clears first.
    void draw(const Image& image, int width, int height);

private:
    Framebuffer source_;  // the image as a texture, read through glBlitFramebuffer
};

}  // namespace gsv
