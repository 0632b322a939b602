// First-order rounding bound of the closed-form polygon integrals (the derivation below), and
// the input errors of the vertices that transformed<> computes, for the polygon-integration tests.
#pragma once

#include "support/polygon_references.hpp"

#include <ltc/core/clamped_cosine.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

namespace ltc_test::polygon_integration {

// ---------------------------------------------------------------------------------------------
// First-order rounding bound of the closed forms.
//
// Every closed form is  I = Sigma / norm,  Sigma a sum of m terms over the edges of the unit
// polygon (clipped to z >= 0 except for the sphere), norm = 4 pi (sphere) or 2 pi. Let u = eps/2
// of T. To first order the computed value differs from I by at most u B / norm + 3u |I|, with
//   B = R + C + (m + 1) Sum|terms|:
//
// * R, the vertices: each unit vertex the library computes points off the exact direction by
//   delta_i u (radians), delta_i = d_i + 2: d_i from the input (0 for the exact, float
//   representable, inputs of the original distributions; for transformed ones the rounding of
//   M^-1 p in T, see transformed_input_error), plus 2 for safe_normalize (v / max and s / |s|
//   round each component once; the rounding of |s| only changes the length, by <= 2u, which the
//   terms below account for where they assume unit vectors).
//   A horizon crossing x ~ in (-out.z) + out in.z (2 roundings per component, relative to
//   |in.z| + |out.z| <= |x| / cos(theta/2)), z := 0, then normalized (2), points off the exact
//   great circle by <= (max(delta_in, delta_out) + 2) / cos(theta/2) + 2 <= (max + 4) kappa,
//   kappa = theta / sin(theta) >= 1 / cos(theta/2), theta the angle of the edge in -> out. Its
//   displacement along the horizon is harmless: it sweeps a triangle of height in.z, i.e. acts as
//   a vertex perturbation of size |d in.z| again. The exact integral of the perturbed polygon
//   differs from the exact one by at most the density times the swept area; moving one end of an
//   arc of length theta by delta sweeps delta tan(theta/2) <= delta theta kappa / 2. So
//     R = rho Sum_edges (delta_a + delta_b) theta kappa / 2,
//   rho the largest "density" of Sigma: 1 for the solid angles (Sigma = Omega), 2 for the cosine
//   (Sigma = 2 int z), 3 for the squared cosine (Sigma = 3 int z^2).
// * C, the terms computed from the rounded unit vertices (absolute errors, in units of u):
//   - eq. (11) edge term t = theta (a x b) / |a x b|, |t| = theta: c = a.b errs by 3;
//     stable_cross a x (b -+ a) by 6 |a x b| (b -+ a 1, products and difference 2, relative to
//     |a| |b -+ a| <= sqrt 2 |a x b|); s = |a x b| by 8 s (6 + dot and sqrt 2); theta = atan2(s, c)
//     by theta (8 c s / theta + 3 s / theta + 1) <= 12 theta; the unit vector (a x b) / s keeps
//     6 (its perpendicular part) + 2 (length rounding); division and product 2: <= 22 theta,
//     times kappa for safety on long edges. With a fitted factor theta / sin(theta) (the default
//     edge_policy::automatic is minimax_rational in float), t = f(c) (a x b).z: f errs by its own
//     relative bound F (minimax_rational: 4.1e-8 + 41 u, tests/test_edge_policies.cpp), the z
//     component of stable_cross by 6, the product by 1: <= (F / u + 7) theta, times kappa too;
//   - Arvo's second-moment edge term (a x b).z / s |b - a| (a + b).z / |a + b| (<= |b - a|
//     <= theta): the first factor errs by 6 + 8 + 1 = 15, |b - a| by 3 |b - a| relative, plus 4
//     absolute from the length errors of a and b, the third factor by 1 + 3 + 1 = 5, two
//     products 2: <= 25 theta + 4;
//   - Van Oosterom triangle (q, a, b) = 2 atan2(y, x), fanned from the first vertex q for the
//     unclipped solid angle: y = (q - a).(a x (b -+ a)), x = 1 + q.a + q.b + a.b,
//     |dy| <= 9 |q - a| |b -+ a| (q - a 1, cross 4.3, dot 3), |dx| <= 27 (three dots of
//     near-unit vectors 3 + 2 each, three additions on |x| <= 4: 12); fanned from the pole z for
//     the clipped ones (pole_triangle_solid_angle): y = (a x (b -+ a)).z, x = 1 + a.z + b.z + a.b,
//     |dy| <= 6 |b -+ a|, |dx| <= 21 (one dot 3, lengths 6, three additions 12);
//     then |d Omega_t| <= 2 (|x| |dy| + |y| |dx|) / (x^2 + y^2) + 2 |Omega_t| (atan2 and x2).
// * (m + 1) Sum|terms|: recursive summation of the m per-edge terms (for the squared cosine each
//   edge adds a triangle and an edge term: one more addition per edge, hence m + 1);
// * 3u |I|: the final division by the rounded 2 pi or 4 pi.
// These are worst-case first-order counts (every rounding error aligned), so the bound is
// pessimistic: the measured errors (printed at the end of the test cases) are 10 to 50 times
// below it. The float checks are therefore sensitive to gross errors only (a relative bias of
// 1e-6 passes them); the double checks catch relative errors down to ~3e-14.

enum class form { sphere, hemisphere, cosine, squared, cosine_unclipped };

inline form form_of(int id) {
    switch (id) {
        case sphere: return form::sphere;
        case hemisphere: return form::hemisphere;
        case cosine: return form::cosine;
        default: return form::squared;
    }
}

/// factor_error of rounding_bound for distribution id in T: the relative error bound, in units of
/// u, of the fitted edge factor clamped_cosine<T> uses by default (0 where it is exact).
template <typename T>
double default_factor_error(int id) {
    using policy = typename ltc::clamped_cosine<T>::EdgePolicy;
    if constexpr (std::is_same_v<policy, ltc::edge_policy::exact>) {
        return 0;
    } else {
        static_assert(std::is_same_v<policy, ltc::edge_policy::minimax_rational>, "a bound for this policy");
        const double u = std::numeric_limits<T>::epsilon() / 2;
        return form_of(id) == form::cosine ? 4.1e-8 / u + 41 : 0;
    }
}

inline double angle(const dvec3& a, const dvec3& b) { return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)); }
inline double kappa(double theta) { return theta > 1e-8 ? theta / std::sin(theta) : 1.0; }

