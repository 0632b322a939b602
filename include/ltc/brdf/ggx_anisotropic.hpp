// ltc/brdf/ggx_anisotropic.hpp -- anisotropic GGX (Trowbridge-Reitz) without Fresnel, in the
// interface of ltc/brdf/model.hpp with alpha = {alpha_x, alpha_y} (tangent +x, bitangent +y).
//
//   D(h)      = 1 / (pi ax ay (x_h^2 / ax^2 + y_h^2 / ay^2 + z_h^2)^2)   (Heitz 2014,
//   Lambda(w) = (-1 + sqrt(1 + (ax^2 x^2 + ay^2 y^2) / z^2)) / 2          "Understanding the
//   G2(V, L)  = 1 / (1 + Lambda(V) + Lambda(L))  (height-correlated)      masking-shadowing
//   eval      = D(h) G2 / (4 V.z) = rho(V, L) cos theta_L                 function", JCGT 3(2))
//   sample    = L reflected about a visible normal: stretch V by (ax, ay, 1), sample the
//               hemisphere, unstretch (Heitz 2018, "Sampling the GGX Distribution of Visible
//               Normals", JCGT 7(4)); pdf = D_V(h) / (4 |V.h|), D_V = G1(V) max(0, V.h) D / V.z
//
// Degenerate input: never NaN or Inf for finite arguments; ax and ay are each clamped by
// ggx<T>::clamp_alpha (NaN -> alpha_min); V.z <= 0 or L.z <= 0: eval = 0; V.z <= 0: pdf = 0;
// L = -V: 0. For ax == ay every result is ggx<T>'s, bit for bit (ggx_anisotropic).
#pragma once

#include <ltc/brdf/ggx.hpp>
#include <ltc/brdf/model.hpp>
#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <cmath>

LTC_NAMESPACE_BEGIN
namespace brdf {

/// The roughness of an anisotropic microfacet model: x = alpha_x along the tangent (+x of the
/// local frame), y = alpha_y along the bitangent (+y). A struct, not a vec2, so that it cannot
/// be swapped with sample()'s random numbers u.
template <typename T>
struct anisotropic_alpha {
    T x;
    T y;
};

/// Anisotropic GGX in the interface of ltc/brdf/model.hpp, alpha an anisotropic_alpha<T>. The
/// forms of ggx<T> (no tan, no 1 - z^2, no division that can vanish), with w a unit vector and
/// the per-call coefficients m = ax ay, p = ax / ay, q = ay / ax (ax, ay clamped):
///   D       = m / (pi d^2),   d = q x_h^2 + p y_h^2 + m z_h^2     (= ax ay (x^2/ax^2 + ...))
///   t(w)    = sqrt(z^2 + m (p x^2 + q y^2))   (= sqrt(z^2 + ax^2 x^2 + ay^2 y^2))
///   Lambda  = m (p x^2 + q y^2) / (2 z (z + t))
///   G1      = 2 z / (z + t),   G2 = 2 z_V z_L / (z_L t_V + z_V t_L)
///   eval    = D z_L / (2 (z_L t_V + z_V t_L)),   pdf = D / (2 (z_V + t_V))
/// Bit for bit ggx<T> at ax == ay: then p = q = 1 exactly, a product by 1 is exact, m = a * a, and
/// each expression has the operations of ggx<T>'s in the same order (d = x^2 + y^2 + a^2 z^2,
/// t = sqrt(z^2 + a^2 (x^2 + y^2)); the sampler's stretch (ax V.x, ay V.y, V.z) is a V.x, a V.y).
/// This holds wherever the compiler does not contract a * b + c into an FMA differently in the two
/// (ltc::ltc's -ffp-contract=off); no branch on ax == ay is needed. The ratios cost a few roundings
/// of relative accuracy in ax^2 and ay^2 (m p, m q), no range: ax, ay in [1e-4, 1e3] keep
/// p, q <= 1e7, d >= 1e-7 and D <= 1e13 / pi, finite in float.
template <typename T>
struct ggx_anisotropic {
    using scalar = T;
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;
    using alpha_type = anisotropic_alpha<T>;

    static constexpr const char* name = "ggx_anisotropic";
    static constexpr T alpha_min = ggx<T>::alpha_min;  // each of alpha_x, alpha_y: see ggx<T>
    static constexpr T alpha_max = ggx<T>::alpha_max;

    /// Each of alpha_x, alpha_y clamped by ggx<T>::clamp_alpha (NaN gives alpha_min).
    LTC_HOST_DEVICE static alpha_type clamp_alpha(const alpha_type& alpha) {
        return alpha_type{ggx<T>::clamp_alpha(alpha.x), ggx<T>::clamp_alpha(alpha.y)};
    }

    /// Anisotropic GGX normal distribution D(h) for a unit microfacet normal h; 0 below the horizon.
    LTC_HOST_DEVICE static T ndf(const vec3& h, const alpha_type& alpha) {
        if (!(h.z > T(0))) return T(0);
        const coefficients c = coefficients_of(alpha);
        const T d = c.q * h.x * h.x + c.p * h.y * h.y + c.m * h.z * h.z;  // >= min(p, q, m) for unit h
        return c.m / (pi<T>() * d * d);
    }

