// Lab 07: every fragment evaluates its element's polynomial at its reference point and colour-maps it.
#include "color_map.glsl"
#include "element_edges.glsl"
#include "spectral.glsl"

in vec2 vReference;
out vec4 fColor;

#ifdef EVALUATION_BASIS
uniform int uBasisIndex;  // k: the basis function drawn
#endif

void main() {
#ifdef EVALUATION_BASIS
    // One Lagrange basis function along xi, the same up every element, in grey (-0.5 black, 1.5 white): what L07-T1
    // computes, before the tensor product and the colour map. 1 at its own node, 0 at every other.
    float l[kNodes];
    lagrangeBasis(vReference.x, l);
    float value = l[clamp(uBasisIndex, 0, DEGREE)];
    fColor = vec4(withElementEdges(vec3(clamp(0.25 + 0.5 * value, 0.0, 1.0)), vReference), 1.0);
#else
    fColor = vec4(withElementEdges(colorMap(elementValue(currentElement(), vReference)), vReference), 1.0);
#endif
}
