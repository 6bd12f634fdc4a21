#pragma once
// Lagrange interpolation on one axis of a spectral element: the node sets, barycentric weights, and an
// evaluation that is exact at the nodes and never divides by zero. Lab 07 evaluates the same formula per
// fragment; this is its double-precision reference.
//
// Convention: "degree p" means a polynomial of degree p per axis, through p + 1 nodes per axis, (p + 1)^2
// values per 2D element. (The seed, Peng and Forsberg 2002, counts n + 2 points per axis for "order n":
// its order n is degree n + 1 here.)
#include <string>
#include <vector>

namespace gsv {

enum class NodeSet {
    GaussLobattoLegendre,  // the endpoints and the roots of P'_p: the spectral element method's nodes
    Equispaced,            // -1 + 2 j / p: Runge's phenomenon at high degree
};

const char* name_of(NodeSet set);              // "gll", "equispaced"
NodeSet parse_node_set(const std::string& name);  // throws gsv::Error naming the known ones

// Degrees 1 .. kMaxLagrangeDegree: beyond it equispaced weights span more than float32 can hold.
inline constexpr int kMaxLagrangeDegree = 24;

// The p + 1 nodes on [-1, 1], ascending, with x_0 = -1 and x_p = 1 exactly and x_{p-j} = -x_j exactly.
// Throws gsv::Error for a degree outside 1 .. kMaxLagrangeDegree.
std::vector<double> lagrange_nodes(NodeSet set, int degree);

// w_j = 1 / prod_{k != j} (x_j - x_k), scaled so that the largest |w_j| is 1 (the barycentric formula
// divides the scale out; float32 then holds them at any degree here). Throws gsv::Error for fewer than two
// nodes or two equal nodes.
std::vector<double> barycentric_weights(const std::vector<double>& nodes);

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

}  // namespace gsv
