// ltc/brdf/schlick.hpp -- a BRDF model (ltc/brdf/model.hpp) times Schlick's
// Fresnel factor, F = F0 + (1 - F0) (1 - V.H)^5, H = (V + L) / |V + L| (Hill 2016's split: the
// integral of f F is F0 times the integral of f, the tables' magnitude, plus (1 - F0) times the
// integral of f (1 - V.H)^5, their fresnel channel; ltc/fitting/moments.hpp):
//
//   fresnel_part<ggx>::model<T>   f (1 - V.H)^5, static members like any model (F0 = 0): what
//                                 the two-lobe fits split between their lobes
//                                 (ltc/fitting/fit_two_lobes.hpp, fresnel_share_of)
//   with_schlick<ggx>{F0}         f F, an instance for ltc::ground_truth::integrate (the
//                                 specular term of a colour channel with specular colour F0)
//
// Both sample and have the density of the underlying model: only eval is weighted.
#pragma once

#include <ltc/config.hpp>

#include <glm/glm.hpp>

LTC_NAMESPACE_BEGIN
namespace brdf {

/// (1 - V.H)^5, H the half vector of V and L (0 where V + L vanishes).
template <typename T>
inline T schlick_weight(const glm::vec<3, T>& V, const glm::vec<3, T>& L) {
    const glm::vec<3, T> h = V + L;
    const T len = glm::length(h);
    if (!(len > T(0))) return T(0);
    const T c = T(1) - glm::clamp(glm::dot(V, h) / len, T(0), T(1));
    const T c2 = c * c;
    return c2 * c2 * c;
}

/// Brdf's Fresnel part, f (1 - V.H)^5: Schlick's factor at F0 = 0.
template <template <typename> class Brdf>
struct fresnel_part {
    template <typename T>
    struct model {
        using vec3 = glm::vec<3, T>;
        static T eval(const vec3& V, const vec3& L, T alpha) {
            const T f = Brdf<T>::eval(V, L, alpha);
            return f > T(0) ? f * schlick_weight(V, L) : T(0);
        }
        static T pdf(const vec3& V, const vec3& L, T alpha) { return Brdf<T>::pdf(V, L, alpha); }
        static vec3 sample(const vec3& V, const glm::vec<2, T>& u, T alpha) { return Brdf<T>::sample(V, u, alpha); }
    };
};

/// Brdf times Schlick's factor with the specular colour f0 (one channel), in double: a model
/// instance for ltc::ground_truth::integrate.
template <template <typename> class Brdf>
struct with_schlick {
    double f0 = 1.0;
    double eval(const glm::dvec3& V, const glm::dvec3& L, double alpha) const {
        const double f = Brdf<double>::eval(V, L, alpha);
        return f > 0.0 ? f * (f0 + (1.0 - f0) * schlick_weight(V, L)) : 0.0;
    }
    double pdf(const glm::dvec3& V, const glm::dvec3& L, double alpha) const { return Brdf<double>::pdf(V, L, alpha); }
    glm::dvec3 sample(const glm::dvec3& V, const glm::dvec2& u, double alpha) const {
        return Brdf<double>::sample(V, u, alpha);
    }
};

}  // namespace brdf
LTC_NAMESPACE_END
