// ltc/brdf/ggx.hpp -- the isotropic GGX (Trowbridge-Reitz) microfacet BRDF without Fresnel,
// the model that the paper fits (section 4), in the interface of ltc/brdf/model.hpp.
//
//   D(h)      = alpha^2 / (pi (cos^2 theta_h (alpha^2 - 1) + 1)^2)   (Walter et al. 2007, GGX)
//   Lambda(w) = (-1 + sqrt(1 + alpha^2 tan^2 theta)) / 2             (Heitz 2014, "Understanding
//   G1(w)     = 1 / (1 + Lambda(w))                                   the masking-shadowing
//   G2(V, L)  = 1 / (1 + Lambda(V) + Lambda(L))  (height-correlated)  function", JCGT 3(2))
//   eval      = D(h) G2 / (4 V.z)           = rho(V, L) cos theta_L,   h = (V + L) / |V + L|
//   sample    = L reflected about a visible normal (Heitz 2018, "Sampling the GGX Distribution
//               of Visible Normals", JCGT 7(4))
//   pdf       = D_V(h) / (4 |V.h|),  D_V(h) = G1(V) max(0, V.h) D(h) / V.z   (Heitz 2018 eq. 1)
//
// Degenerate input: never NaN or Inf for finite arguments (the forms evaluated: ggx); alpha is
// clamped to [alpha_min, alpha_max] = [1e-4, 1e3] (NaN -> alpha_min, roughness 0.01: below any a
// table resolves); V.z <= 0 or L.z <= 0: eval = 0; V.z <= 0: pdf = 0; L = -V: 0 (clamp_alpha).
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

/// GGX in the interface of ltc/brdf/model.hpp. Every formula is evaluated in a form without tan,
/// 1 - z^2 or a division that can vanish (w a unit vector, z = w.z, s^2 = w.x^2 + w.y^2, which is
/// accurate even at the pole):
///   D       = alpha^2 / (pi (s_h^2 + alpha^2 z_h^2)^2)
///   t(w)    = sqrt(z^2 + alpha^2 s^2)          (= z sqrt(1 + alpha^2 tan^2 theta))
///   Lambda  = alpha^2 s^2 / (2 z (z + t))      (no cancellation in -1 + sqrt(1 + x) at x -> 0)
///   G1      = 2 z / (z + t)
///   G2      = 2 z_V z_L / (z_L t_V + z_V t_L)
///   eval    = D z_L / (2 (z_L t_V + z_V t_L))
///   pdf     = D / (2 (z_V + t_V))              (V.h = |V + L| / 2 >= 0 for h the half vector)
template <typename T>
struct ggx {
    using scalar = T;
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;

    static constexpr const char* name = "ggx";
    static constexpr T alpha_min = T(1e-4);  // see the file comment
    static constexpr T alpha_max = T(1e3);

    /// alpha clamped to [alpha_min, alpha_max]; NaN gives alpha_min. Degenerate input (never NaN
    /// or Inf for finite arguments):
    ///   - alpha -> 0 is a mirror (a Dirac, not a density). The library uses alpha = roughness^2
    ///     with roughness in [0, 1], so alpha_min = 1e-4 is roughness 0.01, below any roughness a
    ///     fit table resolves; there the peak D(n) = 1 / (pi alpha^2) ~ 3.2e7 and alpha^4 = 1e-16
    ///     are still comfortably inside float's range. alpha_max = 1e3 keeps alpha^4 = 1e12
    ///     finite in float.
    ///   - V.z <= 0 or L.z <= 0: eval = 0; V.z <= 0: pdf = 0; L = -V (no half vector): 0.
    ///   - ndf(h) = 0 for h.z <= 0; g1(w) = 0 for w.z <= 0; lambda(w) is the largest finite T for
    ///     w.z <= 0 (its limit at the horizon is +infinity).
    LTC_HOST_DEVICE static T clamp_alpha(T alpha) {
        return alpha > alpha_min ? (alpha < alpha_max ? alpha : alpha_max) : alpha_min;
    }

    /// GGX normal distribution D(h) for a unit microfacet normal h; 0 below the horizon.
    LTC_HOST_DEVICE static T ndf(const vec3& h, T alpha) {
        if (!(h.z > T(0))) return T(0);
        const T a2 = clamp_alpha(alpha) * clamp_alpha(alpha);
        const T d = h.x * h.x + h.y * h.y + a2 * h.z * h.z;  // cos^2 (a^2 - 1) + 1, >= a^2 / 2
        return a2 / (pi<T>() * d * d);
    }

    /// Smith Lambda(w) for a unit direction w (w.z > 0), without tan (the struct's comment).
    LTC_HOST_DEVICE static T lambda(const vec3& w, T alpha) {
        constexpr T big = largest();
        if (!(w.z > T(0))) return big;
        const T a2s2 = clamp_alpha(alpha) * clamp_alpha(alpha) * (w.x * w.x + w.y * w.y);
        const T den = T(2) * w.z * (w.z + t_of(w, alpha));
        const T r = den > T(0) ? a2s2 / den : big;
        return r < big ? r : big;
    }

    /// Smith masking G1(w) = 1 / (1 + Lambda(w)) = 2 z / (z + t); 0 for w.z <= 0.
    LTC_HOST_DEVICE static T g1(const vec3& w, T alpha) {
        if (!(w.z > T(0))) return T(0);
        return T(2) * w.z / (w.z + t_of(w, alpha));
    }

