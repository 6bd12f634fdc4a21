// Lab 01 fragment stage: per-fragment shading (or the blended per-vertex colour), silhouettes.
#include "lighting.glsl"

in vec3 vEyePosition;
in vec3 vEyeNormal;
in vec3 vObjectPosition;
#ifdef SHADING_RATE_VERTEX
in vec3 vFrontColor;
in vec3 vBackColor;
#endif

uniform float uCut;            // discard the part of the model beyond x = uCut, opening it up
uniform float uEdgeThreshold;  // silhouette where |n.v| falls below this

out vec4 fColor;

void main() {
    if (vObjectPosition.x > uCut) discard;

    // TODO(L01-T5): the interpolated normal is shorter than 1 between vertices: renormalize it (and
    // never divide by zero: see safeNormalize in shaders/gsv/math.glsl). Where the viewer sees a
    // back face (a cut-open model, the teapot from below) the normal points away: flip it.
//@solution L01-T5
    vec3 n = safeNormalize(vEyeNormal, vec3(0.0, 0.0, 1.0));
    if (!gl_FrontFacing) n = -n;
//@starter
//    vec3 n = vEyeNormal;
//@end

#if defined(SHADING_NORMALS)
    // The normal's direction as a colour (n/2 + 1/2): what L01-T1 hands on, before L01-T5 or any light touches it.
    // Where shading looks wrong, this view tells a wrong normal from a wrong lighting model.
    vec3 color = 0.5 * safeNormalize(vEyeNormal, vec3(0.0, 0.0, 1.0)) + 0.5;
#elif defined(SHADING_RATE_VERTEX)
    vec3 color = gl_FrontFacing ? vFrontColor : vBackColor;
#else
    vec3 color = shade(n, vEyePosition);
#endif

#ifdef EFFECT_SILHOUETTE
    // TODO(L01-T6): silhouette edges, an optional extra: where the surface turns away from the eye
    // (|n.v| below uEdgeThreshold, v the unit vector to the eye) paint the fragment dark grey.
//@solution L01-T6
    vec3 v = safeNormalize(-vEyePosition, n);
    if (abs(dot(n, v)) < uEdgeThreshold) color = vec3(0.08);
//@starter
//    color = kNotDone;
//@end
#endif
    fColor = vec4(color, 1.0);
}
