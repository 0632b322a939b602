// ltc/brdf/beckmann.hpp -- the isotropic Beckmann microfacet BRDF without Fresnel, in the
// interface of ltc/brdf/model.hpp (the paper fits it next to GGX, section 4).
//
//   D(h)      = exp(-tan^2 theta_h / alpha^2) / (pi alpha^2 cos^4 theta_h)  (Walter et al. 2007)
//   Lambda(w) = (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)),  a = 1 / (alpha tan theta)
//   G1(w)     = 1 / (1 + Lambda(w))                             (Heitz 2014, JCGT 3(2))
//   G2(V, L)  = 1 / (1 + Lambda(V) + Lambda(L))  (height-correlated)
//   eval      = D(h) G2 / (4 V.z)  = rho(V, L) cos theta_L,   h = (V + L) / |V + L|
//   sample    = L reflected about a normal drawn from D(h) cos theta_h:
//               tan^2 theta_h = -alpha^2 log(1 - u.x), phi_h = 2 pi u.y (Walter et al. 2007)
//   pdf       = D(h) cos theta_h / (4 |V.h|)
//
// Degenerate input (never NaN or Inf for finite arguments): alpha clamped to
// [alpha_min, alpha_max] as for ltc::brdf::ggx (NaN -> alpha_min; alpha -> 0 is a Dirac);
// V.z <= 0 or L.z <= 0: eval = 0; V.z <= 0: pdf = 0; L = -V: 0 (numerics: beckmann).
#pragma once

#include <ltc/brdf/model.hpp>
#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <cfloat>
#include <cmath>
#include <limits>
#include <type_traits>

LTC_NAMESPACE_BEGIN
namespace brdf {

/// Beckmann in the interface of ltc/brdf/model.hpp.
///
/// Numerics (w a unit vector, z = w.z, s = sqrt(w.x^2 + w.y^2), accurate at the pole):
///   - D = exp(-s^2 / (alpha^2 z^2)) / (pi alpha^2 z^4), 0 as soon as the exponential
///     underflows (so that 1 / z^4 is then never formed);
///   - Lambda with a = z / (alpha s) and erf(a) - 1 = -erfc(a) (no cancellation in 1 - erf);
///     s = 0 (normal incidence, a = inf) gives Lambda = 0; the result is clamped to [0, max];
///   - sampling uses log1p(-u.x) (accurate for small u.x) and u.x < 1.
///
/// Sampling D(h) cos theta_h (not the visible normals) draws normals with V.h < 0 too: their
/// reflection L = 2 (V.h) h - V lies below the horizon (L.z = 2 (V.h) h.z - V.z < 0), and the half
/// vector of V and L is then -h. pdf() therefore uses h = +-(V + L) / |V + L|, whichever has
/// h.z > 0: the map h -> L is one-to-one from the upper hemisphere, and pdf integrates to 1 over
/// the whole sphere. It has an integrable 1 / |V + L| singularity at L = -V (V.h -> 0), where the
/// result is clamped to the largest finite T.
template <typename T>
struct beckmann {
    using scalar = T;
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;

    static constexpr const char* name = "beckmann";
    /// Same range and rationale as ggx: alpha = roughness^2, roughness in [0, 1]; 1e-4 is
    /// roughness 0.01, where the peak 1 / (pi alpha^2) ~ 3.2e7 is still far inside float's range.
    static constexpr T alpha_min = T(1e-4);
    static constexpr T alpha_max = T(1e3);

    LTC_HOST_DEVICE static T clamp_alpha(T alpha) {
        return alpha > alpha_min ? (alpha < alpha_max ? alpha : alpha_max) : alpha_min;
    }

    /// Beckmann normal distribution D(h) for a unit microfacet normal h; 0 below the horizon.
    LTC_HOST_DEVICE static T ndf(const vec3& h, T alpha) {
        if (!(h.z > T(0))) return T(0);
        const T a2 = clamp_alpha(alpha) * clamp_alpha(alpha);
        const T z2 = h.z * h.z;
        if (!(a2 * z2 > T(0))) return T(0);  // z2 underflows: tan -> inf, D -> 0
        const T e = std::exp(-(h.x * h.x + h.y * h.y) / (a2 * z2));  // exp(-tan^2 / alpha^2)
        if (!(e > T(0))) return T(0);  // underflow (or z2 -> 0): the limit is 0
        return e / (pi<T>() * a2 * z2 * z2);
    }

