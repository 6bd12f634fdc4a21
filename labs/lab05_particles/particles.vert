// Lab 05: each particle a point, read from the storage buffers bound as vertex arrays.
#ifdef EFFECT_COLOR_BY_SPEED
layout(location = 3) in vec4 aColor;  // particle_buffers.h: kColorSlot
#endif

uniform float uPointSize;

out vec3 vColor;

void main() {
    gl_Position = uModelViewProjectionMatrix * vec4(aVertex.xyz, 1.0);
    gl_PointSize = uPointSize;  // ES takes a point's size only from here; desktop GL once GL_PROGRAM_POINT_SIZE is on
#ifdef EFFECT_COLOR_BY_SPEED
    vColor = aColor.rgb;
#else
    vColor = vec3(0.85, 0.88, 0.95);
#endif
}
