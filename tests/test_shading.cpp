// Tests of ltc/shading/polygon_light.hpp: the shading frame, the diffuse and specular terms against the
// library's closed forms, sidedness, degenerate input, and the shading_first clip order against an
// explicitly clipped polygon. Other edge policies and the scale of M^-1 are in
// test_shading_accuracy.cpp; the GGX table and the Monte Carlo ground truth in test_shading_ggx.cpp.
#include <catch2/catch.hpp>

#include <ltc/ltc.hpp>
#include <ltc/shading/polygon_light.hpp>

#include "support/rng.hpp"
#include "support/shading_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ltc_test_shading {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::shading_checks;  // lobes, random scenes, rel_diff

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

}  // namespace ltc_test_shading
