// Lab 06: the canvas puts the ray caster's image (premultiplied, transparent where rays saw nothing) over
// the opaque geometry's image, and both over the background. The rays stopped at the geometry (it was
// drawn into the exit points), so nothing behind it shows through.
uniform sampler2D uImage;
uniform sampler2D uGeometryImage;
uniform bool uHasGeometry;
uniform vec3 uBackground;

out vec4 fColor;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 volume = texelFetch(uImage, pixel, 0);
    vec4 behind = vec4(uBackground, 1.0);
    if (uHasGeometry) {
        vec4 geometry = texelFetch(uGeometryImage, pixel, 0);
        if (geometry.a > 0.0) behind = geometry;
    }
    fColor = volume + (1.0 - volume.a) * behind;
}
