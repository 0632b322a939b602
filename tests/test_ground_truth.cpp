// Tests of ltc/reference/ground_truth.hpp: the spherical triangle and polygon samplers, and the Monte
// Carlo estimator against closed forms (a Lambertian "BRDF" against ltc::form_factor, the LTC
// distribution itself against transformed::integrate), for each technique and heuristic.
//
// Every random test uses a fixed seed, so it is deterministic; the tolerances are 4 to 5
// standard errors, which a correct estimator fails with probability < 1e-4 per check for the
// seed chosen (and, being deterministic, either always or never).
#include <catch2/catch.hpp>

#include <ltc/fitting/brdf/ggx.hpp>
#include <ltc/reference/ground_truth.hpp>
#include <ltc/ltc.hpp>

#include "support/rng.hpp"

#include <cmath>
#include <vector>

namespace {

using glm::dvec2;
using glm::dvec3;
namespace gt = ltc::ground_truth;
constexpr double pi = 3.141592653589793;

/// The clamped cosine as a "BRDF": eval = max(0, L.z) / pi (a white Lambertian, its cosine
/// included), sampled by ltc::clamped_cosine.
struct lambert {
    double eval(const dvec3&, const dvec3& L, double) const { return L.z > 0 ? L.z / ltc::pi<double>() : 0.0; }
    double pdf(const dvec3& V, const dvec3& L, double a) const { return eval(V, L, a); }
    dvec3 sample(const dvec3&, const dvec2& u, double) const { return ltc::clamped_cosine<double>::sample(u); }
};

/// A linearly transformed cosine as the "BRDF" (stateful: called through the instance).
struct ltc_model {
    ltc::transformed<ltc::clamped_cosine<double>> d;
    double eval(const dvec3&, const dvec3& L, double) const { return d.eval(L); }
    double pdf(const dvec3&, const dvec3& L, double) const { return d.pdf(L); }
    dvec3 sample(const dvec3&, const dvec2& u, double) const { return d.sample(u); }
};

/// The constant 1 with uniform sphere sampling: the estimate is the solid angle.
struct constant_one {
    double eval(const dvec3&, const dvec3&, double) const { return 1.0; }
    double pdf(const dvec3&, const dvec3&, double) const { return 1.0 / (4 * ltc::pi<double>()); }
    dvec3 sample(const dvec3&, const dvec2& u, double) const {
        const double z = 1 - 2 * u.x, r = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * ltc::pi<double>() * u.y;
        return {r * std::cos(phi), r * std::sin(phi), z};
    }
};

struct named_polygon {
    const char* name;
    std::vector<dvec3> v;
};

/// Test polygons: above the horizon, straddling it, non-convex (an L and a star), both windings.
std::vector<named_polygon> polygons() {
    std::vector<named_polygon> p;
    p.push_back({"quad above", {{-1, 0, 0.5}, {1, 0, 0.5}, {1, 2, 1.5}, {-1, 2, 1.5}}});
    p.push_back({"quad straddling", {{-1, 0, -0.5}, {1, 0, -0.5}, {1, 2, 1.5}, {-1, 2, 1.5}}});
    p.push_back({"triangle straddling, reversed", {{-0.2, 1, 0.6}, {1, 0.3, 1.0}, {-1, -0.5, -0.5}}});
    p.push_back({"small triangle", {{0.3, 0.1, 2}, {0.32, 0.1, 2}, {0.3, 0.12, 2}}});
    // An L-shaped hexagon in the plane z = 1 (non-convex; the fan from vertex 0 has a negative
    // triangle), clockwise as seen from the origin.
    p.push_back({"L shape", {{-1, -1, 1}, {1, -1, 1}, {1, 0, 1}, {0, 0, 1}, {0, 1, 1}, {-1, 1, 1}}});
    // A 5-pointed star in a tilted plane, partly below the horizon.
    std::vector<dvec3> star;
    for (int i = 0; i < 10; ++i) {
        const double phi = ltc::pi<double>() * i / 5, r = i % 2 ? 0.35 : 1.0;
        const dvec2 q(r * std::cos(phi), r * std::sin(phi));
        star.push_back(dvec3(q.x, 0.8 + 0.5 * q.y, 0.3 + q.y));
    }
    p.push_back({"star", star});
    return p;
}

/// Spherical triangle (a, b, c) contains w (either orientation).
bool in_triangle(const dvec3& a, const dvec3& b, const dvec3& c, const dvec3& w) {
    const double s = glm::dot(a, glm::cross(b, c)) > 0 ? 1.0 : -1.0;
    const double eps = -1e-12;
    return s * glm::dot(w, glm::cross(a, b)) >= eps && s * glm::dot(w, glm::cross(b, c)) >= eps &&
           s * glm::dot(w, glm::cross(c, a)) >= eps;
}

}  // namespace

