// Lab 07: every fragment evaluates its element's polynomial at its reference point and colour-maps it.
#include "color_map.glsl"
#include "element_edges.glsl"
#include "spectral.glsl"

in vec2 vReference;
out vec4 fColor;

void main() {
    fColor = vec4(withElementEdges(colorMap(elementValue(currentElement(), vReference)), vReference), 1.0);
}
