// For the change-tracking test: uShade is used, uIgnored is declared but dropped by the compiler.
in vec2 vTexCoord;
uniform float uShade;
uniform float uIgnored;
out vec4 fColor;
void main() {
#ifdef EFFECT_GLOW
    fColor = vec4(uShade, 1.0, 0.0, 1.0);
#else
    fColor = vec4(uShade, 0.0, 0.0, 1.0);
#endif
}
