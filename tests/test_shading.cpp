// Tests of ltc/shading/polygon_light.hpp: the shading frame, the diffuse and specular terms against the
// library's closed forms, sidedness, degenerate input, the shading_first clip order against an
// explicitly clipped polygon, and the LTC shading against the Monte Carlo ground truth of the
// real GGX integral over a small documented grid.
#include <catch2/catch.hpp>

#include <ltc/fitting/brdf/ggx.hpp>
#include <ltc/reference/ground_truth.hpp>
#include <ltc/ltc.hpp>
#include <ltc/shading/polygon_light.hpp>

#include "support/rng.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace {

using glm::dmat3;
using glm::dvec3;
using clip_mode = ltc::horizon_clipping;
constexpr double pi = 3.141592653589793;

const clip_mode all_modes[] = {clip_mode::ltc_space, clip_mode::shading_first, clip_mode::sphere_analytic,
                               clip_mode::sphere_table};

/// A lobe of the paper's form [a 0 b; 0 c 0; d 0 1] (as M^-1), with magnitude and Fresnel terms.
ltc::ltc_coefficients<double> lobe(double a, double b, double c, double d, double magnitude = 0.8, double fresnel = 0.1) {
    ltc::ltc_coefficients<double> k;
    k.m_inv = glm::transpose(dmat3(a, 0, b, 0, c, 0, d, 0, 1));
    k.magnitude = magnitude;
    k.fresnel = fresnel;
    return k;
}

/// A random rotation (from three random directions, Gram-Schmidt).
dmat3 random_rotation(ltc_test::rng& rng) {
    // (one random call per statement: argument evaluation order is unspecified)
    const dvec3 a = rng.direction();
    const dvec3 c = rng.direction();
    const dvec3 b = glm::normalize(c - a * glm::dot(a, c));
    return dmat3(a, b, glm::cross(a, b));
}

/// A scene: shading point, normal, view, and a light (world space).
struct scene {
    dvec3 P, N, V;
    std::vector<dvec3> light;
};

/// Random scenes: a quad, a triangle or a non-convex hexagon, at random places, often straddling
/// the shading horizon, front- or back-facing.
std::vector<scene> random_scenes(int count, std::uint64_t seed) {
    ltc_test::rng rng(seed);
    std::vector<scene> s;
    for (int k = 0; k < count; ++k) {
        scene sc;
        for (int i = 0; i < 3; ++i) sc.P[i] = rng.uniform(-2, 2);
        sc.N = rng.direction();
        dvec3 v = rng.direction();
        if (glm::dot(v, sc.N) < 0) v = -v;
        sc.V = v;
        const dmat3 R = random_rotation(rng);
        const double distance = rng.uniform(0.5, 3);
        const dvec3 centre = sc.P + distance * rng.direction();
        const double size = rng.uniform(0.1, 2);
        // (built once: assigning an initializer list here trips GCC 12's -Wnonnull, a false positive)
        static const std::vector<glm::dvec2> shapes[3] = {
            {{-1, -0.5}, {1, -0.5}, {1, 0.5}, {-1, 0.5}},
            {{0, 1}, {0.9, -0.5}, {-0.9, -0.4}},
            {{-1, -1}, {1, -1}, {1, 0}, {0, 0}, {0, 1}, {-1, 1}},  // L shape
        };
        for (const auto& q : shapes[k % 3]) sc.light.push_back(centre + size * (R * dvec3(q, 0)));
        s.push_back(sc);
    }
    return s;
}

/// The light in the shading frame (T1, T2, N), as polygon_light.hpp builds it.
std::vector<dvec3> local_light(const scene& sc) {
    const auto f = ltc::make_shading_frame(sc.N, sc.V);
    std::vector<dvec3> v;
    for (const dvec3& p : sc.light) v.push_back(f.to_local(p - sc.P));
    return v;
}

/// |a - b| relative to max(|a|, |b|, 0.01): values near zero (edge-on or horizon-grazing lights,
/// where relative differences mean nothing) are compared absolutely.
double rel_diff(double a, double b) { return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-2}); }

}  // namespace

