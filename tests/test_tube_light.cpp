// The tube light as its ribbon quad (ltc/shading/tube_light.hpp): (a) a long tube parallel to the
// floor against the infinite cylinder's exact form factor, (b) P inside the tube (or beyond an end,
// within its radius) against the openings' disk form factors, (c) the ribbon is shade_polygon_light_one_lobe
// of the quad, bit for bit, (d) degenerate and huge input, (e) GGX against Monte Carlo of the real
// cylinder within tools/shape_error_report's measurements.
#include <ltc/brdf/ggx.hpp>
#include <ltc/reference/ground_truth.hpp>
#include <ltc/reference/shape_ground_truth.hpp>
#include <ltc/shading/polygon_light.hpp>
#include <ltc/shading/tube_light.hpp>

#include "support/rng.hpp"
#include "support/shading_scene.hpp"

#include <catch2/catch.hpp>
#include <glm/glm.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace ltc_test_tube_light {  // the file's own names, apart from the other files of a unity batch

namespace {

using glm::dvec3;
template <typename T> using vec3 = glm::vec<3, T>;
namespace gt = ltc::ground_truth;
constexpr double pi = 3.141592653589793, deg = pi / 180;

/// A random world frame: P in [-1, 1]^3, unit N, V at cos_theta_v from N, (t1, t2, N) as
/// ltc::make_shading_frame's (t1 along V's tangential part).
using scene = ltc_test::shading_scene;
inline scene random_scene(ltc_test::rng& r, double cos_theta_v) { return ltc_test::random_shading_scene(r, cos_theta_v); }

template <typename T> vec3<T> cast(const dvec3& v) { return vec3<T>(v); }

}  // namespace

TEMPLATE_TEST_CASE("tube light: a long tube parallel to the floor has the infinite cylinder's form factor",
                   "[tube_light]", float, double) {
    // In the cross-section (x across, h up) the cylinder covers the wedge phi in [c - d, c + d] from
    // the normal, c = atan2(x, h), d = asin(r / rho); an infinite object's form factor is
    // (sin phi2 - sin phi1) / 2 (Hottel's crossed strings), clipped to phi in [-pi/2, pi/2]. The tube's
    // half-length H = 1000 rho leaves out (rho / H)^3 / pi of it, and the ends' sliver r / H of that.
    using T = TestType;
    ltc_test::rng r(0x70BE);
    const vec3<T> one(1);
    double worst = 0;
    for (int i = 0; i < 400; ++i) {
        const scene s = random_scene(r, r.uniform(0.05, 1));
        const double x = r.uniform(-2, 2), h = r.uniform(-0.6, 2), rho = std::hypot(x, h);
        const double rad = rho * r.uniform(0.02, 0.95), H = 1000 * rho, az = r.uniform(0, 2 * pi);
        const dvec3 axis(std::cos(az), std::sin(az), 0), across(-axis.y, axis.x, 0), c = x * across + dvec3(0, 0, h);
        const double c_phi = std::atan2(x, h), d_phi = std::asin(rad / rho);
        const double lo = std::max(-pi / 2, c_phi - d_phi), hi = std::min(pi / 2, c_phi + d_phi);
        const double exact = hi > lo ? (std::sin(hi) - std::sin(lo)) / 2 : 0.0;
        const auto res = ltc::shade_tube_light(cast<T>(s.P), cast<T>(s.N), cast<T>(s.V), T(0.5), one, one, one,
                                               cast<T>(s.world(c - H * axis)), cast<T>(s.world(c + H * axis)), T(rad));
        // Tolerance: float geometry at |p| ~ H rounds the quad's corners by u H, i.e. u H / r of its width.
        const double tol = std::is_same<T, float>::value ? 1e-6 * H / rad + 1e-6 : 1e-9;
        const double err = std::abs(double(res.diffuse.x) - exact);
        CAPTURE(i, x, h, rad, exact, res.diffuse.x);
        CHECK(err <= tol * std::max(exact, 1e-3));
        worst = std::max(worst, err / (tol * std::max(exact, 1e-3)));
    }
    std::printf("tube light, long tube vs the infinite cylinder's form factor (%s): worst error / tolerance %.3g\n",
                std::is_same<T, float>::value ? "float" : "double", worst);
}

