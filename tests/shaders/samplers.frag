// For the texture-unit test: a 2D sampler, a 3D sampler and an array of 2D samplers, each read so none is dropped.
in vec2 vTexCoord;
uniform sampler2D uFirst;
uniform sampler3D uVolume;
uniform sampler2D uLayers[3];
out vec4 fColor;
void main() {
    vec4 sum = texture(uFirst, vTexCoord) + texture(uVolume, vec3(vTexCoord, 0.5));
    for (int k = 0; k < 3; ++k) sum += texture(uLayers[k], vTexCoord) * float(k + 1);
    fColor = sum;
}
