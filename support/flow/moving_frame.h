#pragma once
// A flow seen by an observer who moves along +x: the observer's velocity subtracted from the field (a Galilean
// change of frame). Streamlines are not invariant under it: a vortex street drifting with the stream shows in the
// lab's frame as wavy streaks along the stream, and as the vortices themselves (closed streamlines about each
// centre) in a frame that moves with them. Labs 02 and 03 take the observer's velocity as the parameter
// `observer_velocity`, a fraction of the field's largest speed (`speed`).
#include "support/flow/flow_field.h"

namespace gsv {

// `field` with velocity_x texels per step taken off every texel's x velocity. Throws gsv::Error for a non-finite
// velocity_x.
FlowField seen_from_moving_frame(FlowField field, double velocity_x);
FlowSequence seen_from_moving_frame(FlowSequence sequence, double velocity_x);
// The same for a field given everywhere (the exact streamlines of lab 02's sweep).
VelocityAt seen_from_moving_frame(VelocityAt field, double velocity_x);

}  // namespace gsv
