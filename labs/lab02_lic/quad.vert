// Lab 02 vertex stage: a full-screen quad; the texture coordinate names the pixel's point in the field.
out vec2 vTexCoord;

void main() {
    vTexCoord = aVertex.xy * 0.5 + 0.5;
    gl_Position = vec4(aVertex.xy, 0.0, 1.0);
}
