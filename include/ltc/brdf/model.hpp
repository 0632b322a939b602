// ltc/brdf/model.hpp -- the small interface that a BRDF model offers to the LTC fitter and to
// the Monte Carlo ground truth (paper section 4).
//
// A model is a class template B<T> (T = float or double) with static members, in the local
// shading frame N = +z, for a unit view direction V with V.z > 0 and the microfacet roughness
// alpha (the library's convention is alpha = roughness^2):
//
//   static T    eval(const vec3& V, const vec3& L, T alpha);    // rho(V, L) * max(0, L.z):
//                                                               // the cosine-weighted BRDF
//   static T    pdf(const vec3& V, const vec3& L, T alpha);     // density of sample(), per sr
//   static vec3 sample(const vec3& V, const vec2& u, T alpha);  // u in [0, 1)^2 -> direction L
//   static constexpr const char* name;                          // "ggx", "beckmann"
//
// eval is 0 for L.z <= 0; no Fresnel term (the fit factors it out, Hill 2016). sample() may return
// directions below the horizon (eval 0 there); pdf is sample()'s exact density: eval / pdf unbiased.
#pragma once

#include <ltc/config.hpp>

#include <glm/glm.hpp>

#include <cmath>

LTC_NAMESPACE_BEGIN
namespace brdf {

/// The view direction of the fit's local frame: V = (sin theta_v, 0, cos theta_v).
template <typename T>
LTC_HOST_DEVICE inline glm::vec<3, T> view_from_cos(T cos_theta_v) {
    const T c = glm::clamp(cos_theta_v, T(0), T(1));
    return glm::vec<3, T>(std::sqrt(glm::max(T(0), (T(1) - c) * (T(1) + c))), T(0), c);
}

}  // namespace brdf
LTC_NAMESPACE_END
