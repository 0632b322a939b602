// ltc/core/ellipse_integral.hpp -- the clamped cosine's integral over an ellipse, horizon-clipped
// in closed form, and disk lights through an LTC (Heitz et al. 2016, eq. (3) and (11); disks as
// in Heitz and Hill 2017, "Real-Time Line- and Disk-Light Shading with Linearly Transformed
// Cosines", SIGGRAPH course, which Blender EEVEE's ltc_evaluate_disk follows).
//
//   float e = ltc::integrate_ellipse_cosine(c, a, b);   // ellipse c + a s + b t, s^2 + t^2 <= 1
//   float i = ltc::integrate_disk(d, centre, normal, radius, ltc::sidedness::one_sided);
//   float j = ltc::integrate_disk_2017(d, centre, normal, radius);   // the 2017 approximation
//
// Conventions: as polygons (ltc/core/polygon.hpp), z the normal; results signed, in [-1, 1],
// positive when c.(a x b) > 0; a disk's positive on its +normal side (one-sided: max(0, signed)).
// Degenerate cases: never NaN or Inf for finite input; 0 for radius <= 0, a zero normal, a
// segment (a x b = 0), non-finite input, an ellipse below or in the horizon plane; the shading
// point on the disk gives a polygon's value there (integrate_ellipse_cosine).
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/core/detail/ellipse_cone.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/core/detail/vertices.hpp>
#include <ltc/core/sphere_form_factor.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>

LTC_NAMESPACE_BEGIN

namespace detail {

/// The origin in the ellipse's plane (l = 0): is it strictly inside?
template <typename T>
LTC_HOST_DEVICE inline bool origin_inside(const ellipse_frame<T>& f) {
    const T u = f.x0 * f.e2, v = f.y0 * f.e1, r = f.e1 * f.e2;
    return u * u + v * v < r * r;
}

/// The cone's axis in the caller's frame (towards the ellipse).
template <typename T>
LTC_HOST_DEVICE inline glm::vec<3, T> axis_direction(const ellipse_frame<T>& f, const cone_axis<T>& ax) {
    const glm::vec<3, T> u = ax.v / ax.length_v;
    return u.x * f.v1 + u.y * f.v2 + u.z * f.v3;
}

}  // namespace detail

/// Vector form factor F = 1/(2 pi) contour (x cross dx) / |x|^2 of the unclipped ellipse
/// c + a s + b t (s^2 + t^2 <= 1), signed by the orientation of c + a cos phi + b sin phi (as
/// integrate_ellipse_cosine). F.z is the unclipped cosine integral; |F| = sin^2 sigma and the
/// direction of F (the cone's axis) give the equivalent sphere of the 2017 approximation.
template <typename T>
LTC_HOST_DEVICE inline glm::vec<3, T> ellipse_vector_form_factor(const glm::vec<3, T>& c, const glm::vec<3, T>& a,
                                                                 const glm::vec<3, T>& b) {
    const detail::ellipse_frame<T> f = detail::make_ellipse_frame(c, a, b);
    if (f.sign == T(0)) return glm::vec<3, T>(T(0));
    if (detail::needs_wider_type(f))
        return glm::vec<3, T>(ellipse_vector_form_factor(glm::dvec3(c), glm::dvec3(a), glm::dvec3(b)));
    if (f.l == T(0)) return detail::origin_inside(f) ? f.v3 : glm::vec<3, T>(T(0));
    const detail::cone_axis<T> ax = detail::make_cone_axis(f);
    return (f.sign * ax.form_factor) * detail::axis_direction(f, ax);
}

