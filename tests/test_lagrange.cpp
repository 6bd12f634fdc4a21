// Lab 07's interpolation and meshes on the CPU (support/spectral/lagrange.h, support/spectral/spectral_mesh.h): the node sets,
// barycentric evaluation exact at the nodes with no 0/0, the Lebesgue constants that separate GLL from
// equispaced nodes, and the element layout the shaders read.
#include "catch.hpp"

#include "common/core/error.h"
#include "reference/spectral/lagrange_basis.h"
#include "support/spectral/lagrange.h"
#include "support/spectral/spectral_mesh.h"

#include <cmath>
#include <limits>

using namespace gsv;

namespace {

// P'_p(x) by the recurrence for P and the identity (1 - x^2) P'_p = p (P_{p-1} - x P_p).
double legendre_derivative(int p, double x) {
    double previous = 1.0, current = x;
    for (int k = 2; k <= p; ++k) {
        const double next = ((2.0 * k - 1.0) * x * current - (k - 1.0) * previous) / k;
        previous = current;
        current = next;
    }
    return p * (previous - x * current) / (1.0 - x * x);
}

}  // namespace

TEST_CASE("lagrange: GLL nodes are the endpoints and the roots of P'_p, ascending and exactly symmetric", "[unit][spectral]") {
    for (int p = 1; p <= kMaxLagrangeDegree; ++p) {
        INFO("degree " << p);
        const std::vector<double> x = lagrange_nodes(NodeSet::GaussLobattoLegendre, p);
        REQUIRE(x.size() == static_cast<std::size_t>(p + 1));
        CHECK(x.front() == -1.0);
        CHECK(x.back() == 1.0);
        for (int j = 0; j < p; ++j) CHECK(x[j] < x[j + 1]);
        for (int j = 0; j <= p; ++j) CHECK(x[j] == -x[p - j]);
        for (int j = 1; j < p; ++j) CHECK(std::abs(legendre_derivative(p, x[j])) < 1e-11 * p * p);
    }
    // Known values: degree 3, +-1/sqrt(5); degree 4, 0 and +-sqrt(3/7).
    CHECK(lagrange_nodes(NodeSet::GaussLobattoLegendre, 3)[1] == Approx(-1.0 / std::sqrt(5.0)).epsilon(1e-15));
    CHECK(lagrange_nodes(NodeSet::GaussLobattoLegendre, 4)[3] == Approx(std::sqrt(3.0 / 7.0)).epsilon(1e-15));
    CHECK(lagrange_nodes(NodeSet::GaussLobattoLegendre, 4)[2] == 0.0);
    CHECK(lagrange_nodes(NodeSet::Equispaced, 4) == std::vector<double>{-1.0, -0.5, 0.0, 0.5, 1.0});
    CHECK_THROWS_WITH(lagrange_nodes(NodeSet::Equispaced, 0), "Lagrange degree 0 is out of range [1, 24]");
    CHECK_THROWS_WITH(parse_node_set("chebyshev"), "unknown node set 'chebyshev' (known: gll, equispaced)");
}

TEST_CASE("lagrange: the Lebesgue constant at degree 16 is 934.5 on equispaced nodes and 2.47 on GLL nodes", "[unit][spectral]") {
    CHECK(lebesgue_constant(NodeSet::Equispaced, 16) == Approx(934.53).epsilon(1e-4));
    CHECK(lebesgue_constant(NodeSet::GaussLobattoLegendre, 16) == Approx(2.4684).epsilon(1e-4));
    // GLL grows like log p, equispaced like 2^p / (p log p).
    CHECK(lebesgue_constant(NodeSet::GaussLobattoLegendre, 24) < 3.0);
    CHECK(lebesgue_constant(NodeSet::Equispaced, 24) > 1e5);
    CHECK(lebesgue_constant(NodeSet::Equispaced, 1) == Approx(1.0));
}

TEST_CASE("lagrange: at a node the basis is exactly that node's unit vector, with no 0/0", "[unit][spectral]") {
    for (NodeSet set : {NodeSet::GaussLobattoLegendre, NodeSet::Equispaced})
        for (int p : {1, 2, 5, 16, 24}) {
            const auto x = lagrange_nodes(set, p);
            const auto w = barycentric_weights(x);
            for (int j = 0; j <= p; ++j) {
                const auto l = lagrange_basis(x, w, x[j]);
                for (int k = 0; k <= p; ++k) CHECK(l[k] == (k == j ? 1.0 : 0.0));
            }
        }
}

TEST_CASE("lagrange: next to a node the basis stays finite and tends to the node's unit vector", "[unit][spectral]") {
    const auto x = lagrange_nodes(NodeSet::GaussLobattoLegendre, 8);
    const auto w = barycentric_weights(x);
    for (double offset : {1e-300, std::numeric_limits<double>::denorm_min(), 1e-17, 1e-9}) {
        const auto l = lagrange_basis(x, w, x[3] + offset);
        double sum = 0;
        for (double v : l) {
            CHECK(std::isfinite(v));
            sum += v;
        }
        CHECK(sum == Approx(1.0).epsilon(1e-12));
        CHECK(l[3] == Approx(1.0).epsilon(1e-6));
    }
}

