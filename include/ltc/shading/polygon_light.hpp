// ltc/shading/polygon_light.hpp -- shading a point with a constant-radiance polygonal light (paper section 5.1;
// Hill and Heitz 2016 for the Fresnel term and the clipless variant).
//
//   #include <ltc/shading/polygon_light.hpp>
//   ltc::polygon_light_result<float> r = ltc::shade_polygon_light(
//       P, N, V, roughness, F0, albedo, radiance, vertices, n, ltc::sidedness::one_sided);
//   glm::vec3 colour = r.specular + r.diffuse;
//
// Inputs, all in world space: the shading point P, the normal N, the direction V towards the eye
// (N and V are normalized here), the roughness (alpha = roughness^2, the convention of the GGX
// tables), the specular colour F0, the diffuse albedo, the light's radiance and its n >= 3
// vertices (a simple planar polygon, any n). Outputs:
//
//   diffuse  = albedo * radiance * E(P)                        Lambert: albedo/pi int_P cos dw
//   specular = radiance sum over lobes (F0 magnitude + (1 - F0) fresnel) * I_lobe(P)
//
// with E the clipped form factor (paper eq. 11, with the chosen edge policy; in the sphere modes
// the clipless approximation) and I_lobe the integral of a lobe over the polygon (eq. 3), its
// coefficients (M^-1, magnitude, fresnel) taken from a GGX table at (cos theta_v, roughness).
// The default table (issue 16) has two lobes per node: an LTC and the clamped cosine about the
// normal, whose integral is E itself (ltc/shading/cosine_lobe_polygon_light.hpp), so that the
// specular term costs one LTC integral, as with the paper's single LTC, which
// shade_polygon_light_one_lobe keeps (ltc::ggx::fetch's table). Their sum approximates int_P rho
// cos (the fit's error, measured by examples/ggx_error_report/ against
// ltc/reference/ground_truth.hpp: 4.35% mean with the default table, 9.40% with one lobe).
//
// The pieces, each of which can be included on its own:
//   ltc/shading/shading_frame.hpp            the local frame (T1, T2, N) and cos theta_v
//                                            (shading_frame, make_shading_frame)
//   ltc/shading/polygon_light_integrals.hpp  E and I_ltc, signed, with the horizon-clipping
//                                            strategies (horizon_clipping, integrate_polygon_light)
//   ltc/shading/polygon_light_radiance.hpp   radiance from explicit coefficients
//                                            (polygon_light_result, shade_polygon_light(frame, lobe, ...))
// This header adds the world-space functions with the GGX tables (shade_polygon_light,
// shade_polygon_light_one_lobe).
//
// Sign convention. A polygon's integrals are signed (polygon.hpp): positive when its vertices
// turn clockwise as seen from the shading point, i.e. when its right-hand normal
// (p1 - p0) x (p2 - p0) points away from P. A one-sided light emits from that front face only
// (max(0, signed)): a light whose vertices appear counter-clockwise from P contributes 0. A
// two-sided light takes |signed|. The same facing test applies to diffuse and specular.
//
// Degenerate input gives finite results: n < 3, a vertex at the shading point (the light is
// seen edge-on) and N = 0 give 0; a light entirely below the horizon gives 0 diffuse, and 0
// specular except for ltc_space's leak (ltc/shading/polygon_light_integrals.hpp).
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
/// Shading with the library's one-lobe GGX table (the default before issue 16): cos theta_v from
/// N and V, the coefficients from ltc::ggx::fetch(cos theta_v, roughness) (alpha = roughness^2).
/// The textured, line, disk, sphere and tube lights use this table.
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
/// (ltc/shading/cosine_lobe_polygon_light.hpp): it calls shade_polygon_light_cosine_lobe.
/// Against shade_polygon_light_one_lobe: half the error (README, "Shading polygonal lights with
/// GGX"), for the same integrals and a second table fetch.
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
