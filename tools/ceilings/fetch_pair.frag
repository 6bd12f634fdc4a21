// gsv-ceilings: lookups of two textures taking turns, shaped as LIC's loop is (lab 02, lab 03): a step reads the flow
// (uFlow) where the streamline is, moves by what it read, then reads the input (uInput) there, FETCHES lookups a
// fragment in all. One format's benchmark alone (fetch.frag) is not the most a frame of two formats can do: on
// llvmpipe LIC's two formats together ran faster than either's benchmark, so a pair is measured as the labs read it.
// FLOW_2D, FLOW_ARRAY or FLOW_3D picks the flow's sampler; the input is a 2D texture.
#if defined(FLOW_3D)
uniform sampler3D uFlow;
#elif defined(FLOW_ARRAY)
uniform sampler2DArray uFlow;
#else
uniform sampler2D uFlow;
#endif
uniform sampler2D uInput;
uniform int uSteps;  // FETCHES / 2, in a uniform: the loop is not unrolled, as LIC's (uLength) is not
uniform vec3 uStep;  // a texel along a slanted direction, in texture coordinates

in vec2 vTexCoord;
out vec4 fColor;

vec4 flowAt(vec3 p) {
#if defined(FLOW_3D)
    return texture(uFlow, p);
#elif defined(FLOW_ARRAY)
    return texture(uFlow, vec3(p.xy, 0.0));
#else
    return texture(uFlow, p.xy);
#endif
}

void main() {
    vec4 sum = vec4(0.0);
    vec3 p = vec3(vTexCoord, 0.5);
    for (int i = 0; i < uSteps; ++i) {
        // The texels hold values in [0, 1): each step moves up to half a texel, by what the flow read (the next
        // lookup waits on this one, as a streamline's does), so the path wanders near its pixel and the caches hold
        // it. Measured on llvmpipe, this ran about 1.4x a fixed direction's steps of a sixteenth of a texel.
        p.xy += uStep.xy * (flowAt(p).xy - 0.5);
        sum += texture(uInput, p.xy);
    }
    fColor = sum * (1.0 / float(FETCHES));
}
