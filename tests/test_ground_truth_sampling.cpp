// Tests of the samplers of ltc/reference/ground_truth.hpp: its random number generator
// (splitmix64.hpp), the spherical triangle sampler (spherical_triangle.hpp), and the spherical
// polygon (spherical_polygon.hpp: winding, density, solid angle).
//
// Every random test uses a fixed seed, so it is deterministic; the tolerances are 4 to 5
// standard errors, which a correct estimator fails with probability < 1e-4 per check for the
// seed chosen (and, being deterministic, either always or never).
#include <catch2/catch.hpp>

#include <ltc/reference/ground_truth.hpp>
#include <ltc/ltc.hpp>

#include "support/ground_truth_models.hpp"
#include "support/rng.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace ltc_test_ground_truth_sampling {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::ground_truth_checks;  // the "BRDFs" and the test polygons

namespace {

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

}  // namespace ltc_test_ground_truth_sampling
