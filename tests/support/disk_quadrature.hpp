// Brute-force reference integration over ellipses (disks seen from a point, or through M^-1),
// independent of the closed form of ltc/core/ellipse_integral.hpp: the integral of a direction
// function f over the solid angle of E = {c + a s + b t : s^2 + t^2 <= 1} as an area integral,
//
//     int_{s^2 + t^2 <= 1} f(x / |x|) |<c, a x b>| / |x|^3 ds dt,     x = c + a s + b t
//
// (dA = |a x b| ds dt, and the cosine at the light is |<x, n>| / |x| = |<c, a x b>| / (|a x b| |x|)).
//
// Kink. f may have a kink or jump across the plane <w, h> = 0 (h = z for the clamped cosine; for
// D = transformed<...>::eval, h = the third row of M^-1). In (s, t) that plane is the line
// <c, h> + |k| u = 0, u the coordinate along k = (<a, h>, <b, h>); only the part u >= u0 = -<c, h>
// / |k| is integrated (f = 0 below: the clamped densities), parameterized by u = cos(beta),
// beta in [0, beta0 = acos(u0)], and the coordinate across, v = xi sin(beta), xi in [-1, 1]
// (Jacobian sin^2 beta): f is analytic on the closed rectangle. f receives the unit direction w
// and <w, h>, computed where the plane cuts the disk as |k| (cos beta - cos beta0) / |x| =
// 2 |k| sin((beta0 - beta) / 2) sin((beta0 + beta) / 2) / |x|: accurate next to the cut.
//
// Rule. Adaptive product Gauss-Legendre on (beta, xi), N = 16: a rectangle is accepted when its
// N- and 2N-point rules agree within its share (by area) of the tolerance, or within 64 u of its
// sum |terms| (the rounding floor, below which splitting cannot help), else split in four; the
// peak of 1 / |x|^3 next to a close origin ends up in small rectangles. For an analytic
// integrand the error falls geometrically with N, so |Q_N - Q_2N| bounds the error of Q_2N with
// a wide margin (N = 8 proved too few for the peak: its estimate stalled).
// Estimate: e = sum over the leaves of |Q_N - Q_2N| + u (8N + 40) sum |terms| (1 + 4 span / |x|):
// first-order rounding of the double evaluation (nested sums of 2N terms, ~40 operations per
// node), and the node's position error <= 3 u span (span = |c| + |a| + |b|), relative to |x|
// and raised to the power ~4 by f / |x|^3 (large next to a close origin).
#pragma once

#include "support/gauss_legendre.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace ltc_test {

struct disk_quadrature_result {
    double value = 0;
    double error = 0;
    std::size_t leaves = 0;
    bool converged = true;
};

struct disk_quadrature_options {
    std::size_t order = 16;
    double rel_tol = 1e-13;
    double abs_floor = 1e-17;
    std::size_t max_leaves = 20000;
};