/// Signed integral of max(0, z) / pi over the solid angle of the ellipse c + a s + b t
/// (s^2 + t^2 <= 1), horizon-clipped exactly.
///
/// Method. The clamped cosine's integral over a region is the z component of its vector form
/// factor, a boundary integral by Stokes' theorem (the identity behind eq. (11)'s edge sum):
///   I = 1/(2 pi) contour (x cross dx).z / |x|^2
/// over the boundary of the part above the horizon: an elliptic arc and a chord in z = 0. The
/// chord is a straight edge: eq. (11)'s edge term, its angle (in closed form, so that it stays
/// accurate between nearly antipodal ends). The arc is integrated in closed form in the frame of
/// the cone that the ellipse subtends, where the integrand is (A + B cos th + C sin th) /
/// (P cos^2 th + Q sin^2 th): an angle plus an atan or atanh (ltc/core/detail/ellipse_cone.hpp derives
/// it). Finding that frame takes a 1D secular equation (Newton from a lower bound, 2-4 steps) and
/// a 2 x 2 SVD, in which every quantity is a sum or product of positive terms. Exact to rounding
/// relative to the integral's own scale, the ellipse's angular diameter (polygons' edge terms
/// carry errors of epsilon times their angles likewise), or within the integral's sensitivity to
/// rounding its inputs where that is larger (a point very close to a thin ellipse's plane; one
/// within rounding of both the plane and the rim, where any value in [-1, 1] is that close: finite,
/// in range, see make_cone_axis); tests/test_ellipse_integral.cpp, docs/design_notes.md.
///
/// Sign: positive when the boundary c + a cos phi + b sin phi, phi increasing, turns clockwise as
/// seen from the origin, i.e. when c.(a x b) > 0, as polygons (ltc/core/polygon.hpp); the result
/// is in [-1, 1] (units of the normalized D: the fraction of D's mass over the light).
///
/// Degenerate input never yields NaN or Inf for finite input:
///   - a x b = 0 (a segment), a non-finite input: 0;
///   - the origin in the plane of the ellipse: 0 outside it; inside it the boundary is a great
///     circle, and the results are those of a polygon in the same position: F = the plane's unit
///     normal nu = a x b / |a x b|, and the clipped integral nu.z / 2, the mean of the one-sided
///     limits (1 + nu.z) / 2 (the origin on the side a x b points away from) and -(1 - nu.z) / 2;
///   - an ellipse entirely below the horizon, or lying in the plane z = 0: 0;
///   - huge or tiny coordinates: rescaled by powers of two (exact: results do not change); float
///     geometry spanning more than 2^40 (an ellipse thinner than 1e-12 of its size or distance,
///     a point that close to its plane) is evaluated in double.
template <typename T>
LTC_HOST_DEVICE inline T integrate_ellipse_cosine(const glm::vec<3, T>& c, const glm::vec<3, T>& a,
                                                  const glm::vec<3, T>& b) {
    if (!(c.z + std::abs(a.z) + std::abs(b.z) > T(0))) return T(0);  // below (cheap test)
    const detail::ellipse_frame<T> f = detail::make_ellipse_frame(c, a, b);
    if (f.sign == T(0)) return T(0);
    if (detail::needs_wider_type(f)) return T(integrate_ellipse_cosine(glm::dvec3(c), glm::dvec3(a), glm::dvec3(b)));
    // The ellipse spans zc -+ zr in z (in f's rescaled units).
    const T zc = f.x0 * f.v1.z + f.y0 * f.v2.z + f.l * f.v3.z;
    const T zr = std::sqrt(f.e1 * f.e1 * f.v1.z * f.v1.z + f.e2 * f.e2 * f.v2.z * f.v2.z);
    if (!(zc + zr > T(0))) return T(0);
    if (f.l == T(0)) return detail::origin_inside(f) ? f.v3.z / T(2) : T(0);
    const detail::cone_axis<T> ax = detail::make_cone_axis(f);
    if (zc - zr >= T(0)) return f.sign * ax.form_factor * detail::axis_direction(f, ax).z;
    const detail::cone_frame<T> k = detail::make_cone_frame(f, ax);
    const glm::vec<3, T> h(f.v1.z, f.v2.z, f.v3.z);  // the horizon's normal in (v1, v2, v3)
    return f.sign * detail::clipped_cone_integral(k, glm::dot(h, k.u1), glm::dot(h, k.u2), glm::dot(h, k.axis));
}

