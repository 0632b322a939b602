// Tests of the Monte Carlo reference of the textured light, ltc/reference/textured_ground_truth.hpp:
// a constant texture against the exact LTC integral, a gradient texture against Gauss-Legendre
// quadrature.
#include <ltc/brdf/ggx.hpp>
#include <ltc/reference/textured_ground_truth.hpp>

#include "support/gauss_legendre.hpp"
#include "support/rng.hpp"
#include "support/textured_quads.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

namespace ltc_test_textured_ground_truth {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::textured_checks;  // ggx_lobe, random_quad, finite

TEST_CASE("textured ground truth: constant texture against the exact LTC integral", "[textured][ground_truth]") {
    ltc_test::rng r(17);
    for (int i = 0; i < 6; ++i) {
        dvec3 q[4];
        random_quad(r, q);
        const auto d = ggx_lobe(r.uniform(0, 1), r.uniform(0.1, 1));
        ltc::textured_ground_truth::ltc_lobe lobe{d};
        ltc::textured_ground_truth::options opt;
        opt.samples = 20000;
        opt.seed = 100 + i;
        const dvec3 c(0.5, 1.0, 2.0);
        const auto e = ltc::textured_ground_truth::integrate(lobe, q, [&](double, double) { return c; }, opt);
        const double exact = d.integrate(q, 4);
        // Unbiased estimator, 2e4 iterations: 4 standard errors (a false failure has
        // probability ~6e-5 per check for a normal mean; the seeds are fixed anyway).
        for (int k = 0; k < 3; ++k) CHECK(std::abs(e.mean[k] - c[k] * exact) <= 4 * e.standard_error[k] + 1e-12);
    }
}

TEST_CASE("textured ground truth: a gradient texture against Gauss-Legendre quadrature", "[textured][ground_truth]") {
    // M = I (the clamped cosine), a 1 x 1 square at z = 1 offset from the shading point, and
    // L(u, v) = (u, v, u v). The integral of L D over the quad is, by the change of variables
    // dw = cos_x / |x|^2 dA, int_0^1 int_0^1 L(u, v) z^2 / (pi |x|^4) A du dv: analytic in u, v,
    // so Gauss-Legendre converges geometrically and |GL(24) - GL(48)| bounds GL(48)'s error.
    const dvec3 q[4] = {{0.2, -0.3, 1}, {1.2, -0.3, 1}, {1.2, 0.7, 1}, {0.2, 0.7, 1}};
    const auto L = [](double u, double v) { return dvec3(u, v, u * v); };
    const auto quad_rule = [&](std::size_t n) {
        const auto g = ltc_test::gauss_legendre(n);
        dvec3 s(0.0);
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) {
                const dvec3 x = q[0] + g.x[i] * (q[1] - q[0]) + g.x[j] * (q[3] - q[0]);
                const double l2 = glm::dot(x, x);
                s += g.w[i] * g.w[j] * L(g.x[i], g.x[j]) * (x.z * x.z / (3.141592653589793 * l2 * l2));
            }
        return s;
    };
    const dvec3 ref = quad_rule(48), err = glm::abs(ref - quad_rule(24));
    ltc::textured_ground_truth::options opt;
    opt.samples = 40000;
    const auto e = ltc::textured_ground_truth::integrate(ltc::textured_ground_truth::ltc_lobe{}, q, L, opt);
    // 4 standard errors plus the quadrature's error bound.
    for (int k = 0; k < 3; ++k) CHECK(std::abs(e.mean[k] - ref[k]) <= 4 * e.standard_error[k] + err[k] + 1e-12);
    // The same with area sampling proportional to arbitrary texel weights (still unbiased).
    std::vector<double> wgt(6 * 5);
    for (std::size_t i = 0; i < wgt.size(); ++i) wgt[i] = double((i * 7) % 5);
    const ltc::textured_ground_truth::texel_distribution dist(6, 5, wgt.data());
    opt.seed = 2;
    const auto e2 = ltc::textured_ground_truth::integrate(ltc::textured_ground_truth::ltc_lobe{}, q, L, opt, &dist);
    for (int k = 0; k < 3; ++k) CHECK(std::abs(e2.mean[k] - ref[k]) <= 4 * e2.standard_error[k] + err[k] + 1e-12);
    // And the BRDF lobe runs (GGX rho cos) with a finite, positive estimate.
    ltc::textured_ground_truth::brdf_lobe<ltc::brdf::ggx<double>> g{ltc::brdf::view_from_cos(0.7), 0.3};
    opt.samples = 2000;
    const auto eg = ltc::textured_ground_truth::integrate(g, q, L, opt);
    CHECK(finite(eg.mean));
    CHECK(eg.mean.x > 0);
}

}  // namespace ltc_test_textured_ground_truth
