// Lab 01 vertex stage: from the model's space into eye space (for lighting) and clip space (for the
// rasterizer). The kit's prelude declares aVertex, aNormal and the u...Matrix uniforms in the core
// profile; in the compatibility profile they are the seeds' gl_Vertex, gl_Normal, gl_...Matrix.
#include "lighting.glsl"

out vec3 vEyePosition;
out vec3 vEyeNormal;
out vec3 vObjectPosition;
#ifdef SHADING_RATE_VERTEX
out vec3 vFrontColor;
out vec3 vBackColor;
#endif

void main() {
    vObjectPosition = aVertex.xyz;
    // TODO(L01-T1): the position in eye space (uModelViewMatrix) and the normal in eye space. Normals
    // are not positions: under a non-uniform scale they must go through the inverse transpose of the
    // model-view matrix, which the kit provides as uNormalMatrix.
    vEyePosition = aVertex.xyz;
    vEyeNormal = aNormal;
    gl_Position = uModelViewProjectionMatrix * aVertex;
#ifdef SHADING_RATE_VERTEX
    // Per-vertex (Gouraud) shading: light the vertices, let the rasterizer blend the colours. The
    // vertex stage cannot know which side will face the viewer, so it lights both.
    vec3 n = safeNormalize(vEyeNormal, vec3(0.0, 0.0, 1.0));
    vFrontColor = shade(n, vEyePosition);
    vBackColor = shade(-n, vEyePosition);
#endif
}
