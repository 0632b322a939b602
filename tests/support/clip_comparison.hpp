// Random polygons and matrices for the tests that compare two evaluations of the clipped
// clamped-cosine integral (the batch API and the scalar path's quad fast path against the general
// path), and the tolerance of such a comparison, derived in tests/test_batch.cpp's header comment.
#pragma once

#include "rng.hpp"

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/polygon.hpp>
#include <ltc/core/transformed.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

namespace ltc_test {

inline constexpr double kPi = 3.141592653589793238462643383279502884;
inline constexpr double kU = 0x1.0p-24;  // unit roundoff of float

// GGX-fit-like M^-1 = [a 0 b; 0 c 0; d 0 1] (row-major), or a general random matrix (any sign of
// the determinant) kept away from singular.
inline glm::mat3 random_matrix(ltc_test::rng& g, bool general) {
    if (!general) {
        const double a = 0.05 + g.uniform(), b = -0.5 + g.uniform(), c = 0.05 + g.uniform(), d = -0.5 + g.uniform();
        return glm::mat3(glm::transpose(glm::dmat3(a, 0, b, 0, c, 0, d, 0, 1)));
    }
    for (;;) {
        glm::dmat3 m;
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) m[c][r] = g.uniform(-1, 1);
        const double det = glm::determinant(m);
        if (std::abs(det) > 0.05) return glm::mat3(m);
    }
}

// A planar polygon of n vertices around a centre in front of or around the shading point, in a
// random orientation: convex (regular-ish) or star-shaped non-convex (alternating radii), either
// winding. Rounded to float.
inline std::vector<glm::vec3> random_polygon(ltc_test::rng& g, std::size_t n, bool convex, bool reverse) {
    const glm::dvec3 centre(g.uniform(-1, 1), g.uniform(-1, 1), g.uniform(-0.6, 1.0));
    const glm::dvec3 normal = g.direction();
    const glm::dvec3 helper = std::abs(normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 ex = glm::normalize(glm::cross(normal, helper)), ey = glm::cross(normal, ex);
    const double size = g.uniform(0.2, 1.5), phase = g.uniform(0, 2 * kPi);
    std::vector<glm::vec3> v(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double t = phase + 2 * kPi * static_cast<double>(k) / static_cast<double>(n);
        const double r = size * (convex ? g.uniform(0.8, 1.0) : (k % 2 ? g.uniform(0.15, 0.4) : 1.0));
        v[k] = glm::vec3(centre + r * (std::cos(t) * ex + std::sin(t) * ey));
    }
    if (reverse) std::reverse(v.begin(), v.end());
    return v;
}

// theta / sin(theta) of unit vectors a, b, in double.
inline double theta_over_sin(const glm::dvec3& a, const glm::dvec3& b) {
    const double s = glm::length(glm::cross(a, b)), c = glm::dot(a, b);
    return s > 0 ? std::atan2(s, c) / s : (c > 0 ? 1.0 : 1e30);
}

// The per-item tolerance derived in the header comment of tests/test_batch.cpp, over the T
// scalar path's own clipped edges and terms (what both paths actually sum) and its crossings:
//   u / (2 pi) * [ sum_j ((32 + 2 m + 8 k_j) |e_j| + 8 (1 + t_j))  +  sum_X 8 kappa_X (2 + t_X) ],
// u the unit roundoff of T (float: kU; double: 2^-53, where the kernel's normalization is
// 1 / sqrt, within 1.5 u, so that the float derivation's 4.5 u bounds it).
// k_j is the conditioning of theta / sin(theta) with respect to c = a.b: 0 for the exact,
// polynomial and minimax_rational policies (they take the sine from |a x b|, and
// theta / sin(theta) is flat where they use c), but for rational and fp16_quadratic, which use sqrt(1 - c^2) for c < 0, a change of a
// few u in c (the unit vectors' lengths differ by a few u between the paths) changes the term by
// |c| / (1 - c^2) times as much, up to their clamps (1e-7, 1e-4).
// With same_normalization (the scalar quad path against the general path: both normalize M^-1 p
// by the same operations, so the unit vertices and the terms of unclipped edges are bitwise
// equal), only the summation order (2 m u |e_j|), the crossings and, for the policies that use
// c, the change of c at a crossing's edges (8 k_j u |e_j|) remain.
template <typename Policy, typename T>
double clip_tolerance(const glm::mat<3, 3, T>& mi, const std::vector<glm::vec<3, T>>& v,
                      bool same_normalization = false) {
    const double m = static_cast<double>(ltc::clipped_capacity(v.size()));
    constexpr bool uses_c = std::is_same_v<Policy, ltc::edge_policy::rational> ||
                            std::is_same_v<Policy, ltc::edge_policy::fp16_quadratic>;
    const double floor = std::is_same_v<Policy, ltc::edge_policy::rational> ? 1e-7 : 1e-4;
    double sum = 0;
    ltc::detail::for_each_unit_edge<T, true>(
        ltc::detail::transformed_vertices<T>{mi, v.data()}, v.size(),
        [&](const glm::vec<3, T>& a, const glm::vec<3, T>& b, const glm::vec<3, T>&) {
            const double c = glm::dot(glm::dvec3(a), glm::dvec3(b));
            const double k = uses_c && c < 0 ? -c / std::max(1 - c * c, floor) : 0.0;
            const double e = std::abs(static_cast<double>(ltc::edge_integral_z<Policy>(a, b)));
            if (same_normalization) {
                sum += (2 * m + 8 * k) * e;  // k: a crossing's rounding moves c by a few u
            } else {
                sum += (32 + 2 * m + 8 * k) * e;
                sum += 8 * (1 + theta_over_sin(glm::dvec3(a), glm::dvec3(b)));
            }
        });
    // Crossings: X = in (-out.z) + out in.z cancels when in and out are nearly opposite (an edge
    // passing close to the shading point); the per-component rounding of the unit vertices (a few
    // u, different in the two paths) then moves X by kappa_X times as much along the horizon.
    const ltc::detail::transformed_vertices<T> at{mi, v.data()};
    for (std::size_t k = 0; k < v.size(); ++k) {
        const glm::dvec3 p(at(k == 0 ? v.size() - 1 : k - 1)), q(at(k));
        if ((p.z >= 0) == (q.z >= 0)) continue;
        const glm::dvec3 in = p.z >= 0 ? p : q, out = p.z >= 0 ? q : p;
        const glm::dvec3 x = in * (-out.z) + out * in.z;
        const double kappa = (std::abs(in.z) + std::abs(out.z)) / std::max(glm::length(x), 1e-300);
        sum += 8 * kappa * (2 + theta_over_sin(glm::normalize(glm::dvec3(x.x, x.y, 0)), in));
    }
    return sum * (std::numeric_limits<T>::epsilon() / 2) / (2 * kPi);
}

}  // namespace ltc_test
