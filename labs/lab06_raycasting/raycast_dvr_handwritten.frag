// Lab 06: one single-purpose ray caster written out by hand: DVR, central-difference gradients, a 1D
// transfer function, Phong shading, early ray termination. No modules and no placeholders: what the lab
// measures the specialised raycast.frag against, to see what assembling it from modules costs. The
// loop-invariant values (voxel step, physical scale, opacity exponent) are worked out before the loop, as
// the skeleton has the modules do (rcPrepareVolumeGeometry, RC_START). It takes the same uniforms and
// computes the same image as raycast.frag for that configuration.
#include "gsv/math.glsl"
#include "gsv/not_done.glsl"

uniform sampler2D uEntryPoints;     // texture coordinates in RGB, alpha 1 where the proxy covers the pixel
uniform sampler2D uExitPoints;
uniform sampler3D uVolume;          // R32F, values in [0, 1]
uniform sampler2D uTransferFunction;  // RGBA, height 1, straight colour
uniform float uStepSize;            // in texture coordinates
uniform float uReferenceStepSize;   // the step the transfer function's opacities are meant for
uniform float uEarlyRayThreshold;
uniform vec3 uVoxelSpacing;
uniform vec3 uLightPosition;        // texture coordinates
uniform vec3 uCameraPosition;       // texture coordinates
uniform float uAmbient;
uniform float uDiffuse;
uniform float uSpecular;
uniform float uShininess;
uniform mat4 uTextureToClip;
uniform vec4 uBackground;           // premultiplied

out vec4 fColor;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 entry = texelFetch(uEntryPoints, pixel, 0);
    vec4 exit = texelFetch(uExitPoints, pixel, 0);
    vec3 span = exit.rgb - entry.rgb;
    float len = length(span);
    // No proxy here, or entry == exit: nothing to march, and no direction to divide by.
    if (entry.a < 0.5 || exit.a < 0.5 || !(uStepSize > 0.0) || len < 1e-6) {
        fColor = uBackground;
        gl_FragDepth = 1.0;
        return;
    }
    // TODO(L06-T3): this is the DVR of L06-T1..T3 written out by hand, for the timing comparison; the
    // reference solution has it. Until then it draws "not done".
    fColor = vec4(kNotDone, 1.0);
    gl_FragDepth = 1.0;
}