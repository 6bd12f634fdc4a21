// Lab 07: an element's patch. The reference coordinates (xi, eta) travel to the fragments, which evaluate
// the element's polynomial there; the positions only place the (possibly curved) element.
out vec2 vReference;

#ifdef GSV_NO_PRIMITIVE_ID
// The stand-in for gl_PrimitiveID (spectral.glsl): each element has this many vertices of its own, in
// element order (support/spectral/spectral_mesh.h), so the vertex's number gives its element.
uniform int uVerticesPerElement;
flat out int vElement;
#endif

void main() {
    vReference = aTexCoord0.xy;
#ifdef GSV_NO_PRIMITIVE_ID
    vElement = gl_VertexID / max(uVerticesPerElement, 1);
#endif
    gl_Position = uModelViewProjectionMatrix * vec4(aVertex.xyz, 1.0);
}
