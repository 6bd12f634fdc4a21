#pragma once
// Lab 07's polynomial evaluated on the CPU, in double: the Lagrange basis by the barycentric formula (L07-T1),
// an element's value from its node values (L07-T2) and from its corners only (L07-T4), and the Lebesgue
// constant the slides quote. The instructor's yardstick of the lab's fragment shader, kept out of support/ so
// that no student's copy holds the answers.
#include "support/spectral/lagrange.h"
#include "support/spectral/spectral_mesh.h"

#include <vector>

namespace gsv {

// Every l_j(x), j = 0 .. p, by the second (true) barycentric formula
//   l_j(x) = (w_j / (x - x_j)) / sum_k (w_k / (x - x_k)),
// except where x equals a node exactly: there l_j is 1 at that node and 0 elsewhere, which is the limit,
// and 0/0 is never formed. Away from the nodes the sum of the l_j is 1 to rounding. `x` may lie outside
// [-1, 1] (extrapolation).
std::vector<double> lagrange_basis(const std::vector<double>& nodes, const std::vector<double>& weights, double x);

// sum_j values[j] l_j(x).
double lagrange_interpolate(const std::vector<double>& nodes, const std::vector<double>& weights,
                            const std::vector<double>& values, double x);

// max over [-1, 1] of sum_j |l_j(x)|, sampled at `samples` evenly spaced points plus the midpoints between
// neighbouring nodes (where the maximum of each lobe lies closely for these sets): how much interpolation
// can amplify an error in the values.
double lebesgue_constant(NodeSet set, int degree, int samples = 20000);

// sum_ij values(e, j, i) l_i(xi) l_j(eta) in double, from the float values: what the GPU's per-fragment
// evaluation computes, without its float32 arithmetic.
double evaluate_element(const std::vector<float>& values, const std::vector<double>& nodes,
                        const std::vector<double>& weights, int element, double xi, double eta);

// The bilinear blend of the element's four corner values: what drawing the quad from its corners shows.
double evaluate_corners(const std::vector<float>& values, int degree, int element, double xi, double eta);

}  // namespace gsv
