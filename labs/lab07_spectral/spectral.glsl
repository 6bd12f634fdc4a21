// Lab 07: a spectral element's field at one point of its reference square, from the element's node values.
// DEGREE (a compile-time parameter) fixes the number of nodes per axis, so every loop has a constant bound.
#pragma once
#include "gsv/buffer_fetch.glsl"
#include "gsv/not_done.glsl"

const int kNodes = DEGREE + 1;

// The nodes x_i and their barycentric weights w_i: 8 bytes a node, whatever the number of elements.
// Uniforms rather than a texture: on llvmpipe two texel fetches a node cost a fifth of the frame at degree 4.
uniform float uNodes[kNodes];
uniform float uWeights[kNodes];
// Every element's (DEGREE + 1)^2 values, element by element, then rows of nodes (eta), xi fastest.
uniform BUFFER_SAMPLER uValues;

// l_i(x) for i = 0 .. DEGREE, the Lagrange basis on the nodes.
void lagrangeBasis(float x, out float l[kNodes]) {
    // TODO(L07-T1): the barycentric formula l_i(x) = (w_i / (x - x_i)) / sum_k (w_k / (x - x_k)). Where x
    // is exactly a node, l is 1 there and 0 elsewhere: return that before anything divides by x - x_i = 0.
    for (int i = 0; i < kNodes; ++i) l[i] = 0.0;
}

float nodeValue(int element, int i, int j) {
    return bufferFetch(uValues, (element * kNodes + j) * kNodes + i).r;
}

// The field at reference point r = (xi, eta) of the element.
float elementValue(int element, vec2 r) {
#ifdef EVALUATION_CORNERS
    // TODO(L07-T4): what a quad drawn from its corners shows: the bilinear blend of the four corner values
    // (nodes (0, 0), (DEGREE, 0), (0, DEGREE), (DEGREE, DEGREE)), with (xi, eta) = (-1, -1) at the first.
    return 0.0;
#else
    // TODO(L07-T2): the tensor product: the sum over i and j of nodeValue(element, i, j) l_i(xi) l_j(eta).
    return 0.0;
#endif
}

#ifdef GSV_NO_PRIMITIVE_ID
// OpenGL ES before 3.2 has no gl_PrimitiveID here: element.vert sends the element, flat (every vertex of an
// element's triangles is that element's own, so whichever vertex GL takes it from names the same element).
flat in int vElement;

int currentElement() { return vElement; }
#else
// Each element is drawn as the same number of triangles, in element order.
uniform int uTrianglesPerElement;

int currentElement() { return gl_PrimitiveID / max(uTrianglesPerElement, 1); }
#endif