TEST_CASE("splitmix64 is deterministic and matches the tests' generator", "[ground_truth]") {
    gt::splitmix64 a(42), b(42), c(43);
    ltc_test::rng ref(42);
    for (int i = 0; i < 100; ++i) {
        const std::uint64_t x = a.next();
        CHECK(x == b.next());
        CHECK(x == ref.next_u64());
        CHECK(x != c.next());
    }
    int out_of_range = 0;
    for (int i = 0; i < 1000; ++i) {
        const double u = a.uniform();
        out_of_range += !(u >= 0.0 && u < 1.0);
    }
    CHECK(out_of_range == 0);
}

TEST_CASE("spherical triangle sampler: inside, uniform, right mean direction", "[ground_truth]") {
    struct tri {
        dvec3 a, b, c;
    };
    const tri tris[] = {
        {{0, 0, 1}, {1, 0, 0.2}, {0, 1, 0.5}},                 // large
        {{0, 1, 0.5}, {1, 0, 0.2}, {0, 0, 1}},                 // the same, other orientation
        {{1, 0, 0.01}, {-0.5, 0.87, 0.01}, {-0.5, -0.87, 1}},  // nearly a hemisphere, flat
        {{0.2, 0.1, 1}, {0.21, 0.1, 1}, {0.2, 0.11, 1}},       // small (1e-4 sr)
        {{1, 0, 0}, {0, 1e-3, 1}, {-1, 1e-3, 0}},               // thin sliver
    };
    const int n = 200000;
    for (const tri& t : tris) {
        const dvec3 a = glm::normalize(t.a), b = glm::normalize(t.b), c = glm::normalize(t.c);
        const double omega = std::abs(ltc::triangle_solid_angle(a, b, c));
        const gt::spherical_triangle_sampler sampler(a, b, c);
        CAPTURE(a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, omega);
        CHECK_THAT(sampler.solid_angle(), Catch::Matchers::WithinRel(omega, 1e-9));
        // Sub-triangles from the edge midpoints, then again: 16 cells of known solid angle.
        std::vector<std::array<dvec3, 3>> cells = {{a, b, c}};
        for (int level = 0; level < 2; ++level) {
            std::vector<std::array<dvec3, 3>> next;
            for (const auto& q : cells) {
                const dvec3 ab = glm::normalize(q[0] + q[1]), bc = glm::normalize(q[1] + q[2]),
                            ca = glm::normalize(q[2] + q[0]);
                next.push_back({q[0], ab, ca});
                next.push_back({ab, q[1], bc});
                next.push_back({ca, bc, q[2]});
                next.push_back({ab, bc, ca});
            }
            cells = next;
        }
        std::vector<int> count(cells.size(), 0);
        gt::splitmix64 rng(7);
        dvec3 mean(0), m2(0);
        int outside = 0, not_unit = 0;
        for (int i = 0; i < n; ++i) {
            const dvec3 w = sampler.sample(rng.uniform2());
            if (!(std::abs(glm::length(w) - 1) < 1e-12)) ++not_unit;
            if (!in_triangle(a, b, c, w)) ++outside;
            for (std::size_t k = 0; k < cells.size(); ++k)
                if (in_triangle(cells[k][0], cells[k][1], cells[k][2], w)) {
                    ++count[k];
                    break;
                }
            mean += w;
            m2 += w * w;
        }
        CHECK(outside == 0);
        CHECK(not_unit == 0);
        for (std::size_t k = 0; k < cells.size(); ++k) {
            const double p = std::abs(ltc::triangle_solid_angle(cells[k][0], cells[k][1], cells[k][2])) / omega;
            const double sigma = std::sqrt(n * p * (1 - p));
            CAPTURE(k, p, count[k]);
            CHECK(std::abs(count[k] - n * p) <= 5 * sigma + 1);
        }
        // Mean direction: int_T w dw / Omega = pi F / Omega (F the vector form factor, whose
        // sign follows the orientation).
        const dvec3 vertices[3] = {a, b, c};
        const double sign = ltc::triangle_solid_angle(a, b, c) > 0 ? 1.0 : -1.0;
        const dvec3 expected = sign * ltc::pi<double>() * ltc::vector_form_factor(vertices, 3) / omega;
        mean /= double(n);
        const dvec3 var = m2 / double(n) - mean * mean;
        for (int k = 0; k < 3; ++k) {
            CAPTURE(k, mean[k], expected[k]);
            CHECK(std::abs(mean[k] - expected[k]) <= 5 * std::sqrt(var[k] / n) + 1e-12);
        }
    }
}

