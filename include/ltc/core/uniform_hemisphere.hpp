// ltc/core/uniform_hemisphere.hpp -- the uniform hemispherical distribution, D_o = 1 / (2 pi) for
// z >= 0. Supplement section 1.2.
#pragma once

#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/core/solid_angle.hpp>

#include <glm/glm.hpp>

#include <cstddef>

LTC_NAMESPACE_BEGIN

template <typename T>
struct uniform_hemisphere {
    using scalar = T;
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;

    LTC_HOST_DEVICE static T eval(const vec3& w) {
        return w.z >= T(0) ? T(1) / (T(2) * pi<T>()) : T(0);
    }
    LTC_HOST_DEVICE static T pdf(const vec3& w) { return eval(w); }

    /// Inversion: cos(theta) = 1 - u.x (uniform in (0, 1] for u.x in [0, 1)), phi = 2 pi u.y.
    /// (The supplement gives no sampler for this distribution.)
    LTC_HOST_DEVICE static vec3 sample(const vec2& u) {
        const T cos_theta = T(1) - u.x;
        const T sin_theta = detail::safe_sqrt(u.x * (T(2) - u.x));  // = sqrt(1 - cos^2)
        return detail::spherical_direction(cos_theta, sin_theta, detail::azimuth(u.y));
    }

    /// Signed integral: solid angle of the horizon-clipped polygon / (2 pi).
    template <typename Vertices>
    LTC_HOST_DEVICE static T signed_integral(const Vertices& v, std::size_t n) {
        return detail::clipped_solid_angle<T>(v, n) / (T(2) * pi<T>());
    }

    /// Integral of D_o over the spherical polygon subtended by v[0..n), one- or two-sided as
    /// apply_sidedness makes the signed integral; two-sided (|signed|) by default, as
    /// transformed::integrate (which states why).
    LTC_HOST_DEVICE LTC_INLINE static T integrate(const vec3* v, std::size_t n, sidedness s = sidedness::two_sided) {
        return apply_sidedness(signed_integral(v, n), s);
    }
};

LTC_NAMESPACE_END
