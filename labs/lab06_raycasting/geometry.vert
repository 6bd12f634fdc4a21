// Lab 06: opaque geometry embedded in the volume (the probe), shaded in its own image. Positions are
// volume texture coordinates, as for the proxy; normals are in model space.
out vec3 vViewNormal;
out vec3 vViewPosition;

void main() {
    vViewNormal = uNormalMatrix * aNormal;
    vViewPosition = (uModelViewMatrix * vec4(aVertex.xyz, 1.0)).xyz;
    gl_Position = uModelViewProjectionMatrix * vec4(aVertex.xyz, 1.0);
}