TEST_CASE("lagrange: polynomials up to the degree are reproduced to rounding, and Runge's function is not on equispaced nodes", "[unit][spectral]") {
    auto cubic = [](double t) { return 2 * t * t * t - t * t + 0.25 * t - 3; };
    auto runge = [](double t) { return 1.0 / (1.0 + 25.0 * t * t); };
    for (NodeSet set : {NodeSet::GaussLobattoLegendre, NodeSet::Equispaced})
        for (int p = 3; p <= 12; ++p) {
            const auto x = lagrange_nodes(set, p);
            const auto w = barycentric_weights(x);
            std::vector<double> f;
            for (double t : x) f.push_back(cubic(t));
            for (double t = -1.0; t <= 1.0; t += 0.0137) CHECK(lagrange_interpolate(x, w, f, t) == Approx(cubic(t)).margin(1e-12));
        }
    auto worst_error = [&](NodeSet set, int p) {
        const auto x = lagrange_nodes(set, p);
        const auto w = barycentric_weights(x);
        std::vector<double> f;
        for (double t : x) f.push_back(runge(t));
        double worst = 0;
        for (double t = -1.0; t <= 1.0; t += 0.001) worst = std::max(worst, std::abs(lagrange_interpolate(x, w, f, t) - runge(t)));
        return worst;
    };
    CHECK(worst_error(NodeSet::Equispaced, 16) > 10.0);
    CHECK(worst_error(NodeSet::GaussLobattoLegendre, 16) < 0.05);
    CHECK(worst_error(NodeSet::GaussLobattoLegendre, 24) < worst_error(NodeSet::GaussLobattoLegendre, 16));
}

TEST_CASE("spectral mesh: values lie element by element, xi fastest, and evaluate back exactly at the nodes", "[unit][spectral]") {
    ElementMesh mesh;
    mesh.columns = 5;
    mesh.rows = 3;
    const int p = 4;
    const auto x = lagrange_nodes(NodeSet::GaussLobattoLegendre, p);
    const auto w = barycentric_weights(x);
    const std::vector<float> values = sample_element_values(mesh, SpectralField::Waves, x, 0.7);
    REQUIRE(values.size() == static_cast<std::size_t>(15 * 25));
    for (int e : {0, 7, 14})
        for (int j = 0; j <= p; ++j)
            for (int i = 0; i <= p; ++i) {
                const float expected = static_cast<float>(spectral_field(SpectralField::Waves, mesh.position(e, x[i], x[j]), 0.7));
                CHECK(values[(e * 5 + j) * 5 + i] == expected);
                CHECK(evaluate_element(values, x, w, e, x[i], x[j]) == static_cast<double>(expected));
            }
    // Corners: the bilinear blend equals the corner values at the corners and their mean at the centre.
    CHECK(evaluate_corners(values, p, 7, -1, -1) == Approx(values[7 * 25]));
    CHECK(evaluate_corners(values, p, 7, 1, 1) == Approx(values[7 * 25 + 24]));
    CHECK(evaluate_corners(values, p, 7, 0, 0) ==
          Approx(0.25 * (values[7 * 25] + values[7 * 25 + 4] + values[7 * 25 + 20] + values[7 * 25 + 24])));
    // A degree-3 field on degree-3 elements is the field itself, up to float rounding of the values.
    ElementMesh grid;
    grid.shape = ElementMesh::Shape::Grid;
    grid.columns = grid.rows = 2;
    const auto x3 = lagrange_nodes(NodeSet::Equispaced, 3);
    const auto w3 = barycentric_weights(x3);
    const std::vector<float> cubic = sample_element_values(grid, SpectralField::Polynomial, x3, 0);
    for (int e = 0; e < 4; ++e)
        for (double xi : {-0.9, -0.31, 0.5, 0.77})
            CHECK(evaluate_element(cubic, x3, w3, e, xi, -xi / 2) ==
                  Approx(spectral_field(SpectralField::Polynomial, grid.position(e, xi, -xi / 2), 0)).margin(1e-6));
}

TEST_CASE("spectral mesh: annulus elements follow the ring, neighbours share their edges, and patches are in element order", "[unit][spectral]") {
    ElementMesh mesh;
    mesh.columns = 8;
    mesh.rows = 2;
    for (int e = 0; e < mesh.element_count(); ++e)
        for (double xi : {-1.0, 0.0, 1.0})
            for (double eta : {-1.0, 1.0}) {
                const double r = glm::length(mesh.position(e, xi, eta));
                CHECK(r == Approx(e / 8 == 0 ? (eta < 0 ? 0.35 : 0.675) : (eta < 0 ? 0.675 : 1.0)));
            }
    // Element 0's right edge is element 1's left edge; the last column closes the ring onto the first.
    CHECK(glm::length(mesh.position(0, 1, 0.3) - mesh.position(1, -1, 0.3)) < 1e-15);
    CHECK(glm::length(mesh.position(7, 1, 0.3) - mesh.position(0, -1, 0.3)) < 1e-15);
    const MeshData patches = element_patches(mesh, 3);
    CHECK(patches.triangle_count() == static_cast<std::size_t>(16 * 2 * 9));
    CHECK(patches.positions.size() == static_cast<std::size_t>(16 * 16));
    // The edges carry xi and eta of exactly -1 and 1.
    CHECK(patches.texcoords[0] == glm::vec2(-1.0f, -1.0f));
    CHECK(patches.texcoords[15] == glm::vec2(1.0f, 1.0f));
    // Element e's triangles come as the e-th block: their vertices are e's.
    for (std::size_t t = 0; t < patches.triangle_count(); ++t)
        CHECK(patches.indices[3 * t] / 16 == t / 18);
    CHECK_THROWS_WITH(element_patches(mesh, 0), "element subdivisions = 0 is out of range [1, 64]");
    ElementMesh bad = mesh;
    bad.inner = 1.5;
    CHECK_THROWS_WITH(validate(bad), Catch::Contains("need 0 <= inner < outer"));
    bad = mesh;
    bad.columns = 0;
    CHECK_THROWS_WITH(validate(bad), "element columns = 0 is out of range [1, 4096]");
    CHECK_THROWS_WITH(parse_spectral_field("sine"), "unknown field 'sine' (known: waves, runge, polynomial)");
}
