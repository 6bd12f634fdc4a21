// gsv-ceilings: storage-buffer bandwidth, the particle lab's access (vec4s read and written in index order), as a
// copy: 32 bytes an item. A fixed grid of GROUPS work groups strides over the items, so that no count needs
// splitting over a second axis.
layout(local_size_x = 128) in;
uniform uint uCount;
layout(std430, binding = 0) readonly buffer Source { vec4 source[]; };
layout(std430, binding = 1) writeonly buffer Target { vec4 target[]; };

void main() {
    const uint stride = uint(GROUPS) * 128u;
    for (uint i = gl_GlobalInvocationID.x; i < uCount; i += stride) target[i] = source[i];
}
