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
//@solution L07-T1
    float sum = 0.0;
    for (int i = 0; i < kNodes; ++i) {
        float d = x - uNodes[i];
        if (d == 0.0) {
            for (int k = 0; k < kNodes; ++k) l[k] = 0.0;
            l[i] = 1.0;
            return;
        }
        l[i] = uWeights[i] / d;
        sum += l[i];
    }
    for (int i = 0; i < kNodes; ++i) l[i] /= sum;
//@starter
//    for (int i = 0; i < kNodes; ++i) l[i] = 0.0;
//@end
}

float nodeValue(int element, int i, int j) {
    return bufferFetch(uValues, (element * kNodes + j) * kNodes + i).r;
}

// The field at reference point r = (xi, eta) of the element.
float elementValue(int element, vec2 r) {
#ifdef EVALUATION_CORNERS
    // TODO(L07-T4): what a quad drawn from its corners shows: the bilinear blend of the four corner values
    // (nodes (0, 0), (DEGREE, 0), (0, DEGREE), (DEGREE, DEGREE)), with (xi, eta) = (-1, -1) at the first.
//@solution L07-T4
    vec2 t = 0.5 * (r + 1.0);
    float bottom = mix(nodeValue(element, 0, 0), nodeValue(element, DEGREE, 0), t.x);
    float top = mix(nodeValue(element, 0, DEGREE), nodeValue(element, DEGREE, DEGREE), t.x);
    return mix(bottom, top, t.y);
//@starter
//    return 0.0;
//@end
#else
    // TODO(L07-T2): the tensor product: the sum over i and j of nodeValue(element, i, j) l_i(xi) l_j(eta).
//@solution L07-T2
    float lx[kNodes], ly[kNodes];
    lagrangeBasis(r.x, lx);
    lagrangeBasis(r.y, ly);
    float sum = 0.0;
    for (int j = 0; j < kNodes; ++j) {
        float row = 0.0;
        for (int i = 0; i < kNodes; ++i) row += nodeValue(element, i, j) * lx[i];
        sum += row * ly[j];
    }
    return sum;
//@starter
//    return 0.0;
//@end
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
