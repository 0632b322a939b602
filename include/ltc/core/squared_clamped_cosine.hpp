// ltc/core/squared_clamped_cosine.hpp -- the squared clamped cosine distribution,
// D_o = 3 max(0, z)^2 / (2 pi). Supplement section 1.4.
#pragma once

#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/core/horizon_clip.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/core/solid_angle.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <limits>

LTC_NAMESPACE_BEGIN

namespace detail {

/// Edge term of Arvo's second axial moment (Arvo 1995, "Applications of irradiance tensors to
/// the simulation of non-Lambertian phenomena", recurrence for tau^n with n = 2):
///   tau^2 = 1/3 (Omega + sum_i (n_i . z) int_edge (z . u) dtheta),
/// n_i = a x b / |a x b|. Along the great arc from a to b, int (z . u) dtheta =
/// tan(theta/2) (a.z + b.z) = |b - a| (a + b).z / |a + b|: twice the sine of the half angle times
/// the height of the arc's midpoint, bounded by 2 and free of the 1 / sin(theta) singularity.
template <typename T>
LTC_HOST_DEVICE inline T second_moment_edge(const glm::vec<3, T>& a, const glm::vec<3, T>& b) {
    const T c = glm::dot(a, b);
    const glm::vec<3, T> axb = stable_cross(a, b, c);
    const T s = glm::length(axb);
    const glm::vec<3, T> sum = a + b;
    const T l = glm::length(sum);
    // s ~ 0: zero-length edge (term -> 0); l ~ 0: edge through the origin (no great circle).
    if (!(s > min_normal<T>()) || !(l > min_normal<T>())) return T(0);
    return (axb.z / s) * glm::length(b - a) * (sum.z / l);
}

}  // namespace detail

template <typename T>
struct squared_clamped_cosine {
    using scalar = T;
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;

    LTC_HOST_DEVICE static T eval(const vec3& w) {
        return w.z > T(0) ? T(3) * w.z * w.z / (T(2) * pi<T>()) : T(0);
    }
    LTC_HOST_DEVICE static T pdf(const vec3& w) { return eval(w); }

    /// Inversion: cos(theta) = (1 - u.x)^(1/3), phi = 2 pi u.y (the supplement's
    /// acos(rand^(1/3)) with u -> 1 - u).
    LTC_HOST_DEVICE static vec3 sample(const vec2& u) {
        const T cos_theta = std::cbrt(T(1) - u.x);
        const T sin_theta = detail::safe_sqrt((T(1) - cos_theta) * (T(1) + cos_theta));
        return detail::spherical_direction(cos_theta, sin_theta, detail::azimuth(u.y));
    }

    /// Signed integral: 3 / (2 pi) tau^2 = (Omega + sum of second_moment_edge) / (2 pi), over
    /// the horizon-clipped polygon; Omega by a fan from the pole (see clipped_solid_angle).
    template <typename Vertices>
    LTC_HOST_DEVICE static T signed_integral(const Vertices& v, std::size_t n) {
        T sum(0);
        const bool ok = detail::for_each_unit_edge<T, true>(
            v, n, [&](const vec3& a, const vec3& b, const vec3&) {
                sum += detail::pole_triangle_solid_angle(a, b) + detail::second_moment_edge(a, b);
            });
        return ok ? sum / (T(2) * pi<T>()) : T(0);
    }

    /// Integral of D_o over the spherical polygon subtended by v[0..n), one- or two-sided as
    /// apply_sidedness makes the signed integral; two-sided (|signed|) by default, as
    /// transformed::integrate (which states why).
    LTC_HOST_DEVICE LTC_INLINE static T integrate(const vec3* v, std::size_t n, sidedness s = sidedness::two_sided) {
        return apply_sidedness(signed_integral(v, n), s);
    }
};

LTC_NAMESPACE_END
