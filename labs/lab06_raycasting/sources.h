#pragma once
// Lab 06's source processors: the volume, the proxy geometry cut by a clipping plane, and an opaque probe
// sphere to embed in the volume.
#include "lab_processor.h"

#include "common/params/change_tracker.h"

#include <memory>
#include <string>

namespace lab06 {

enum class VolumeKind { MarschnerLobb, Anatomical, Constant, File };
inline constexpr gsv::EnumName<VolumeKind> kVolumeKinds[] = {{VolumeKind::MarschnerLobb, "marschner_lobb"},
                                                             {VolumeKind::Anatomical, "anatomical"},
                                                             {VolumeKind::Constant, "constant"},
                                                             {VolumeKind::File, "file"}};

// Reads or generates the volume and uploads it as an R32F 3D texture (linear, clamp to edge).
//   volume: marschner_lobb (the test signal, ml_size^3 over [-1,1]^3, values rho in [0, 1] as they are),
//           anatomical (the MRI head from python3-nibabel, normalised), constant (16^3 of 0.5: a zero
//           gradient everywhere), file (volume_file, a NIfTI-1 file, normalised).
class VolumeSource final : public LabProcessor {
public:
    VolumeSource();
    void process() override;

private:
    gsv::EnumParam<VolumeKind> kind_;
    gsv::Param<std::string> file_;
    gsv::Param<int> ml_size_;
    gsv::Tracked<std::shared_ptr<VolumeData>> data_;
};

// The volume's box as proxy geometry, cut by one clipping plane: texture space, keeping the points t with
// dot(n, t - (0.5, 0.5, 0.5)) <= clip_offset |n|, n = clip_normal; n = 0,0,0 cuts nothing.
class ProxySource final : public LabProcessor {
public:
    ProxySource();
    void process() override;

private:
    gsv::Param<glm::vec3> clip_normal_;
    gsv::Param<double> clip_offset_;
    gsv::Tracked<std::shared_ptr<GeometryData>> data_;
};

// A sphere of probe_radius model units at probe_position (model space: the box is centred at the origin,
// its largest side 2), as opaque geometry the rays stop at.
class ProbeSource final : public LabProcessor {
public:
    ProbeSource();
    void process() override;

private:
    gsv::Param<glm::vec3> position_;
    gsv::Param<float> radius_;
    gsv::Tracked<std::shared_ptr<GeometryData>> data_;
};

}  // namespace lab06
