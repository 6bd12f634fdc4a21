// A triangle in the kit's own names (aVertex, uModelViewProjectionMatrix): builds in both profiles.
out vec3 vNormal;
out vec2 vTexCoord;
void main() {
    vNormal = uNormalMatrix * aNormal;
    vTexCoord = aTexCoord0.st;
    gl_Position = uModelViewProjectionMatrix * aVertex;
}