    /// Height-correlated masking-shadowing G2 = 1 / (1 + Lambda(V) + Lambda(L))
    /// = 2 z_V z_L / (z_L t_V + z_V t_L); 0 unless V.z > 0 and L.z > 0.
    LTC_HOST_DEVICE static T g2(const vec3& V, const vec3& L, T alpha) {
        if (!(V.z > T(0)) || !(L.z > T(0))) return T(0);
        const T den = L.z * t_of(V, alpha) + V.z * t_of(L, alpha);
        return den > T(0) ? T(2) * V.z * L.z / den : T(0);
    }

    /// rho(V, L) cos theta_L = D(h) G2(V, L) / (4 V.z); 0 unless V.z > 0 and L.z > 0.
    LTC_HOST_DEVICE static T eval(const vec3& V, const vec3& L, T alpha) {
        if (!(V.z > T(0)) || !(L.z > T(0))) return T(0);
        const vec3 h = detail::safe_normalize(V + L);  // h.z > 0 here
        const T den = T(2) * (L.z * t_of(V, alpha) + V.z * t_of(L, alpha));
        return den > T(0) ? ndf(h, alpha) * L.z / den : T(0);
    }

    /// Density of sample() per steradian of L: D_V(h) / (4 V.h) = G1(V) D(h) / (4 V.z)
    /// = D(h) / (2 (z_V + t_V)), h the half vector of V and L (over the whole sphere of L).
    LTC_HOST_DEVICE static T pdf(const vec3& V, const vec3& L, T alpha) {
        if (!(V.z > T(0))) return T(0);
        // V.h = |V + L| / 2 >= 0 for unit V, L, so only L = -V (no half vector) is excluded; a
        // test on dot(V, h) would cancel catastrophically next to L = -V.
        const vec3 h = detail::safe_normalize(V + L);  // zero vector for L = -V: ndf = 0
        return ndf(h, alpha) / (T(2) * (V.z + t_of(V, alpha)));
    }

    /// A visible normal for the view V (Heitz 2018, listing 1): sampled in the hemisphere
    /// configuration, u in [0, 1)^2. Its density is D_V(h).
    LTC_HOST_DEVICE static vec3 sample_visible_normal(const vec3& V, const vec2& u, T alpha) {
        const T a = clamp_alpha(alpha);
        // Section 3.2: the view direction in the hemisphere configuration (stretch by alpha).
        vec3 Vh = detail::safe_normalize(vec3(a * V.x, a * V.y, V.z));
        if (!(Vh.z >= T(0))) Vh = vec3(Vh.x, Vh.y, T(0));  // V below the horizon: no density
        // Section 4.1: an orthonormal basis around Vh (T1 = (1, 0, 0) at normal incidence).
        vec3 T1 = detail::safe_normalize(vec3(-Vh.y, Vh.x, T(0)));
        if (!(T1.x != T(0) || T1.y != T(0))) T1 = vec3(T(1), T(0), T(0));
        const vec3 T2 = glm::cross(Vh, T1);
        // Section 4.2: a point of the unit disk, warped onto the projected visible hemisphere.
        const T r = std::sqrt(u.x);
        const T phi = detail::azimuth(u.y);
        const T t1 = r * std::cos(phi);
        const T s = T(0.5) * (T(1) + Vh.z);
        const T t2 = (T(1) - s) * detail::safe_sqrt(T(1) - t1 * t1) + s * (r * std::sin(phi));
        // Section 4.3: reprojection onto the hemisphere.
        const vec3 Nh = t1 * T1 + t2 * T2 + detail::safe_sqrt(T(1) - t1 * t1 - t2 * t2) * Vh;
        // Section 3.4: back to the ellipsoid configuration (unstretch).
        const vec3 Ne = detail::safe_normalize(vec3(a * Nh.x, a * Nh.y, glm::max(T(0), Nh.z)));
        return (Ne.x != T(0) || Ne.y != T(0) || Ne.z != T(0)) ? Ne : vec3(T(0), T(0), T(1));
    }

    /// L = the reflection of V about a visible normal; may lie below the horizon (eval = 0).
    LTC_HOST_DEVICE static vec3 sample(const vec3& V, const vec2& u, T alpha) {
        const vec3 h = sample_visible_normal(V, u, alpha);
        return detail::safe_normalize(T(2) * glm::dot(V, h) * h - V);
    }

  private:
    /// Largest finite T, usable in CUDA device code (std::numeric_limits members are host-only
    /// constexpr functions there).
    LTC_HOST_DEVICE static constexpr T largest() {
        if constexpr (std::is_same_v<T, float>) return FLT_MAX;
        else if constexpr (std::is_same_v<T, double>) return DBL_MAX;
        else return std::numeric_limits<T>::max();
    }

    /// t(w) = sqrt(z^2 + alpha^2 s^2) = z sqrt(1 + alpha^2 tan^2 theta), for any z.
    LTC_HOST_DEVICE static T t_of(const vec3& w, T alpha) {
        const T a = clamp_alpha(alpha);
        return std::sqrt(w.z * w.z + a * a * (w.x * w.x + w.y * w.y));
    }
};

}  // namespace brdf
LTC_NAMESPACE_END
