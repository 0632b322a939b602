// Conventions of ltc/core/polygon.hpp: the sign of the signed integrals, one- and two-sided
// form factors, clipping to the horizon, and the vector form factor; checked against the
// brute-force integration of support/brute_force.hpp where a value is compared, with the
// tolerances of test_polygon_integration.cpp.
#include <ltc/ltc.hpp>

#include "support/brute_force.hpp"
#include "support/polygon_references.hpp"
#include "support/rng.hpp"
#include "support/rounding_bound.hpp"
#include "support/star_polygons.hpp"

#include <catch2/catch.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace ltc_test_polygon_conventions {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::polygon_integration;  // support/polygon_references.hpp and the bound

TEST_CASE("sign convention: signed integrals are positive when dot(p0, (p1 - p0) x (p2 - p0)) > 0", "[polygon][sign]") {
    ltc_test::rng r(0x5eed0003);
    for (int i = 0; i < 50; ++i) {
        // convex polygons (all radii equal), where the header's literal formula applies
        ltc_test::polygon_options o;
        o.above_horizon = true;
        ltc_test::test_polygon tp = ltc_test::random_polygon(r, o);
        // make it convex: project every vertex onto the circle of radius 1 around the kernel
        const dvec3 c = tp.kernel;
        for (dvec3& v : tp.v) {
            const dvec3 d = v - c - glm::dot(v - c, tp.normal) * tp.normal;
            v = dvec3(glm::vec3(c + glm::normalize(d)));
        }
        if (!std::all_of(tp.v.begin(), tp.v.end(), [](const dvec3& v) { return v.z > 0; })) continue;
        const poly_t& p = tp.v;
        const double literal = glm::dot(p[0], glm::cross(p[1] - p[0], p[2] - p[0]));
        const int sign = literal > 0 ? 1 : -1;
        const auto vd = to<double>(p);
        const auto vf = to<float>(p);
        const std::string polygon = str(p);
        CAPTURE(polygon, literal);
        CHECK(sign == ltc_test::orientation_sign(p, c));
        CHECK(ltc::solid_angle(vd.data(), vd.size()) * sign > 0);
        CHECK(ltc::solid_angle(vf.data(), vf.size()) * sign > 0);
        CHECK(ltc::clipped_solid_angle(vd.data(), vd.size()) * sign > 0);
        CHECK(ltc::form_factor_signed(vd.data(), vd.size()) * sign > 0);
        CHECK(ltc::form_factor_signed(vf.data(), vf.size()) * sign > 0);
        CHECK(ltc::vector_form_factor(vd.data(), vd.size()).z * sign > 0);
        for (int id = 0; id < 4; ++id) {
            CHECK(closed_form_signed<double>(id, p) * sign > 0);
            CHECK(closed_form_signed<float>(id, p) * sign > 0);
            CHECK(closed_form_signed<double>(id, reversed(p)) * sign < 0);
        }
    }
}

TEST_CASE("form_factor: one-sided is max(0, signed), two-sided is |signed|", "[polygon][sidedness]") {
    ltc_test::rng r(0x5eed0004);
    for (int i = 0; i < 40; ++i) {
        ltc_test::polygon_options o;
        o.cross_horizon = i % 2 == 1;
        o.orientation = 1;
        const ltc_test::test_polygon tp = ltc_test::random_polygon(r, o);
        for (const poly_t& p : {tp.v, reversed(tp.v)}) {
            const auto v = to<float>(p);
            const float s = ltc::form_factor_signed(v.data(), v.size());
            CAPTURE(s);
            CHECK(ltc::form_factor(v.data(), v.size(), ltc::sidedness::one_sided) == std::max(s, 0.0f));
            CHECK(ltc::form_factor(v.data(), v.size(), ltc::sidedness::two_sided) == std::abs(s));
            CHECK(ltc::apply_sidedness(-s, ltc::sidedness::one_sided) == std::max(-s, 0.0f));
        }
        const auto v = to<double>(tp.v);
        const auto vr = to<double>(reversed(tp.v));
        const double s = ltc::form_factor_signed(v.data(), v.size());
        if (s != 0) {
            // the polygon faces the shading point: the one-sided emitter shows, reversed it does not
            CHECK(s > 0);
            CHECK(ltc::form_factor(v.data(), v.size(), ltc::sidedness::one_sided) == s);
            CHECK(ltc::form_factor(vr.data(), vr.size(), ltc::sidedness::one_sided) == 0);
            CHECK(ltc::form_factor(vr.data(), vr.size(), ltc::sidedness::two_sided) > 0);
        }
    }
}

