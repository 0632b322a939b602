// ltc/brdf/charlie.hpp -- the "Charlie" sheen BRDF of glTF's KHR_materials_sheen (Estevez and Kulla
// 2017, "Production Friendly Microfacet Sheen BRDF"), without the sheen colour, in the interface of
// ltc/brdf/model.hpp; alpha = sheenRoughness^2 (the spec's alpha_g).
//
//   D(h)      = (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi)   (Estevez and Kulla 2017; the spec's
//                                                                "Sheen distribution")
//   l(x)      = a / (1 + b x^c) + d x + e, each of a..e interpolated between its two fitted values
//               by (1 - alpha)^2                                 (KHR_materials_sheen, "Sheen
//   Lambda(w) = exp(l(cos)) for cos < 1/2, else exp(2 l(1/2) - l(1 - cos))   visibility")
//   eval      = D(h) / (4 V.z (1 + Lambda(V) + Lambda(L)))  = rho(V, L) cos theta_L
//   sample    = uniform over the upper hemisphere, pdf = 1 / (2 pi)  (see charlie::sample)
//
// Degenerate input: never NaN or Inf for finite arguments (the forms evaluated: charlie); alpha is
// clamped to [alpha_min, alpha_max] = [1e-4, 1] (NaN -> alpha_min); V.z <= 0 or L.z <= 0: eval = 0;
// V.z <= 0 or L.z <= 0: pdf = 0; L = -V: 0.
#pragma once

#include <ltc/brdf/model.hpp>
#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <cmath>

LTC_NAMESPACE_BEGIN
namespace brdf {

/// Charlie sheen in the interface of ltc/brdf/model.hpp, as KHR_materials_sheen's implementation
/// notes define it ("Sheen distribution" and "Sheen visibility": the Charlie visibility with the
/// fitted l(x), not the Ashikhmin alternative), with the sheen colour and any Fresnel term left
/// out (the spec's F = 1). Forms evaluated (w a unit vector, z = w.z, s^2 = w.x^2 + w.y^2, which
/// is sin^2 theta accurately even at the pole):
///   D       = (2 + 1/alpha) (s_h^2)^(1 / (2 alpha)) / (2 pi)     with s_h^2 clamped to [0, 1]
///   G2      = 1 / (1 + Lambda(V) + Lambda(L))                    (what the spec's visibility
///   eval    = D G2 / (4 z_V)                                      times 4 V.z L.z is)
/// Reciprocal: eval / L.z is symmetric in V and L. D is normalized: the integral of D cos theta_h
/// over the hemisphere of h is 1 (tests/test_charlie.cpp).
template <typename T>
struct charlie {
    using scalar = T;
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;

    static constexpr const char* name = "charlie";
    static constexpr T alpha_min = T(1e-4);  // see the file comment
    static constexpr T alpha_max = T(1);

    /// alpha clamped to [alpha_min, alpha_max]; NaN gives alpha_min. Degenerate input (never NaN
    /// or Inf for finite arguments):
    ///   - alpha -> 0: 1/alpha -> infinity and D -> a ring of microfibres at the horizon (no
    ///     density). alpha_min = 1e-4 (sheenRoughness 0.01) keeps 1/alpha = 1e4 and the peak of D,
    ///     (2 + 1e4) / (2 pi), finite; (s^2)^(1 / (2 alpha)) with s^2 in [0, 1] is in [0, 1] for any
    ///     such exponent (0^p = 0), so it never gives NaN. alpha_max = 1 is the end of the
    ///     interpolation of l(x) (the spec's sheenRoughness is in [0, 1]).
    ///   - V.z <= 0 or L.z <= 0: eval = 0. Lambda is at most exp(l(0)) (finite: the fitted l(x)
    ///     is a + e at x = 0), so eval grows like 1 / V.z as V.z -> 0; V.z below the smallest
    ///     normal T is read as that value, which keeps eval finite.
    ///   - V.z <= 0 or L.z <= 0: pdf = 0; L = -V (no half vector): eval = 0.
    LTC_HOST_DEVICE static T clamp_alpha(T alpha) {
        return alpha > alpha_min ? (alpha < alpha_max ? alpha : alpha_max) : alpha_min;
    }

    /// The Charlie distribution D(h) for a unit microfacet normal h; 0 below the horizon.
    LTC_HOST_DEVICE static T ndf(const vec3& h, T alpha) {
        if (!(h.z >= T(0))) return T(0);
        const T a = clamp_alpha(alpha);
        const T inv = T(1) / a;
        T s2 = h.x * h.x + h.y * h.y;
        s2 = s2 < T(1) ? s2 : T(1);
        return (T(2) + inv) * std::pow(s2, T(0.5) * inv) / (T(2) * pi<T>());
    }

