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
// table), the specular colour F0, the diffuse albedo, the light's radiance and its n >= 3
// vertices (a simple planar polygon, any n). Outputs:
//
//   diffuse  = albedo * radiance * E(P)                        Lambert: albedo/pi int_P cos dw
//   specular = radiance * (F0 magnitude + (1 - F0) fresnel) * I_ltc(P)
//
// with E the clipped form factor (paper eq. 11, with the chosen edge policy; in the sphere modes
// the clipless approximation) and I_ltc the integral of the LTC
// distribution over the polygon (eq. 3), its coefficients (M^-1, magnitude, fresnel) taken from
// the GGX table at (cos theta_v, roughness). magnitude I_ltc approximates int_P rho cos (the
// fit's error, measured by examples/ggx_error_report/ against ltc/reference/ground_truth.hpp).
//
// The pieces, each of which can be included on its own:
//   ltc/shading/shading_frame.hpp            the local frame (T1, T2, N) and cos theta_v
//                                            (shading_frame, make_shading_frame)
//   ltc/shading/polygon_light_integrals.hpp  E and I_ltc, signed, with the horizon-clipping
//                                            strategies (horizon_clipping, integrate_polygon_light)
// This header turns them into radiance (polygon_light_result, shade_polygon_light).
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

#include <ltc/shading/polygon_light_integrals.hpp>  // horizon_clipping, integrate_polygon_light
#include <ltc/shading/shading_frame.hpp>            // shading_frame, make_shading_frame

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/shading/clipless.hpp>
#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/core/polygon.hpp>
#include <ltc/shading/table.hpp>
#include <ltc/core/transformed.hpp>

#include <ltc/shading/ggx_fetch.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <type_traits>

namespace ltc {

/// Specular and diffuse radiance reflected towards V (RGB, or any 3 channels).
template <typename T>
struct polygon_light_result {
    glm::vec<3, T> specular{T(0)};
    glm::vec<3, T> diffuse{T(0)};
};

/// The radiance of the file comment from the two signed integrals (the light's facing applied).
template <typename T>
LTC_HOST_DEVICE inline polygon_light_result<T> polygon_light_radiance(const polygon_light_integrals<T>& I,
                                                                      const ltc_coefficients<T>& lobe,
                                                                      const glm::vec<3, T>& F0, const glm::vec<3, T>& albedo,
                                                                      const glm::vec<3, T>& radiance, sidedness side) {
    polygon_light_result<T> r;
    r.specular = radiance * brdf_scale(F0, lobe) * apply_sidedness(I.ltc, side);
    r.diffuse = albedo * radiance * apply_sidedness(I.form_factor, side);
    return r;
}

/// Shading with explicit LTC coefficients (m_inv in the local frame of `frame`, magnitude,
/// fresnel; e.g. from ltc::ltc_table::fetch(frame.cos_theta_v, roughness)).
template <typename Policy = edge_policy::automatic, typename T>
LTC_HOST_DEVICE inline polygon_light_result<T> shade_polygon_light(
    const shading_frame<T>& frame, const ltc_coefficients<T>& lobe, const glm::vec<3, T>& P,
    const glm::vec<3, T>& F0, const glm::vec<3, T>& albedo, const glm::vec<3, T>& radiance,
    const glm::vec<3, T>* vertices, std::size_t n, sidedness side,
    horizon_clipping clip = horizon_clipping::ltc_space) {
    return polygon_light_radiance(integrate_polygon_light<Policy>(frame, lobe.m_inv, P, vertices, n, clip), lobe, F0,
                                  albedo, radiance, side);
}

/// Shading with the library's GGX table: cos theta_v from N and V, the coefficients from
/// ltc::ggx::fetch(cos theta_v, roughness) (alpha = roughness^2).
template <typename Policy = edge_policy::automatic, typename T>
inline polygon_light_result<T> shade_polygon_light(const glm::vec<3, T>& P, const glm::vec<3, T>& N,
                                                   const glm::vec<3, T>& V, T roughness, const glm::vec<3, T>& F0,
                                                   const glm::vec<3, T>& albedo, const glm::vec<3, T>& radiance,
                                                   const glm::vec<3, T>* vertices, std::size_t n, sidedness side,
                                                   horizon_clipping clip = horizon_clipping::ltc_space) {
    const shading_frame<T> frame = make_shading_frame(N, V);
    return shade_polygon_light<Policy>(frame, ggx::fetch<T>(frame.cos_theta_v, roughness), P, F0, albedo, radiance, vertices,
                               n, side, clip);
}

}  // namespace ltc
