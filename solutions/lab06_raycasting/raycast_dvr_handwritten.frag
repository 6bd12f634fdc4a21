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
//@solution L06-T3
    vec3 direction = span / len;
    int samples = max(int(ceil(min(len / uStepSize, 16384.0) - 1e-3)), 1);
    float step = len / float(samples);

    vec3 spacing = all(greaterThan(uVoxelSpacing, vec3(0.0))) ? uVoxelSpacing : vec3(1.0);
    vec3 size = vec3(textureSize(uVolume, 0));
    vec3 h = 1.0 / size;
    vec3 toPhysical = size * spacing;
    float exponent = uReferenceStepSize > 0.0 ? step / uReferenceStepSize : 1.0;

    vec4 result = vec4(0.0);
    float hitT = -1.0;
    for (int i = 0; i < samples; ++i) {
        float t = (float(i) + 0.5) * step;
        vec3 p = entry.rgb + t * direction;
        vec4 color = texture(uTransferFunction, vec2(texture(uVolume, p).r, 0.5));
        if (color.a <= 0.0) continue;

        vec3 gradient = (vec3(texture(uVolume, p + vec3(h.x, 0.0, 0.0)).r,
                              texture(uVolume, p + vec3(0.0, h.y, 0.0)).r,
                              texture(uVolume, p + vec3(0.0, 0.0, h.z)).r) -
                         vec3(texture(uVolume, p - vec3(h.x, 0.0, 0.0)).r,
                              texture(uVolume, p - vec3(0.0, h.y, 0.0)).r,
                              texture(uVolume, p - vec3(0.0, 0.0, h.z)).r)) / (2.0 * spacing);
        vec3 n = -safeNormalize(gradient, vec3(0.0));
        vec3 l = safeNormalize((uLightPosition - p) * toPhysical, vec3(0.0));
        vec3 v = safeNormalize((uCameraPosition - p) * toPhysical, vec3(0.0));
        if (dot(n, v) < 0.0) n = -n;
        float diffuse = max(dot(n, l), 0.0);
        float rv = max(dot(reflect(-l, n), v), 0.0);
        float specular = diffuse > 0.0 && rv > 0.0 ? pow(rv, max(uShininess, 0.0)) : 0.0;
        color.rgb = color.rgb * (uAmbient + uDiffuse * diffuse) + vec3(uSpecular * specular);

        float alpha = 1.0 - pow(1.0 - min(color.a, 1.0), exponent);
        if (hitT < 0.0) hitT = t;
        result += (1.0 - result.a) * vec4(alpha * color.rgb, alpha);
        if (uEarlyRayThreshold > 0.0 && result.a >= uEarlyRayThreshold) break;
    }
    fColor = result + (1.0 - result.a) * uBackground;

    float depth = 1.0;
    vec4 clip = uTextureToClip * vec4(entry.rgb + hitT * direction, 1.0);
    if (hitT >= 0.0 && clip.w > 0.0)
        depth = gl_DepthRange.near + gl_DepthRange.diff * (0.5 * clamp(clip.z / clip.w, -1.0, 1.0) + 0.5);
    gl_FragDepth = depth;
//@starter
//    fColor = vec4(kNotDone, 1.0);
//    gl_FragDepth = 1.0;
//@end
}