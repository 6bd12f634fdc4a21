// Lab 07: an element's patch. The reference coordinates (xi, eta) travel to the fragments, which evaluate
// the element's polynomial there; the positions only place the (possibly curved) element.
out vec2 vReference;

void main() {
    vReference = aTexCoord0.xy;
    gl_Position = uModelViewProjectionMatrix * vec4(aVertex.xyz, 1.0);
}
