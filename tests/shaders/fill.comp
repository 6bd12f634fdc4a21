// Writes each invocation's index into a storage buffer: the smallest compute shader, for version checks.
layout(local_size_x = 64) in;

layout(std430, binding = 0) buffer Values {
    float values[];
};

void main() {
    values[gl_GlobalInvocationID.x] = float(gl_GlobalInvocationID.x);
}
