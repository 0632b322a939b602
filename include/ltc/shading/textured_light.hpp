// ltc/shading/textured_light.hpp -- the deprecated shading function of textured quad lights, a
// one-line wrapper over ltc::shade<ltc::ggx::one_lobe>(surface, textured_quad_light)
// (ltc/shading/lights/textured_quad_light.hpp: the light, its equations, methods and degenerate
// cases), kept with the same results; and that header's names, through it.
#pragma once

#include <ltc/config.hpp>

#include <ltc/core/sidedness.hpp>
#include <ltc/shading/lights/textured_quad_light.hpp>
#include <ltc/shading/shade.hpp>

#include <glm/glm.hpp>

LTC_NAMESPACE_BEGIN

/// Deprecated: ltc::shade<ltc::ggx::one_lobe>(surface, textured_quad_light) (ltc/shading/shade.hpp).
/// A textured quad light in world space (section 5.2 with the one-lobe GGX table of section 4):
///
///   specular = (F0 magnitude + (1 - F0) fresnel) I_D I_L       (LTC of GGX, Hill 2016 Fresnel)
///   diffuse  = albedo I_D,cos I_L,cos                          (the clamped cosine itself: M = I)
///
/// P the shading point, N the normal, V towards the eye (both normalized here), alpha =
/// roughness^2, quad[0..3] the world-space corners with uv (0,0), (1,0), (1,1), (0,1). The frame
/// is the one of shade_polygon_light (ltc/shading/polygon_light.hpp, make_shading_frame): T1 = normalize(V -
/// N (V.N)), T2 = N x T1, robust when V ~ N; cos theta_v = clamp(N.V, 0, 1). With a constant
/// texture c it equals shade_polygon_light_one_lobe(..., radiance = c, ...) with ltc_space clipping.
/// Zero for N = 0; finite for any finite input. `policy` picks the textured integral of both
/// terms (textured_method; the paper's fetch by default).
template <typename T>
inline textured_light_result<T> shade_textured_quad_light(const glm::vec<3, T>& P, const glm::vec<3, T>& N,
                                                          const glm::vec<3, T>& V, T roughness,
                                                          const glm::vec<3, T>& F0, const glm::vec<3, T>& albedo,
                                                          const glm::vec<3, T> quad[4], const light_texture<T>& tex,
                                                          sidedness side, const textured_policy& policy = {}) {
    return shade<ggx::one_lobe>(surface<T>{P, N, V, roughness, F0, albedo},
                                side == sidedness::one_sided ? textured_quad_light<T>::one_sided(quad, winding::clockwise_front, tex, policy)
                                                             : textured_quad_light<T>::two_sided(quad, tex, policy));
}

LTC_NAMESPACE_END
