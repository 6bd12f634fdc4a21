#pragma once
// Where a volume's box sits in model space, and the linear map between its texture coordinates and model
// positions. The raycaster's proxy geometry is built in texture space (support/raycast/proxy_geometry.h); this map
// is the model matrix that places it.
//
// Convention: model space is the box centred at the origin, scaled so that its largest side is 2 and the
// others keep the physical proportions. So an anisotropic volume (MRI slices thicker than their pixels)
// keeps its true shape, and every volume lies in the sphere of radius sqrt 3 about the origin (a cube's
// corners are on it), which lab 06's camera frames. A texture coordinate t in [0,1]^3 is at model position (t - 1/2) * size(): texture (0,0,0) is the
// corner (-size/2), texture (1,1,1) the corner (+size/2).
#include "support/geometry/plane.h"

#include <glm/glm.hpp>

namespace gsv {

class VolumeBox {
public:
    // `extent` is the physical size of the volume (Volume::extent(): voxels times spacing, in mm for medical
    // data). Throws gsv::Error naming it unless all three sides are positive and finite.
    explicit VolumeBox(glm::dvec3 extent);

    glm::dvec3 extent() const { return extent_; }
    glm::dvec3 size() const { return size_; }  // model-space sides; the largest is exactly 2
    // Physical length of one model unit (mm per unit for medical data): half the largest physical side.
    // A step of s mm along a ray is s / physical_per_model() model units.
    double physical_per_model() const { return extent_scale_; }

    glm::dvec3 model_from_texture(glm::dvec3 texture) const { return (texture - 0.5) * size_; }
    glm::dvec3 texture_from_model(glm::dvec3 model) const { return model / size_ + 0.5; }
    // Directions have no offset: a model-space step d is the texture-space step d / size().
    glm::dvec3 texture_direction(glm::dvec3 model_direction) const { return model_direction / size_; }

    // model_from_texture as a matrix: Transforms::model for the proxy mesh, whose positions are texture
    // coordinates. Its inverse is texture_from_model_matrix().
    glm::mat4 model_from_texture_matrix() const;
    glm::mat4 texture_from_model_matrix() const;

    // The same half-space described in texture space, normal made unit length. The normal changes direction
    // under the anisotropic scale: n_texture is parallel to n_model * size(), not to n_model.
    Plane texture_plane(const Plane& model_plane) const;

private:
    glm::dvec3 extent_;
    glm::dvec3 size_;
    double extent_scale_;
};

}  // namespace gsv
