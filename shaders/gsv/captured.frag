// The fragment stage of a program whose vertex outputs are captured by transform feedback (ProgramSpec::captured) and
// never rasterised (GL_RASTERIZER_DISCARD): OpenGL ES 3.0 links no program without one. Writes nothing that is seen.
out vec4 fColor;

void main() { fColor = vec4(0.0); }