struct unit_vertex {
    dvec3 w;
    double delta;  // direction error in units of u
};

struct bound_parts {
    double region = 0, terms = 0, summation = 0, norm = 1;
};

/// q: the polygon in D_o space, in double; d: input direction errors per vertex in units of u
/// (empty: exact input), to which `normalize` is added for the normalization of the vertices.
/// factor_error: the relative error bound of a fitted theta / sin(theta) in units of u (0: the
/// exact policy's atan2).
inline bound_parts rounding_parts(form f, const poly_t& q, const std::vector<double>& d, double normalize,
                                  double factor_error = 0) {
    std::vector<unit_vertex> in;
    for (std::size_t i = 0; i < q.size(); ++i)
        in.push_back({glm::normalize(q[i]), (d.empty() ? 0.0 : d[i]) + normalize});
    std::vector<unit_vertex> w;  // the polygon the library sums over
    const bool clip = f != form::sphere && f != form::cosine_unclipped;
    if (!clip) {
        w = in;
    } else {
        for (std::size_t i = 0; i < in.size(); ++i) {
            const unit_vertex& p = in[i];
            const unit_vertex& n = in[(i + 1) % in.size()];
            const bool p_in = p.w.z >= 0, n_in = n.w.z >= 0;
            if (p_in != n_in) {
                const unit_vertex& a = p_in ? p : n;
                const unit_vertex& b = p_in ? n : p;
                dvec3 x = a.w * (-b.w.z) + b.w * a.w.z;
                x.z = 0;
                w.push_back({glm::normalize(x), (std::max(a.delta, b.delta) + 4) * kappa(angle(a.w, b.w))});
            }
            if (n_in) w.push_back(n);
        }
    }
    const std::size_t m = w.size();
    bound_parts parts;
    parts.norm = f == form::sphere ? 4 * kPi : 2 * kPi;
    if (m < 3) return parts;  // nothing above the horizon: the library returns exactly 0
    const double rho = f == form::cosine || f == form::cosine_unclipped ? 2 : (f == form::squared ? 3 : 1);
    double region = 0, terms = 0, sum_abs = 0;
    const dvec3 q0 = w[0].w;
    for (std::size_t i = 0; i < m; ++i) {
        const dvec3 a = w[i].w, b = w[(i + 1) % m].w;
        const double th = angle(a, b), k = kappa(th);
        region += rho * (w[i].delta + w[(i + 1) % m].delta) * th * k / 2;
        if (f == form::cosine || f == form::cosine_unclipped) {
            terms += (factor_error > 0 ? factor_error + 7 : 22) * th * k;
            sum_abs += th;
        }
        if (f == form::squared) {
            terms += 25 * th + 4;
            sum_abs += glm::length(b - a);
        }
        if (f != form::cosine && f != form::cosine_unclipped) {
            // apex: the first vertex (unclipped solid angle) or the pole (clipped ones)
            const dvec3 apex = clip ? dvec3(0, 0, 1) : q0;
            const double ab = glm::dot(a, b);
            const double y = glm::dot(apex - a, glm::cross(a, ab >= 0 ? b - a : b + a));
            const double x = 1 + glm::dot(apex, a) + glm::dot(apex, b) + ab;
            const double r2 = x * x + y * y;
            const double omega = 2 * std::atan2(y, x);
            const double dy = clip ? 6 * glm::length(ab >= 0 ? b - a : b + a)
                                   : 9 * glm::length(q0 - a) * glm::length(ab >= 0 ? b - a : b + a);
            const double dx = clip ? 21 : 27;
            if (r2 > 0) terms += 2 * (std::abs(x) * dy + std::abs(y) * dx) / r2;
            terms += 2 * std::abs(omega);
            sum_abs += std::abs(omega);
        }
    }
    parts.region = region;
    parts.terms = terms;
    parts.summation = double(m + 1) * sum_abs;
    return parts;
}

