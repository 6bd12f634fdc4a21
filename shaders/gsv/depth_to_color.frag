// A depth buffer as colour: OpenGL ES reads back colour only (glReadPixels of GL_DEPTH_COMPONENT is desktop
// GL's), so LabKit::read_depth draws the depth texture into a float target with this and reads that.
uniform sampler2D uDepth;

out vec4 fColor;

void main() {
    fColor = vec4(texelFetch(uDepth, ivec2(gl_FragCoord.xy), 0).r, 0.0, 0.0, 1.0);
}