namespace detail {

/// The 2017 approximation for the ellipse (c, a, b), signed: the sphere of its unclipped F
/// (towards the ellipse), clipped; 0 with the origin in the ellipse's plane, as ltc::clipless.
template <typename T>
LTC_HOST_DEVICE inline T ellipse_sphere_2017(const glm::vec<3, T>& c, const glm::vec<3, T>& a,
                                             const glm::vec<3, T>& b) {
    const ellipse_frame<T> f = make_ellipse_frame(c, a, b);
    if (f.sign == T(0) || f.l == T(0)) return T(0);
    if (needs_wider_type(f)) return T(ellipse_sphere_2017(glm::dvec3(c), glm::dvec3(a), glm::dvec3(b)));
    const cone_axis<T> ax = make_cone_axis(f);
    return f.sign * clipless::sphere_form_factor(ax.form_factor, axis_direction(f, ax).z);
}

/// A disk's boundary through M^-1: c' + a' cos phi + b' sin phi, oriented so that c'.(a' x b') has
/// the sign of det(M^-1) times that of "the origin is on the +normal side" (integrate_disk). For
/// huge or tiny coordinates M^-1 and the disk are first rescaled by powers of two (exact).
template <typename T>
struct disk_ellipse {
    glm::vec<3, T> c, a, b;
    T det_sign;
    bool valid;
    bool edge_on;  // the origin exactly in the disk's plane (before M^-1, which would blur it)
    T on_disk;     // then: 0 outside the disk; on it, the mean of the one-sided limits
};

template <typename T>
LTC_HOST_DEVICE inline disk_ellipse<T> make_disk_ellipse(const glm::mat<3, 3, T>& m_inv, T det_inv,
                                                         glm::vec<3, T> centre, glm::vec<3, T> normal, T radius) {
    using vec3 = glm::vec<3, T>;
    disk_ellipse<T> e{vec3(T(0)), vec3(T(0)), vec3(T(0)), det_inv < T(0) ? T(-1) : T(1), false, false, T(0)};
    const vec3 n = safe_normalize(normal);
    const T big = glm::max(glm::max(glm::max(std::abs(centre.x), std::abs(centre.y)), std::abs(centre.z)), radius);
    if (!(radius > T(0)) || n == vec3(T(0)) || !std::isfinite(big) || !is_finite(centre))
        return e;
    // Duff et al. 2017, listing 3: t1 x t2 = n; the boundary runs along t2, then t1 (a' x b' ~ -n).
    const T sign = std::copysign(T(1), n.z), k = T(-1) / (sign + n.z), xy = n.x * n.y * k;
    const vec3 t1(T(1) + sign * n.x * n.x * k, sign * xy, -sign * n.x), t2(xy, sign + n.y * n.y * k, -n.y);
    glm::mat<3, 3, T> m = m_inv;
    if (big < T(0x1p-60) || big > T(0x1p60)) {
        const int ex = std::ilogb(big);
        centre = vec3(std::ldexp(centre.x, -ex), std::ldexp(centre.y, -ex), std::ldexp(centre.z, -ex));
        radius = std::ldexp(radius, -ex);
    }
    e.c = m * centre, e.a = m * (radius * t2), e.b = m * (radius * t1);
    if (!is_finite(e.c) || !is_finite(e.a) || !is_finite(e.b)) {
        m = rescale_pow2(m_inv);
        e.c = m * centre, e.a = m * (radius * t2), e.b = m * (radius * t1);
    }
    e.valid = is_finite(e.c) && is_finite(e.a) && is_finite(e.b);
    // Edge-on: decided on the disk itself (as given: n's rounding would blur it too). On the disk,
    // its image's boundary is a great circle of normal nu = a' x b' / |a' x b'|, and the mean
    // value is that of the ellipse, nu.z / 2, signed as the disk's (integrate_disk).
    e.edge_on = glm::dot(centre, normal) == T(0);
    if (e.edge_on && glm::dot(centre, centre) < radius * radius)
        e.on_disk = e.det_sign * safe_normalize(glm::cross(safe_normalize(e.a), safe_normalize(e.b))).z / T(2);
    return e;
}

}  // namespace detail

/// Integral of the LTC d over the disk (centre, normal, radius), in d's frame with the shading
/// point at the origin: integrate_ellipse_cosine of its image under M^-1 (eq. 3), signed by the
/// disk's facing (positive when the origin is on the +normal side), then made non-negative by
/// `side`. Exact to rounding (integrate_ellipse_cosine).
///
/// The disk becomes under w -> M^-1 w the ellipse c' = M^-1 centre, a' = M^-1 (r t2),
/// b' = M^-1 (r t1), with (t1, t2, normal) orthonormal (Duff et al. 2017): D's integral over the
/// disk is the clamped cosine's over that ellipse (eq. 3). Its boundary runs so that its integrals
/// are positive when the shading point is on the +normal side: a one-sided disk emits towards
/// +normal (apply_sidedness: max(0, signed)), a two-sided one both ways.
///
/// Degenerate input: radius <= 0, a zero normal, a non-finite input: 0; the shading point in the
/// disk's plane (a disk seen edge-on, tested on its own plane, before M^-1 blurs it): 0 outside
/// the disk, on it the ellipse's mean of the one-sided limits (integrate_ellipse_cosine); the
/// ellipse's other cases as integrate_ellipse_cosine; a singular M^-1 as transformed<>.
template <typename T, typename Policy>
LTC_HOST_DEVICE inline T integrate_disk(const transformed<clamped_cosine<T, Policy>>& d, const glm::vec<3, T>& centre,
                                        const glm::vec<3, T>& normal, T radius, sidedness side = sidedness::two_sided) {
    const detail::disk_ellipse<T> e =
        detail::make_disk_ellipse(d.inverse_matrix(), d.inverse_determinant(), centre, normal, radius);
    if (!e.valid) return T(0);
    if (e.edge_on) return apply_sidedness(e.on_disk, side);
    return apply_sidedness(e.det_sign * integrate_ellipse_cosine(e.c, e.a, e.b), side);
}

