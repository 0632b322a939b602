// Tests of the Charlie sheen: the BRDF (ltc/brdf/charlie.hpp: D's normalization, the sampler's
// density, reciprocity), its table and fetch (ltc/shading/charlie_fetch.hpp: the magnitude is the
// directional albedo, the fetched LTC against Monte Carlo over polygons within the bound the fit
// achieves), the model of ltc::shade (ltc/shading/sheen_models.hpp) on a polygon and a sphere, and
// the degenerate input.
#include <catch2/catch.hpp>

#include <ltc/brdf/charlie.hpp>
#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/fitting/error_metric.hpp>
#include <ltc/reference/ground_truth.hpp>
#include <ltc/reference/shape_ground_truth.hpp>
#include <ltc/shading/charlie_fetch.hpp>
#include <ltc/shading/lights/polygon_light.hpp>
#include <ltc/shading/lights/sphere_light.hpp>
#include <ltc/shading/shade.hpp>
#include <ltc/shading/sheen_models.hpp>

#include "support/rng.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace ltc_test_charlie {  // the file's own names, apart from the other files of a unity batch

namespace {

using glm::dvec3;
using B = ltc::brdf::charlie<double>;
constexpr double pi = 3.141592653589793;

/// The directional albedo of the BRDF at V by the midpoint rule on an n x n grid in
/// (cos theta_L, phi), i.e. uniform in solid angle: independent of the fitter's moments.
double albedo_by_quadrature(const dvec3& V, double alpha, int n) {
    double s = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double z = (i + 0.5) / n, phi = 2 * pi * (j + 0.5) / n, r = std::sqrt(1 - z * z);
            s += B::eval(V, dvec3(r * std::cos(phi), r * std::sin(phi), z), alpha);
        }
    return s * 2 * pi / (double(n) * n);
}

dvec3 view_at(double theta_deg) {
    const double t = theta_deg * pi / 180;
    return {std::sin(t), 0, std::cos(t)};
}

/// A square of half-size h at unit distance around the unit direction c, facing the origin (its
/// vertices clockwise as seen from there: the front face of polygon_light).
std::vector<dvec3> quad_around(const dvec3& c, double h) {
    const dvec3 t1 = glm::normalize(std::abs(c.z) < 0.9 ? glm::cross(dvec3(0, 0, 1), c) : glm::cross(dvec3(1, 0, 0), c));
    const dvec3 t2 = glm::cross(c, t1);
    std::vector<dvec3> q = {c + h * (t1 + t2), c + h * (-t1 + t2), c + h * (-t1 - t2), c + h * (t1 - t2)};
    if (glm::dot(q[0], glm::cross(q[1] - q[0], q[2] - q[0])) < 0) std::reverse(q.begin(), q.end());
    return q;
}

}  // namespace

TEST_CASE("Charlie: D is normalized, the integral of D cos theta_h over the hemisphere is 1", "[brdf][charlie]") {
    // With u = sin theta_h, D cos theta_h dw = 2 pi D(u) u du dphi / (2 pi), so the integral is
    // int_0^1 g(u) du with g(u) = 2 pi D(u) u = (2 + 1/a) u^(1/a + 1). The midpoint rule on n
    // intervals errs by at most max|g''| / (24 n^2), max|g''| = (2 + 1/a)(1/a + 1)(1/a) at u = 1.
    for (const double a : {0.01, 0.1, 0.5, 1.0}) {
        const int n = 1 << 16;
        double s = 0;
        for (int i = 0; i < n; ++i) {
            const double u = (i + 0.5) / n;
            s += 2 * pi * B::ndf(dvec3(u, 0, std::sqrt(1 - u * u)), a) * u;
        }
        s /= n;
        const double bound = (2 + 1 / a) * (1 / a + 1) * (1 / a) / (24.0 * n * double(n)) + 1e-12;
        CAPTURE(a, s, bound);
        CHECK(std::abs(s - 1) <= bound);
    }
}

