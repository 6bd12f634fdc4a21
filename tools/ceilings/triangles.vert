// gsv-ceilings: the triangle rate's vertex stage: a vertex of make_grid's (x, 0, z) grid over [0, 1]^2 straight to
// its point of the target, z downwards so that the grid's triangles face the viewer (counter-clockwise on screen);
// nothing else computed and nothing passed on (fill.frag colours the fragments).
void main() { gl_Position = vec4(aVertex.x * 2.0 - 1.0, 1.0 - aVertex.z * 2.0, 0.0, 1.0); }
