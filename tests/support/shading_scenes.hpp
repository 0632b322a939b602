// Shared pieces of the polygon-light shading tests (test_shading.cpp, test_shading_accuracy.cpp,
// test_shading_ggx.cpp): lobes of the paper's form, random scenes (a shading point, normal, view
// and a light that often straddles the horizon) and the comparison of shaded values.
#pragma once

#include <ltc/ltc.hpp>
#include <ltc/shading/polygon_light.hpp>

#include "support/rng.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace ltc_test::shading_checks {

using glm::dmat3;
using glm::dvec3;
using clip_mode = ltc::horizon_clipping;
inline constexpr double pi = 3.141592653589793;

inline const clip_mode all_modes[] = {clip_mode::ltc_space, clip_mode::shading_first, clip_mode::sphere_analytic,
                                      clip_mode::sphere_table};

/// A lobe of the paper's form [a 0 b; 0 c 0; d 0 1] (as M^-1), with magnitude and Fresnel terms.
inline ltc::ltc_coefficients<double> lobe(double a, double b, double c, double d, double magnitude = 0.8,
                                          double fresnel = 0.1) {
    ltc::ltc_coefficients<double> k;
    k.m_inv = glm::transpose(dmat3(a, 0, b, 0, c, 0, d, 0, 1));
    k.magnitude = magnitude;
    k.fresnel = fresnel;
    return k;
}

/// A random rotation (from three random directions, Gram-Schmidt).
inline dmat3 random_rotation(ltc_test::rng& rng) {
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
inline std::vector<scene> random_scenes(int count, std::uint64_t seed) {
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
inline std::vector<dvec3> local_light(const scene& sc) {
    const auto f = ltc::make_shading_frame(sc.N, sc.V);
    std::vector<dvec3> v;
    for (const dvec3& p : sc.light) v.push_back(f.to_local(p - sc.P));
    return v;
}

/// |a - b| relative to max(|a|, |b|, 0.01): values near zero (edge-on or horizon-grazing lights,
/// where relative differences mean nothing) are compared absolutely.
inline double rel_diff(double a, double b) { return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-2}); }

/// A rectangle of half-sizes a x b at distance 1 in the direction (azimuth, elevation) in
/// degrees, facing the origin (front face: clockwise as seen from it).
inline std::vector<dvec3> facing_rectangle(double azimuth_deg, double elevation_deg, double a, double b) {
    const double az = azimuth_deg * pi / 180, el = elevation_deg * pi / 180;
    const dvec3 c(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
    const dvec3 e1 = std::abs(c.z) > 0.999 ? dvec3(0, 1, 0) : glm::normalize(glm::cross(dvec3(0, 0, 1), c));
    const dvec3 e2 = glm::cross(c, e1);
    std::vector<dvec3> v = {c - a * e1 - b * e2, c + a * e1 - b * e2, c + a * e1 + b * e2, c - a * e1 + b * e2};
    if (glm::dot(v[0], glm::cross(v[1] - v[0], v[2] - v[0])) < 0) std::reverse(v.begin(), v.end());
    return v;
}

/// The normalized M^-1 stored at node (u, a) of a table (its middle element 1).
inline glm::dmat3 node_m_inv(const ltc::ltc_table& t, int u, int a) {
    glm::dmat3 m(0.0);
    m[0][0] = t.node(u, a, ltc::channel::m_inv_00);
    m[0][2] = t.node(u, a, ltc::channel::m_inv_02);
    m[2][0] = t.node(u, a, ltc::channel::m_inv_20);
    m[2][2] = t.node(u, a, ltc::channel::m_inv_22);
    m[1][1] = 1;
    return m;
}

}  // namespace ltc_test::shading_checks