TEST_CASE("Charlie: the sampler's density integrates to 1 and matches its samples", "[brdf][charlie]") {
    const dvec3 V = view_at(50);
    const double alpha = 0.3;
    // pdf over the sphere, midpoint rule in (cos theta, phi): exact for a constant per hemisphere.
    double total = 0;
    const int n = 64;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < 2 * n; ++i) {
            const double z = -1 + (i + 0.5) / n, phi = 2 * pi * (j + 0.5) / n, r = std::sqrt(1 - z * z);
            total += B::pdf(V, dvec3(r * std::cos(phi), r * std::sin(phi), z), alpha);
        }
    CHECK(total * (2.0 / (2 * n)) * (2 * pi / n) == Approx(1).epsilon(1e-12));
    // Samples in 4 x 4 bins of (cos theta, phi): each holds 1/16 of the density; binomial, 4 sigma.
    ltc_test::rng rng(0xC4A5u);
    const int samples = 1 << 16;
    int bins[4][4] = {};
    for (int k = 0; k < samples; ++k) {
        const dvec3 L = B::sample(V, rng.uniform2<double>(), alpha);
        REQUIRE(std::abs(glm::length(L) - 1) < 1e-12);
        REQUIRE(L.z > 0);
        const double phi = std::atan2(L.y, L.x) + pi;
        ++bins[std::min(3, int(L.z * 4))][std::min(3, int(phi / (2 * pi) * 4))];
    }
    const double p = 1.0 / 16, sigma = std::sqrt(p * (1 - p) / samples);
    for (const auto& row : bins)
        for (const int b : row) CHECK(std::abs(double(b) / samples - p) <= 4 * sigma);
    // eval / pdf through the sampler: an unbiased estimate of the albedo (4 standard errors).
    for (const double theta : {0.0, 45.0, 80.0}) {
        const dvec3 W = view_at(theta);
        double mean = 0, m2 = 0;
        for (int k = 1; k <= samples; ++k) {
            const dvec3 L = B::sample(W, rng.uniform2<double>(), alpha);
            const double x = B::eval(W, L, alpha) / B::pdf(W, L, alpha), d = x - mean;
            mean += d / k;
            m2 += d * (x - mean);
        }
        const double se = std::sqrt(m2 / (samples - 1.0) / samples);
        CAPTURE(theta, mean, se);
        CHECK(std::abs(mean - albedo_by_quadrature(W, alpha, 512)) <= 4 * se);
    }
}

TEST_CASE("Charlie: rho is reciprocal and the spec's visibility", "[brdf][charlie]") {
    ltc_test::rng rng(7);
    for (int k = 0; k < 200; ++k) {
        dvec3 V = rng.direction(), L = rng.direction();
        V.z = std::abs(V.z), L.z = std::abs(L.z);
        const double alpha = rng.uniform(0.01, 1.0);
        CAPTURE(V.x, V.y, V.z, L.x, L.y, L.z, alpha);
        const double a = B::eval(V, L, alpha) / L.z, b = B::eval(L, V, alpha) / V.z;
        CHECK(a == Approx(b).epsilon(1e-12));
        // The spec's form: sheen_distribution * sheen_visibility, visibility = 1 / ((1 + lambda(V)
        // + lambda(L)) 4 V.z L.z).
        const double vis = 1 / ((1 + B::lambda(V, alpha) + B::lambda(L, alpha)) * 4 * V.z * L.z);
        CHECK(a == Approx(B::ndf(glm::normalize(V + L), alpha) * vis).epsilon(1e-12));
    }
    // lambda is continuous where the spec switches branches (cos = 1/2).
    for (const double alpha : {0.01, 0.25, 1.0}) {
        const double below = B::lambda(dvec3(std::sqrt(1 - 0.4999999 * 0.4999999), 0, 0.4999999), alpha);
        const double above = B::lambda(dvec3(std::sqrt(1 - 0.5 * 0.5), 0, 0.5), alpha);
        CHECK(below == Approx(above).epsilon(1e-5));
    }
}

TEST_CASE("Charlie table: the magnitude is the directional albedo", "[charlie][table]") {
    // At nodes (exact node coordinates) against the quadrature above at 256 x 256; the table's
    // own moments are a 64 x 64 midpoint rule through the uniform sampler (ltc/fitting/moments.hpp),
    // whose error grows where the lobe narrows: roughness >= 0.25 and albedo >= 1e-2 here.
    const int n = ltc::charlie::table.width();
    REQUIRE(n == ltc::charlie::table.height());
    for (int a = 16; a < n; a += 9)
        for (int t = 0; t < n; t += 7) {
            const double x = double(t) / (n - 1);
            const double cos_theta = std::max(1 - x * x, 7.9632671073326335e-4);
            const double roughness = double(a) / (n - 1);
            const double albedo = albedo_by_quadrature(ltc::brdf::view_from_cos(cos_theta), roughness * roughness, 256);
            const auto c = ltc::charlie::fetch(cos_theta, roughness);
            CAPTURE(t, a, cos_theta, roughness, albedo, c.magnitude);
            CHECK(c.fresnel == 0);
            if (albedo >= 1e-2) CHECK(c.magnitude == Approx(albedo).epsilon(5e-3));
        }
}

