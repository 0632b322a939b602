// Tests of ltc/fitting/fit_anisotropic.hpp and anisotropic_parameters.hpp: the canonical form
// (invariant under the LTC's own invariances, equivariant under the mirrors and the swap), a
// fitted node and a shipped node integrated over a few polygons against the Monte Carlo ground
// truth within the fit's own error bound, and a small table (3^4, cheap settings) that is the
// same bytes on 1 and 2 threads, with the symmetries built in.
//
// The bound: for any polygon P, |m I_ltc(P) - integral_P f| <= integral |f - m D| = L1 (the
// triangle inequality), L1 estimated by the fit's MIS estimator with 64 x 64 samples per
// distribution and a 25% margin for that estimator's noise; plus 4 standard errors of the
// truth (ground_truth::integrate, 2^15 iterations, fixed seeds).
#include <ltc/brdf/ggx_anisotropic.hpp>
#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/fitting/fit_anisotropic.hpp>
#include <ltc/reference/ground_truth.hpp>
#include <ltc/shading/ggx_anisotropic_fetch.hpp>

#include <catch2/catch.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstring>
#include <vector>

namespace ltc_test_fit_anisotropic {  // the file's own names, apart from the other files of a unity batch

namespace {

using glm::dmat3;
using glm::dvec3;
using ltc::fit::anisotropic_alpha;

dmat3 unit_scale(const dmat3& m) {
    double r = 0;
    for (int c = 0; c < 3; ++c)
        for (int w = 0; w < 3; ++w) r = std::max(r, std::abs(m[c][w]));
    return m / r;
}

double distance(const dmat3& a, const dmat3& b) {
    const dmat3 d = unit_scale(a) - unit_scale(b);
    double r = 0;
    for (int c = 0; c < 3; ++c)
        for (int w = 0; w < 3; ++w) r = std::max(r, std::abs(d[c][w]));
    return r;
}

dmat3 rotation_z(double a) {
    return dmat3(dvec3(std::cos(a), std::sin(a), 0), dvec3(-std::sin(a), std::cos(a), 0), dvec3(0, 0, 1));
}

std::vector<dvec3> square(const dvec3& c, double s) {
    const dvec3 e1 = glm::normalize(glm::cross(dvec3(0, 0, 1), c)), e2 = glm::cross(c, e1);
    return {c - s * e1 - s * e2, c + s * e1 - s * e2, c + s * e1 + s * e2, c - s * e1 + s * e2};
}

/// Checks magnitude * I_ltc against the Monte Carlo truth over three squares, within the bound of
/// the file comment.
void check_against_truth(const dvec3& V, const anisotropic_alpha& a, const dmat3& m_inv, double magnitude, std::uint64_t seed) {
    ltc::fit::anisotropic_sample_set s;
    ltc::fit::make_anisotropic_sample_set<ltc::brdf::ggx_anisotropic>(V, a, glm::inverse(m_inv), 64, s);
    const double l1 = s.all(m_inv, std::abs(glm::determinant(m_inv)), magnitude).l1;
    const auto D = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(m_inv);
    const dvec3 mirror(-V.x, -V.y, V.z);
    const std::vector<dvec3> lights[] = {square(glm::normalize(mirror + dvec3(0, 0, 0.2)), 0.25),
                                         square(glm::normalize(dvec3(0.1, 0.1, 1)), 0.6),
                                         square(glm::normalize(dvec3(-V.y, V.x, 0.7)), 0.35)};
    for (const auto& P : lights) {
        ltc::ground_truth::options opt;
        opt.samples = 1u << 15;
        opt.seed = seed++;
        const auto gt = ltc::ground_truth::integrate(ltc::brdf::ggx_anisotropic<double>{}, V, a, P.data(), P.size(), opt);
        const double ltc_value = magnitude * D.integrate(P.data(), P.size());
        CAPTURE(ltc_value, gt.mean, gt.standard_error, l1);
        CHECK(std::abs(ltc_value - gt.mean) <= 1.25 * l1 + 4 * gt.standard_error);
    }
}

}  // namespace

TEST_CASE("canonical_inverse: one form per LTC, equivariant under the symmetries", "[fit_anisotropic]") {
    const dmat3 m(dvec3(1.3, 0.2, -0.4), dvec3(-0.3, 0.7, 0.25), dvec3(0.5, -0.1, 0.9));
    const dmat3 c = ltc::fit::canonical_inverse(m);
    CHECK(glm::determinant(c) > 0);
    CHECK(std::abs(c[1][0] - c[0][1]) < 1e-14);  // symmetric upper-left block
    CHECK(c[0][0] + c[1][1] == Approx(2.0).epsilon(1e-14));
    // The same LTC: s Q m for a rotation Q about z, for the mirror diag(1, -1, 1), for s > 0.
    for (const double a : {0.3, 2.0, -1.1, 3.1}) {
        CHECK(distance(ltc::fit::canonical_inverse(2.5 * rotation_z(a) * m), c) < 1e-13);
        const dmat3 F(dvec3(1, 0, 0), dvec3(0, -1, 0), dvec3(0, 0, 1));
        CHECK(distance(ltc::fit::canonical_inverse(F * rotation_z(a) * m), c) < 1e-13);
    }
    // A lobe rotated by R (m R^T), mirrored (F m F) or swapped (S m S): the canonical form follows.
    const dmat3 R = rotation_z(0.8);
    CHECK(distance(ltc::fit::canonical_inverse(m * glm::transpose(R)), R * c * glm::transpose(R)) < 1e-13);
    CHECK(distance(ltc::fit::canonical_inverse(ltc::detail::mirror(m, true, false)), ltc::detail::mirror(c, true, false)) < 1e-13);
    CHECK(distance(ltc::fit::canonical_inverse(ltc::detail::swap_xy(m)), ltc::detail::swap_xy(c)) < 1e-13);
    // The stored M: |M e_z| = 1, the inverse of the canonical form up to scale.
    const dmat3 M = ltc::fit::canonical_matrix(c);
    CHECK(glm::length(M[2]) == Approx(1.0).epsilon(1e-14));
    CHECK(distance(glm::inverse(M), c) < 1e-13);
}

TEST_CASE("fit_anisotropic_node against the Monte Carlo truth over polygons", "[fit_anisotropic]") {
    ltc::fit::anisotropic_options opt;  // the shipped table's settings
    const double t = 0.7, p = 0.5;
    const dvec3 V(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
    const anisotropic_alpha a{0.5, 0.2};
    ltc::fit::anisotropic_parameters start;
    start.m11 = 0.5, start.m22 = 0.2;
    const auto r = ltc::fit::fit_anisotropic_node<ltc::brdf::ggx_anisotropic>(V, a, ltc::fit::node_symmetry::general, start, opt);
    CHECK(r.relative_l1 < 0.5);
    CHECK(r.magnitude > 0.5);
    check_against_truth(V, a, r.m_inv, r.magnitude, 11);
}

TEST_CASE("the shipped table against the Monte Carlo truth at a node and between nodes", "[fit_anisotropic]") {
    const int n = ltc::tables::ggx_anisotropic_size;
    // Node (5, 2, 3, 2), and a point inside a cell (its own LTC, bounded the same way).
    const double t_node = ltc::fit::anisotropic_node_theta(3, n), p_node = ltc::fit::anisotropic_node_phi(2, n);
    const struct {
        double ax, ay, theta, phi;
    } at[] = {{5.0 / (n - 1), 2.0 / (n - 1), t_node, p_node}, {0.62, 0.33, 0.9, 2.4}};
    std::uint64_t seed = 101;
    for (const auto& q : at) {
        const dvec3 V(std::sin(q.theta) * std::cos(q.phi), std::sin(q.theta) * std::sin(q.phi), std::cos(q.theta));
        const auto c = ltc::ggx_anisotropic::fetch(V.z, q.phi, q.ax, q.ay);
        CAPTURE(q.ax, q.ay, q.theta, q.phi);
        check_against_truth(V, anisotropic_alpha{q.ax, q.ay}, c.m_inv, c.magnitude, seed);
        seed += 10;
    }
}

TEST_CASE("fit_anisotropic_table: the same bytes on 1 and 2 threads, the symmetries built in", "[fit_anisotropic]") {
    ltc::fit::anisotropic_options opt;  // cheap settings: determinism, not accuracy
    opt.size = 3;
    opt.moment_samples = 12;
    opt.error_samples = 8;
    opt.rounds = 1;
    opt.max_evaluations = 150;
    opt.threads = 1;
    const auto a = ltc::fit::fit_anisotropic_table<ltc::brdf::ggx_anisotropic>(opt);
    opt.threads = 2;
    const auto b = ltc::fit::fit_anisotropic_table<ltc::brdf::ggx_anisotropic>(opt);
    const std::vector<float> pa = a.packed(), pb = b.packed();
    REQUIRE(pa.size() == ltc::anisotropic_layout::float_count(3));
    REQUIRE(pb.size() == pa.size());
    CHECK(std::memcmp(pa.data(), pb.data(), pa.size() * sizeof(float)) == 0);
    const ltc::anisotropic_table view(pa.data(), 3);
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) {
            // The diagonal: l and 2 - l swapped; phi = 0 symmetric in y; normal incidence the same for all phi.
            CHECK(view.matrix<float>(i, i, k, 2) == ltc::detail::swap_xy(view.matrix<float>(i, i, k, 0)));
            const glm::mat3 m0 = view.matrix<float>(i, 0, k, 0);
            CHECK((m0[0][1] == 0 && m0[1][0] == 0 && m0[1][2] == 0 && m0[2][1] == 0));
            CHECK(view.matrix<float>(i, 0, 0, 1) == view.matrix<float>(i, 0, 0, 0));
        }
    for (const auto& node : a.nodes) {
        CHECK(std::isfinite(node.magnitude));
        CHECK(glm::determinant(node.matrix) > 0);
    }
}

TEST_CASE("fit_anisotropic_table: a size below 2 is rejected", "[fit_anisotropic]") {
    ltc::fit::anisotropic_options opt;
    opt.size = 1;
    CHECK_THROWS_AS(ltc::fit::fit_anisotropic_table<ltc::brdf::ggx_anisotropic>(opt), std::invalid_argument);
}

}  // namespace ltc_test_fit_anisotropic
