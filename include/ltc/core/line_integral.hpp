// ltc/core/line_integral.hpp -- line (tube) lights: the integral of the clamped cosine, and of a
// linearly transformed cosine (eq. 1), over a thin cylinder around the segment p1-p2, per unit of
// the cylinder's diameter. Via Heitz and Hill, "Real-Time Line- and Disk-Light Shading with
// Linearly Transformed Cosines" (SIGGRAPH 2017 course); the derivation (integrate_line_cosine,
// integrate_line) is our own.
//
//   float f = ltc::integrate_line_cosine(p1, p2);  // D_o = max(0, z) / pi, eq. (L1)-(L2)
//   float s = ltc::integrate_line(d, p1, p2);      // d: transformed<clamped_cosine<float>>, (L3)
//   // a tube of radiance L and radius r << its distance: L * 2r * s (plus O(r^2))
//
// Conventions: shading point at the origin, z the normal; >= 0, in units of 1/length, symmetric
// in p1 and p2, no sidedness (a tube glows all around); horizon-clipped exactly. Degenerate
// cases: never NaN or Inf for finite input; 0 for p1 = p2, an axis through the origin, a segment
// below or in the horizon plane; saturated at the largest finite value (integrate_line_cosine).
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/edge_policy.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <cfloat>
#include <cmath>
#include <limits>
#include <type_traits>

LTC_NAMESPACE_BEGIN

