// The Lagrange basis, an element's polynomial and the Lebesgue constant, in double.
#include "reference/spectral/lagrange_basis.h"

#include "common/core/error.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

namespace gsv {

std::vector<double> lagrange_basis(const std::vector<double>& nodes, const std::vector<double>& weights, double x) {
    std::vector<double> l(nodes.size(), 0.0);
    for (std::size_t j = 0; j < nodes.size(); ++j)
        if (x == nodes[j]) {
            l[j] = 1.0;
            return l;
        }
    double sum = 0;
    for (std::size_t j = 0; j < nodes.size(); ++j) {
        l[j] = weights[j] / (x - nodes[j]);
        sum += l[j];
    }
    for (double& v : l) v /= sum;
    return l;
}

double lagrange_interpolate(const std::vector<double>& nodes, const std::vector<double>& weights,
                            const std::vector<double>& values, double x) {
    const std::vector<double> l = lagrange_basis(nodes, weights, x);
    double sum = 0;
    for (std::size_t j = 0; j < l.size(); ++j) sum += values.at(j) * l[j];
    return sum;
}

double lebesgue_constant(NodeSet set, int degree, int samples) {
    const std::vector<double> x = lagrange_nodes(set, degree);
    const std::vector<double> w = barycentric_weights(x);
    std::vector<double> points;
    for (int i = 0; i <= samples; ++i) points.push_back(-1.0 + 2.0 * i / samples);
    for (std::size_t j = 0; j + 1 < x.size(); ++j) points.push_back(0.5 * (x[j] + x[j + 1]));
    double worst = 0;
    for (double t : points) {
        double sum = 0;
        for (double l : lagrange_basis(x, w, t)) sum += std::abs(l);
        worst = std::max(worst, sum);
    }
    return worst;
}

double evaluate_element(const std::vector<float>& values, const std::vector<double>& nodes,
                        const std::vector<double>& weights, int element, double xi, double eta) {
    const std::size_t n = nodes.size();
    const std::size_t base = static_cast<std::size_t>(element) * n * n;
    if (element < 0 || base + n * n > values.size())
        throw Error("element " + std::to_string(element) + " has no values (" + std::to_string(values.size()) + " values)");
    const std::vector<double> lx = lagrange_basis(nodes, weights, xi);
    const std::vector<double> ly = lagrange_basis(nodes, weights, eta);
    double sum = 0;
    for (std::size_t j = 0; j < n; ++j)
        for (std::size_t i = 0; i < n; ++i) sum += static_cast<double>(values[base + j * n + i]) * lx[i] * ly[j];
    return sum;
}

double evaluate_corners(const std::vector<float>& values, int degree, int element, double xi, double eta) {
    const std::size_t n = static_cast<std::size_t>(degree) + 1;
    const std::size_t base = static_cast<std::size_t>(element) * n * n;
    if (element < 0 || base + n * n > values.size())
        throw Error("element " + std::to_string(element) + " has no values (" + std::to_string(values.size()) + " values)");
    const double u = 0.5 * (xi + 1.0), v = 0.5 * (eta + 1.0);
    const double f00 = values[base], f10 = values[base + n - 1];
    const double f01 = values[base + (n - 1) * n], f11 = values[base + n * n - 1];
    return (1 - v) * ((1 - u) * f00 + u * f10) + v * ((1 - u) * f01 + u * f11);
}

}  // namespace gsv
