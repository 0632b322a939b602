// ltc/shading/polygon_light.hpp -- the deprecated world-space shading functions of polygonal
// lights with the GGX tables, one-line wrappers over ltc::shade (ltc/shading/shade.hpp) kept with
// the same results:
//
//   shade_polygon_light(P, N, V, roughness, F0, albedo, radiance, vertices, n, side[, clip])
//       = ltc::shade<ltc::ggx::ltc_and_cosine>(surface, light, {clip})
//   shade_polygon_light_one_lobe(...) = ltc::shade<ltc::ggx::one_lobe>(surface, light, {clip})
//
// with light the polygon of the old winding rule: a one-sided light emits from the face from
// which its vertices turn clockwise (ltc::winding::clockwise_front). New code builds an
// ltc::polygon_light with an emission normal instead (ltc/shading/lights/polygon_light.hpp).
// Also brings in the pieces they used (shading_frame.hpp, polygon_light_integrals.hpp,
// polygon_light_radiance.hpp, cosine_lobe_polygon_light.hpp).
#pragma once

#include <ltc/config.hpp>

#include <ltc/shading/polygon_light_radiance.hpp>      // polygon_light_result, shade_polygon_light(frame, lobe, ...)
#include <ltc/shading/cosine_lobe_polygon_light.hpp>   // shade_polygon_light_cosine_lobe: the default
#include <ltc/shading/polygon_light_integrals.hpp>     // horizon_clipping, integrate_polygon_light
#include <ltc/shading/shading_frame.hpp>               // shading_frame, make_shading_frame

#include <ltc/core/edge_policy.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/shading/lights/polygon_light.hpp>
#include <ltc/shading/shade.hpp>

#include <glm/glm.hpp>

#include <cstddef>

LTC_NAMESPACE_BEGIN

/// Deprecated: ltc::shade<ltc::ggx::one_lobe> (ltc/shading/shade.hpp).
/// Shading with the library's one-lobe GGX table: cos theta_v from N and V, the coefficients
/// from ltc::ggx::fetch(cos theta_v, roughness) (alpha = roughness^2).
template <typename Policy = edge_policy::automatic, typename T>
inline polygon_light_result<T> shade_polygon_light_one_lobe(const glm::vec<3, T>& P, const glm::vec<3, T>& N,
                                                            const glm::vec<3, T>& V, T roughness,
                                                            const glm::vec<3, T>& F0, const glm::vec<3, T>& albedo,
                                                            const glm::vec<3, T>& radiance,
                                                            const glm::vec<3, T>* vertices, std::size_t n,
                                                            sidedness side,
                                                            horizon_clipping clip = horizon_clipping::ltc_space) {
    return shade<ggx::one_lobe, Policy>(surface<T>{P, N, V, roughness, F0, albedo},
                                        detail::polygon_light_access<T>::with_sidedness(vertices, n, side, radiance),
                                        shade_options{clip});
}

/// Deprecated: ltc::shade (ltc/shading/shade.hpp).
/// Shading with the library's default GGX table, an LTC and the clamped cosine about the normal
/// (ltc/shading/cosine_lobe_polygon_light.hpp).
template <typename Policy = edge_policy::automatic, typename T>
inline polygon_light_result<T> shade_polygon_light(const glm::vec<3, T>& P, const glm::vec<3, T>& N,
                                                   const glm::vec<3, T>& V, T roughness, const glm::vec<3, T>& F0,
                                                   const glm::vec<3, T>& albedo, const glm::vec<3, T>& radiance,
                                                   const glm::vec<3, T>* vertices, std::size_t n, sidedness side,
                                                   horizon_clipping clip = horizon_clipping::ltc_space) {
    return shade<ggx::ltc_and_cosine, Policy>(surface<T>{P, N, V, roughness, F0, albedo},
                                              detail::polygon_light_access<T>::with_sidedness(vertices, n, side, radiance),
                                              shade_options{clip});
}

LTC_NAMESPACE_END