TEST_CASE("clip_to_horizon", "[polygon][clip]") {
    SECTION("a triangle with one vertex below: 4 vertices, crossing points exactly on z = 0") {
        const glm::dvec3 in[3] = {{0, 1, 1}, {1, 1, -1}, {-1, 1, 2}};
        glm::dvec3 out[ltc::clipped_capacity(3)];
        REQUIRE(ltc::clip_to_horizon(in, 3, out) == 4);
        // the order is kept: v0, crossing on 0 -> 1, crossing on 1 -> 2, v2
        CHECK(out[0] == in[0]);
        CHECK(out[1].z == 0);
        CHECK(out[2].z == 0);
        CHECK(out[3] == in[2]);
        CHECK(glm::length(glm::cross(out[1] - in[0], in[1] - in[0])) < 1e-15);  // on the edges
        CHECK(glm::length(glm::cross(out[2] - in[1], in[2] - in[1])) < 1e-15);
    }
    SECTION("fully above, fully below, n < 3, a vertex on the horizon") {
        const glm::vec3 above[3] = {{0, 0, 1}, {1, 0, 1}, {0, 1, 2}};
        const glm::vec3 below[3] = {{0, 0, -1}, {1, 0, -1}, {0, 1, -2}};
        const glm::vec3 touching[3] = {{1, 0, 0}, {1, 1, -1}, {0, 1, 2}};
        glm::vec3 out[ltc::clipped_capacity(3)];
        // a polygon above the horizon is copied unchanged
        CHECK(ltc::clip_to_horizon(above, 3, out) == 3);
        CHECK((out[0] == above[0] && out[1] == above[1] && out[2] == above[2]));
        CHECK(ltc::clip_to_horizon(below, 3, out) == 0);
        CHECK(ltc::clip_to_horizon(above, 2, out) == 0);
        CHECK(ltc::form_factor_signed(below, 3) == 0);
        CHECK(ltc::clipped_solid_angle(below, 3) == 0);
        // a vertex on z = 0 counts as inside; the crossing on its outgoing edge is the vertex
        // itself (a zero-length edge, which contributes 0)
        REQUIRE(ltc::clip_to_horizon(touching, 3, out) == 4);
        CHECK(out[0] == touching[0]);
        CHECK(out[1] == touching[0]);
        CHECK(out[2].z == 0);
        CHECK(out[3] == touching[2]);
    }
    SECTION("a non-convex star crossing the horizon three times") {
        // 12-gon star in the plane y = 1 around (0, 1, 0.5): spikes of radius 2 every 60 degrees,
        // inner vertices of radius 0.4 between them. The spikes at 210, 270 and 330 degrees
        // dip below the horizon, the inner vertices between them stay above: three runs below.
        poly_t p;
        const dvec3 c(0, 1, 0.5);
        for (int k = 0; k < 12; ++k) {
            const double a = kPi / 6 * (k + 1) - kPi / 6 * 2;  // k = 0: -30 degrees (a spike)
            const double rad = k % 2 == 0 ? 2 : 0.4;
            p.push_back(dvec3(glm::vec3(c + rad * dvec3(std::cos(a), 0, std::sin(a)))));
        }
        int below = 0;
        for (const dvec3& v : p) below += v.z < 0;
        REQUIRE(below == 3);
        const auto v = to<double>(p);
        std::vector<dvec3> out(ltc::clipped_capacity(p.size()));
        const std::size_t m = ltc::clip_to_horizon(v.data(), v.size(), out.data());
        CHECK(m == 12 - 3 + 2 * 3);
        REQUIRE(m <= ltc::clipped_capacity(12));
        int on_horizon = 0;
        for (std::size_t i = 0; i < m; ++i) {
            CHECK(out[i].z >= 0);
            on_horizon += out[i].z == 0;
        }
        CHECK(on_horizon == 6);
        // Integrals of the clipped polygon without clipping equal the clipped integrals of the
        // original (the back-and-forth edges along z = 0 cancel); and both equal the brute force.
        const double ff = ltc::form_factor_signed(v.data(), v.size());
        const double ff_clipped = ltc::vector_form_factor(out.data(), m).z;
        const double omega = ltc::clipped_solid_angle(v.data(), v.size());
        const double omega_clipped = ltc::solid_angle(out.data(), m);
        const auto bf = ltc_test::integrate_polygon<4>(p, c, dvec3(0, 0, 1), reference_densities);
        const double u = unit_roundoff<double>();
        const poly_t clipped(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(m));
        // tolerances: rounding bounds of both closed forms (+ the quadrature estimate)
        const double b_ff = rounding_bound(form::cosine, p, {}, u, std::abs(ff)) +
                            rounding_bound(form::cosine_unclipped, clipped, {}, u, std::abs(ff));
        const double b_om = 2 * kPi *
                            (rounding_bound(form::hemisphere, p, {}, u, std::abs(omega) / (2 * kPi)) +
                             rounding_bound(form::sphere, clipped, {}, u, std::abs(omega) / (4 * kPi)) * 2);
        CAPTURE(ff, ff_clipped, omega, omega_clipped, bf.value[cosine], bf.value[hemisphere], b_ff, b_om);
        CHECK(std::abs(ff - ff_clipped) <= b_ff);
        CHECK(std::abs(omega - omega_clipped) <= b_om);
        CHECK(std::abs(std::abs(ff) - bf.value[cosine]) <= bf.error[cosine] + b_ff);
        CHECK(std::abs(std::abs(omega) / (2 * kPi) - bf.value[hemisphere]) <= bf.error[hemisphere] + b_om / (2 * kPi));
    }
    SECTION("random polygons: the clipped vertex count follows the runs below the horizon") {
        ltc_test::rng r(0x5eed0005);
        for (int i = 0; i < 100; ++i) {
            ltc_test::polygon_options o;
            o.cross_horizon = true;
            const ltc_test::test_polygon tp = ltc_test::random_polygon(r, o);
            const auto v = to<float>(tp.v);
            std::vector<glm::vec3> out(ltc::clipped_capacity(v.size()));
            const std::size_t m = ltc::clip_to_horizon(v.data(), v.size(), out.data());
            std::size_t above = 0, sign_changes = 0;
            for (std::size_t k = 0; k < v.size(); ++k) {
                above += v[k].z >= 0;
                sign_changes += (v[k].z >= 0) != (v[(k + 1) % v.size()].z >= 0);
            }
            CHECK(m == above + sign_changes);
            for (std::size_t k = 0; k < m; ++k) CHECK(out[k].z >= 0);
        }
    }
}