/// int over the solid angle of the ellipse (c, a, b) of f(w, <w, h>), restricted to <w, h> >= 0.
template <typename F>
disk_quadrature_result integrate_ellipse(const glm::dvec3& c, const glm::dvec3& a, const glm::dvec3& b,
                                         const glm::dvec3& h, const F& f, const disk_quadrature_options& o = {}) {
    const double pi = 3.141592653589793;
    disk_quadrature_result r;
    const double weight = std::abs(glm::dot(c, glm::cross(a, b)));
    const double span = glm::length(c) + glm::length(a) + glm::length(b);
    const double h0 = glm::dot(c, h), k1 = glm::dot(a, h), k2 = glm::dot(b, h), k = std::hypot(k1, k2);
    double beta0 = pi, e1 = 1, e2 = 0;  // the whole disk when <x, h> is constant and positive
    bool cut = false;                   // does the plane cut the disk (-1 < u0 < 1)?
    if (k > 0) {
        e1 = k1 / k, e2 = k2 / k;
        const double u0 = -h0 / k;
        cut = u0 > -1 && u0 < 1;
        beta0 = std::acos(std::max(-1.0, std::min(1.0, u0)));
    } else if (!(h0 > 0)) {
        return r;
    }
    if (!(beta0 > 0) || weight == 0) return r;
    const quadrature_rule lo = gauss_legendre(o.order), hi = gauss_legendre(2 * o.order);
    const double u = std::numeric_limits<double>::epsilon() / 2;
    struct rect { double b0, b1, x0, x1; };
    // Q over one rectangle with rule q; `terms` accumulates sum |term|.
    const auto rule = [&](const rect& R, const quadrature_rule& q, double& terms) {
        double sum = 0;
        for (std::size_t i = 0; i < q.x.size(); ++i) {
            const double beta = R.b0 + (R.b1 - R.b0) * q.x[i], wb = (R.b1 - R.b0) * q.w[i];
            const double cu = std::cos(beta), sb = std::sin(beta);
            const double above =
                cut ? 2 * k * std::sin((beta0 - beta) / 2) * std::sin((beta0 + beta) / 2) : h0 + k * cu;
            for (std::size_t j = 0; j < q.x.size(); ++j) {
                const double xi = R.x0 + (R.x1 - R.x0) * q.x[j], wx = (R.x1 - R.x0) * q.w[j];
                const double v = xi * sb, s = cu * e1 - v * e2, t = cu * e2 + v * e1;
                const glm::dvec3 x = c + a * s + b * t;
                const double len = glm::length(x);
                const double term = f(x / len, above / len) * weight / (len * len * len) * sb * sb * wb * wx;
                sum += term;
                terms += std::abs(term) * (1 + 4 * span / len);  // x's rounding: <= 3 u span

            }
        }
        return sum;
    };
    const double half = beta0 / 2;
    std::vector<rect> todo{{0, half, -1, 0}, {0, half, 0, 1}, {half, beta0, -1, 0}, {half, beta0, 0, 1}};
    // A first pass for the scale of the integral (the tolerance is relative to int |f|).
    double scale = 0;
    for (const rect& R : todo) {
        double terms = 0;
        rule(R, hi, terms);
        scale += terms;
    }
    const double tol = std::max(o.rel_tol * scale, o.abs_floor);
    const double total_area = beta0 * 2;
    double terms = 0, quad_error = 0;
    while (!todo.empty()) {
        const rect R = todo.back();
        todo.pop_back();
        double t_lo = 0, t_hi = 0;
        const double q_lo = rule(R, lo, t_lo), q_hi = rule(R, hi, t_hi);
        // accepted at its share of the tolerance, or once the two rules agree to rounding
        const double share = std::max(tol * (R.b1 - R.b0) * (R.x1 - R.x0) / total_area, 64 * u * t_hi);
        if (std::abs(q_hi - q_lo) <= share || r.leaves + todo.size() >= o.max_leaves) {
            if (std::abs(q_hi - q_lo) > share) r.converged = false;
            r.value += q_hi;
            quad_error += std::abs(q_hi - q_lo);
            terms += t_hi;
            ++r.leaves;
            continue;
        }
        const double bm = (R.b0 + R.b1) / 2, xm = (R.x0 + R.x1) / 2;
        todo.push_back({R.b0, bm, R.x0, xm});
        todo.push_back({R.b0, bm, xm, R.x1});
        todo.push_back({bm, R.b1, R.x0, xm});
        todo.push_back({bm, R.b1, xm, R.x1});
    }
    r.error = quad_error + u * (8.0 * double(o.order) + 40) * terms;
    return r;
}

/// The clamped cosine's integral over the ellipse, horizon-clipped: the reference for
/// ltc::integrate_ellipse_cosine, signed by c.(a x b) like it.
inline disk_quadrature_result cosine_over_ellipse(const glm::dvec3& c, const glm::dvec3& a, const glm::dvec3& b,
                                                  const disk_quadrature_options& o = {}) {
    const double inv_pi = 0.3183098861837907;
    disk_quadrature_result r = integrate_ellipse(
        c, a, b, glm::dvec3(0, 0, 1), [&](const glm::dvec3&, double s) { return s * inv_pi; }, o);
    if (glm::dot(c, glm::cross(a, b)) < 0) r.value = -r.value;
    return r;
}

}  // namespace ltc_test
