#pragma once
// What lab 06 lends the sweep plan that measures it (the instructor's reference/lab06_raycasting/): the ray caster of
// the last frame and the view it drew with, and whether the sweep should also time the other shaders.
#include "lab_processor.h"
#include "ray_traversal.h"

namespace lab06 {

class SweepView {
public:
    virtual ~SweepView() = default;
    // The network's processor named "raycaster"; none where the network has none.
    virtual RayTraversal* raycaster() = 0;
    virtual const FrameView& frame_view() const = 0;
    virtual bool compare_shaders() const = 0;
};

}  // namespace lab06
