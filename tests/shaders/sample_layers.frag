// Samples a 2D array at an integer layer and a 3D texture at the matching slice centre.
in vec2 vTexCoord;
uniform sampler2DArray uArray;
uniform sampler3D uVolume;
uniform float uLayer;
uniform float uDepth;
out vec4 fColor;
void main() {
    float from_array = texture(uArray, vec3(vTexCoord, uLayer)).r;
    float from_volume = texture(uVolume, vec3(vTexCoord, (uLayer + 0.5) / uDepth)).r;
    fColor = vec4(from_array, from_volume, 0.0, 1.0);
}
