// Lab 06: the proxy geometry (and any opaque geometry drawn into the entry and exit images). Positions are
// volume texture coordinates; the model matrix places them in the volume's box. The colour a face gets
// is its texture coordinate, interpolated: each pixel's entry or exit point.
out vec3 vTexturePosition;

void main() {
    vTexturePosition = aVertex.xyz;
    gl_Position = uModelViewProjectionMatrix * vec4(aVertex.xyz, 1.0);
}