namespace detail {

/// x clamped to [0, largest finite] (NaN, which finite input never produces, to 0).
template <typename T>
LTC_HOST_DEVICE LTC_INLINE T saturate_line(T x) {
    return !(x > T(0)) ? T(0) : (x < largest_finite<T>() ? x : largest_finite<T>());
}

/// Coordinates whose largest magnitude lies in [1/line_scale, line_scale] are used as they are:
/// products of two of them then stay within 2^32 (float) or 2^256 (double) of those of the
/// rescaled computation, far inside the exponent range; others are rescaled first.
template <typename T>
LTC_HOST_DEVICE constexpr T line_scale() {
    return std::is_same_v<T, float> ? T(65536) : T(3.4028236692093846346e38);  // 2^16, 2^128
}

/// m within [line_scale^-power, line_scale^power] (power 3 for |M^-1|, a product of three entries:
/// the GGX table's reach 1e-10).
template <int power = 1, typename T>
LTC_HOST_DEVICE LTC_INLINE bool line_moderate(T m) {
    constexpr T s = power == 3 ? line_scale<T>() * line_scale<T>() * line_scale<T>() : line_scale<T>();
    return m >= T(1) / s && m <= s;
}

template <typename T>
LTC_HOST_DEVICE LTC_INLINE T max_abs(const glm::vec<3, T>& a, const glm::vec<3, T>& b) {
    const glm::vec<3, T> m = glm::max(glm::abs(a), glm::abs(b));
    return glm::max(glm::max(m.x, m.y), m.z);
}

template <typename T>
LTC_HOST_DEVICE inline glm::vec<3, T> ldexp3(const glm::vec<3, T>& v, int k) {
    return glm::vec<3, T>(std::ldexp(v.x, k), std::ldexp(v.y, k), std::ldexp(v.z, k));
}

template <typename T>
LTC_HOST_DEVICE LTC_NOINLINE T line_length_rescaled(const glm::vec<3, T>& v) {
    const T m = glm::max(glm::max(std::abs(v.x), std::abs(v.y)), std::abs(v.z));
    if (!(m > T(0))) return T(0);
    const int k = std::ilogb(m);
    return std::ldexp(glm::length(ldexp3(v, -k)), k);
}

/// |v| without the underflow of |v|^2 for tiny v (a segment passing within ~sqrt(min_normal) of the
/// origin, relative to its size): exact power-of-two rescaling below the normal range.
template <typename T>
LTC_HOST_DEVICE LTC_INLINE T line_length(const glm::vec<3, T>& v) {
    const T l2 = glm::dot(v, v);
    return l2 > min_normal<T>() / epsilon<T>() ? std::sqrt(l2) : line_length_rescaled(v);
}

/// D - sin(D) for D in [0, pi] given s = sin(D): Taylor series below 1, where the difference
/// cancels (the first omitted terms, D^13/13! in float and D^21/21! in double, are below half an
/// ulp of the result); the difference itself above (losing at most 3 bits, at D = 1).
template <typename T>
LTC_HOST_DEVICE LTC_INLINE T angle_minus_sine(T delta, T s) {
    if (delta >= T(1)) return delta - s;
    const T x = delta * delta;
    T p;
    if constexpr (std::is_same_v<T, float>) {
        p = T(1.0 / 6) + x * (T(-1.0 / 120) + x * (T(1.0 / 5040) + x * (T(-1.0 / 362880) + x * T(1.0 / 39916800))));
    } else {
        const T tail = T(-1.0 / 6227020800) +
                       x * (T(1.0 / 1307674368000) + x * (T(-1.0 / 355687428096000) + x * T(1.0 / 121645100408832000)));
        p = T(1.0 / 6) + x * (T(-1.0 / 120) + x * (T(1.0 / 5040) + x * (T(-1.0 / 362880) +
                                                                      x * (T(1.0 / 39916800) + x * tail))));
    }
    return delta * x * p;
}

/// The angle D in [0, pi] of sine s >= 0 and cosine c: by the edge policy's theta / sin(theta) (the
/// clamped cosine's: a float-accurate fit in float, atan2 in double), or D = s, pi - s where s is
/// too small for the policies (they return 0 for nearly opposite directions, which are here a
/// segment passing next to the origin, where D -> pi matters).
template <typename Policy, typename T>
LTC_HOST_DEVICE LTC_INLINE T line_angle(T s, T c) {
    if constexpr (std::is_same_v<Policy, edge_policy::exact>) {
        return std::atan2(s, c);
    } else {
        if (!(s > T(1e-15))) return c > T(0) ? s : pi<T>() - s;  // D = s or pi - s to s^2/6 relative
        return s * Policy::theta_over_sin(c, glm::vec<3, T>(s, T(0), T(0)));
    }
}

/// (L2) for the segment a-b given e ~ b - a and c ~ a x e with |c| = cn (the callers compute
/// them from their own inputs, each as accurately as those allow), at moderate scale.
template <typename Policy, typename T>
LTC_HOST_DEVICE LTC_INLINE T line_cosine(const glm::vec<3, T>& a, const glm::vec<3, T>& b, const glm::vec<3, T>& e,
                                         const glm::vec<3, T>& c, T cn) {
    if (!(a.z > T(0) || b.z > T(0))) return T(0);  // below or in the horizon plane: D_o = 0
    const T len = line_length(e), inv_len = T(1) / len;
    const T d = cn * inv_len;
    if (!(d > T(0)) || !(len > T(0))) return T(0);  // zero length, or an axis through the origin (edge-on)
    const glm::vec<3, T> t = e * inv_len;
    const T nz = (t.x * c.y - t.y * c.x) / cn;  // n = t x c / |c|, the foot point's direction
    T la = glm::dot(a, t), lb = glm::dot(b, t), ra = line_length(a), rb = line_length(b), l = len;
    // Horizon: the part above z = 0 has length l = len z_in / (z_in - z_out) from the end above.
    if (a.z < T(0)) {
        l = len * (b.z / (b.z - a.z));
        la = lb - l;
        ra = line_length(glm::vec<3, T>(d, la, T(0)));
    } else if (b.z < T(0)) {
        l = len * (a.z / (a.z - b.z));
        lb = la + l;
        rb = line_length(glm::vec<3, T>(d, lb, T(0)));
    }
    const T inv_rab = T(1) / (ra * rb);
    const T sin_delta = d * l * inv_rab;
    const T cos_delta = (d * d + la * lb) * inv_rab;  // a.b / (|a| |b|)
    const T delta = line_angle<Policy>(sin_delta, cos_delta);
    const T da = d * (ra + rb) * inv_rab;  // d/|a| + d/|b|
    const T one_plus_cos_sum = cos_delta >= T(0) ? da * da / (T(1) + cos_delta) : T(1) + (d * d - la * lb) * inv_rab;
    // K / d diverges like pi / d for a segment passing next to the origin: it may overflow, so
    // n.z = 0 skips it (no 0 * Inf) and saturate_line caps the sum (and maps the NaN of an
    // Inf - Inf, possible only for d within a few ulps of the smallest subnormal, to 0).
    const T k_over_d = angle_minus_sine(delta, sin_delta) / d + l * one_plus_cos_sum * inv_rab;
    const T sum = (nz != T(0) ? nz * k_over_d : T(0)) + t.z * (sin_delta * ((la + lb) * inv_rab));
    return saturate_line(sum * (T(0.5) / pi<T>()));
}

template <typename Policy, typename T>
LTC_HOST_DEVICE LTC_INLINE T line_cosine(const glm::vec<3, T>& a, const glm::vec<3, T>& b) {
    const glm::vec<3, T> e = b - a;
    const glm::vec<3, T> c = glm::cross(a, e);  // a x (b - a): accurate for nearly collinear a, b
    return line_cosine<Policy>(a, b, e, c, line_length(c));
}

/// The slow path of integrate_line_cosine: both points times one power of two 2^-k, the result
/// times 2^-k (the integral has units of 1/length), saturated.
template <typename Policy, typename T>
LTC_HOST_DEVICE LTC_NOINLINE T line_cosine_rescaled(const glm::vec<3, T>& p1, const glm::vec<3, T>& p2) {
    const T m = max_abs(p1, p2);
    if (!(m > T(0)) || !(m <= largest_finite<T>())) return T(0);  // both at the origin (or not finite)
    const int k = std::ilogb(m);
    return saturate_line(std::ldexp(line_cosine<Policy>(ldexp3(p1, -k), ldexp3(p2, -k)), -k));
}

/// (L3) at moderate scale: I_line(M^-1 p1, M^-1 p2) / |M^T m|, with q_i = M^-1 p_i given.
template <typename Policy, typename T>
LTC_HOST_DEVICE LTC_INLINE T line_ltc(const glm::mat<3, 3, T>& m_inv, T abs_det, const glm::vec<3, T>& p1,
                                      const glm::vec<3, T>& p2, const glm::vec<3, T>& q1, const glm::vec<3, T>& q2) {
    const glm::vec<3, T> e = p2 - p1;
    const glm::vec<3, T> eq = m_inv * e;  // M^-1 (p2 - p1), not q2 - q1: accurate for short segments
    const glm::vec<3, T> cq = glm::cross(q1, eq);
    const T cqn = line_length(cq);
    const T i = line_cosine<Policy>(q1, q2, eq, cq, cqn);
    if (!(i > T(0))) return T(0);  // also where cqn = 0: no 0 * Inf below
    return saturate_line(abs_det * line_length(glm::cross(p1, e)) / cqn * i);
}

/// The slow path of integrate_line: the points by one power of two (the result by its inverse),
/// M^-1 by another (D does not change), |M^-1| recomputed.
template <typename Policy, typename T>
LTC_HOST_DEVICE LTC_NOINLINE T line_ltc_rescaled(const glm::mat<3, 3, T>& m_inv, const glm::vec<3, T>& p1,
                                                 const glm::vec<3, T>& p2) {
    const T m = max_abs(p1, p2);
    if (!(m > T(0)) || !(m <= largest_finite<T>())) return T(0);
    const int k = std::ilogb(m);
    const glm::vec<3, T> a = ldexp3(p1, -k), b = ldexp3(p2, -k);
    const glm::mat<3, 3, T> s = rescale_pow2(m_inv);
    const T abs_det = std::abs(glm::dot(s[0], glm::cross(s[1], s[2])));
    return saturate_line(std::ldexp(line_ltc<Policy>(s, abs_det, a, b, s * a, s * b), -k));
}

}  // namespace detail

