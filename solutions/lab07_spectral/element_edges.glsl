// Lab 07: a thin dark line where xi or eta reaches -1 or 1, about one pixel wide whatever the zoom, when
// the element_edges effect is on.
#pragma once

vec3 withElementEdges(vec3 color, vec2 reference) {
#ifdef EFFECT_ELEMENT_EDGES
    vec2 edge = (1.0 - abs(reference)) / max(fwidth(reference), vec2(1e-8));
    color *= mix(0.25, 1.0, clamp(min(edge.x, edge.y), 0.0, 1.0));
#endif
    return color;
}
