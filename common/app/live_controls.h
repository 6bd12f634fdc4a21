#pragma once
// What the live views (the window, the browser page) do to parameters on their own: play the animated parameter,
// orbit and zoom the camera with the mouse. One place, so a drag turns the camera as far in the page as in the window.
#include "common/params/params.h"

namespace gsv {

// Moves the animated parameter on by `seconds` of wall time, wrapping at the end of its range. Wall time, not
// frames, drives it: one sweep of the range takes 8 s on llvmpipe and on a GPU alike. No animated parameter: nothing.
void play_animation(Params& params, double seconds);
// A mouse drag of (dx, dy) pixels turns the orbit camera (add_orbit_camera); false where the lab has none.
bool orbit_drag(Params& params, double dx, double dy);
// A scroll of `steps` notches moves the camera nearer (positive) or further; false where the lab has no camera.
bool orbit_zoom(Params& params, double steps);

}  // namespace gsv