/// (L1)-(L2): the integral of D_o = max(0, z)/pi over a thin cylinder around the segment p1-p2
/// (shading point at the origin, z the shading normal), divided by the cylinder's diameter, in the
/// limit of zero radius: int_segment D_o(x/|x|) d/|x|^3 dl, d the distance from the origin to the
/// segment's line. Clipped to the horizon exactly; >= 0; units of 1/length; degenerate input
/// below. Policy: how the angle D is evaluated, as for the polygon integrals.
///
/// Derivation. Shading point at the origin, axis through p1 and p2 at distance d from it. A
/// cylinder of radius r seen from the origin is 2r/|x| wide at its axis point x (across the plane
/// of the origin and the axis), and an axis element dl spans dl sin(phi)/|x| along that plane,
/// phi the angle between the axis and x: sin(phi) = d/|x|. Hence dw = 2r d/|x|^3 dl + O(r^2) and
///   I_line = lim_{r->0} (1/2r) int_cylinder D_o(w) dw = int_{p1}^{p2} D_o(x/|x|) d/|x|^3 dl.  (L1)
/// With the foot point d n of the origin on the axis (n unit), the tangent t, x = d n + l t and
/// l = d tan(theta) (theta: the angle of x from n), D_o(x/|x|) = (cos(theta) n.z + sin(theta) t.z)/pi:
///   I_line = 1/(pi d) int cos(theta) x^.z dtheta
///          = 1/(2 pi d) [n.z (theta + sin(theta) cos(theta)) + t.z sin^2(theta)]_{theta_a}^{theta_b}  (L2)
/// (in l: the antiderivatives d int (d^2 + l^2)^-2 dl and d int l (d^2 + l^2)^-2 dl, the course's
/// Fpo and Fwt). With D = theta_b - theta_a and S = theta_a + theta_b the bracket is
/// n.z K + t.z sin(D) sin(S), K = (D - sin D) + sin(D) (1 + cos S): two non-negative terms, so K
/// keeps its relative accuracy where the segment points at the origin (cos S -> -1) and the
/// endpoint terms of (L2) would cancel. For endpoints a, b at l_a < l_b, L = l_b - l_a:
///   sin D = d L / (|a| |b|),  D = atan2(d L, d^2 + l_a l_b),  sin S = d (l_a + l_b) / (|a| |b|),
///   1 + cos S = (d/|a| + d/|b|)^2 / (1 + cos D)       if cos D >= 0,
///             = (|a| |b| + d^2 - l_a l_b) / (|a| |b|)  otherwise (then l_a l_b < 0),
/// sums of positive terms; d L = |a x (b - a)| (no cancellation for nearly collinear segments).
/// D itself comes from sin D and cos D through the clamped cosine's edge policy (edge_policy.hpp:
/// atan2 in double, the float-accurate fit of theta / sin(theta) in float), D - sin D from a series
/// where it cancels.
/// Horizon: x.z is linear along the axis, so clipping to z >= 0 moves an end along the same line
/// (d, n and t unchanged): exact.
///
/// Semantics: >= 0, in units of 1/length (I(s p1, s p2) = I(p1, p2) / s), symmetric in p1 and p2; a
/// tube glows all around, so there is no sidedness. Degenerate input, never NaN or Inf when finite:
///   - p1 = p2, or an axis through the origin (the segment through, ending at, or pointing at the
///     shading point: seen edge-on): 0. For a segment pointing at the origin that is the limit
///     (the integral vanishes like d); one passing through it diverges like 1/d as d -> 0 and 0 is
///     a convention, as for polygons with a vertex at the shading point;
///   - a segment below or in the horizon plane: 0;
///   - values beyond the largest finite one (I ~ 1/(2d): a segment passing within about half the
///     reciprocal of it from the origin) saturate to it;
///   - huge or tiny (even subnormal) coordinates and M^-1 entries are rescaled by powers of two.
template <typename T, typename Policy = edge_policy::automatic>
LTC_HOST_DEVICE inline T integrate_line_cosine(const glm::vec<3, T>& p1, const glm::vec<3, T>& p2) {
    using P = edge_policy::resolve_t<Policy, T>;
    if (detail::line_moderate(detail::max_abs(p1, p2))) return detail::line_cosine<P>(p1, p2);
    return detail::line_cosine_rescaled<P>(p1, p2);
}