    /// Smith Lambda(w) for a unit direction w (w.z > 0); the largest finite T for w.z <= 0.
    LTC_HOST_DEVICE static T lambda(const vec3& w, T alpha) {
        constexpr T big = largest();
        if (!(w.z > T(0))) return big;
        const T s = std::sqrt(w.x * w.x + w.y * w.y);
        if (!(s > T(0))) return T(0);  // normal incidence: a = inf
        const T a = w.z / (clamp_alpha(alpha) * s);  // 1 / (alpha tan theta)
        if (!(a > T(0))) return big;                  // underflow: grazing, Lambda -> inf
        // (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)); a = inf gives 0 - 0.
        const T inv_sqrt_pi = T(0.564189583547756286948079451560772586L);
        const T r = T(0.5) * (std::exp(-a * a) * inv_sqrt_pi / a - std::erfc(a));
        return r > T(0) ? (r < big ? r : big) : T(0);
    }

    /// Smith masking G1(w) = 1 / (1 + Lambda(w)); 0 for w.z <= 0.
    LTC_HOST_DEVICE static T g1(const vec3& w, T alpha) {
        if (!(w.z > T(0))) return T(0);
        return T(1) / (T(1) + lambda(w, alpha));
    }

    /// Height-correlated masking-shadowing G2 = 1 / (1 + Lambda(V) + Lambda(L)); 0 unless
    /// V.z > 0 and L.z > 0.
    LTC_HOST_DEVICE static T g2(const vec3& V, const vec3& L, T alpha) {
        if (!(V.z > T(0)) || !(L.z > T(0))) return T(0);
        return T(1) / (T(1) + lambda(V, alpha) + lambda(L, alpha));  // 1 / inf = 0 is fine
    }

    /// rho(V, L) cos theta_L = D(h) G2(V, L) / (4 V.z); 0 unless V.z > 0 and L.z > 0.
    /// (G2 <= 1 / (1 + Lambda(V)) ~ 2 sqrt(pi) V.z / (alpha s_V) as V.z -> 0: bounded ratio.)
    LTC_HOST_DEVICE static T eval(const vec3& V, const vec3& L, T alpha) {
        if (!(V.z > T(0)) || !(L.z > T(0))) return T(0);
        const vec3 h = detail::safe_normalize(V + L);
        return ndf(h, alpha) * g2(V, L, alpha) / (T(4) * V.z);
    }

    /// Density of sample() per steradian of L: D(h) cos theta_h / (4 |V.h|), h the half vector
    /// of V and L turned into the upper hemisphere (the struct's comment), over the whole sphere of L.
    /// V and L unit.
    LTC_HOST_DEVICE static T pdf(const vec3& V, const vec3& L, T alpha) {
        constexpr T big = largest();
        if (!(V.z > T(0))) return T(0);
        const vec3 s = V + L;
        // V.h = (1 + V.L) / |V + L| = |V + L| / 2 for unit V, L: taken from the length, because
        // dot(V, h) cancels catastrophically next to L = -V (where samples with V.h ~ 0 land).
        const T vh = T(0.5) * glm::length(s);
        if (!(vh > T(0))) return T(0);  // L = -V
        vec3 h = detail::safe_normalize(s);
        if (h.z < T(0)) h = -h;
        const T r = ndf(h, alpha) * h.z / (T(4) * vh);
        return r < big ? r : big;
    }

    /// A microfacet normal drawn from D(h) cos theta_h, u in [0, 1)^2 (u.x = 1 is treated as the
    /// largest T below 1).
    LTC_HOST_DEVICE static vec3 sample_normal(const vec2& u, T alpha) {
        const T a = clamp_alpha(alpha);
        const T below_one = T(1) - eps() / T(2);
        const T ux = u.x < below_one ? (u.x > T(0) ? u.x : T(0)) : below_one;
        const T tan2 = -a * a * std::log1p(-ux);  // tan^2 theta_h >= 0, finite
        const T cos_theta = T(1) / std::sqrt(T(1) + tan2);
        const T sin_theta = std::sqrt(tan2) * cos_theta;
        return detail::spherical_direction(cos_theta, sin_theta, detail::azimuth(u.y));
    }

    /// L = the reflection of V about a normal from sample_normal(); may lie below the horizon.
    LTC_HOST_DEVICE static vec3 sample(const vec3& V, const vec2& u, T alpha) {
        const vec3 h = sample_normal(u, alpha);
        return detail::safe_normalize(T(2) * glm::dot(V, h) * h - V);
    }

  private:
    /// Largest finite T and machine epsilon, usable in CUDA device code (std::numeric_limits
    /// members are host-only constexpr functions there).
    LTC_HOST_DEVICE static constexpr T largest() {
        if constexpr (std::is_same_v<T, float>) return FLT_MAX;
        else if constexpr (std::is_same_v<T, double>) return DBL_MAX;
        else return std::numeric_limits<T>::max();
    }
    LTC_HOST_DEVICE static constexpr T eps() {
        if constexpr (std::is_same_v<T, float>) return FLT_EPSILON;
        else if constexpr (std::is_same_v<T, double>) return DBL_EPSILON;
        else return std::numeric_limits<T>::epsilon();
    }
};

}  // namespace brdf
LTC_NAMESPACE_END
