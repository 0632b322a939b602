// ltc/shading/cosine_lobe_polygon_light.hpp -- shading a point with a constant-radiance polygonal
// light with the GGX table of one LTC plus the clamped cosine about the normal
// (ltc/shading/ggx_cosine_lobe_fetch.hpp), the library's default (ltc::shade_polygon_light's
// world-space overload calls this one, ltc/shading/polygon_light.hpp):
//
//   specular = radiance ((F0 m_c + (1 - F0) f_c) E + (F0 m_M + (1 - F0) f_M) I_M)
//
// with E the form factor (the cosine lobe's integral: paper eq. 11, the one the diffuse term
// uses), I_M the LTC's integral (eq. 3), and each lobe's magnitude m and Fresnel term f carrying
// its share. The diffuse term is the one-lobe shading's.
//
//   #include <ltc/shading/cosine_lobe_polygon_light.hpp>
//   ltc::polygon_light_result<float> r = ltc::shade_polygon_light_cosine_lobe(
//       P, N, V, roughness, F0, albedo, radiance, vertices, n, ltc::sidedness::one_sided);
#pragma once

#include <ltc/config.hpp>

#include <ltc/shading/ggx_cosine_lobe_fetch.hpp>
#include <ltc/shading/polygon_light_radiance.hpp>
#include <ltc/shading/shade.hpp>

#include <glm/glm.hpp>

#include <array>
#include <cstddef>

LTC_NAMESPACE_BEGIN

/// Deprecated: ltc::shade_lobes with lobes::ltc_and_cosine (ltc/shading/lobes.hpp).
/// Shading with explicit coefficients (lobes[0] the cosine's magnitude and Fresnel term, its
/// m_inv unused; lobes[1] the LTC, m_inv in the local frame of `frame`; each magnitude and
/// fresnel carrying its share, as ggx_cosine_lobe::fetch returns them).
template <typename Policy = edge_policy::automatic, typename T>
inline polygon_light_result<T> shade_polygon_light_cosine_lobe(
    const shading_frame<T>& frame, const std::array<ltc_coefficients<T>, 2>& lobes, const glm::vec<3, T>& P,
    const glm::vec<3, T>& F0, const glm::vec<3, T>& albedo, const glm::vec<3, T>& radiance,
    const glm::vec<3, T>* vertices, std::size_t n, sidedness side, horizon_clipping clip = horizon_clipping::ltc_space) {
    return shade_lobes<Policy>(shading_point<T>{frame, P, F0, albedo}, lobes::ltc_and_cosine<T>{lobes[1], lobes[0]},
                               detail::polygon_light_access<T>::with_sidedness(vertices, n, side, radiance), shade_options{clip});
}

/// Deprecated: ltc::shade<ltc::ggx::ltc_and_cosine> (ltc/shading/shade.hpp).
/// Shading with the GGX table of an LTC and the cosine: cos theta_v from N and V, both lobes from
/// ggx_cosine_lobe::fetch(cos theta_v, roughness) (alpha = roughness^2).
/// Same inputs, conventions, horizon clipping and degenerate cases as shade_polygon_light_one_lobe,
/// and the same integrals (one form factor, one LTC integral): the extra cost is the second table
/// fetch. The cosine's integral is the form factor of the clipping mode, which is its exact
/// integral with ltc_space and shading_first clipping (the cosine needs no clipping in its own
/// space but the horizon's) and the clipless approximation with the sphere modes.
template <typename Policy = edge_policy::automatic, typename T>
inline polygon_light_result<T> shade_polygon_light_cosine_lobe(const glm::vec<3, T>& P, const glm::vec<3, T>& N,
                                                               const glm::vec<3, T>& V, T roughness,
                                                               const glm::vec<3, T>& F0, const glm::vec<3, T>& albedo,
                                                               const glm::vec<3, T>& radiance,
                                                               const glm::vec<3, T>* vertices, std::size_t n,
                                                               sidedness side,
                                                               horizon_clipping clip = horizon_clipping::ltc_space) {
    return shade<ggx::ltc_and_cosine, Policy>(surface<T>{P, N, V, roughness, F0, albedo},
                                              detail::polygon_light_access<T>::with_sidedness(vertices, n, side, radiance),
                                              shade_options{clip});
}

LTC_NAMESPACE_END
