in vec3 vNormal;
in vec2 vTexCoord;
uniform vec3 uColor;
out vec4 fColor;
void main() {
    // Encodes the interpolated inputs so a test can see that every built-in was fed.
    fColor = vec4(uColor.r, vTexCoord, 0.5 + 0.5 * normalize(vNormal).z);
}