/// (L3): the same integral for the LTC distribution D of eq. (1): the width factor
/// 1/|M^T m| = |det M^-1| |p1 x p2| / |M^-1 p1 x M^-1 p2| times integrate_line_cosine(M^-1 p1,
/// M^-1 p2). Exact in the thin limit; uses only M^-1 and its determinant.
///
/// Derivation of (L3). D integrates over the cylinder as D_o over its image under w -> M^-1 w / |M^-1 w|
/// (eq. 1-3). The cylinder's rays are those within r/|x| of the plane of the origin and the segment
/// (unit normal m): |w.m| <= r/|x| to first order. Since m.y = (M^T m).(M^-1 y), M^-1 maps that
/// plane to the one of normal M^T m and divides distances from it by |M^T m|: the image is the
/// same band about a thin cylinder of radius r/|M^T m| around M^-1 p1 - M^-1 p2. So, exactly in the
/// limit r -> 0 (the only approximation, as in (L1)), with a width factor constant along the segment,
///   I_line,D(p1, p2) = I_line(M^-1 p1, M^-1 p2) / |M^T m|,
///   1/|M^T m| = |det M^-1| |p1 x p2| / |M^-1 p1 x M^-1 p2|                                     (L3)
/// by the cofactor identity (A u) x (A v) = det(A) A^-T (u x v) with A = M^-1.
template <typename T, typename Policy>
LTC_HOST_DEVICE inline T integrate_line(const transformed<clamped_cosine<T, Policy>>& d, const glm::vec<3, T>& p1,
                                        const glm::vec<3, T>& p2) {
    using P = typename clamped_cosine<T, Policy>::EdgePolicy;
    const glm::mat<3, 3, T>& m_inv = d.inverse_matrix();
    const T abs_det = std::abs(d.inverse_determinant());
    const glm::vec<3, T> q1 = m_inv * p1, q2 = m_inv * p2;
    if (detail::line_moderate(detail::max_abs(p1, p2)) && detail::line_moderate(detail::max_abs(q1, q2)) &&
        detail::line_moderate<3>(abs_det))
        return detail::line_ltc<P>(m_inv, abs_det, p1, p2, q1, q2);
    return detail::line_ltc_rescaled<P>(m_inv, p1, p2);
}

LTC_NAMESPACE_END