/// The first-order bound on |computed - exact| for the closed form of magnitude `value`
/// (factor_error: see rounding_parts).
inline double rounding_bound(form f, const poly_t& q, const std::vector<double>& d, double u, double value,
                             double factor_error = 0) {
    const bound_parts b = rounding_parts(f, q, d, 2, factor_error);
    if (b.region == 0 && b.terms == 0) return 0;
    return u * (b.region + b.terms + b.summation) / b.norm + 3 * u * std::abs(value);
}

/// The change of the exact integral when every vertex direction of q moves by up to delta u
/// (the region term alone): the error of a reference whose input polygon is rounded.
inline double region_bound(form f, const poly_t& q, double delta, double u) {
    const bound_parts b = rounding_parts(f, q, {}, delta);
    return u * b.region / b.norm;
}

/// d_i of rounding_bound for the vertices M^-1 p_i that transformed<> computes in T, in units of
/// u: m_inv * (p / s) is 1 division and a 3-term dot product per component, so each component is
/// off by <= 4u (|M^-1| |p|)_i / s, a direction error <= 4u kappa_p with the condition ratio
/// kappa_p = | |M^-1| |p| | / |M^-1 p|; plus the difference between the M^-1 the library stores
/// (inverse_matrix(), rounded in T) and the exact one, projected orthogonally to M^-1 p (a
/// common scale factor does not change directions).
inline std::vector<double> transformed_input_error(const dmat3& m_inv_exact, const dmat3& m_inv_used,
                                                   const poly_t& p, double u) {
    std::vector<double> d;
    const dmat3 abs_m(glm::abs(m_inv_exact[0]), glm::abs(m_inv_exact[1]), glm::abs(m_inv_exact[2]));
    const dmat3 delta = m_inv_used - m_inv_exact;
    for (const dvec3& x : p) {
        const dvec3 q = m_inv_exact * x;
        const double lq = glm::length(q);
        const double kappa_p = glm::length(abs_m * glm::abs(x)) / lq;
        const dvec3 dq = delta * x;
        const dvec3 qh = q / lq;
        const double perp = glm::length(dq - glm::dot(dq, qh) * qh) / lq;
        d.push_back(4 * kappa_p + perp / u);
    }
    return d;
}

template <typename T>
constexpr double unit_roundoff() {
    return std::numeric_limits<T>::epsilon() / 2;
}

}  // namespace ltc_test::polygon_integration
