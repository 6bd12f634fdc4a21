#pragma once
// Lab 06: each pixel's ray as two images, after Voreen. The proxy's front faces, coloured by their texture
// coordinates, give where each ray enters the volume; its back faces where it leaves. Opaque geometry
// (the probe) is drawn into both with an ordinary depth test, so a ray ends where it meets the geometry
// and a pixel where the geometry lies in front of the volume gets no ray at all.
#include "lab_processor.h"

#include "common/shader/shader_library.h"

namespace lab06 {

class EntryExitPoints final : public LabProcessor {
public:
    EntryExitPoints();
    void process() override;

private:
    const gsv::ShaderLibrary::Entry* program_ = nullptr;
    std::shared_ptr<ImageData> entry_, exit_;
};

}  // namespace lab06
