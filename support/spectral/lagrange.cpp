#include "support/spectral/lagrange.h"

#include "common/core/enum_names.h"
#include "common/core/error.h"

#include <algorithm>
#include <cmath>

namespace gsv {
namespace {

const double kPi = 3.14159265358979323846;

void check_degree(int degree) {
    if (degree < 1 || degree > kMaxLagrangeDegree)
        throw Error("Lagrange degree " + std::to_string(degree) + " is out of range [1, " + std::to_string(kMaxLagrangeDegree) + "]");
}

// Interior Gauss-Lobatto-Legendre nodes by Newton's method on q(x) = x P_p(x) - P_{p-1}(x), which is
// (1 - x^2) P'_p(x) / p up to a factor and vanishes exactly at all p + 1 nodes, starting from the
// Chebyshev-Gauss-Lobatto points -cos(pi j / p) that lie close to them.
std::vector<double> gll_nodes(int p) {
    std::vector<double> x(static_cast<std::size_t>(p) + 1);
    for (int j = 0; j <= p; ++j) x[j] = -std::cos(kPi * j / p);
    for (int j = 1; j < p; ++j) {
        double xi = x[j];
        for (int iteration = 0; iteration < 100; ++iteration) {
            // P_k by the three-term recurrence; P_{p+1} gives q's derivative: q'(x) = (p + 1) P_p(x).
            double previous = 1.0, current = xi;
            for (int k = 2; k <= p; ++k) {
                const double next = ((2.0 * k - 1.0) * xi * current - (k - 1.0) * previous) / k;
                previous = current;
                current = next;
            }
            const double step = (xi * current - previous) / ((p + 1.0) * current);
            xi -= step;
            if (std::abs(step) < 1e-16) break;
        }
        x[j] = xi;
    }
    return x;
}

}  // namespace

const char* name_of(NodeSet set) { return name_of(kNodeSetNames, set); }
NodeSet parse_node_set(const std::string& name) { return parse_enum(kNodeSetNames, "node set", name); }

std::vector<double> lagrange_nodes(NodeSet set, int degree) {
    check_degree(degree);
    std::vector<double> x = set == NodeSet::GaussLobattoLegendre ? gll_nodes(degree) : std::vector<double>(degree + 1);
    if (set == NodeSet::Equispaced)
        for (int j = 0; j <= degree; ++j) x[j] = -1.0 + 2.0 * j / degree;
    // Exact endpoints and exact symmetry: a fragment at the centre of an element meets the middle node as
    // exactly 0, and mirrored elements evaluate alike.
    for (int j = 0; j <= degree / 2; ++j) {
        const double half = 0.5 * (x[degree - j] - x[j]);
        x[j] = -half;
        x[degree - j] = half;
    }
    x.front() = -1.0;
    x.back() = 1.0;
    if (degree % 2 == 0) x[degree / 2] = 0.0;
    return x;
}

std::vector<double> barycentric_weights(const std::vector<double>& nodes) {
    if (nodes.size() < 2) throw Error("barycentric weights need at least two nodes");
    std::vector<double> w(nodes.size(), 1.0);
    for (std::size_t j = 0; j < nodes.size(); ++j)
        for (std::size_t k = 0; k < nodes.size(); ++k) {
            if (k == j) continue;
            const double d = nodes[j] - nodes[k];
            if (d == 0.0) throw Error("barycentric weights: nodes " + std::to_string(j) + " and " + std::to_string(k) + " are equal");
            w[j] /= d;
        }
    double largest = 0;
    for (double v : w) largest = std::max(largest, std::abs(v));
    for (double& v : w) v /= largest;
    return w;
}

}  // namespace gsv
