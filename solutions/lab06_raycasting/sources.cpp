#include "sources.h"

#include "common/core/error.h"
#include "support/volume/marschner_lobb.h"
#include "support/volume/nifti_file.h"

#include <cmath>

namespace lab06 {
namespace {

gsv::Volume load_volume(VolumeKind kind, const std::string& file, int ml_size, const gsv::Assets& assets) {
    if (kind == VolumeKind::MarschnerLobb) return gsv::make_marschner_lobb_volume(ml_size);
    if (kind == VolumeKind::Anatomical) {
        // The scan's own range runs up to a few dozen bright voxels at up to 2.3 times the white matter: normalised
        // over it, all the tissue would fall in [0.17, 0.45]. Windowed like a viewer opens it, from the 0.1th to
        // the 99.5th percentile, cerebrospinal fluid, grey and white matter spread over [0, 1] (about 0.1-0.35,
        // 0.45-0.65 and 0.75-0.95), where the tissue transfer function tells them apart.
        gsv::Volume head = gsv::load_nifti(assets.data_file("volumes/anatomical.nii"));
        head.set_percentile_window(0.001, 0.995);
        // Its voxels run from the subject's right to left (i), back to front (j) and bottom to top (k): drawn as they
        // are, the head lies on its back, mirrored. With j and k exchanged it stands upright facing +z, and the
        // exchange undoes the mirror (x to the subject's left, y up, z forward is a right-handed frame).
        return head.normalized().with_y_and_z_exchanged();
    }
    if (kind == VolumeKind::Constant) {
        gsv::Volume v;
        v.nx = v.ny = v.nz = 16;
        v.values.assign(16 * 16 * 16, 0.5f);
        v.update_range();
        v.name = "constant";
        return v;
    }
    if (file.empty()) throw gsv::Error("volume=file needs volume_file=PATH (a NIfTI-1 .nii file)");
    return gsv::load_nifti(assets.user_file(file)).normalized();
}

gsv::MeshData to_texture_space(gsv::MeshData mesh, const gsv::VolumeBox& box) {
    for (auto& p : mesh.positions) p = glm::vec3(box.texture_from_model(glm::dvec3(p)));
    return mesh;
}

}  // namespace

VolumeSource::VolumeSource() : LabProcessor("VolumeSource") {
    add_output("volume", gsv::PortType::Volume);
    gsv::Params& p = params();
    // Only the processor reads it: it picks what goes into the texture the ray caster samples as uVolume.
    kind_ = p.add_enum("volume", VolumeKind::MarschnerLobb, kVolumeKinds,
                       "the test signal (exact values known), the MRI head, a constant (zero gradient), or volume_file")
                .without_uniform();
    file_ = p.add_file("volume_file", "", "a NIfTI-1 volume (.nii or .nii.gz), with volume=file").applies_when(kind_, {VolumeKind::File});
    ml_size_ = p.add_int("ml_size", 41, 8, 256, "voxels per side of the Marschner-Lobb volume")
                   .applies_when(kind_, {VolumeKind::MarschnerLobb});
}

void VolumeSource::process() {
    data_.update(params(), [&] {
        auto data = std::make_shared<VolumeData>();
        data->volume = load_volume(kind_.get(), file_.get(), ml_size_.get(), kit().assets());
        const gsv::Volume& v = data->volume;
        data->texture = gsv::Texture::create_3d(v.nx, v.ny, v.nz, gsv::TexelFormat::R32F, v.values.data());
        data->box = gsv::VolumeBox(v.extent());
        return data;
    });
    set_output("volume", *data_);
}

ProxySource::ProxySource() : LabProcessor("ProxySource") {
    add_input("volume", gsv::PortType::Volume);
    add_output("geometry", gsv::PortType::Geometry);
    gsv::Params& p = params();
    clip_normal_ = p.add_vec3("clip_normal", {0.0f, 0.0f, 0.0f}, -1, 1, "a clipping plane's normal in texture space (0,0,0: none)");
    clip_offset_ = p.add_float("clip_offset", 0, -1, 1, "keeps dot(n, t - centre) <= offset |n|")
                       .with_step(0.05)
                       .may_draw_the_same("with clip_normal 0,0,0 there is no plane to move")
                       .in_double();
}

void ProxySource::process() {
    auto volume = input<VolumeData>("volume");
    const glm::dvec3 e = volume->box.extent();
    data_.update(params(), [&] {
        const glm::dvec3 n(clip_normal_.get());
        std::vector<gsv::Plane> planes;
        if (n != glm::dvec3(0.0)) {
            const glm::dvec3 unit = glm::normalize(n);
            planes.push_back({unit, clip_offset_.get() + glm::dot(unit, glm::dvec3(0.5))});
        }
        auto data = std::make_shared<GeometryData>();
        data->proxy.emplace(planes);
        data->mesh = data->proxy->mesh();
        if (!data->mesh.indices.empty()) data->gpu = gsv::GpuMesh(data->mesh, kit().profile());
        data->box = volume->box;
        return data;
    }, e.x, e.y, e.z);
    set_output("geometry", *data_);
}

ProbeSource::ProbeSource() : LabProcessor("ProbeSource") {
    add_input("volume", gsv::PortType::Volume);
    add_output("geometry", gsv::PortType::Geometry);
    gsv::Params& p = params();
    position_ = p.add_vec3("probe_position", {0.3f, -0.2f, 0.4f}, -1.5, 1.5, "the probe's centre (model space, the box's largest side 2)");
    radius_ = p.add_float("probe_radius", 0.25, 0.02, 1, "the probe's radius (model units)").with_step(0.02);
}

void ProbeSource::process() {
    auto volume = input<VolumeData>("volume");
    const glm::dvec3 e = volume->box.extent();
    data_.update(params(), [&] {
        gsv::MeshData sphere = gsv::make_uv_sphere(48, 24, radius_.get());
        const glm::vec3 centre = position_.get();
        for (auto& p : sphere.positions) p += centre;
        auto data = std::make_shared<GeometryData>();
        data->mesh = to_texture_space(std::move(sphere), volume->box);
        data->gpu = gsv::GpuMesh(data->mesh, kit().profile());
        data->box = volume->box;
        return data;
    }, e.x, e.y, e.z);
    set_output("geometry", *data_);
}

}  // namespace lab06
