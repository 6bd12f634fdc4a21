// Desktop GLSL turns the int into a float; GLSL ES has no implicit conversions, so ES refuses line 5.
out vec4 fColor;

void main() {
    float level = 1;
    fColor = vec4(level);
}
