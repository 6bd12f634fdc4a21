// Lab 05: a particle's colour, as the compute stage left it.
in vec3 vColour;
out vec4 fColor;

void main() { fColor = vec4(vColour, 1.0); }
