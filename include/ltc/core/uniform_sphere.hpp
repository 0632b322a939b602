// ltc/core/uniform_sphere.hpp -- the uniform spherical distribution, D_o = 1 / (4 pi).
// Supplement section 1.1.
#pragma once

#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/core/solid_angle.hpp>

#include <glm/glm.hpp>

#include <cstddef>

LTC_NAMESPACE_BEGIN

template <typename T>
struct uniform_sphere {
    using scalar = T;
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;

    /// Density at the unit direction w.
    LTC_HOST_DEVICE static T eval(const vec3&) { return T(1) / (T(4) * pi<T>()); }
    LTC_HOST_DEVICE static T pdf(const vec3& w) { return eval(w); }

    /// Inversion: cos(theta) = 1 - 2 u.x (the supplement's acos(2 rand - 1)), phi = 2 pi u.y.
    LTC_HOST_DEVICE static vec3 sample(const vec2& u) {
        const T cos_theta = T(1) - T(2) * u.x;
        const T sin_theta = T(2) * detail::safe_sqrt(u.x * (T(1) - u.x));  // = sqrt(1 - cos^2)
        return detail::spherical_direction(cos_theta, sin_theta, detail::azimuth(u.y));
    }

    /// Signed integral over the polygon: its solid angle / (4 pi) (see polygon.hpp).
    template <typename Vertices>
    LTC_HOST_DEVICE static T signed_integral(const Vertices& v, std::size_t n) {
        return detail::solid_angle<T>(v, n) / (T(4) * pi<T>());
    }

    /// Integral of D_o over the spherical polygon subtended by v[0..n), one- or two-sided as
    /// apply_sidedness makes the signed integral; two-sided (|signed|) by default, as
    /// transformed::integrate (which states why).
    LTC_HOST_DEVICE LTC_INLINE static T integrate(const vec3* v, std::size_t n, sidedness s = sidedness::two_sided) {
        return apply_sidedness(signed_integral(v, n), s);
    }
};

LTC_NAMESPACE_END
