// Lab 07's measurements: the value itself, not its colour, with where it was evaluated: value, xi, eta and
// element + 1 (0: no element here), into a float target.
#include "spectral.glsl"

in vec2 vReference;
out vec4 fColor;

void main() {
    int element = currentElement();
    fColor = vec4(elementValue(element, vReference), vReference, float(element + 1));
}
