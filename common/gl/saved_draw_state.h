#pragma once
// What a pass drawn on the side (a legend probe, a depth read-back) changes, put back when it ends: the lab
// draws its next frame into the target it had bound, with its own viewport, depth test and blending.
#include "common/gl/gl.h"

namespace gsv {

class SavedDrawState {
public:
    SavedDrawState() {
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer_);
        glGetIntegerv(GL_VIEWPORT, viewport_);
        depth_ = glIsEnabled(GL_DEPTH_TEST);
        blend_ = glIsEnabled(GL_BLEND);
    }
    ~SavedDrawState() {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(framebuffer_));
        glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
        depth_ ? glEnable(GL_DEPTH_TEST) : glDisable(GL_DEPTH_TEST);
        blend_ ? glEnable(GL_BLEND) : glDisable(GL_BLEND);
    }
    SavedDrawState(const SavedDrawState&) = delete;
    SavedDrawState& operator=(const SavedDrawState&) = delete;

private:
    GLint framebuffer_ = 0;
    GLint viewport_[4] = {0, 0, 0, 0};
    GLboolean depth_ = GL_FALSE, blend_ = GL_FALSE;
};

}  // namespace gsv
