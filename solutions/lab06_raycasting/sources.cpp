#include "sources.h"

#include "common/core/error.h"
#include "support/volume/marschner_lobb.h"
#include "support/volume/nifti_file.h"

#include <cmath>

namespace lab06 {
namespace {

gsv::Volume load_volume(const std::string& kind, const std::string& file, int ml_size, const gsv::Assets& assets) {
    if (kind == "marschner_lobb") return gsv::make_marschner_lobb_volume(ml_size);
    if (kind == "anatomical") {
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
    if (kind == "constant") {
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
    add_property("volume", "marschner_lobb", {"marschner_lobb", "anatomical", "constant", "file"});
    add_property("volume_file", "");
    add_property("ml_size", "41");
}

void VolumeSource::process() {
    const std::string kind = property("volume");
    const std::string file = property("volume_file");
    const int ml_size = static_cast<int>(number("ml_size", 2, 512));
    const std::string key = kind + "|" + file + "|" + std::to_string(ml_size);
    if (key != loaded_ || !data_) {
        auto data = std::make_shared<VolumeData>();
        data->volume = load_volume(kind, file, ml_size, kit().assets());
        const gsv::Volume& v = data->volume;
        data->texture = gsv::Texture::create_3d(v.nx, v.ny, v.nz, gsv::TexelFormat::R32F, v.values.data());
        data->box = gsv::VolumeBox(v.extent());
        data_ = std::move(data);
        loaded_ = key;
    }
    set_output("volume", data_);
}

ProxySource::ProxySource() : LabProcessor("ProxySource") {
    add_input("volume", gsv::PortType::Volume);
    add_output("geometry", gsv::PortType::Geometry);
    add_property("clip_normal", "0,0,0");
    add_property("clip_offset", "0");
}

void ProxySource::process() {
    auto volume = input<VolumeData>("volume");
    const glm::dvec3 n(vec3("clip_normal"));
    const double offset = number("clip_offset", -2, 2);
    const glm::dvec3 e = volume->box.extent();
    const std::string key = property("clip_normal") + "|" + property("clip_offset") + "|" + std::to_string(e.x) +
                            "," + std::to_string(e.y) + "," + std::to_string(e.z);
    if (key != built_ || !data_) {
        std::vector<gsv::Plane> planes;
        if (n != glm::dvec3(0.0)) {
            const glm::dvec3 unit = glm::normalize(n);
            planes.push_back({unit, offset + glm::dot(unit, glm::dvec3(0.5))});
        }
        auto data = std::make_shared<GeometryData>();
        data->proxy.emplace(planes);
        data->mesh = data->proxy->mesh();
        if (!data->mesh.indices.empty()) data->gpu = gsv::GpuMesh(data->mesh, kit().profile());
        data->box = volume->box;
        data_ = std::move(data);
        built_ = key;
    }
    set_output("geometry", data_);
}

ProbeSource::ProbeSource() : LabProcessor("ProbeSource") {
    add_input("volume", gsv::PortType::Volume);
    add_output("geometry", gsv::PortType::Geometry);
    add_property("probe_position", "0.3,-0.2,0.4");
    add_property("probe_radius", "0.25");
}

void ProbeSource::process() {
    auto volume = input<VolumeData>("volume");
    const glm::vec3 centre = vec3("probe_position");
    const float radius = static_cast<float>(number("probe_radius", 0.01, 2));
    const std::string key = property("probe_position") + "|" + property("probe_radius");
    if (key != built_ || !data_ || data_->box.extent() != volume->box.extent()) {
        gsv::MeshData sphere = gsv::make_uv_sphere(48, 24, radius);
        for (auto& p : sphere.positions) p += centre;
        auto data = std::make_shared<GeometryData>();
        data->mesh = to_texture_space(std::move(sphere), volume->box);
        data->gpu = gsv::GpuMesh(data->mesh, kit().profile());
        data->box = volume->box;
        data_ = std::move(data);
        built_ = key;
    }
    set_output("geometry", data_);
}

}  // namespace lab06
