// ltc/core/clamped_cosine.hpp -- the clamped cosine distribution, D_o = max(0, z) / pi: the
// "cosine" of Linearly Transformed Cosines. Supplement section 1.3; paper section 3.
#pragma once

#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/core/form_factor.hpp>
#include <ltc/core/sidedness.hpp>

#include <glm/glm.hpp>

#include <cstddef>

LTC_NAMESPACE_BEGIN

/// Policy selects how integrate() evaluates the edge terms (ltc/core/edge_policy.hpp); the
/// default, edge_policy::automatic, is minimax_rational in float and exact in double.
template <typename T, typename Policy = edge_policy::automatic>
struct clamped_cosine {
    using EdgePolicy = edge_policy::resolve_t<Policy, T>;
    using scalar = T;
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;

    LTC_HOST_DEVICE static T eval(const vec3& w) { return w.z > T(0) ? w.z / pi<T>() : T(0); }
    LTC_HOST_DEVICE static T pdf(const vec3& w) { return eval(w); }

    /// Inversion: cos(theta) = sqrt(1 - u.x), phi = 2 pi u.y. The supplement's acos(rand^(1/2))
    /// with u -> 1 - u, so that u.x in [0, 1) never yields a zero-density direction.
    LTC_HOST_DEVICE static vec3 sample(const vec2& u) {
        const T cos_theta = detail::safe_sqrt(T(1) - u.x);
        const T sin_theta = detail::safe_sqrt(u.x);  // = sqrt(1 - cos^2) exactly
        return detail::spherical_direction(cos_theta, sin_theta, detail::azimuth(u.y));
    }

    /// Signed integral: eq. (11) over the horizon-clipped polygon (ltc::form_factor_signed).
    template <typename Vertices>
    LTC_HOST_DEVICE LTC_INLINE static T signed_integral(const Vertices& v, std::size_t n) {
        return detail::form_factor<T, EdgePolicy>(v, n);
    }

    /// Integral of D_o over the spherical polygon subtended by v[0..n), one- or two-sided as
    /// apply_sidedness makes the signed integral; two-sided (|signed|) by default, as
    /// transformed::integrate (which states why).
    LTC_HOST_DEVICE LTC_INLINE static T integrate(const vec3* v, std::size_t n, sidedness s = sidedness::two_sided) {
        return apply_sidedness(signed_integral(v, n), s);
    }
};

LTC_NAMESPACE_END
