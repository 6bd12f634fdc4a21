uniform float uZero;
out vec4 fColor;
void main() {
    // 0/0 from a uniform, so no compiler can fold it away.
    fColor = vec4(uZero / uZero, 0.0, 0.0, 1.0);
}