TEST_CASE("spherical polygon: winding, density and solid angle", "[ground_truth]") {
    for (const auto& poly : polygons()) {
        CAPTURE(poly.name);
        const std::size_t n = poly.v.size();
        const gt::spherical_polygon sp(poly.v.data(), n);
        CHECK_THAT(sp.signed_solid_angle(), Catch::Matchers::WithinRel(ltc::solid_angle(poly.v.data(), n), 1e-9));
        // The winding number is +-1 exactly where a ray hits the planar polygon: test rays
        // through points of the plane, inside and outside (point-in-polygon in the plane).
        gt::splitmix64 rng(11);
        const dvec3 p0 = poly.v[0];
        const dvec3 nrm = glm::normalize(glm::cross(poly.v[1] - p0, poly.v[2] - p0));
        const dvec3 e1 = glm::normalize(poly.v[1] - p0), e2 = glm::cross(nrm, e1);
        const int sign = ltc::solid_angle(poly.v.data(), n) > 0 ? 1 : -1;
        double extent = 0;
        for (const dvec3& v : poly.v) extent = std::max(extent, glm::length(v - p0));
        int wrong = 0, inside = 0;
        for (int i = 0; i < 2000; ++i) {
            // A point of the plane near the polygon; its 2D winding number by crossings.
            const dvec2 u = rng.uniform2();
            const dvec3 q = p0 + extent * ((u.x * 4 - 2) * e1 + (u.y * 4 - 2) * e2);
            const double qx = glm::dot(q - p0, e1), qy = glm::dot(q - p0, e2);
            bool in = false;
            for (std::size_t k = 0, j = n - 1; k < n; j = k++) {
                const double ax = glm::dot(poly.v[k] - p0, e1), ay = glm::dot(poly.v[k] - p0, e2);
                const double bx = glm::dot(poly.v[j] - p0, e1), by = glm::dot(poly.v[j] - p0, e2);
                if ((ay > qy) != (by > qy) && qx < (bx - ax) * (qy - ay) / (by - ay) + ax) in = !in;
            }
            if (glm::dot(q, q) == 0) continue;
            const dvec3 w = glm::normalize(q);
            wrong += sp.winding(w) != (in ? sign : 0);
            inside += in;
        }
        CHECK(wrong == 0);
        CHECK(inside > 0);
        // Solid angle by polygon sampling alone: convex polygons give it exactly (density
        // 1 / Omega), non-convex ones within the error.
        gt::options opt;
        opt.samples = 100000;
        opt.use = gt::techniques::polygon_only;
        const gt::estimate e = gt::integrate(constant_one{}, dvec3(0, 0, 1), 0.0, poly.v.data(), n, opt);
        CHECK(std::abs(e.mean - sp.solid_angle()) <= 4 * e.standard_error + 1e-9 * sp.solid_angle());
        // ... and by uniform sphere sampling (BRDF technique only), which tests the indicator
        // (not for the small triangle: 1e-4 sr is rarely hit).
        if (sp.solid_angle() > 0.01) {
            opt.use = gt::techniques::brdf_only;
            const gt::estimate f = gt::integrate(constant_one{}, dvec3(0, 0, 1), 0.0, poly.v.data(), n, opt);
            CHECK(std::abs(f.mean - sp.solid_angle()) <= 4 * f.standard_error);
        }
        // The density integrates to 1: E[pdf(w) 4 pi] over uniform sphere directions.
        double acc = 0;
        constant_one sphere;
        for (int i = 0; i < 100000; ++i) acc += sp.pdf(sphere.sample(dvec3(0), rng.uniform2(), 0));
        const double integral = acc / 100000 * 4 * ltc::pi<double>();
        // Standard error of that estimate: pdf takes the values 0 and k / Omega_+.
        CHECK(std::abs(integral - 1) <= 4 * std::sqrt(4 * ltc::pi<double>() / sp.solid_angle() / 100000) + 1e-12);
    }
}

