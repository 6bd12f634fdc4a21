#pragma once
// What lab 07 shows, read-only, to the sweep plan that measures it (the instructor's reference/lab07_spectral/): the
// elements of the last frame, the programs that draw and probe them, and the view they were drawn with.
#include "common/app/app.h"
#include "common/scene/transforms.h"
#include "element_data.h"
#include "element_measure.h"

namespace lab07 {

class SweepView {
public:
    virtual ~SweepView() = default;
    virtual const ElementData& element_data() const = 0;
    virtual const MeasurePrograms& measure_programs() const = 0;
    virtual gsv::Transforms transforms(const gsv::Frame& frame) const = 0;
};

}  // namespace lab07