TEST_CASE("shading frame: orthonormal, right-handed, V in the xz half-plane, V parallel to N", "[shading]") {
    ltc_test::rng rng(3);
    for (int k = 0; k < 1000; ++k) {
        const dvec3 N = rng.direction();
        dvec3 V = rng.direction();
        if (k % 10 == 0) V = N;                                    // exactly parallel
        if (k % 10 == 1) V = glm::normalize(N + 1e-9 * rng.direction());  // nearly
        if (k % 10 == 2) V = -N;                                   // from below
        const auto f = ltc::make_shading_frame(N, V);
        REQUIRE(f.valid);
        CHECK(std::abs(glm::length(f.t1) - 1) < 1e-14);
        CHECK(std::abs(glm::length(f.t2) - 1) < 1e-14);
        CHECK(std::abs(glm::dot(f.t1, N)) < 1e-14);
        CHECK(std::abs(glm::dot(f.t2, N)) < 1e-14);
        CHECK(std::abs(glm::dot(f.t1, f.t2)) < 1e-14);
        CHECK(glm::length(glm::cross(f.t1, f.t2) - N) < 1e-14);
        const dvec3 v = f.to_local(V);
        CHECK(std::abs(v.y) < 1e-14);
        CHECK(v.x >= -1e-15);
        CHECK(std::abs(f.cos_theta_v - glm::clamp(glm::dot(N, V), 0.0, 1.0)) <= 1e-15);
    }
    CHECK(!ltc::make_shading_frame(dvec3(0), dvec3(0, 0, 1)).valid);
    CHECK(ltc::make_shading_frame(dvec3(0, 0, 2), dvec3(0)).valid);  // V = 0: any T1
    // Duff et al.'s basis at both poles and on the equator.
    for (const dvec3 n : {dvec3(0, 0, 1), dvec3(0, 0, -1), dvec3(1, 0, 0), dvec3(0, -1, 0)}) {
        const dvec3 t = ltc::orthonormal_tangent(n);
        CHECK(std::abs(glm::length(t) - 1) < 1e-15);
        CHECK(std::abs(glm::dot(t, n)) < 1e-15);
    }
}

TEST_CASE("diffuse is albedo * radiance * form factor; specular is the Fresnel-weighted LTC integral", "[shading]") {
    const auto k = lobe(0.4, 0.15, 0.5, -0.2, 0.7, 0.12);
    const dvec3 F0(0.04, 0.5, 1.0), albedo(0.2, 0.5, 0.9), radiance(1.0, 2.0, 4.0);
    int checked = 0;
    for (const scene& sc : random_scenes(300, 17)) {
        const auto local = local_light(sc);
        const std::size_t n = local.size();
        const auto frame = ltc::make_shading_frame(sc.N, sc.V);
        const auto d = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(k.m_inv);
        for (const auto side : {ltc::sidedness::one_sided, ltc::sidedness::two_sided}) {
            const double E = ltc::form_factor(local.data(), n, side);
            const double I = d.integrate(local.data(), n, side);
            const auto r = ltc::shade_polygon_light(frame, k, sc.P, F0, albedo, radiance, sc.light.data(), n, side);
            for (int c = 0; c < 3; ++c) {
                CHECK(rel_diff(r.diffuse[c], albedo[c] * radiance[c] * E) <= 1e-12);
                const double scale = F0[c] * k.magnitude + (1 - F0[c]) * k.fresnel;
                CHECK(rel_diff(r.specular[c], radiance[c] * scale * I) <= 1e-12);
            }
            // shading_first shares its clip with the diffuse term: the same exact form factor.
            const auto s = ltc::shade_polygon_light(frame, k, sc.P, F0, albedo, radiance, sc.light.data(), n, side,
                                                    clip_mode::shading_first);
            for (int c = 0; c < 3; ++c) CHECK(rel_diff(s.diffuse[c], r.diffuse[c]) <= 1e-12);
            checked += E > 0;
        }
    }
    CHECK(checked > 100);
}