TEST_CASE("ground truth of a Lambertian BRDF matches the exact form factor within 4 sigma", "[ground_truth]") {
    const dvec3 V = glm::normalize(dvec3(0.5, 0, 0.8));
    for (const auto& poly : polygons()) {
        CAPTURE(poly.name);
        const std::size_t n = poly.v.size();
        const double exact = ltc::form_factor(poly.v.data(), n, ltc::sidedness::two_sided);
        for (const auto use : {gt::techniques::mis, gt::techniques::brdf_only, gt::techniques::polygon_only})
            for (const auto h : {gt::heuristic::balance, gt::heuristic::power}) {
                if (use != gt::techniques::mis && h == gt::heuristic::power) continue;
                // BRDF sampling alone rarely hits a 1e-4 sr triangle: nothing to test there.
                if (use == gt::techniques::brdf_only && ltc::solid_angle(poly.v.data(), n) < 0.01) continue;
                gt::options opt;
                opt.samples = 100000;
                opt.use = use;
                opt.weighting = h;
                opt.seed = 1234;
                const gt::estimate e = gt::integrate(lambert{}, V, 0.0, poly.v.data(), n, opt);
                CAPTURE(int(use), int(h), e.mean, e.standard_error, exact);
                CHECK(e.samples == opt.samples);
                // For the tiny triangle, BRDF samples hit about once per 1e5 iterations: the
                // standard error cannot see that technique's share (ground_truth.hpp, caveat),
                // at most Omega max(p_brdf) = Omega / pi of the integral.
                const double omega = std::abs(ltc::solid_angle(poly.v.data(), n));
                const double rare = use == gt::techniques::polygon_only || omega > 0.01 ? 0.0 : omega / pi * exact;
                CHECK(std::abs(e.mean - exact) <= 4 * e.standard_error + rare + 1e-12);
                CHECK(e.standard_error <= 0.02 * exact + 1e-9);  // the estimator is useful
            }
    }
}

TEST_CASE("ground truth of an LTC as the BRDF matches transformed::integrate within 4 sigma", "[ground_truth]") {
    // Two matrices of the paper's form and a general one; the LTC leaks below the horizon,
    // and the ground truth integrates over the whole polygon, as integrate() does.
    const glm::dmat3 Ms[] = {
        glm::transpose(glm::dmat3(0.3, 0, 0.2, 0, 0.4, 0, -0.1, 0, 1)),
        glm::transpose(glm::dmat3(1, 0, 0.6, 0, 1, 0, 0.5, 0, 1)),
        glm::transpose(glm::dmat3(0.1, 0.5, 1, 0.2, 1, 1, 0, 2, 0.5)),  // the supplement's
    };
    for (const glm::dmat3& M : Ms) {
        const ltc_model model{ltc::transformed<ltc::clamped_cosine<double>>(M)};
        for (const auto& poly : polygons()) {
            CAPTURE(poly.name);
            const double exact = model.d.integrate(poly.v.data(), poly.v.size());
            gt::options opt;
            opt.samples = 100000;
            opt.seed = 99;
            const gt::estimate e = gt::integrate(model, dvec3(0, 0, 1), 0.0, poly.v.data(), poly.v.size(), opt);
            CAPTURE(e.mean, e.standard_error, exact);
            // The rare BRDF hits of the tiny triangle (see the Lambertian case): their share is
            // about Omega D (D nearly constant over the triangle).
            const double omega = std::abs(ltc::solid_angle(poly.v.data(), poly.v.size()));
            const double rare = omega > 0.01 ? 0.0 : 1.5 * omega * model.d.eval(glm::normalize(poly.v[0])) * exact;
            CHECK(std::abs(e.mean - exact) <= 4 * e.standard_error + rare + 1e-12);
        }
    }
}

