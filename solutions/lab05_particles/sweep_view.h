#pragma once
// What lab 05 lends the sweep plan that measures it (the instructor's reference/lab05_particles/): its stepper over
// its own buffers, the particles they started from and the steps taken since, so the plan can run the same steps
// again beside the CPU's. Measuring restarts the buffers, and the plan says so.
#include "common/app/app.h"
#include "particle_stepper.h"
#include "support/particles/particle_motion.h"

namespace lab05 {

class SweepView {
public:
    virtual ~SweepView() = default;
    virtual Stepper stepper(gsv::LabKit& kit) = 0;
    virtual const gsv::ParticleSet& initial_particles() const = 0;
    virtual long steps_done() const = 0;
    // The buffers were restarted by someone else: the next frame steps them again from the start.
    virtual void buffers_restarted() = 0;
};

}  // namespace lab05