/// The 2017 approximation (Heitz and Hill 2017; EEVEE): the unclipped vector form factor F of the
/// disk's ellipse (exact: ellipse_vector_form_factor's), then the horizon-clipped form factor of
/// the sphere with the same F (ltc::clipless::sphere_form_factor, f = |F|, cos omega = F's
/// elevation) in place of the ellipse's own clipping. Equal to integrate_disk while that sphere
/// lies above the horizon (cos omega >= sqrt(f): both are F.z, bit for bit); elsewhere an
/// approximation (its errors over random GGX disks: tests/test_disk_light.cpp,
/// docs/design_notes.md). Signed and made non-negative as integrate_disk; 0 when the shading point
/// is in the disk's plane, as ltc::clipless.
template <typename T, typename Policy>
LTC_HOST_DEVICE inline T integrate_disk_2017(const transformed<clamped_cosine<T, Policy>>& d,
                                             const glm::vec<3, T>& centre, const glm::vec<3, T>& normal, T radius,
                                             sidedness side = sidedness::two_sided) {
    const detail::disk_ellipse<T> e =
        detail::make_disk_ellipse(d.inverse_matrix(), d.inverse_determinant(), centre, normal, radius);
    if (!e.valid || e.edge_on) return T(0);
    return apply_sidedness(e.det_sign * detail::ellipse_sphere_2017(e.c, e.a, e.b), side);
}

/// The disk as a regular n_edges-gon of the same area (circumradius r sqrt(2 pi / (n sin(2 pi /
/// n)))), oriented as the disk, through d's polygon integral (eq. 11), for comparison with
/// integrate_disk (the difference's convergence in n: tests/test_disk_light.cpp,
/// docs/design_notes.md). n_edges < 3 gives 0; vertices are made on the fly.
template <typename T, typename Policy>
inline T integrate_disk_polygon(const transformed<clamped_cosine<T, Policy>>& d, const glm::vec<3, T>& centre,
                                const glm::vec<3, T>& normal, T radius, std::size_t n_edges,
                                sidedness side = sidedness::two_sided) {
    using vec3 = glm::vec<3, T>;
    if (n_edges < 3) return T(0);
    detail::disk_ellipse<T> e =
        detail::make_disk_ellipse(d.inverse_matrix(), d.inverse_determinant(), centre, normal, radius);
    if (!e.valid) return T(0);
    // One power-of-two scale for the three vectors (exact), so that no vertex overflows.
    const glm::vec<3, T> m3 = glm::max(glm::max(glm::abs(e.c), glm::abs(e.a)), glm::abs(e.b));
    const T big = glm::max(glm::max(m3.x, m3.y), m3.z);
    if (big > T(0x1p60) || (big > T(0) && big < T(0x1p-60))) {
        const int ex = std::ilogb(big);
        for (int i = 0; i < 3; ++i)
            e.c[i] = std::ldexp(e.c[i], -ex), e.a[i] = std::ldexp(e.a[i], -ex), e.b[i] = std::ldexp(e.b[i], -ex);
    }
    const T step = T(2) * pi<T>() / T(n_edges);
    const T scale = std::sqrt(step / std::sin(step));  // equal area: n R^2 sin(step) / 2 = pi r^2
    const auto raw = [&](std::size_t i) {
        const T phi = step * T(i);
        return vec3(e.c + scale * (std::cos(phi) * e.a + std::sin(phi) * e.b));
    };
    const T s = clamped_cosine<T, Policy>::signed_integral(detail::make_directions(raw), n_edges);
    return apply_sidedness(e.det_sign * s, side);
}

LTC_NAMESPACE_END