TEMPLATE_TEST_CASE("tube light: P inside the tube sees all but the openings", "[tube_light]", float, double) {
    // The axis along N through P: the opening at height z (radius r) has the form factor r^2 / (z^2 + r^2)
    // above the horizon, 0 below. Within the span: E = 1 - that of the upper opening; below the tube
    // (0 < z0 < z1): E = F(z0) - F(z1), the wall seen through the near opening.
    using T = TestType;
    ltc_test::rng r(0x1D5);
    const vec3<T> one(1);
    const auto F = [](double z, double rad) { return z > 0 ? rad * rad / (z * z + rad * rad) : 0.0; };
    for (int i = 0; i < 100; ++i) {
        const scene s = random_scene(r, r.uniform(0.05, 1));
        const double rad = r.uniform(0.1, 2), a = r.uniform(0.1, 3), b = r.uniform(0.1, 3);
        const auto shade = [&](double z0, double z1) {
            return ltc::shade_tube_light(cast<T>(s.P), cast<T>(s.N), cast<T>(s.V), T(r.uniform(0.05, 1)), one, one,
                                         one, cast<T>(s.world(dvec3(0, 0, z0))), cast<T>(s.world(dvec3(0, 0, z1))),
                                         T(rad));
        };
        const auto in = shade(-a, b), below = shade(a, a + b);
        CAPTURE(i, rad, a, b, in.diffuse.x, below.diffuse.x);
        CHECK(std::abs(in.diffuse.x - (1 - F(b, rad))) <= 1e-5);
        CHECK(std::abs(below.diffuse.x - (F(a, rad) - F(a + b, rad))) <= 1e-5);
        for (const auto& res : {in, below}) {  // magnitude * I in [0, magnitude]; magnitude <= 1
            CHECK(res.specular.x >= 0);
            CHECK(res.specular.x <= 1);
        }
    }
}

TEMPLATE_TEST_CASE("tube light: the ribbon is shade_polygon_light_one_lobe of its quad, bit for bit", "[tube_light]", float,
                   double) {
    using T = TestType;
    ltc_test::rng r(0xB17);
    const vec3<T> F0(T(0.9), T(0.5), T(0.04)), albedo(T(0.2), T(0.7), T(1)), radiance(T(3), T(1), T(0.5));
    int ribbons = 0;
    for (int i = 0; i < 500; ++i) {
        const scene s = random_scene(r, r.uniform(0, 1));
        const vec3<T> P = cast<T>(s.P), p0 = cast<T>(s.world(2.0 * r.direction())),
                      p1 = cast<T>(s.world(2.0 * r.direction()));
        const T rad = T(r.uniform(0.001, 1)), rough = T(r.uniform(0.05, 1));
        const ltc::tube_ribbon<T> q = ltc::make_tube_ribbon(P, p0, p1, rad);
        const auto a = ltc::shade_tube_light(P, cast<T>(s.N), cast<T>(s.V), rough, F0, albedo, radiance, p0, p1, rad);
        if (q.kind != ltc::tube_ribbon<T>::ribbon) continue;
        ++ribbons;
        REQUIRE(q.origin == P);
        const auto b = ltc::shade_polygon_light_one_lobe(P, cast<T>(s.N), cast<T>(s.V), rough, F0, albedo, radiance,
                                                         q.corner, 4, ltc::sidedness::two_sided);
        CAPTURE(i);
        CHECK(a.specular == b.specular);
        CHECK(a.diffuse == b.diffuse);
    }
    CHECK(ribbons > 400);
}

TEMPLATE_TEST_CASE("tube light: degenerate and huge input gives finite results", "[tube_light]", float, double) {
    using T = TestType;
    const T inf = std::numeric_limits<T>::infinity(), nan = std::numeric_limits<T>::quiet_NaN(),
            big = std::numeric_limits<T>::max();
    const vec3<T> P(0), N(0, 0, 1), V(T(0.6), 0, T(0.8)), one(1), p0(-1, 0, 1), p1(1, 0, 1);
    const auto shade = [&](vec3<T> p, vec3<T> n, vec3<T> a, vec3<T> b, T rad) {
        return ltc::shade_tube_light(p, n, V, T(0.3), one, one, one, a, b, rad);
    };
    const auto finite = [](const ltc::polygon_light_result<T>& res) {
        return std::isfinite(res.specular.x) && std::isfinite(res.diffuse.x) && res.specular.x >= 0 &&
               res.diffuse.x >= 0 && res.diffuse.x <= 1;
    };
    const auto zero = [](const ltc::polygon_light_result<T>& res) { return res.specular.x == 0 && res.diffuse.x == 0; };
    CHECK(zero(shade(P, N, p0, p0, T(0.1))));             // zero length
    CHECK(zero(shade(P, N, p0, p1, T(0))));               // radius 0, negative, NaN, infinite
    CHECK(zero(shade(P, N, p0, p1, T(-1))));
    CHECK(zero(shade(P, N, p0, p1, nan)));
    CHECK(zero(shade(P, N, p0, p1, inf)));
    CHECK(zero(shade(P, vec3<T>(0), p0, p1, T(0.1))));    // N = 0
    CHECK(zero(shade(P, N, vec3<T>(inf, 0, 1), p1, T(0.1))));
    CHECK(zero(shade(vec3<T>(nan), N, p0, p1, T(0.1))));
    CHECK(finite(shade(P, N, vec3<T>(-1, 0, 0), vec3<T>(1, 0, 0), T(0.1))));  // the axis through P
    CHECK(finite(shade(P, N, vec3<T>(-1, 0, T(0.1)), vec3<T>(1, 0, T(0.1)), T(0.1))));  // P on the surface
    CHECK(finite(shade(P, N, p0, p1, big)));                                   // a huge radius: inside
    CHECK(finite(shade(vec3<T>(-big), N, vec3<T>(big), vec3<T>(big, big, -big), T(1))));
    CHECK(finite(shade(vec3<T>(big, 0, 0), N, vec3<T>(-big, 0, big), vec3<T>(-big, big, big), big / 2)));
    CHECK(finite(shade(P, N, p0, p1, std::numeric_limits<T>::min())));        // a tiny radius
    // Within 16x of overflow everything is scaled by a power of two: the same result as the unscaled.
    const T k = std::ldexp(T(1), std::numeric_limits<T>::max_exponent - 3);
    const auto a = shade(P, N, p0, p1, T(0.1)), b = shade(P * k, N, p0 * k, p1 * k, T(0.1) * k);
    CHECK(b.specular.x == Approx(a.specular.x).epsilon(1e-5));
    CHECK(b.diffuse.x == Approx(a.diffuse.x).epsilon(1e-5));
    CHECK(a.diffuse.x > 0);
}

