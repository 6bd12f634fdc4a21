// Samples a 3D texture at the middle of s and t and at r = uR.
uniform sampler3D uVolume;
uniform float uR;
out vec4 fColor;
void main() {
    fColor = vec4(texture(uVolume, vec3(0.5, 0.5, uR)).r, 0.0, 0.0, 1.0);
}
