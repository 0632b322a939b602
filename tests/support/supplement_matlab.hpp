// The supplemental material's MATLAB/Octave validation functions (Heitz et al. 2016,
// supplement sections 2.2-2.4), transcribed loop for loop so that the printed example
// sessions can be reproduced and compared with the exact values of the library.
//
// Transcription notes (what the printed code does, including its quirks):
//  - test_polygonal_integration: a Riemann sum over the 401 x 401 grid x, y = 0:0.0025:1 of the
//    unit square, folded onto the triangle (x > y and x <= y give the two halves), weight
//    dx^2 * A. The grid includes both end points, so the weights sum to A (1 + dx)^2, not A.
//    `res` is used uninitialized in the listing; we start it at 0.
//  - test_sampling's reference moments: theta = 0:0.01:pi (315 values, last 3.14) and
//    phi = 0:0.01:2*pi (629 values, last 6.28), weight dangle^2 sin(theta) D(w). Neither grid
//    closes: the phi cells cover 6.29 rad, so the directions near phi = 0 are counted twice
//    over 0.0068 rad, and the theta grid stops 0.0016 rad short of pi.
//  - Section 2.2 prints w = (sin t cos p, cos t cos p, cos t), which is not a unit vector
//    (a typo); the code of test_sampling uses (cos p sin t, sin p sin t, cos t), as we do.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace ltc_supplement {

using Do_function = double (*)(const glm::dvec3&);

/// The supplement prints matrices row by row: M = [a b c; d e f; g h i].
inline glm::dmat3 row_major(double a, double b, double c, double d, double e, double f, double g,
                            double h, double i) {
    return glm::transpose(glm::dmat3(a, b, c, d, e, f, g, h, i));
}

/// The supplement's example matrix M = [0.1 0.5 1; 0.2 1 1; 0 2 0.5].
inline glm::dmat3 example_matrix() { return row_major(0.1, 0.5, 1, 0.2, 1, 1, 0, 2, 0.5); }

/// D(w, M, Do) of section 2.1: inv(M), |det(invM)| / norm(invM w)^3, Do(invM w / norm(invM w)).
inline double D(const glm::dvec3& w, const glm::dmat3& M, Do_function Do) {
    const glm::dmat3 inv_m = glm::inverse(M);
    const glm::dvec3 v = inv_m * w;
    const double l = glm::length(v);
    return Do(v / l) * std::abs(glm::determinant(inv_m)) / (l * l * l);
}

/// MATLAB colon operator a:d:b, element i (MATLAB computes a + i*d).
inline double colon(double a, double d, int i) { return a + i * d; }
inline int colon_count(double a, double d, double b) {
    return static_cast<int>(std::floor((b - a) / d + 1e-10)) + 1;
}

/// Riemann sum of f(P) |<P/|P|, N>| / |P|^2 over the triangle, as in test_polygonal_integration.
template <typename F>
double folded_triangle_sum(const glm::dvec3& P1, const glm::dvec3& P2, const glm::dvec3& P3, F f,
                           double dx) {
    const glm::dvec3 c = glm::cross(P1 - P2, P1 - P3);
    const glm::dvec3 N = c / glm::length(c);
    const double A = 0.5 * glm::length(c);
    const int count = colon_count(0, dx, 1);
    double res = 0;
    for (int i = 0; i < count; ++i) {
        const double x = colon(0, dx, i);
        for (int j = 0; j < count; ++j) {
            const double y = colon(0, dx, j);
            const glm::dvec3 P = x > y ? (1.0 - x) * P1 + (x - y) * P2 + y * P3
                                       : (1.0 - y) * P1 + (y - x) * P2 + x * P3;
            const glm::dvec3 wo = P / glm::length(P);
            const double d2 = glm::dot(P, P);
            res += dx * dx * A * std::abs(glm::dot(wo, N)) / d2 * f(wo);
        }
    }
    return res;
}

/// test_polygonal_integration(P1, P2, P3, M, Do): D_o over the transformed triangle M^-1 P.
inline double test_polygonal_integration(glm::dvec3 P1, glm::dvec3 P2, glm::dvec3 P3,
                                         const glm::dmat3& M, Do_function Do, double dx = 0.0025) {
    const glm::dmat3 Minv = glm::inverse(M);
    return folded_triangle_sum(Minv * P1, Minv * P2, Minv * P3, Do, dx);
}

/// test_polygonal_integration_reference (not listed in the supplement): D over P itself, with
/// the same discretization.
inline double test_polygonal_integration_reference(const glm::dvec3& P1, const glm::dvec3& P2,
                                                   const glm::dvec3& P3, const glm::dmat3& M,
                                                   Do_function Do, double dx = 0.0025) {
    return folded_triangle_sum(P1, P2, P3, [&](const glm::dvec3& w) { return D(w, M, Do); }, dx);
}

/// The "reference" half of test_sampling: moments of D by the (theta, phi) Riemann sum.
/// Also returns the sum of the weights (the discretized normalization of section 2.2).
struct riemann_moments {
    double norm;
    glm::dvec3 first;
};

inline riemann_moments test_sampling_reference(const glm::dmat3& M, Do_function Do,
                                               double dangle = 0.01) {
    const double pi = 3.141592653589793;
    riemann_moments r{0, glm::dvec3(0)};
    const int nt = colon_count(0, dangle, pi), np = colon_count(0, dangle, 2 * pi);
    for (int i = 0; i < nt; ++i) {
        const double theta = colon(0, dangle, i);
        for (int j = 0; j < np; ++j) {
            const double phi = colon(0, dangle, j);
            const glm::dvec3 w(std::cos(phi) * std::sin(theta), std::sin(phi) * std::sin(theta),
                               std::cos(theta));
            const double weight = dangle * dangle * std::sin(theta) * D(w, M, Do);
            r.norm += weight;
            r.first += weight * w;
        }
    }
    return r;
}

/// The same rule on a grid that closes: dtheta = pi / n and dphi = pi / n, theta = 0..pi
/// (n + 1 points; sin(theta) vanishes at both ends, so this is the trapezoidal rule) and phi over
/// exactly one period (2 n points, the periodic trapezoidal rule). Not in the supplement: used
/// to show that its grid, which does not close, explains its printed digits.
inline riemann_moments closed_grid_moments(const glm::dmat3& M, Do_function Do, int n) {
    const double pi = 3.141592653589793, h = pi / n;
    riemann_moments r{0, glm::dvec3(0)};
    for (int i = 0; i <= n; ++i) {
        const double theta = i * h;
        for (int j = 0; j < 2 * n; ++j) {
            const double phi = j * h;
            const glm::dvec3 w(std::cos(phi) * std::sin(theta), std::sin(phi) * std::sin(theta),
                               std::cos(theta));
            const double weight = h * h * std::sin(theta) * D(w, M, Do);
            r.norm += weight;
            r.first += weight * w;
        }
    }
    return r;
}

// The supplement's original distributions, Do_*(w), transcribed.
inline double Do_uniform_sphere(const glm::dvec3&) { return 1 / (4 * 3.141592653589793); }
inline double Do_uniform_hemisphere(const glm::dvec3& w) {
    return w.z < 0 ? 0 : 1 / (2 * 3.141592653589793);
}
inline double Do_clamped_cosine(const glm::dvec3& w) { return std::max(0.0, w.z) / 3.141592653589793; }
inline double Do_squared_clamped_cosine(const glm::dvec3& w) {
    const double z = std::max(0.0, w.z);
    return z * z * 3 / (2 * 3.141592653589793);
}

}  // namespace ltc_supplement
