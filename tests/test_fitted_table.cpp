// Two properties of the distributions fitted into the shipped GGX table (ltc/shading/ggx_fetch.hpp):
// energy over the hemisphere and over polygons, and the cosine at roughness 1.
#include <catch2/catch.hpp>

#include <ltc/brdf/ggx.hpp>
#include <ltc/core/clamped_cosine.hpp>
#include <ltc/fitting/fit.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/core/transformed.hpp>

#include "support/ggx_table.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace ltc_test_fitted_table {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::table_checks;  // n, table_options

namespace {

/// A quad that covers the upper hemisphere but for a band of 1e-6 rad above the horizon.
const glm::dvec3 hemisphere_quad[4] = {{1e6, 1e6, 1}, {-1e6, 1e6, 1}, {-1e6, -1e6, 1}, {1e6, -1e6, 1}};

}  // namespace

TEST_CASE("magnitude times the fitted LTC's integral over the hemisphere is the albedo", "[fit][table]") {
    // The LTC integrates to 1 over the sphere; what leaks below the horizon is error that the
    // L3 fit keeps small (here at most ~1.2%), so magnitude * (integral over the upper
    // hemisphere) matches the directional albedo, computed independently on a 256 x 256 grid.
    double worst = 0;
    for (int a = 8; a < n; a += 11)
        for (int t = 0; t < n; t += 9) {
            CAPTURE(a, t);
            const double cos_theta = ltc::fit::node_cos_theta(t, n, table_options().cos_theta_min);
            const double alpha = ltc::fit::node_alpha(a, n, table_options().alpha_min);
            const double albedo = ltc::fit::compute_moments<ltc::brdf::ggx>(ltc::brdf::view_from_cos(cos_theta), alpha, 256)
                                      .magnitude;
            const auto c = ltc::ggx::fetch(cos_theta, double(a) / (n - 1));
            const auto d = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(c.m_inv);
            const double e = c.magnitude * d.integrate(hemisphere_quad, 4);
            CHECK(e == Approx(albedo).epsilon(0.02));
            CHECK(e <= albedo * 1.002);  // the LTC only loses energy (the albedo is known to ~1e-3)
            worst = std::max(worst, std::abs(e / albedo - 1));
        }
    INFO("largest relative deviation " << worst);
    CHECK(worst < 0.02);
}

TEST_CASE("magnitude times the fetched LTC's polygon integral approximates rho cos over the polygon", "[fit][table]") {
    // The public contract, conventions included (local frame, V in the xz-plane with V.x >= 0,
    // m_inv rather than M): for any polygon P, |magnitude I_ltc(P) - integral over P of f| <=
    // integral of |f - magnitude D| = relative_l1 * albedo. The integral of f over P is computed
    // by 256 x 256 BRDF samples; the bound by measure_error (128 x 128 per distribution).
    struct node {
        int t, a;
    };
    for (const node nd : {node{10, 20}, node{30, 35}, node{45, 50}, node{20, 60}, node{55, 15}}) {
        const double x = double(nd.t) / (n - 1);
        const double cos_theta = 1 - x * x;
        const double alpha = ltc::fit::node_alpha(nd.a, n, 1e-4);
        const glm::dvec3 V = ltc::brdf::view_from_cos(cos_theta);
        const auto c = ltc::ggx::fetch(cos_theta, double(nd.a) / (n - 1));
        const auto d = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(c.m_inv);
        const ltc::fit::node_error bound = ltc::fit::measure_error<ltc::brdf::ggx>(cos_theta, alpha, c.m_inv, c.magnitude, 128);
        // Quads of half-size h at unit distance around a few directions near the lobe.
        const glm::dvec3 mirror(-V.x, 0, V.z);
        for (const glm::dvec3& centre : {mirror, glm::normalize(mirror + glm::dvec3(0.3, 0.2, 0)),
                                         glm::normalize(mirror + glm::dvec3(-0.4, -0.3, 0.1)), glm::dvec3(0, 0, 1)})
            for (const double h : {0.05, 0.2, 0.6}) {
                CAPTURE(nd.t, nd.a, centre.x, centre.y, centre.z, h);
                const glm::dvec3 t1 = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), centre));
                const glm::dvec3 t2 = glm::cross(centre, t1);
                const glm::dvec3 quad[4] = {centre + h * (t1 + t2), centre + h * (-t1 + t2), centre + h * (-t1 - t2),
                                            centre + h * (t1 - t2)};
                const double shaded = c.magnitude * d.integrate(quad, 4);
                const int m = 256;
                double truth = 0;
                for (int j = 0; j < m; ++j)
                    for (int i = 0; i < m; ++i) {
                        const glm::dvec3 L = ltc::brdf::ggx<double>::sample(V, glm::dvec2((i + 0.5) / m, (j + 0.5) / m), alpha);
                        const double cl = glm::dot(L, centre);
                        if (!(cl > 0) || !(L.z > 0)) continue;
                        const glm::dvec3 hit = L / cl - centre;
                        if (std::abs(glm::dot(hit, t1)) > h || std::abs(glm::dot(hit, t2)) > h) continue;
                        truth += ltc::brdf::ggx<double>::eval(V, L, alpha) / ltc::brdf::ggx<double>::pdf(V, L, alpha);
                    }
                truth /= double(m) * m;
                CHECK(std::abs(shaded - truth) <= bound.relative_l1 * bound.albedo + 0.01 * bound.albedo);
            }
    }
}

TEST_CASE("at roughness 1 and normal incidence the fitted LTC is close to a cosine", "[fit][table]") {
    const auto c = ltc::ggx::fetch(1.0, 1.0);
    CHECK(c.m_inv[0][2] == 0);
    CHECK(c.m_inv[2][0] == 0);
    CHECK(c.m_inv[0][0] == Approx(1));  // isotropic at normal incidence: m_inv = diag(1, 1, s)
    CHECK(c.m_inv[2][2] == Approx(1).epsilon(0.2));
    // L1 distance between the LTC and the clamped cosine (0 for equal, 2 for disjoint
    // distributions), by the LTC's own samples and the cosine's (MIS, 128 x 128 each): small
    // (0.12: GGX at alpha = 1 with Smith shadowing is a little flatter than a cosine).
    const auto d = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(c.m_inv);
    const int m = 128;
    double l1 = 0;
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
            const glm::dvec2 u((i + 0.5) / m, (j + 0.5) / m);
            for (const glm::dvec3& L : {d.sample(u), ltc::clamped_cosine<double>::sample(u)}) {
                const double p = d.pdf(L), q = ltc::clamped_cosine<double>::pdf(L);
                l1 += std::abs(p - q) / (double(m) * m * (p + q));
            }
        }
    CHECK(l1 < 0.2);
    // And the fit itself, from the cosine: it stays there.
    ltc::fit::options opt = table_options();
    const ltc::fit::node_result r = ltc::fit::fit_node<ltc::brdf::ggx>(1.0, 1.0, ltc::fit::ltc_parameters{}, opt);
    CHECK(r.parameters.m11 == r.parameters.m22);
    CHECK(r.parameters.m11 == Approx(1).epsilon(0.2));
    CHECK(r.relative_l1 < 0.05);
}

}  // namespace ltc_test_fitted_table
