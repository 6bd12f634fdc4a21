// A full-screen quad (make_fullscreen_quad's [-1,1]^2); the texture coordinate names the pixel's point
// in the field or image the fragment stage looks up.
out vec2 vTexCoord;

void main() {
    vTexCoord = aVertex.xy * 0.5 + 0.5;
    gl_Position = vec4(aVertex.xy, 0.0, 1.0);
}
