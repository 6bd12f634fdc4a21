// Lab 07: every fragment evaluates its element's polynomial at its reference point and colour-maps it.
#include "colour_map.glsl"
#include "element_edges.glsl"
#include "spectral.glsl"

in vec2 vReference;
out vec4 fColor;

void main() {
    fColor = vec4(with_element_edges(colour_map(element_value(current_element(), vReference)), vReference), 1.0);
}