TEST_CASE("Charlie table: magnitude times the fetched LTC approximates rho cos over polygons", "[charlie][table]") {
    // |magnitude I_ltc(P) - integral over P of f| <= integral of |f - magnitude D| = relative_l1 *
    // albedo (measure_error, 128 x 128 per distribution), plus the estimator's slack (1% of the
    // albedo, as tests/test_fitted_table.cpp) and 4 standard errors of the Monte Carlo truth.
    // Off the nodes: the bound holds for whatever the interpolated lookup returns.
    struct cell {
        double theta, roughness;
    };
    for (const cell cl : {cell{20, 0.9}, cell{45, 0.6}, cell{70, 0.35}, cell{85, 0.3}}) {
        const dvec3 V = view_at(cl.theta);
        const double alpha = cl.roughness * cl.roughness;
        const auto c = ltc::charlie::fetch(V.z, cl.roughness);
        const auto d = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(c.m_inv);
        const ltc::fit::node_error bound = ltc::fit::measure_error<ltc::brdf::charlie>(V.z, alpha, c.m_inv, c.magnitude, 128);
        const dvec3 forward = glm::normalize(dvec3(V.x + 0.2, 0, 0.3));  // towards the grazing sheen
        for (const dvec3& centre : {dvec3(0, 0, 1), dvec3(-V.x, 0, V.z), forward, glm::normalize(dvec3(0.1, 1, 0.4))})
            for (const double h : {0.3, 1.0}) {
                const std::vector<dvec3> q = quad_around(centre, h);
                ltc::ground_truth::options o;
                o.samples = 1u << 13;
                o.seed = 0xC0FFEEu;
                const auto truth = ltc::ground_truth::integrate(B{}, V, alpha, q.data(), q.size(), o);
                const double shaded = c.magnitude * d.integrate(q.data(), q.size());
                CAPTURE(cl.theta, cl.roughness, centre.x, centre.y, centre.z, h, shaded, truth.mean, bound.relative_l1);
                CHECK(std::abs(shaded - truth.mean) <=
                      bound.relative_l1 * bound.albedo + 0.01 * bound.albedo + 4 * truth.standard_error);
            }
    }
}

TEST_CASE("shade<sheen::charlie>: a polygon and a sphere light against Monte Carlo", "[charlie][shade]") {
    // The surface at the origin, N = +z and V in the xz-plane: the tables' frame is the world's.
    const double theta = 60, roughness = 0.5, alpha = roughness * roughness, radiance = 2;
    const dvec3 V = view_at(theta), colour(0.9, 0.5, 0.2);
    const ltc::surface<double> s{dvec3(0), dvec3(0, 0, 1), V, roughness, colour, dvec3(0)};
    const auto c = ltc::charlie::fetch(V.z, roughness);
    const ltc::fit::node_error bound = ltc::fit::measure_error<ltc::brdf::charlie>(V.z, alpha, c.m_inv, c.magnitude, 128);
    const double slack = bound.relative_l1 * bound.albedo + 0.01 * bound.albedo;
    ltc::ground_truth::options o;
    o.samples = 1u << 14;
    o.seed = 0x5EEDu;

    // A quad towards the grazing sheen, one-sided, emitting towards the point (its right-hand
    // normal points away from it: quad_around).
    const std::vector<dvec3> q = quad_around(glm::normalize(dvec3(0.8, 0.2, 0.5)), 0.6);
    const dvec3 emission = -glm::normalize(glm::cross(q[1] - q[0], q[2] - q[0]));
    const auto quad = ltc::polygon_light<double>::one_sided(q.data(), q.size(), emission, dvec3(radiance));
    const auto r = ltc::shade<ltc::sheen::charlie>(s, quad);
    CHECK(r.diffuse == dvec3(0));
    const double I = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(c.m_inv).integrate(q.data(), q.size());
    for (int k = 0; k < 3; ++k) CHECK(r.specular[k] == Approx(colour[k] * radiance * c.magnitude * I).epsilon(1e-9));
    const auto truth = ltc::ground_truth::integrate(B{}, V, alpha, q.data(), q.size(), o);
    CAPTURE(r.specular.x, truth.mean, slack);
    CHECK(truth.mean > 0.05 * bound.albedo);  // a light that matters
    CHECK(std::abs(r.specular.x / (colour.x * radiance) - truth.mean) <= slack + 4 * truth.standard_error);

    // A sphere above the horizon, off the plane of incidence.
    const dvec3 centre(1.2, 0.8, 1.0);
    const double radius = 0.7;
    const auto sphere = ltc::sphere_light<double>{centre, radius, dvec3(radiance)};
    const auto rs = ltc::shade<ltc::sheen::charlie>(s, sphere);
    const auto ts = ltc::ground_truth::integrate_sphere(B{}, V, alpha, centre, radius, o);
    CAPTURE(rs.specular.x, ts.mean);
    CHECK(rs.diffuse == dvec3(0));
    CHECK(ts.mean > 0.05 * bound.albedo);
    CHECK(std::abs(rs.specular.x / (colour.x * radiance) - ts.mean) <= slack + 4 * ts.standard_error);
    CHECK(rs.specular.y / rs.specular.x == Approx(colour.y / colour.x).epsilon(1e-12));

    // The spec's albedo scaling of the base layer: 1 - max(colour) E(cos theta_v).
    CHECK(ltc::sheen::albedo_scaling(colour, V.z, roughness) == Approx(1 - 0.9 * c.magnitude).epsilon(1e-12));
}