TEST_CASE("ground truth of GGX: the techniques agree, and adaptive mode reaches its target", "[ground_truth]") {
    const auto polys = polygons();
    for (const double theta : {0.0, 60.0, 85.0})
        for (const double alpha : {0.01, 0.2, 1.0}) {
            const dvec3 V = ltc::brdf::view_from_cos(std::cos(theta * ltc::pi<double>() / 180));
            for (const auto& poly : {polys[0], polys[1], polys[4]}) {
                CAPTURE(theta, alpha, poly.name);
                gt::options opt;
                opt.samples = 50000;
                opt.seed = 5;
                const gt::estimate mis = gt::integrate(ltc::brdf::ggx<double>{}, V, alpha, poly.v.data(), poly.v.size(), opt);
                opt.use = gt::techniques::polygon_only;
                opt.seed = 6;
                const gt::estimate pol = gt::integrate(ltc::brdf::ggx<double>{}, V, alpha, poly.v.data(), poly.v.size(), opt);
                opt.use = gt::techniques::mis;
                opt.weighting = gt::heuristic::power;
                opt.seed = 7;
                const gt::estimate pow = gt::integrate(ltc::brdf::ggx<double>{}, V, alpha, poly.v.data(), poly.v.size(), opt);
                CAPTURE(mis.mean, mis.standard_error, pol.mean, pol.standard_error, pow.mean, pow.standard_error);
                CHECK(std::abs(mis.mean - pol.mean) <= 4.5 * std::hypot(mis.standard_error, pol.standard_error) + 1e-15);
                CHECK(std::abs(mis.mean - pow.mean) <= 4.5 * std::hypot(mis.standard_error, pow.standard_error) + 1e-15);
            }
        }
    gt::options opt;
    opt.samples = 4096;
    opt.target_relative_error = 0.01;
    const auto& quad = polys[0];
    const gt::estimate e = gt::integrate(ltc::brdf::ggx<double>{}, ltc::brdf::view_from_cos(0.7), 0.3, quad.v.data(), 4, opt);
    CHECK(e.standard_error <= 0.01 * e.mean);
    CHECK(e.samples % 4096 == 0);
    CHECK(e.samples <= opt.max_samples);
}

TEST_CASE("ground truth is deterministic and handles degenerate polygons", "[ground_truth]") {
    const auto polys = polygons();
    const dvec3 V = ltc::brdf::view_from_cos(0.6);
    gt::options opt;
    opt.samples = 1000;
    const gt::estimate a = gt::integrate(ltc::brdf::ggx<double>{}, V, 0.1, polys[1].v.data(), 4, opt);
    const gt::estimate b = gt::integrate(ltc::brdf::ggx<double>{}, V, 0.1, polys[1].v.data(), 4, opt);
    CHECK(a.mean == b.mean);
    CHECK(a.standard_error == b.standard_error);
    opt.seed = 2;
    const gt::estimate c = gt::integrate(ltc::brdf::ggx<double>{}, V, 0.1, polys[1].v.data(), 4, opt);
    CHECK(a.mean != c.mean);

    const dvec3 below[3] = {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}};
    const gt::estimate e = gt::integrate(lambert{}, V, 0.0, below, 3, opt);
    CHECK(e.mean == 0.0);
    CHECK(e.standard_error == 0.0);
    const dvec3 at_origin[3] = {{0, 0, 0}, {1, 0, 1}, {0, 1, 1}};
    CHECK(gt::integrate(lambert{}, V, 0.0, at_origin, 3, opt).mean == 0.0);
    CHECK(gt::integrate(lambert{}, V, 0.0, at_origin, 2, opt).mean == 0.0);
    const dvec3 collinear[3] = {{0, 0, 1}, {1, 0, 1}, {2, 0, 1}};
    CHECK(gt::integrate(lambert{}, V, 0.0, collinear, 3, opt).mean == 0.0);
}
