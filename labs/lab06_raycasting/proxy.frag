// Lab 06: writes the interpolated texture coordinate as the colour, alpha 1: "a ray enters (or leaves)
// here". Pixels the geometry does not cover keep the clear colour's alpha 0: no ray.
in vec3 vTexturePosition;
out vec4 fColor;

void main() { fColor = vec4(vTexturePosition, 1.0); }