TEST_CASE("Charlie: degenerate input gives finite values", "[charlie][bad-input]") {
    using F = ltc::brdf::charlie<float>;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float tiny = std::numeric_limits<float>::denorm_min();
    const glm::vec3 views[] = {{0, 0, 1}, {1, 0, 0}, {0.6f, 0, -0.8f}, {1, 0, tiny}, {0.8f, 0, 0.6f}};
    const glm::vec3 lights[] = {{0, 0, 1}, {-0.8f, 0, -0.6f}, {-1, 0, tiny}, {0, 1, 0}, {0.3f, 0.4f, 0.866f}};
    for (const float alpha : {0.0f, -1.0f, nan, 1e-30f, 1e-4f, 0.5f, 1.0f, 1e30f})
        for (const glm::vec3& V : views)
            for (const glm::vec3& L : lights) {
                CAPTURE(alpha, V.x, V.z, L.x, L.y, L.z);
                const float e = F::eval(V, L, alpha), p = F::pdf(V, L, alpha);
                CHECK(std::isfinite(e));
                CHECK(e >= 0);
                CHECK(std::isfinite(p));
                CHECK(std::isfinite(F::ndf(L, alpha)));
                CHECK(std::isfinite(F::lambda(V, alpha)));
                const glm::vec3 s = F::sample(V, glm::vec2(0.9999999f, 0), alpha);
                CHECK((std::isfinite(s.x) && std::isfinite(s.y) && std::isfinite(s.z)));
            }
    CHECK(F::eval(glm::vec3(0.8f, 0, 0.6f), glm::vec3(-0.8f, 0, -0.6f), 0.5f) == 0);  // L = -V
    CHECK(F::eval(glm::vec3(0.6f, 0, -0.8f), glm::vec3(0, 0, 1), 0.5f) == 0);         // V below
    // The table over a fine grid of lookups, nodes and between them, in float: finite LTC
    // integrals of a quad straddling the horizon, and finite coefficients for any input.
    const glm::vec3 quad[4] = {{-1, 0.5f, -0.2f}, {1, 0.5f, -0.2f}, {1, 1.5f, 1.5f}, {-1, 1.5f, 1.5f}};
    for (int i = 0; i <= 130; ++i)
        for (int j = 0; j <= 130; ++j) {
            const auto c = ltc::charlie::fetch(float(i) / 130, float(j) / 130);
            const float I = ltc::transformed<ltc::clamped_cosine<float>>::from_inverse(c.m_inv).integrate(quad, 4);
            if (!std::isfinite(I) || !(I >= 0) || !std::isfinite(c.magnitude)) {
                CAPTURE(i, j, I, c.magnitude);
                FAIL_CHECK("not finite");
            }
        }
    for (const float x : {nan, -1.0f, 2.0f, std::numeric_limits<float>::infinity()}) {
        const auto c = ltc::charlie::fetch(x, x);
        CHECK((std::isfinite(c.magnitude) && std::isfinite(c.m_inv[0][0]) && std::isfinite(c.m_inv[2][2])));
        const float k = ltc::sheen::albedo_scaling(glm::vec3(x, 0.5f, nan), x, x);
        CHECK((k >= 0 && k <= 1));
    }
    // shade with a NaN roughness reads it as 0 (the table's domain): finite.
    const ltc::surface<double> s{dvec3(0), dvec3(0, 0, 1), view_at(30), std::numeric_limits<double>::quiet_NaN(),
                                 dvec3(1), dvec3(0)};
    const auto r = ltc::shade<ltc::sheen::charlie>(s, ltc::sphere_light<double>{dvec3(0, 1, 1), 0.5, dvec3(1)});
    CHECK((std::isfinite(r.specular.x) && r.specular.x >= 0));
}

}  // namespace ltc_test_charlie
