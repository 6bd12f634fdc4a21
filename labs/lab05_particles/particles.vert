// Lab 05: each particle a point, read from the storage buffers bound as vertex arrays.
#ifdef EFFECT_COLOUR_BY_SPEED
layout(location = 3) in vec4 aColour;  // particle_buffers.h: kColourSlot
#endif

out vec3 vColour;

void main() {
    gl_Position = uModelViewProjectionMatrix * vec4(aVertex.xyz, 1.0);
#ifdef EFFECT_COLOUR_BY_SPEED
    vColour = aColour.rgb;
#else
    vColour = vec3(0.85, 0.88, 0.95);
#endif
}