    /// The spec's fitted l(x, alpha) for x in [0, 1] (clamped): a / (1 + b x^c) + d x + e, each
    /// coefficient mix(value at alpha = 1, value at alpha = 0, (1 - alpha)^2).
    LTC_HOST_DEVICE static T l(T x, T alpha) {
        const T t = (T(1) - clamp_alpha(alpha)) * (T(1) - clamp_alpha(alpha));
        const auto mix = [t](T at_one, T at_zero) { return at_one * (T(1) - t) + at_zero * t; };
        const T a = mix(T(21.5473), T(25.3245));
        const T b = mix(T(3.82987), T(3.32435));
        const T c = mix(T(0.19823), T(0.16801));
        const T d = mix(T(-1.97760), T(-1.27393));
        const T e = mix(T(-4.32054), T(-4.85967));
        const T xc = x > T(0) ? (x < T(1) ? x : T(1)) : T(0);
        return a / (T(1) + b * std::pow(xc, c)) + d * xc + e;
    }

    /// The spec's lambda_sheen(cos theta_w) for a unit direction w (|w.z| used, as the spec's
    /// abs): exp(l(cos)) below cos = 1/2, exp(2 l(1/2) - l(1 - cos)) above. Finite for any w.
    LTC_HOST_DEVICE static T lambda(const vec3& w, T alpha) {
        T c = w.z < T(0) ? -w.z : w.z;
        c = c < T(1) ? c : T(1);
        if (!(c == c)) c = T(0);
        return c < T(0.5) ? std::exp(l(c, alpha)) : std::exp(T(2) * l(T(0.5), alpha) - l(T(1) - c, alpha));
    }

    /// 1 / (1 + Lambda(V) + Lambda(L)): the masking-shadowing that the spec's visibility holds;
    /// 0 unless V.z > 0 and L.z > 0.
    LTC_HOST_DEVICE static T g2(const vec3& V, const vec3& L, T alpha) {
        if (!(V.z > T(0)) || !(L.z > T(0))) return T(0);
        return T(1) / (T(1) + lambda(V, alpha) + lambda(L, alpha));
    }

    /// rho(V, L) cos theta_L = D(h) G2 / (4 V.z); 0 unless V.z > 0 and L.z > 0.
    LTC_HOST_DEVICE static T eval(const vec3& V, const vec3& L, T alpha) {
        if (!(V.z > T(0)) || !(L.z > T(0))) return T(0);
        const vec3 h = detail::safe_normalize(V + L);  // h.z > 0 here
        const T zv = V.z > detail::min_normal<T>() ? V.z : detail::min_normal<T>();
        return ndf(h, alpha) * g2(V, L, alpha) / (T(4) * zv);
    }

    /// Density of sample() per steradian of L: 1 / (2 pi) over the upper hemisphere; 0 for
    /// L.z <= 0 and for V.z <= 0 (no lobe).
    LTC_HOST_DEVICE static T pdf(const vec3& V, const vec3& L, T /*alpha*/) {
        if (!(V.z > T(0)) || !(L.z > T(0))) return T(0);
        return T(1) / (T(2) * pi<T>());
    }

    /// L uniform over the upper hemisphere, u in [0, 1)^2: cos theta_L = 1 - u.x, phi = 2 pi u.y.
    /// Why not a lobe-shaped sampler: sampling h from D cos theta_h and reflecting V gives a
    /// density D cos theta_h / (4 V.h) that vanishes against f where D has its mass (horizontal
    /// h, cos theta_h -> 0), so the weights f / pdf are unbounded; f itself is bounded for
    /// V.z > 0 and, at low roughness, lies at grazing L, where a cosine-weighted sampler puts few
    /// samples (the fit's moments, a midpoint rule through this sampler, converge faster with the
    /// uniform one there). The density is exact: eval / pdf is unbiased.
    LTC_HOST_DEVICE static vec3 sample(const vec3& /*V*/, const vec2& u, T /*alpha*/) {
        const T cos_theta = T(1) - u.x;
        const T sin_theta = detail::safe_sqrt(u.x * (T(2) - u.x));  // = sqrt(1 - cos^2)
        return detail::spherical_direction(cos_theta, sin_theta, detail::azimuth(u.y));
    }
};

}  // namespace brdf
LTC_NAMESPACE_END
