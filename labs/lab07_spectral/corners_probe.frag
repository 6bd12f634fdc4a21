// Lab 07: the same patches drawn from each element's corner values only, whatever `evaluation` says, and
// otherwise as element.frag draws them (edges included): what the full evaluation's frame time is
// measured against.
#ifndef EVALUATION_CORNERS
#define EVALUATION_CORNERS 1
#endif
#include "color_map.glsl"
#include "element_edges.glsl"
#include "spectral.glsl"

in vec2 vReference;
out vec4 fColor;

void main() {
    fColor = vec4(withElementEdges(colorMap(elementValue(currentElement(), vReference)), vReference), 1.0);
}