TEST_CASE("shading_first equals the LTC integral of the polygon clipped to the shading horizon", "[shading]") {
    const ltc::ltc_coefficients<double> lobes[] = {lobe(0.4, 0.15, 0.5, -0.2), lobe(1, 0.6, 1, 0.5),
                                                   lobe(0.05, -0.02, 0.06, 0.3)};
    std::size_t straddling = 0, differs = 0;
    for (const auto& k : lobes) {
        const auto d = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(k.m_inv);
        for (const scene& sc : random_scenes(300, 23)) {
            const auto local = local_light(sc);
            const std::size_t n = local.size();
            std::vector<dvec3> clipped(ltc::clipped_capacity(n));
            const std::size_t m = ltc::clip_to_horizon(local.data(), n, clipped.data());
            const auto frame = ltc::make_shading_frame(sc.N, sc.V);
            const auto first = ltc::integrate_polygon_light(frame, k.m_inv, sc.P, sc.light.data(), n, clip_mode::shading_first);
            const auto exact = ltc::integrate_polygon_light(frame, k.m_inv, sc.P, sc.light.data(), n, clip_mode::ltc_space);
            const double ref = d.integrate_signed(clipped.data(), m);
            CHECK(std::abs(first.ltc - ref) <= 1e-12 * std::max(std::abs(ref), 1e-3));
            CHECK(std::abs(first.form_factor - ltc::form_factor_signed(local.data(), n)) <= 1e-13);
            bool below = false, above = false;
            for (const auto& p : local) below = below || p.z < 0, above = above || p.z > 0;
            if (!below) CHECK(std::abs(first.ltc - exact.ltc) <= 1e-12 * std::max(std::abs(exact.ltc), 1e-3));
            if (below && above) {
                ++straddling;
                differs += std::abs(first.ltc - exact.ltc) > 1e-6;
            }
        }
    }
    CHECK(straddling > 100);
    CHECK(differs > straddling / 2);  // the order matters for lights that straddle the horizon
}

TEST_CASE("shading_first streams any vertex count without a buffer", "[shading]") {
    // A 2000-vertex star (non-convex), straddling the horizon: against clip_to_horizon into a
    // vector and transformed::integrate.
    const std::size_t n = 2000;
    std::vector<dvec3> star;
    for (std::size_t i = 0; i < n; ++i) {
        const double phi = 2 * pi * double(i) / double(n), r = i % 2 ? 0.4 : 1.0;
        star.push_back(dvec3(0.3 + r * std::cos(phi), r * std::sin(phi), 0.2 + 0.9 * r * std::sin(phi)) + dvec3(0, 0, 0.3));
    }
    const auto k = lobe(0.3, 0.1, 0.35, -0.25);
    const auto d = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(k.m_inv);
    std::vector<dvec3> clipped(ltc::clipped_capacity(n));
    const std::size_t m = ltc::clip_to_horizon(star.data(), n, clipped.data());
    REQUIRE(m > 3);
    REQUIRE(m != n);
    const ltc::shading_frame<double> frame;  // identity: N = z, V in the xz-plane
    const auto r = ltc::integrate_polygon_light(frame, k.m_inv, dvec3(0), star.data(), n, clip_mode::shading_first);
    CHECK_THAT(r.ltc, Catch::Matchers::WithinRel(d.integrate_signed(clipped.data(), m), 1e-11));
    CHECK_THAT(r.form_factor, Catch::Matchers::WithinRel(ltc::form_factor_signed(star.data(), n), 1e-11));
}

