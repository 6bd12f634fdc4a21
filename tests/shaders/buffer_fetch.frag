// Texel x + uRow * width of a buffer texture into the red channel: reads the same whichever way the kit stored it.
#include "gsv/buffer_fetch.glsl"

uniform BUFFER_SAMPLER uValues;
uniform int uRow;

out vec4 fColor;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    fColor = vec4(bufferFetch(uValues, pixel.x + (pixel.y + uRow) * 64).r, 0.0, 0.0, 1.0);
}
