// gsv-ceilings: texelFetch from an R32F buffer texture in a fragment shader, FETCHES a fragment, as lab 07 reads its
// node values (spectral.glsl's nodeValue: bufferFetch of (element * n + j) * n + i, in loops of constant bounds).
// Lab 07's fragments of one element all read that element's n^2 values, consecutive in the buffer, and the next
// element's are the next n^2. Here every fragment of a TILE x TILE block of pixels reads the same FETCHES consecutive
// texels, and the next block the next FETCHES (the buffer walked through block by block, wrapping at BUFFER_TEXELS):
// the same access, at its best. Neighbouring fragments read one address together (a GPU's warp broadcasts it), a
// fragment's lookups share cache lines, a block's come from the cache, and the loop's count is a constant (unrolled,
// as lab 07's are): nothing a frame of such lookups could do goes faster, so the rate is a ceiling.
// Summed into the colour, so that no lookup is dead code.
#include "gsv/buffer_fetch.glsl"

uniform BUFFER_SAMPLER uValues;
out vec4 fColor;

void main() {
    const int blocksAcross = (SIDE + TILE - 1) / TILE;
    ivec2 block = ivec2(gl_FragCoord.xy) / TILE;
    int first = ((block.y * blocksAcross + block.x) * FETCHES) % BUFFER_TEXELS;
    float sum = 0.0;
    for (int i = 0; i < FETCHES; ++i) sum += bufferFetch(uValues, first + i).r;
    fColor = vec4(sum * (1.0 / float(FETCHES)));
}