TEST_CASE("tube light: GGX against Monte Carlo within shape_error_report's measured errors", "[tube_light]") {
    // Tubes of tools/shape_error_report's grid (grid.hpp, restated), with the report's figures
    // (--list, 2^16 iterations): shade_tube_light's signed error against MC of the cylinder, that MC's
    // relative standard error, and the ribbon's silhouette error (MC of the GGX over the quad against MC
    // of the cylinder) and that MC's. Bound as test_shape_lights.cpp's: |reported| + 0.005% + 4 standard
    // errors of the independent runs' difference.
    struct report_case {
        const char* name;
        int placement;  // 0 mirror-across, 1 mirror-along, 2 side
        double theta, roughness, angle, radius;
        double error, rse, silhouette, ribbon_rse;
    } const cases[] = {
        {"th 30 r 0.10 2 deg mirror-across", 0, 30, 0.1, 2, 0.01, -0.0060, 0.00374, -0.0047, 0.0025},
        {"th 0 r 0.25 close mirror-across", 0, 0, 0.25, 30, 1 / 3.0, +0.0041, 0.00150, -0.0047, 0.0017},
        {"th 0 r 1.00 close mirror-across", 0, 0, 1.0, 30, 1 / 3.0, -0.1383, 0.00593, -0.1248, 0.0009},
        {"th 60 r 0.50 close mirror-along", 1, 60, 0.5, 30, 1 / 3.0, -0.0426, 0.00304, -0.0376, 0.0019},
    };
    const auto bound = [](double reported, double a, double b) { return std::abs(reported) + 0.00005 + 4 * std::hypot(a, b); };
    const auto rse = [](const gt::estimate& e) { return e.standard_error / e.mean; };
    ltc_test::rng r(0x7B3);
    const ltc::brdf::ggx<double> ggx;
    const dvec3 one(1);
    for (const report_case& k : cases) {
        CAPTURE(k.name);
        const double th = k.theta * deg, alpha = k.roughness * k.roughness;
        const dvec3 V(std::sin(th), 0, std::cos(th)), dir(-V.x, 0, V.z);
        const dvec3 h = glm::cross(dvec3(0, 0, 1), dir);
        const dvec3 across = glm::length(h) > 1e-9 ? glm::normalize(h) : dvec3(0, 1, 0), up = glm::cross(dir, across);
        const dvec3 p0 = dir - std::tan(k.angle * deg) * (k.placement == 1 ? up : across), p1 = 2.0 * dir - p0;
        const scene s = random_scene(r, V.z);
        const double value = ltc::shade_tube_light(s.P, s.N, s.V, k.roughness, one, one, one, s.world(p0),
                                                   s.world(p1), k.radius).specular.x;
        gt::options opt;
        opt.samples = 1u << 16, opt.seed = 0x7E58;
        const gt::estimate e = gt::integrate_tube(ggx, V, alpha, p0, p1, k.radius, opt);
        const ltc::tube_ribbon<double> q = ltc::make_tube_ribbon(dvec3(0), p0, p1, k.radius);
        REQUIRE(q.kind == ltc::tube_ribbon<double>::ribbon);
        opt.seed += 1;
        const gt::estimate quad = gt::integrate(ggx, V, alpha, q.corner, 4, opt);
        const double error = std::abs(value / e.mean - 1), silhouette = std::abs(quad.mean / e.mean - 1);
        CAPTURE(value, e.mean, quad.mean, error, silhouette);
        CHECK(error <= bound(k.error, k.rse, rse(e)));
        CHECK(silhouette <= bound(k.silhouette, std::hypot(k.rse, k.ribbon_rse), std::hypot(rse(e), rse(quad))));
        CHECK(value <= ltc::ggx::fetch(V.z, k.roughness).magnitude);  // never above the whole lobe
        std::printf("tube light vs MC, %-34s error %6.2f%% (report %+6.2f%%), silhouette %6.2f%% (report %+6.2f%%)\n",
                    k.name, 100 * error, 100 * k.error, 100 * silhouette, 100 * k.silhouette);
    }
}

}  // namespace ltc_test_tube_light