TEST_CASE("vector_form_factor: z is the unclipped cosine integral, x and y its other moments",
          "[polygon][vector_form_factor]") {
    ltc_test::rng r(0x5eed0006);
    const double u = unit_roundoff<double>();
    for (int i = 0; i < 60; ++i) {
        ltc_test::polygon_options o;
        o.above_horizon = i % 2 == 0;
        o.cross_horizon = i % 2 == 1;
        const ltc_test::test_polygon tp = ltc_test::random_polygon(r, o);
        const auto v = to<double>(tp.v);
        const dvec3 f = ltc::vector_form_factor(v.data(), v.size());
        const int sign = ltc_test::orientation_sign(tp.v, tp.kernel);
        // F = 1/pi int w dw over the polygon (signed by orientation), with no clamping. The 4th
        // component, 1/pi, bounds the brute force's rounding for the others: a node direction
        // error delta changes w_k / pi by <= delta / pi (direction_condition 1 for it).
        ltc_test::brute_force_options bo;
        bo.direction_condition = 1;
        const auto bf = ltc_test::integrate_polygon<4>(
            tp.v, tp.kernel, dvec3(0),
            [](const dvec3& w, double) {
                return std::array<double, 4>{w.x / kPi, w.y / kPi, w.z / kPi, 1 / kPi};
            },
            bo);
        const double bf_round = bf.error[3] - bf.quadrature_error[3];
        const std::string polygon = str(tp.v);
        for (int k = 0; k < 3; ++k) {
            // the closed form's bound holds for any axis (the edge terms are vectors)
            const double tol =
                bf.error[k] + bf_round + rounding_bound(form::cosine_unclipped, tp.v, {}, u, std::abs(bf.value[k]));
            CAPTURE(polygon, k, f[k], bf.value[k], tol);
            CHECK(std::abs(f[k] * sign - bf.value[k]) <= tol);
        }
        if (o.above_horizon) {
            const double ff = ltc::form_factor_signed(v.data(), v.size());
            const double tol = 2 * rounding_bound(form::cosine, tp.v, {}, u, std::abs(ff));
            CAPTURE(polygon, ff, f.z, tol);
            CHECK(std::abs(f.z - ff) <= tol);
        }
    }
}

}  // namespace ltc_test_polygon_conventions