    /// Smith Lambda(w) for a unit direction w (w.z > 0); the largest finite T for w.z <= 0 (its
    /// limit at the horizon is +infinity).
    LTC_HOST_DEVICE static T lambda(const vec3& w, const alpha_type& alpha) {
        constexpr T big = detail::largest_finite<T>();
        if (!(w.z > T(0))) return big;
        const coefficients c = coefficients_of(alpha);
        const T a2s2 = c.m * (c.p * w.x * w.x + c.q * w.y * w.y);  // ax^2 x^2 + ay^2 y^2
        const T den = T(2) * w.z * (w.z + t_of(w, c));
        const T r = den > T(0) ? a2s2 / den : big;
        return r < big ? r : big;
    }

    /// Smith masking G1(w) = 1 / (1 + Lambda(w)) = 2 z / (z + t); 0 for w.z <= 0.
    LTC_HOST_DEVICE static T g1(const vec3& w, const alpha_type& alpha) {
        if (!(w.z > T(0))) return T(0);
        return T(2) * w.z / (w.z + t_of(w, coefficients_of(alpha)));
    }

    /// Height-correlated masking-shadowing G2 = 1 / (1 + Lambda(V) + Lambda(L))
    /// = 2 z_V z_L / (z_L t_V + z_V t_L); 0 unless V.z > 0 and L.z > 0.
    LTC_HOST_DEVICE static T g2(const vec3& V, const vec3& L, const alpha_type& alpha) {
        if (!(V.z > T(0)) || !(L.z > T(0))) return T(0);
        const coefficients c = coefficients_of(alpha);
        const T den = L.z * t_of(V, c) + V.z * t_of(L, c);
        return den > T(0) ? T(2) * V.z * L.z / den : T(0);
    }

    /// rho(V, L) cos theta_L = D(h) G2(V, L) / (4 V.z); 0 unless V.z > 0 and L.z > 0.
    LTC_HOST_DEVICE static T eval(const vec3& V, const vec3& L, const alpha_type& alpha) {
        if (!(V.z > T(0)) || !(L.z > T(0))) return T(0);
        const coefficients c = coefficients_of(alpha);
        const vec3 h = detail::safe_normalize(V + L);  // h.z > 0 here
        const T den = T(2) * (L.z * t_of(V, c) + V.z * t_of(L, c));
        return den > T(0) ? ndf(h, alpha) * L.z / den : T(0);
    }

    /// Density of sample() per steradian of L: D_V(h) / (4 V.h) = G1(V) D(h) / (4 V.z)
    /// = D(h) / (2 (z_V + t_V)), h the half vector of V and L (over the whole sphere of L).
    LTC_HOST_DEVICE static T pdf(const vec3& V, const vec3& L, const alpha_type& alpha) {
        if (!(V.z > T(0))) return T(0);
        // V.h = |V + L| / 2 >= 0 for unit V, L: only L = -V (no half vector) is excluded, as in
        // ggx<T>::pdf.
        const vec3 h = detail::safe_normalize(V + L);  // zero vector for L = -V: ndf = 0
        return ndf(h, alpha) / (T(2) * (V.z + t_of(V, coefficients_of(alpha))));
    }

    /// A visible normal for the view V (Heitz 2018, listing 1, with ax != ay): sampled in the
    /// hemisphere configuration, u in [0, 1)^2. Its density is D_V(h).
    LTC_HOST_DEVICE static vec3 sample_visible_normal(const vec3& V, const vec2& u, const alpha_type& alpha) {
        const alpha_type a = clamp_alpha(alpha);
        // Section 3.2: the view direction in the hemisphere configuration (stretch by ax, ay).
        vec3 Vh = detail::safe_normalize(vec3(a.x * V.x, a.y * V.y, V.z));
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
        const vec3 Ne = detail::safe_normalize(vec3(a.x * Nh.x, a.y * Nh.y, glm::max(T(0), Nh.z)));
        return (Ne.x != T(0) || Ne.y != T(0) || Ne.z != T(0)) ? Ne : vec3(T(0), T(0), T(1));
    }

    /// L = the reflection of V about a visible normal; may lie below the horizon (eval = 0).
    LTC_HOST_DEVICE static vec3 sample(const vec3& V, const vec2& u, const alpha_type& alpha) {
        const vec3 h = sample_visible_normal(V, u, alpha);
        return detail::safe_normalize(T(2) * glm::dot(V, h) * h - V);
    }

  private:
    /// m = ax ay, p = ax / ay, q = ay / ax of the clamped alpha (the struct's comment).
    struct coefficients {
        T m, p, q;
    };
    LTC_HOST_DEVICE static coefficients coefficients_of(const alpha_type& alpha) {
        const alpha_type a = clamp_alpha(alpha);
        return coefficients{a.x * a.y, a.x / a.y, a.y / a.x};
    }

    /// t(w) = sqrt(z^2 + ax^2 x^2 + ay^2 y^2) = z sqrt(1 + alpha(phi)^2 tan^2 theta), for any z.
    LTC_HOST_DEVICE static T t_of(const vec3& w, const coefficients& c) {
        return std::sqrt(w.z * w.z + c.m * (c.p * w.x * w.x + c.q * w.y * w.y));
    }
};

}  // namespace brdf
LTC_NAMESPACE_END
