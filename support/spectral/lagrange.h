#pragma once
// Lagrange interpolation on one axis of a spectral element: the node sets and their barycentric weights, which
// lab 07 uploads. Evaluating the basis with them is the lab's TODO L07-T1; the instructor's double-precision
// yardstick of it is reference/spectral/lagrange_basis.h.
//
// Convention: "degree p" means a polynomial of degree p per axis, through p + 1 nodes per axis, (p + 1)^2
// values per 2D element. (The seed, Peng and Forsberg 2002, counts n + 2 points per axis for "order n":
// its order n is degree n + 1 here.)
#include "common/core/enum_names.h"

#include <string>
#include <vector>

namespace gsv {

enum class NodeSet {
    GaussLobattoLegendre,  // the endpoints and the roots of P'_p: the spectral element method's nodes
    Equispaced,            // -1 + 2 j / p: Runge's phenomenon at high degree
};
inline constexpr EnumName<NodeSet> kNodeSetNames[] = {{NodeSet::GaussLobattoLegendre, "gll"}, {NodeSet::Equispaced, "equispaced"}};

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

}  // namespace gsv
