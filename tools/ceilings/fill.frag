// gsv-ceilings: fill rate, one constant colour a fragment, nothing read.
uniform vec4 uColor;
out vec4 fColor;

void main() { fColor = uColor; }
