// Lab 06: the ray-casting skeleton. One loop from entry to exit, with the modules left as placeholders
// that whoever includes this defines first:
//   RC_START(ray)                           the state a ray begins with (what every sample would
//                                          otherwise recompute, such as DVR's opacity exponent)
//   RC_COMPOSITE(state, ray, t, intensity)  folds one sample into the state (and calls RC_CLASSIFY,
//                                          RC_GRADIENT and RC_SHADE as its compositing needs them)
//   RC_TERMINATE(state)                     true: the rest of the ray cannot change the pixel enough
//   RC_FINISH(state)                        the pixel's premultiplied colour
// raycast.frag fills them at compile time from the generated rc_config.glsl; raycast_uber.frag with
// uniform-driven switches. Draw a full-screen quad (gsv/fullscreen.vert) the size of the entry texture.
// Give every sampler the program has a texture unit of its own: an unset sampler reads unit 0, and a
// sampler3D and a sampler2D on one unit make every draw fail with GL_INVALID_OPERATION, drawing nothing.
#pragma once
#include "raycast_common.glsl"

// Where each pixel's ray enters and leaves the volume, in texture coordinates in RGB; alpha 1 where the
// proxy geometry covers the pixel, 0 elsewhere. Both the size of the target drawn into.
uniform sampler2D uEntryPoints;
uniform sampler2D uExitPoints;
// Volume texture coordinates to clip space (projection * view * model * texture-to-model), for the depth
// of the hit. Unset, every hit lies at the far plane.
uniform mat4 uTextureToClip;
// Shows where the ray hit nothing and through what it left transparent; premultiplied. Unset: transparent
// black, for a later pass to composite.
uniform vec4 uBackground;

out vec4 fColor;

// False where there is nothing to march: no proxy under the pixel, no step size set, or entry == exit
// (a ray grazing an edge), which has no length to integrate and no direction to divide by.
bool rcSetupRay(out RcRay ray) {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 entry = texelFetch(uEntryPoints, pixel, 0);
    vec4 exit = texelFetch(uExitPoints, pixel, 0);
    ray = RcRay(entry.rgb, vec3(0.0), 0.0, 0.0, 0);
    if (entry.a < 0.5 || exit.a < 0.5 || !(uStepSize > 0.0)) return false;
    vec3 span = exit.rgb - entry.rgb;
    float len = length(span);
    if (len < 1e-6) return false;
    ray.direction = span / len;
    ray.tEnd = len;
    // The 1e-3 keeps a length of exactly n steps, give or take rounding, at n samples and not n + 1.
    float segments = ceil(min(len / uStepSize, float(kRcMaxSamples)) - 1e-3);
    ray.samples = max(int(segments), 1);
    ray.step = len / float(ray.samples);
    return true;
}

// The window-space depth of the point at ray parameter t; the far plane for no hit.
float rcDepth(RcRay ray, float t) {
    if (t < 0.0) return 1.0;
    vec4 clip = uTextureToClip * vec4(rcPosition(ray, t), 1.0);
    // w <= 0: an unset matrix, or a point behind the eye; neither has a depth to divide out.
    if (!(clip.w > 0.0)) return 1.0;
    float ndc = clamp(clip.z / clip.w, -1.0, 1.0);
    return gl_DepthRange.near + gl_DepthRange.diff * (0.5 * ndc + 0.5);
}

void main() {
    RcRay ray;
    if (!rcSetupRay(ray)) {
        fColor = uBackground;
        gl_FragDepth = 1.0;
        return;
    }
#ifdef RC_HAS_VOLUME_GEOMETRY
    rcPrepareVolumeGeometry();  // volume_geometry.glsl is in: its figures once per ray, not once per sample
#endif
    RcState state = RC_START(ray);
    for (int i = 0; i < ray.samples; ++i) {
        float t = (float(i) + 0.5) * ray.step;
        RC_COMPOSITE(state, ray, t, texture(uVolume, rcPosition(ray, t)).r);
        if (RC_TERMINATE(state)) break;
    }
    vec4 color = RC_FINISH(state);
    fColor = color + (1.0 - color.a) * uBackground;
    gl_FragDepth = rcDepth(ray, state.hitT);
}
