// Random star-shaped polygons for the brute-force comparisons (support/brute_force.hpp): planar
// polygons around a kernel point from which every vertex is visible, with control over the
// winding, horizon crossings and rounding to float; and the library's orientation convention.
#pragma once

#include "support/rng.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace ltc_test {

struct test_polygon {
    std::vector<glm::dvec3> v;  // vertices (rounded to float when requested)
    glm::dvec3 kernel;          // a point of the kernel: every vertex is visible from it
    glm::dvec3 normal;          // unit normal of the generating plane
};

struct polygon_options {
    std::size_t min_vertices = 3, max_vertices = 8;
    double size = 1;                            // radii in [0.3, 1.2] size around the centre
    double min_distance = 1, max_distance = 3;  // |centre| in size units
    double min_plane_distance = 0.25;           // reject planes closer than this (times size) to the origin
    /// +1 / -1: force the sign of the library's convention (positive when dot(c, N) > 0 for N
    /// the polygon's oriented area vector, i.e. clockwise as seen from the origin); 0: random.
    int orientation = 0;
    bool cross_horizon = false;  // some vertices with z < 0 and some with z > 0
    bool cross_plane = false;    // the same for <p, plane_normal>
    glm::dvec3 plane_normal{0, 0, 1};
    bool above_horizon = false;  // every vertex with z > 0
    bool round_to_float = true;  // vertices exactly representable as float (exact float input)
};

/// Oriented area vector (Newell) of the polygon: 1/2 sum p_i x p_i+1.
inline glm::dvec3 area_vector(const std::vector<glm::dvec3>& p) {
    glm::dvec3 a(0);
    for (std::size_t i = 0; i < p.size(); ++i) a += glm::cross(p[i], p[(i + 1) % p.size()]);
    return 0.5 * a;
}

/// Sign of the library's orientation convention for a planar polygon not through the origin.
inline int orientation_sign(const std::vector<glm::dvec3>& p, const glm::dvec3& point_on_plane) {
    const double s = glm::dot(point_on_plane, area_vector(p));
    return s > 0 ? 1 : (s < 0 ? -1 : 0);
}

inline test_polygon random_polygon(rng& r, const polygon_options& o) {
    constexpr double two_pi = 6.283185307179586;
    for (;;) {
        test_polygon t;
        // one call per statement: the order of evaluation of operands is unspecified, and the
        // same seed must give the same polygons with every compiler
        const glm::dvec3 n = r.direction();
        const glm::dvec3 c_dir = r.direction();
        const double c_dist = o.size * r.uniform(o.min_distance, o.max_distance);
        const glm::dvec3 c = c_dir * c_dist;
        if (std::abs(glm::dot(c, n)) < o.min_plane_distance * o.size) continue;
        const glm::dvec3 helper = std::abs(n.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        const glm::dvec3 e1 = glm::normalize(glm::cross(n, helper));
        const glm::dvec3 e2 = glm::cross(n, e1);
        const std::size_t k =
            o.min_vertices + static_cast<std::size_t>(r.uniform() * double(o.max_vertices - o.min_vertices + 1));
        // sorted random angles; every gap below 0.9 pi keeps c strictly inside the kernel with
        // margin (every fan triangle (c, p_i, p_i+1) is then non-degenerate and of one orientation)
        std::vector<double> ang(k);
        for (auto& a : ang) a = two_pi * r.uniform();
        std::sort(ang.begin(), ang.end());
        double max_gap = ang[0] + two_pi - ang[k - 1];
        for (std::size_t i = 1; i < k; ++i) max_gap = std::max(max_gap, ang[i] - ang[i - 1]);
        if (max_gap > 0.9 * 3.141592653589793) continue;
        for (std::size_t i = 0; i < k; ++i) {
            const double rad = o.size * r.uniform(0.3, 1.2);
            glm::dvec3 p = c + rad * (std::cos(ang[i]) * e1 + std::sin(ang[i]) * e2);
            if (o.round_to_float) p = glm::dvec3(glm::vec3(p));
            t.v.push_back(p);
        }
        t.kernel = c;
        t.normal = n;
        const auto mixed = [&](const glm::dvec3& h) {
            bool pos = false, neg = false;
            for (const auto& p : t.v) pos = pos || glm::dot(p, h) > 0, neg = neg || glm::dot(p, h) < 0;
            return pos && neg;
        };
        if (o.cross_horizon && !mixed(glm::dvec3(0, 0, 1))) continue;
        if (o.cross_plane && !mixed(o.plane_normal)) continue;
        if (o.above_horizon && !std::all_of(t.v.begin(), t.v.end(), [](const glm::dvec3& p) { return p.z > 0; }))
            continue;
        const int s = orientation_sign(t.v, c);
        if (s == 0) continue;
        if (o.orientation != 0 && s != o.orientation) std::reverse(t.v.begin(), t.v.end());
        return t;
    }
}

}  // namespace ltc_test
