// ltc/shading/two_lobe_polygon_light.hpp -- shading a point with a constant-radiance polygonal
// light with the opt-in two-lobe GGX table (ltc/shading/ggx_two_lobe_fetch.hpp): the specular
// term is the sum of both lobes' exact integrals (paper eq. 3 for each), the diffuse term as in
// ltc/shading/polygon_light.hpp.
//
//   #include <ltc/shading/two_lobe_polygon_light.hpp>
//   ltc::polygon_light_result<float> r = ltc::shade_polygon_light_two_lobe(
//       P, N, V, roughness, F0, albedo, radiance, vertices, n, ltc::sidedness::one_sided);
//
// Same inputs, conventions, horizon clipping and degenerate cases as shade_polygon_light, at
// the cost of one more LTC integral (integrate_polygon_light_ltc: the second lobe's transform,
// clip and edge sum, without a second form factor; its cost: docs/results/speed.md, from
// benchmarks/bench_shading.cpp).
#pragma once

#include <ltc/config.hpp>

#include <ltc/shading/ggx_two_lobe_fetch.hpp>
#include <ltc/shading/polygon_light_integrals.hpp>  // integrate_polygon_light_ltc, horizon_clipping
#include <ltc/shading/polygon_light_radiance.hpp>   // polygon_light_result, shade_polygon_light(frame, lobe, ...)
#include <ltc/shading/shading_frame.hpp>
#include <ltc/shading/shade.hpp>

#include <glm/glm.hpp>

#include <array>
#include <cstddef>

LTC_NAMESPACE_BEGIN

/// Deprecated: a light's ltc_integral (ltc/shading/lobes.hpp, "The light interface").
/// The second lobe's specular term (its magnitude and Fresnel carrying its share), which
/// shade_polygon_light_two_lobe adds to the first lobe's shading: its LTC integral alone.
template <typename Policy = edge_policy::automatic, typename T>
inline glm::vec<3, T> second_lobe_specular(const shading_frame<T>& frame, const ltc_coefficients<T>& lobe,
                                           const glm::vec<3, T>& P, const glm::vec<3, T>& F0,
                                           const glm::vec<3, T>& radiance, const glm::vec<3, T>* vertices, std::size_t n,
                                           sidedness side, horizon_clipping clip = horizon_clipping::ltc_space) {
    const auto light = detail::polygon_light_access<T>::with_sidedness(vertices, n, side, radiance);
    return light.emitted(brdf_scale(F0, lobe), light.template ltc_integral<Policy>(frame, P, lobe.m_inv, shade_options{clip}));
}

/// Deprecated: ltc::shade_lobes with lobes::two (ltc/shading/lobes.hpp).
/// Shading with explicit coefficients for both lobes (m_inv in the local frame of `frame`; each
/// lobe's magnitude and fresnel carrying its share, as ggx_two_lobe::fetch returns them).
template <typename Policy = edge_policy::automatic, typename T>
inline polygon_light_result<T> shade_polygon_light_two_lobe(
    const shading_frame<T>& frame, const std::array<ltc_coefficients<T>, 2>& lobes, const glm::vec<3, T>& P,
    const glm::vec<3, T>& F0, const glm::vec<3, T>& albedo, const glm::vec<3, T>& radiance,
    const glm::vec<3, T>* vertices, std::size_t n, sidedness side, horizon_clipping clip = horizon_clipping::ltc_space) {
    return shade_lobes<Policy>(shading_point<T>{frame, P, F0, albedo}, lobes::two<T>{lobes[0], lobes[1]},
                               detail::polygon_light_access<T>::with_sidedness(vertices, n, side, radiance), shade_options{clip});
}

/// Deprecated: ltc::shade<ltc::ggx::two_lobes> (ltc/shading/shade.hpp).
/// Shading with the two-lobe GGX table: cos theta_v from N and V, both lobes from
/// ggx_two_lobe::fetch(cos theta_v, roughness) (alpha = roughness^2).
template <typename Policy = edge_policy::automatic, typename T>
inline polygon_light_result<T> shade_polygon_light_two_lobe(const glm::vec<3, T>& P, const glm::vec<3, T>& N,
                                                            const glm::vec<3, T>& V, T roughness, const glm::vec<3, T>& F0,
                                                            const glm::vec<3, T>& albedo, const glm::vec<3, T>& radiance,
                                                            const glm::vec<3, T>* vertices, std::size_t n, sidedness side,
                                                            horizon_clipping clip = horizon_clipping::ltc_space) {
    return shade<ggx::two_lobes, Policy>(surface<T>{P, N, V, roughness, F0, albedo},
                                         detail::polygon_light_access<T>::with_sidedness(vertices, n, side, radiance),
                                         shade_options{clip});
}

LTC_NAMESPACE_END