TEST_CASE("sidedness, lights below the horizon, invariance and degenerate input", "[shading]") {
    const auto k = lobe(0.4, 0.15, 0.5, -0.2, 0.7, 0.12);
    const dvec3 F0(0.04), albedo(0.5), radiance(1.0);
    ltc_test::rng rng(41);
    for (const scene& sc : random_scenes(200, 29)) {
        const auto frame = ltc::make_shading_frame(sc.N, sc.V);
        const std::size_t n = sc.light.size();
        std::vector<dvec3> reversed(sc.light.rbegin(), sc.light.rend());
        for (const auto mode : all_modes) {
            CAPTURE(int(mode));
            const auto front = ltc::integrate_polygon_light(frame, k.m_inv, sc.P, sc.light.data(), n, mode);
            const auto back = ltc::integrate_polygon_light(frame, k.m_inv, sc.P, reversed.data(), n, mode);
            // Reversing the vertices negates every signed integral (two-sided lights: symmetric).
            CHECK(std::abs(front.ltc + back.ltc) <= 1e-12 * std::max(std::abs(front.ltc), 1e-3));
            CHECK(std::abs(front.form_factor + back.form_factor) <= 1e-12 * std::max(std::abs(front.form_factor), 1e-3));
            const auto one_f = ltc::shade_polygon_light(frame, k, sc.P, F0, albedo, radiance, sc.light.data(), n, ltc::sidedness::one_sided, mode);
            const auto one_b = ltc::shade_polygon_light(frame, k, sc.P, F0, albedo, radiance, reversed.data(), n, ltc::sidedness::one_sided, mode);
            const auto two_f = ltc::shade_polygon_light(frame, k, sc.P, F0, albedo, radiance, sc.light.data(), n, ltc::sidedness::two_sided, mode);
            const auto two_b = ltc::shade_polygon_light(frame, k, sc.P, F0, albedo, radiance, reversed.data(), n, ltc::sidedness::two_sided, mode);
            // One-sided: exactly one of the two faces can be lit.
            CHECK((one_f.diffuse.x == 0.0 || one_b.diffuse.x == 0.0));
            CHECK((one_f.specular.x == 0.0 || one_b.specular.x == 0.0));
            CHECK(rel_diff(two_f.specular.x, two_b.specular.x) <= 1e-12);
            CHECK(rel_diff(two_f.diffuse.x, two_b.diffuse.x) <= 1e-12);
            CHECK(rel_diff(two_f.specular.x, one_f.specular.x + one_b.specular.x) <= 1e-12);
            // Rotating and translating the whole scene changes nothing.
            const dmat3 R = random_rotation(rng);
            dvec3 t;
            for (int i = 0; i < 3; ++i) t[i] = rng.uniform(-100, 100);
            std::vector<dvec3> moved;
            for (const auto& p : sc.light) moved.push_back(R * p + t);
            const auto frame2 = ltc::make_shading_frame(R * sc.N, R * sc.V);
            const auto r2 = ltc::integrate_polygon_light(frame2, k.m_inv, R * sc.P + t, moved.data(), n, mode);
            CHECK(std::abs(r2.ltc - front.ltc) <= 1e-9 * std::max(std::abs(front.ltc), 1e-3));
            CHECK(std::abs(r2.form_factor - front.form_factor) <= 1e-9 * std::max(std::abs(front.form_factor), 1e-3));
        }
    }
    // A light entirely below the horizon: nothing, whatever the mode and the sidedness (the LTC
    // leaks below the horizon, but exact clipping in LTC space still gives 0 only if M^-1 P is
    // below the LTC horizon too; shading_first always gives 0).
    const dvec3 below[4] = {{-1, -1, -0.5}, {1, -1, -0.5}, {1, 1, -0.5}, {-1, 1, -0.5}};
    const ltc::shading_frame<double> frame;
    for (const auto mode : all_modes) {
        for (const auto side : {ltc::sidedness::one_sided, ltc::sidedness::two_sided}) {
            const auto r = ltc::shade_polygon_light(frame, k, dvec3(0), F0, albedo, radiance, below, 4, side, mode);
            CHECK(r.diffuse == dvec3(0));
            if (mode == clip_mode::shading_first) CHECK(r.specular == dvec3(0));
            CHECK(r.specular.x >= 0);
        }
    }
    // ... and with the identity lobe (no leak) every mode gives 0.
    for (const auto mode : all_modes) {
        const auto r = ltc::shade_polygon_light(frame, lobe(1, 0, 1, 0), dvec3(0), F0, albedo, radiance, below, 4,
                                                ltc::sidedness::two_sided, mode);
        CHECK(r.specular == dvec3(0));
        CHECK(r.diffuse == dvec3(0));
    }
    // Degenerate input: finite, and zero where nothing is seen.
    const dvec3 quad[4] = {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
    for (const auto mode : all_modes) {
        CAPTURE(int(mode));
        const auto zero_n = ltc::make_shading_frame(dvec3(0), dvec3(0, 0, 1));
        CHECK(ltc::shade_polygon_light(zero_n, k, dvec3(0), F0, albedo, radiance, quad, 4, ltc::sidedness::two_sided, mode).diffuse == dvec3(0));
        CHECK(ltc::shade_polygon_light(frame, k, dvec3(0), F0, albedo, radiance, quad, 2, ltc::sidedness::two_sided, mode).specular == dvec3(0));
        const auto at_p = ltc::shade_polygon_light(frame, k, dvec3(1, 1, 1), F0, albedo, radiance, quad, 4, ltc::sidedness::two_sided, mode);
        CHECK(at_p.specular == dvec3(0));
        CHECK(at_p.diffuse == dvec3(0));
        // Huge and tiny coordinates (float): finite, and the same as at unit scale.
        for (const float scale : {1e30f, 1e-30f}) {
            glm::vec3 q[4];
            for (int i = 0; i < 4; ++i) q[i] = glm::vec3(quad[i]) * scale;
            const ltc::shading_frame<float> ff;
            ltc::ltc_coefficients<float> kf;
            kf.m_inv = glm::mat3(k.m_inv);
            kf.magnitude = 0.7f;
            kf.fresnel = 0.12f;
            const auto r = ltc::shade_polygon_light(ff, kf, glm::vec3(0), glm::vec3(0.04f), glm::vec3(0.5f), glm::vec3(1), q, 4, ltc::sidedness::two_sided, mode);
            const glm::vec3 unit[4] = {glm::vec3(quad[0]), glm::vec3(quad[1]), glm::vec3(quad[2]), glm::vec3(quad[3])};
            const auto u = ltc::shade_polygon_light(ff, kf, glm::vec3(0), glm::vec3(0.04f), glm::vec3(0.5f), glm::vec3(1), unit, 4, ltc::sidedness::two_sided, mode);
            CHECK(std::isfinite(r.specular.x));
            CHECK(std::isfinite(r.diffuse.x));
            CHECK(r.specular.x == Approx(u.specular.x).epsilon(1e-5));
            CHECK(r.diffuse.x == Approx(u.diffuse.x).epsilon(1e-5));
        }
    }
}

// Lipschitz constant of the clipless integral with respect to the vector form factor F, per unit
// of a per-component change of F: I = sphere_form_factor(f, c) with f = min(|F|, 1) and
// c = F.z / |F|, so |dI| <= |dI/df| |dF| + |dI/dc| 2 |dF| / f and |dF| <= sqrt(3) per-component.
// The partial derivatives are taken by central differences on a 200 x 400 grid of (f, c).
double clipless_slope() {
    double worst = 0;
    const double h = 1e-5;
    for (int i = 1; i <= 200; ++i)
        for (int j = 0; j <= 400; ++j) {
            const double f = std::min(i / 200.0, 1 - h), c = std::clamp(-1 + j / 200.0, -1 + h, 1 - h);
            const double df = (ltc::clipless::sphere_form_factor(f + h, c) - ltc::clipless::sphere_form_factor(f - h, c)) / (2 * h);
            const double dc = (ltc::clipless::sphere_form_factor(f, c + h) - ltc::clipless::sphere_form_factor(f, c - h)) / (2 * h);
            worst = std::max(worst, std::sqrt(3.0) * (std::abs(df) + 2 * std::abs(dc) / f));
        }
    return worst;
}

TEST_CASE("shading with an edge policy other than exact: same integrals within the policy's bound", "[shading]") {
    // The clipped polygons are the same; only theta / sin(theta) changes, by at most 4.1e-8 + 41 u
    // relative for minimax_rational and 8 u for exact (tests/test_edge_policies.cpp), and each
    // integral is a sum of m <= clipped_capacity(n) terms of size <= pi / (2 pi):
    // |difference| <= bound * m / 2. For the clipless modes the policy enters through the vector
    // form factor F, whose components change by as much, times the sphere's slope in F.
    using fast = ltc::edge_policy::minimax_rational;
    const double factor_bound = 4.1e-8 + (41 + 8) * (std::numeric_limits<double>::epsilon() / 2);
    const double slope = clipless_slope();
    const auto k = lobe(0.4, -0.2, 0.7, 0.1);
    for (const clip_mode mode : all_modes) {
        const bool clipless = mode == clip_mode::sphere_analytic || mode == clip_mode::sphere_table;
        double worst = 0;
        for (const scene& sc : random_scenes(300, 31)) {
            const auto frame = ltc::make_shading_frame(sc.N, sc.V);
            const std::size_t n = sc.light.size();
            const double bound = factor_bound * static_cast<double>(ltc::clipped_capacity(n)) / 2 * (clipless ? slope : 1);
            const auto a = ltc::integrate_polygon_light(frame, k.m_inv, sc.P, sc.light.data(), n, mode);
            const auto b = ltc::integrate_polygon_light<fast>(frame, k.m_inv, sc.P, sc.light.data(), n, mode);
            const double err = std::max(std::abs(a.ltc - b.ltc), std::abs(a.form_factor - b.form_factor));
            worst = std::max(worst, err / bound);
            CHECK(err <= bound);
        }
        CAPTURE(static_cast<int>(mode), worst, slope);
        CHECK(worst > 0);  // the policies do differ: the comparison is not vacuous
    }
}

TEST_CASE("shading is invariant to the scale of M^-1, down to 1e-20 in float", "[shading]") {
    // The LTC does not depend on the scale of M^-1; the edge terms get unit vertices whatever
    // it is (|M^-1 p| ~ 1e-20 would put |a x b| of unnormalized vertices below FLT_MIN). Both
    // sides normalize directions that differ by the rounding of the scaled product: a few float
    // ulps per vertex, amplified by at most the number of edges: 1e-4 relative leaves a margin.
    const auto k = lobe(0.4, -0.2, 0.7, 0.1);
    const glm::mat3 mi(k.m_inv);
    for (const clip_mode mode : {clip_mode::ltc_space, clip_mode::shading_first}) {
        for (const scene& sc : random_scenes(100, 37)) {
            const auto frame = ltc::make_shading_frame(glm::vec3(sc.N), glm::vec3(sc.V));
            std::vector<glm::vec3> light;
            for (const dvec3& v : sc.light) light.push_back(glm::vec3(v));
            const glm::vec3 P(sc.P);
            const float a = ltc::integrate_polygon_light(frame, mi, P, light.data(), light.size(), mode).ltc;
            const float b = ltc::integrate_polygon_light(frame, mi * 1e-20f, P, light.data(), light.size(), mode).ltc;
            CAPTURE(static_cast<int>(mode), a, b);
            CHECK(std::abs(a - b) <= 1e-4f * std::max(std::abs(a), 1e-3f));
        }
    }
}

TEST_CASE("shading with the GGX table: V parallel to N, and float against double", "[shading]") {
    const dvec3 quad[4] = {{-1, -1, 2}, {1, -1, 2}, {1, 1, 2.5}, {-1, 1, 2.5}};
    const dvec3 F0(0.04), albedo(0.5), radiance(1.0);
    for (const auto mode : all_modes) {
        CAPTURE(int(mode));
        // V = N exactly (Duff's tangent) and V within 1e-7 of N in two different directions:
        // at normal incidence the lobe is isotropic, so they all agree.
        const dvec3 N(0, 0, 1);
        const auto exact = ltc::shade_polygon_light(dvec3(0), N, N, 0.3, F0, albedo, radiance, quad, 4, ltc::sidedness::one_sided, mode);
        REQUIRE(exact.specular.x > 0);
        for (const dvec3 tilt : {dvec3(1e-7, 0, 0), dvec3(0, -1e-7, 0), dvec3(-7e-8, 7e-8, 0)}) {
            const auto near = ltc::shade_polygon_light(dvec3(0), N, glm::normalize(N + tilt), 0.3, F0, albedo, radiance, quad, 4,
                                                       ltc::sidedness::one_sided, mode);
            CHECK(rel_diff(near.specular.x, exact.specular.x) <= 1e-6);
            CHECK(rel_diff(near.diffuse.x, exact.diffuse.x) <= 1e-12);
        }
        // float agrees with double.
        glm::vec3 qf[4];
        for (int i = 0; i < 4; ++i) qf[i] = glm::vec3(quad[i]);
        const dvec3 V = glm::normalize(dvec3(0.6, 0.2, 0.5));
        const auto d = ltc::shade_polygon_light(dvec3(0), N, V, 0.4, F0, albedo, radiance, quad, 4, ltc::sidedness::one_sided, mode);
        const auto f = ltc::shade_polygon_light(glm::vec3(0), glm::vec3(N), glm::vec3(V), 0.4f, glm::vec3(F0), glm::vec3(albedo),
                                                glm::vec3(radiance), qf, 4, ltc::sidedness::one_sided, mode);
        CHECK(f.specular.x == Approx(d.specular.x).epsilon(2e-5));
        CHECK(f.diffuse.x == Approx(d.diffuse.x).epsilon(2e-6));
    }
}

TEST_CASE("LTC shading against the Monte Carlo GGX ground truth on a small grid", "[shading][ground_truth]") {
    // Grid (local frame, shading point at the origin, N = +z, V = (sin theta_v, 0, cos theta_v)):
    //   theta_v in {0, 45, 75} deg, roughness in {0.25, 0.5, 1} (alpha = roughness^2), and two
    //   lights facing the origin at distance 1: "mirror", a square of half-size 0.5 centred on
    //   the mirror direction, and "low", a 2:1 rectangle of half-size 1 x 0.5 centred at
    //   azimuth 180 deg, elevation 10 deg (partly below the horizon).
    // Ground truth: ltc::ground_truth::integrate with ltc::brdf::ggx<double>, MIS, 2^17
    // iterations, fixed seeds (standard errors 0.2-0.5%). Specular with F0 = 1 (magnitude *
    // I_ltc), like the ground truth (no Fresnel). The bounds are the measured errors of the
    // shipped table (examples/ggx_error_report.cpp has the full grid), rounded up.
    struct light_case {
        const char* name;
        std::vector<dvec3> v;
    };
    const auto make = [](double azimuth_deg, double elevation_deg, double a, double b) {
        const double az = azimuth_deg * pi / 180, el = elevation_deg * pi / 180;
        const dvec3 c(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
        const dvec3 e1 = std::abs(c.z) > 0.999 ? dvec3(0, 1, 0) : glm::normalize(glm::cross(dvec3(0, 0, 1), c));
        const dvec3 e2 = glm::cross(c, e1);
        std::vector<dvec3> v = {c - a * e1 - b * e2, c + a * e1 - b * e2, c + a * e1 + b * e2, c - a * e1 + b * e2};
        if (glm::dot(v[0], glm::cross(v[1] - v[0], v[2] - v[0])) < 0) std::reverse(v.begin(), v.end());
        return v;
    };
    // Measured with the shipped table and these seeds (max over all 18 configurations, max over
    // the 9 "mirror" ones, mean over all), rounded up in the fourth digit:
    //   exact (ltc_space)  24.62%, 2.181%, 3.695%
    //   shading_first      24.62%, 2.181%, 3.384%
    //   sphere_analytic    46.23%, 2.689%, 5.841%
    // (the 24% and 46% are the "low" light at normal incidence and roughness 0.25, in the tail
    // of the lobe; on the mirror lights the fit is within 2.2%). The ground truth's standard
    // errors are 0.1-0.3%, so another seed moves these figures in their third digit: a new
    // table or new seeds need new figures, from this test's output.
    struct bound {
        double max_all, max_mirror, mean_all;
    };
    const bound bounds[3] = {{0.2463, 0.02181, 0.03696}, {0.2463, 0.02181, 0.03385}, {0.4624, 0.02689, 0.05842}};
    double worst[3] = {0, 0, 0}, worst_mirror[3] = {0, 0, 0}, sum[3] = {0, 0, 0};
    int count = 0;
    int seed = 0;
    for (const double theta : {0.0, 45.0, 75.0})
        for (const double r : {0.25, 0.5, 1.0}) {
            const light_case lights[] = {{"mirror", make(180, 90 - theta, 0.5, 0.5)},
                                         {"low", make(180, 10, 1.0, 0.5)}};
            for (const auto& L : lights) {
                const dvec3 V = ltc::brdf::view_from_cos(std::cos(theta * pi / 180));
                ltc::ground_truth::options opt;
                opt.samples = 1u << 17;
                opt.seed = 1000 + std::uint64_t(seed++);
                const auto gt = ltc::ground_truth::integrate(ltc::brdf::ggx<double>{}, V, r * r, L.v.data(), L.v.size(), opt);
                const clip_mode modes[3] = {clip_mode::ltc_space, clip_mode::shading_first, clip_mode::sphere_analytic};
                for (int m = 0; m < 3; ++m) {
                    const auto s = ltc::shade_polygon_light(dvec3(0), dvec3(0, 0, 1), V, r, dvec3(1), dvec3(0), dvec3(1),
                                                            L.v.data(), L.v.size(), ltc::sidedness::one_sided, modes[m]);
                    const double e = std::abs(s.specular.x - gt.mean) / gt.mean;
                    CAPTURE(theta, r, L.name, m, gt.mean, gt.standard_error, s.specular.x, e);
                    CHECK(gt.standard_error <= 0.006 * gt.mean);
                    worst[m] = std::max(worst[m], e);
                    if (&L == &lights[0]) worst_mirror[m] = std::max(worst_mirror[m], e);
                    sum[m] += e;
                }
                ++count;
            }
        }
    for (int m = 0; m < 3; ++m) {
        CAPTURE(m, worst[m], worst_mirror[m], sum[m] / count);
        CHECK(worst[m] <= bounds[m].max_all);
        CHECK(worst_mirror[m] <= bounds[m].max_mirror);
        CHECK(sum[m] / count <= bounds[m].mean_all);
    }
}
