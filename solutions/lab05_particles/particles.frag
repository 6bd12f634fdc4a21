// Lab 05: a particle's colour, as the compute stage left it.
in vec3 vColor;
out vec4 fColor;

void main() { fColor = vec4(vColor, 1.0); }
