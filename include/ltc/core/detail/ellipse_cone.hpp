// ltc/core/detail/ellipse_cone.hpp -- the cone that an ellipse subtends at the origin, in the frame of
// its axis, and its horizon-clipped cosine integral in closed form (not part of the public API;
// ltc/core/ellipse_integral.hpp states the results, this file the derivation, in four steps:
// ellipse_frame, cone_axis, cone_frame, clipped_cone_integral).
#pragma once

#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <limits>
#include <type_traits>

LTC_NAMESPACE_BEGIN
namespace detail {

/// An ellipse in its principal frame, as seen from the origin.
///
/// 1. Principal frame. The ellipse c + a s + b t (s^2 + t^2 <= 1) has semi-axes e1 >= e2 along
///    v1, v2 and its plane's normal v3 points towards it: c = (x0, y0, l), l > 0.
template <typename T>
struct ellipse_frame {
    glm::vec<3, T> v1, v2, v3;  // principal directions and the plane's normal (towards it)
    T e1{0}, e2{0};             // semi-axes, e1 >= e2 > 0
    T x0{0}, y0{0}, l{0};       // the centre in (v1, v2, v3); l >= 0
    T sign{0};                  // orientation: the sign of c.(a x b); 0 for degenerate input
};

/// a x b with every product exact (one rounding per component): the plane's normal of a thin
/// ellipse given by nearly parallel conjugate semi-axes is otherwise off by epsilon |a| |b| /
/// |a x b|, which tilts it about its minor axis. Products in double for float; for double by
/// Dekker's splitting on the host in every build (not std::fma: a library call without -mfma, and
/// a body that changed with -m flags would break the one definition rule), by FMA on the device.
/// Both give the exact error of the product wherever the splitting does not overflow
/// (|x|, |y| below about 2^996).
template <typename T>
LTC_HOST_DEVICE inline T exact_product_error(T x, T y, T p) {
#if defined(__CUDA_ARCH__)
    return std::fma(x, y, -p);
#else
    const T split = T((1ull << ((std::numeric_limits<T>::digits + 1) / 2)) + 1);
    const T cx = split * x, xh = cx - (cx - x), xl = x - xh;
    const T cy = split * y, yh = cy - (cy - y), yl = y - yh;
    return ((xh * yh - p) + xh * yl + xl * yh) + xl * yl;
#endif
}

template <typename T>
LTC_HOST_DEVICE inline T difference_of_exact_products(T a, T b, T c, T d) {
    const T ab = a * b, cd = c * d;
    return (ab - cd) + (exact_product_error(a, b, ab) - exact_product_error(c, d, cd));
}

template <typename T>
LTC_HOST_DEVICE inline glm::vec<3, T> precise_cross(const glm::vec<3, T>& a, const glm::vec<3, T>& b) {
    if constexpr (std::is_same_v<T, float>) {
        return glm::vec<3, T>(glm::cross(glm::dvec3(a), glm::dvec3(b)));
    } else {
        return glm::vec<3, T>(difference_of_exact_products(a.y, b.z, a.z, b.y),
                              difference_of_exact_products(a.z, b.x, a.x, b.z),
                              difference_of_exact_products(a.x, b.y, a.y, b.x));
    }
}

/// ellipse_frame of c + a s + b t. The inputs are first scaled by a power of two (exact; the
/// integrals only see directions) that brings the largest coordinate into [1, 2). Degenerate
/// (sign 0): a non-finite or zero input, or a x b = 0 (the ellipse is a segment).
template <typename T>
LTC_HOST_DEVICE inline ellipse_frame<T> make_ellipse_frame(glm::vec<3, T> c, glm::vec<3, T> a, glm::vec<3, T> b) {
    using vec3 = glm::vec<3, T>;
    ellipse_frame<T> f;
    const vec3 m3 = glm::max(glm::max(glm::abs(c), glm::abs(a)), glm::abs(b));
    const T m = glm::max(glm::max(m3.x, m3.y), m3.z);
    if (!(m > T(0)) || !std::isfinite(m)) return f;
    const int e = std::ilogb(m);
    if (e > -100 && e < 100) {
        const T s = std::ldexp(T(1), -e);
        c *= s, a *= s, b *= s;
    } else {
        for (int i = 0; i < 3; ++i)
            c[i] = std::ldexp(c[i], -e), a[i] = std::ldexp(a[i], -e), b[i] = std::ldexp(b[i], -e);
    }
    // Principal axes: the Jacobi rotation (a, b) -> (a cs - b sn, a sn + b cs) that makes them
    // orthogonal is a phase shift of the boundary (same ellipse, same a x b).
    const T aa = glm::dot(a, a), bb = glm::dot(b, b), ab = glm::dot(a, b);
    T t(0);
    if (ab != T(0)) {
        const T zeta = (aa - bb) / (T(2) * ab);
        t = -std::copysign(T(1), zeta) / (std::abs(zeta) + std::sqrt(T(1) + zeta * zeta));
    }
    const T cs = T(1) / std::sqrt(T(1) + t * t), sn = t * cs;
    vec3 major = cs * a - sn * b;
    const vec3 minor = sn * a + cs * b;
    if (glm::dot(major, major) < glm::dot(minor, minor)) major = minor;
    // Lengths as n.(n / |n|), with safe_normalize: no square under- or overflows.
    const vec3 n = precise_cross(a, b);
    f.v3 = safe_normalize(n);
    f.v1 = safe_normalize(major);
    const T area = glm::dot(n, f.v3);  // e1 e2
    f.e1 = glm::dot(major, f.v1);
    if (!(area > T(0)) || !(f.e1 > T(0))) return f;
    f.e2 = area / f.e1;  // the minor semi-axis without cancellation
    f.v2 = glm::cross(f.v3, f.v1);
    f.l = glm::dot(c, f.v3);
    f.sign = f.l < T(0) ? T(-1) : T(1);
    if (f.l < T(0)) f.v3 = -f.v3, f.v2 = -f.v2, f.l = -f.l;  // (v1, v2, v3) stays right-handed
    f.x0 = glm::dot(c, f.v1);
    f.y0 = glm::dot(c, f.v2);
    return f;
}

/// The cone's axis (step 2 below), for l > 0: mu, d_i, l^2, the axis v in (v1, v2, v3)
/// (unnormalized) and the unclipped form factor |F|.
///
/// 2. Axis. The cone over it is dual to T = diag(e1^2, e2^2, 0) - c c^T. Its negative eigenvalue
///    -l^2 / mu solves g(mu) = mu (1 + x0^2 / d1 + y0^2 / d2) - 1 = 0, d_i = l^2 + mu e_i^2,
///    a sum of positive terms, increasing and concave on (0, 1], with g' = |v|^2 for the axis
///    v = (x0 l / d1, y0 l / d2, 1): Newton from a lower bound climbs monotonically. The
///    unclipped form factor is |F| = mu e1 e2 / (|v| sqrt(d1 d2)) (for a centred circle of
///    angular radius sigma: mu = 1, |F| = sin^2 sigma), F along v.
template <typename T>
struct cone_axis {
    T mu, d1, d2, l2, length_v, form_factor;
    glm::vec<3, T> v;
};

/// The root of b m^2 + B m - c = 0 that is >= 0 (b, c >= 0), without cancellation.
template <typename T>
LTC_HOST_DEVICE inline T positive_root(T b, T B, T c) {
    const T D = std::sqrt(B * B + T(4) * b * c);
    return B >= T(0) ? T(2) * c / (B + D) : (D - B) / (T(2) * b);
}

/// l is floored at 4 sqrt(min_normal) (the ellipse has unit scale here), so that 1 / l^2 and
/// x0 / l stay finite: far below l's own rounding error (~epsilon |c|) unless |c| is itself tiny
/// against the ellipse (see needs_wider_type).
template <typename T>
LTC_HOST_DEVICE inline cone_axis<T> make_cone_axis(const ellipse_frame<T>& f) {
    const T eps = epsilon<T>();
    const T l = glm::max(f.l, T(4) * std::sqrt(min_normal<T>())), p = l * l;
    const T X = f.x0 * f.x0, Y = f.y0 * f.y0, a = f.e1 * f.e1, b = f.e2 * f.e2;
    // Lower bounds, from quadratics that bound g from above: both terms with e2 (the circle of
    // radius e2), or one term exact and the other at its mu -> infinity bound Y / (mu b).
    T mu = positive_root(b, p + X + Y - b, p);
    const T rx = T(1) - Y / b, ry = T(1) - X / a;
    if (rx > T(0)) mu = glm::max(mu, positive_root(a, p + X - rx * a, rx * p));
    if (ry > T(0)) mu = glm::max(mu, positive_root(b, p + Y - ry * b, ry * p));
    // Newton from below: g < 0 and every step stays below the root (g is concave). Should
    // rounding put a bound above the root, the step from there lands below it (concavity again),
    // and the loop ends: g >= 0 or a negligible step (the step counts: docs/design_notes.md).
    // That step from above is floored at mu / 2: with the origin near both the ellipse's plane
    // and its rim, g ~ mu + (X / a + Y / b - 1) - O(p / mu) and the rim term cancels, so g and
    // the bounds carry absolute errors ~ epsilon while the root mu may be ~ epsilon itself; a
    // bound over it by rounding then has g ~ +epsilon with g' ~ 1, and the tangent's zero could
    // be <= 0 (a NaN from sqrt(mu) downstream; the fuzzer found it in float, and it happens in
    // double alike). The root is in (0, mu), known to no better than that rounding, so mu / 2 is
    // as good a value; an ordinary step (from below, or a rounding overshoot of a well-separated
    // root) moves mu by far less than half and is unchanged.
    for (int i = 0; i < 24; ++i) {
        const T r1 = T(1) / (p + mu * a), r2 = T(1) / (p + mu * b), u1 = X * r1, u2 = Y * r2;
        const T g = mu * (T(1) + u1 + u2) - T(1);
        const T step = g / (T(1) + u1 * (p * r1) + u2 * (p * r2));  // g' = |v|^2, p r_i <= 1
        const bool done = !(g < T(0)) || !(std::abs(step) > T(2) * eps * mu);
        mu = glm::min(glm::max(mu - step, T(0.5) * mu), T(1));
        if (done) break;
    }
    const T d1 = p + mu * a, d2 = p + mu * b;
    cone_axis<T> r{mu, d1, d2, p, T(0), T(0), glm::vec<3, T>(f.x0 * l / d1, f.y0 * l / d2, T(1))};
    r.length_v = glm::dot(r.v, safe_normalize(r.v));  // |v|, up to ~1 / l: no square overflows
    r.form_factor = glm::min(mu * f.e1 * f.e2 / (r.length_v * std::sqrt(d1) * std::sqrt(d2)), T(1));
    return r;
}

/// The cone in its own right-handed frame (u1, u2, axis), in (v1, v2, v3) coordinates, and its
/// half-angles (step 3 below; step 4: clipped_cone_integral); theta increasing is the positive
/// orientation.
///
/// 3. Section. The automorphism of the unit disk (a Lorentz boost of (s, t, 1)) that takes the pole
///    of the vanishing line {x : v.x = 0} to the centre maps the boundary to a parameterization
///    (c - k r_u) + (r_u - k c) cos th + sqrt(1 - k^2) r_p sin th of the same rays, centred on the
///    axis, with k = |w|, w_i = e_i x_i mu / d_i, r_u, r_p the semi-diameters along w and across
///    it, and 1 - k^2 = mu |v|^2. Its conjugate semi-axes, written in (e_p, e_q) with e_q along
///    r_p, are products of positive terms (make_cone_frame); a 2 x 2 SVD gives the principal ones
///    sigma_1, sigma_2 (sigma_2 = det / sigma_1), and the cone's half-angles follow from
///    tan alpha_i = sigma_i sqrt(mu) / l. Nothing above subtracts nearly equal numbers: both
///    half-angles keep their relative accuracy for a needle-thin cone (a small, far light) and
///    for a nearly flat one (a point close to the disk's plane).
template <typename T>
struct cone_frame {
    glm::vec<3, T> u1, u2, axis;
    T sa, ca, sb, cb;
};

template <typename T>
LTC_HOST_DEVICE inline cone_frame<T> make_cone_frame(const ellipse_frame<T>& f, const cone_axis<T>& c) {
    using vec3 = glm::vec<3, T>;
    const T sqrt_mu = std::sqrt(c.mu);
    // w / |w| (the pole's direction) and |r_p| without squaring tiny numbers (safe_normalize)
    const vec3 w(f.e1 * (c.mu / c.d1) * f.x0, f.e2 * (c.mu / c.d2) * f.y0, T(0));
    vec3 wn = safe_normalize(w);
    if (wn == vec3(T(0))) wn = vec3(T(1), T(0), T(0));  // centred on the axis: any diameter will do
    const T w1 = wn.x, w2 = wn.y;
    const vec3 rp(-f.e1 * w2, f.e2 * w1, T(0));
    const vec3 eq = safe_normalize(rp);
    const T q = glm::dot(rp, eq);  // >= e2 > 0
    cone_frame<T> out;
    out.axis = c.v / c.length_v;
    const vec3 ep = glm::cross(eq, out.axis);
    // Conjugate semi-axes of the section, divided by sqrt(1 - k^2): P = (pp, pq) and Q = (0, q)
    // in (ep, eq); its centre is at l / sqrt(mu) on the axis.
    const T pp = sqrt_mu * f.e1 * f.e2 / q;
    const T pq = sqrt_mu * c.length_v * (f.e2 - f.e1) * (f.e2 + f.e1) * w1 * w2 / q;
    // SVD of [P Q], divided by its largest entry m: the major axis of P P^T + Q Q^T at angle phi
    // from ep, with (cos, sin)(2 phi) = (h, o) / R and the half angle taken without cancellation.
    const T m = glm::max(glm::max(pp, std::abs(pq)), q), P1 = pp / m, P2 = pq / m, Q2 = q / m;
    const T h = T(0.5) * (P1 * P1 - P2 * P2 - Q2 * Q2), o = P1 * P2, R = std::sqrt(h * h + o * o);
    const T s1 = std::sqrt(T(0.5) * (P1 * P1 + P2 * P2 + Q2 * Q2) + R);  // sigma_1 / m >= 1 / 2
    const T sigma1 = m * s1, sigma2 = m * (P1 * Q2 / s1);                 // det / sigma_1
    const T c2 = R > T(0) ? h / R : T(1), s2 = R > T(0) ? o / R : T(0);
    T cp, sp;
    if (c2 >= T(0)) cp = std::sqrt(T(0.5) * (T(1) + c2)), sp = s2 / (T(2) * cp);
    else sp = std::copysign(std::sqrt(T(0.5) * (T(1) - c2)), s2), cp = s2 / (T(2) * sp);
    out.u1 = cp * ep + sp * eq;
    out.u2 = cp * eq - sp * ep;
    // (sin, cos) alpha_i = (sigma_i, dist) / |(sigma_i, dist)|, dist = l / sqrt(mu) > 0
    const T dist = std::sqrt(c.l2) / sqrt_mu;
    const auto unit = [](T x, T y, T& sx, T& cx) {
        const T big = glm::max(x, y), a = x / big, b = y / big, n = std::sqrt(a * a + b * b);
        sx = a / n, cx = b / n;
    };
    unit(sigma1, dist, out.sa, out.ca);
    unit(sigma2, dist, out.sb, out.cb);
    return out;
}

/// p q^2 int_0^s dx / (p^2 + (q^2 - p^2) x^2) for |s| <= 1, c^2 = 1 - s^2, p, q >= 0: an atan
/// for q > p, an atanh for q < p, homogeneous of degree 1 in (p, q) (evaluated after dividing by
/// the larger, so that nothing under- or overflows).
template <typename T>
LTC_HOST_DEVICE inline T arc_antiderivative(T s, T c, T p, T q) {
    if (s == T(0) || q == T(0)) return T(0);
    if (q > p) {
        const T t = p / q, r = std::sqrt((T(1) - t) * (T(1) + t));
        return r > T(0) ? q * std::atan2(s * r, t) / r : q * s / t;
    }
    const T t = q / p, r = std::sqrt((T(1) - t) * (T(1) + t));
    if (!(r > T(0))) return p * t * t * s;
    // atanh(y), y = |s| r < 1, with 1 - y = (c^2 + s^2 t^2) / (1 + y) free of cancellation
    const T y = std::abs(s) * r, one_minus_y = (c * c + s * s * t * t) / (T(1) + y);
    return std::copysign(p * t * t * T(0.5) * std::log1p(T(2) * y / one_minus_y) / r, s);
}

/// The horizon-clipped cosine integral of the positively oriented ellipse whose cone is k, with
/// the horizon's normal n in the cone's frame: arc (step 4 below) plus chord, / 2 pi.
///
/// 4. Integral. In the cone's frame, with (sa, ca) = (sin, cos) alpha_1 and (sb, cb) of alpha_2,
///    x(th) ~ (sa cb cos th, ca sb sin th, ca cb), |x|^2 = cb^2 cos^2 th + ca^2 sin^2 th, and the
///    z-weighted boundary integrand (x cross x').n / |x|^2 of ltc/core/ellipse_integral.hpp is
///      (n3 sa sb ca cb - n1 ca^2 cb sb cos th - n2 ca cb^2 sa sin th) / (cb^2 cos^2 + ca^2 sin^2)
///    for the horizon normal n in that frame: the first term integrates to an angle
///    (atan2(ca sin th, cb cos th)), the others to atan or atanh (arc_antiderivative).
template <typename T>
LTC_HOST_DEVICE inline T clipped_cone_integral(const cone_frame<T>& k, T n1, T n2, T n3) {
    const T X = k.sa * k.cb, Y = k.ca * k.sb, Z = k.ca * k.cb;  // x(th) = (X cos, Y sin, Z)
    // n.x(th) = rho cos(th - th0) + m >= 0 on th0 - gamma <= th <= th0 + gamma
    const T px = n1 * X, py = n2 * Y, m = n3 * Z, rho = std::sqrt(px * px + py * py);
    if (m >= rho) return n3 * k.sa * k.sb;  // all above: F.z
    if (m <= -rho) return T(0);
    const T am = std::abs(m);
    const T cg = -m / rho, sg = std::sqrt((rho - am) * (rho + am)) / rho;  // cos, sin gamma
    const T c0 = px / rho, s0 = py / rho;
    const T cs = c0 * cg + s0 * sg, ss = s0 * cg - c0 * sg;  // th_s = th0 - gamma
    const T ce = c0 * cg - s0 * sg, se = s0 * cg + c0 * sg;  // th_e = th0 + gamma
    // psi(th) = atan2(ca sin th, cb cos th) = th + delta(th), |delta| < pi / 2
    const auto delta = [&](T co, T si) {
        return std::atan2((k.ca - k.cb) * si * co, k.cb * co * co + k.ca * si * si);
    };
    const T dpsi = T(2) * std::atan2(sg, cg) + delta(ce, se) - delta(cs, ss);
    T arc = n3 * k.sa * k.sb * dpsi;
    arc -= n1 * k.sb * (arc_antiderivative(se, ce, k.cb, k.ca) - arc_antiderivative(ss, cs, k.cb, k.ca));
    arc += n2 * k.sa * (arc_antiderivative(ce, se, k.ca, k.cb) - arc_antiderivative(cs, ss, k.ca, k.cb));
    // The chord x(th_e) -> x(th_s) lies in the horizon plane: its edge term is + its angle
    // (n.(x_e x x_s) = 2 sin(gamma) X Y Z / rho > 0), with x_e x x_s in closed form, so that it
    // stays accurate for nearly antipodal ends (a point close to the disk's plane).
    using vec3 = glm::vec<3, T>;
    const T cross = T(2) * sg * glm::length(vec3(Y * Z * c0, Z * X * s0, X * Y * cg));
    const T chord = std::atan2(cross, X * X * cs * ce + Y * Y * ss * se + Z * Z);
    return glm::clamp((arc + chord) / (T(2) * pi<T>()), T(0), T(1));
}

/// Float geometry spanning more than 2^40 (an ellipse thinner than 1e-12 of its largest
/// coordinate, or a point that close to its plane) is integrated in double: float's exponent
/// range would underflow its squares. Double has no such fallback: past 1e-150 its results stay
/// finite (the floor of make_cone_axis) but lose accuracy.
template <typename T>
LTC_HOST_DEVICE inline bool needs_wider_type(const ellipse_frame<T>& f) {
    if constexpr (std::is_same_v<T, float>) return f.e2 < 0x1p-40f || (f.l > 0.0f && f.l < 0x1p-40f);
    else return false;
}

}  // namespace detail
LTC_NAMESPACE_END
