// ltc/shading/polygon_light_radiance.hpp -- a polygonal light's radiance from explicit LTC
// coefficients (paper section 5.1; Hill and Heitz 2016 for the Fresnel term): the piece of
// ltc/shading/polygon_light.hpp that the GGX tables' shading functions share.
//
//   diffuse  = albedo * radiance * E(P)                        Lambert: albedo/pi int_P cos dw
//   specular = radiance * (F0 magnitude + (1 - F0) fresnel) * I_ltc(P)
//
// with E the clipped form factor (eq. 11) and I_ltc the LTC's integral over the polygon (eq. 3),
// both signed, the light's facing applied (ltc/shading/polygon_light.hpp: the conventions).
#pragma once

#include <ltc/shading/polygon_light_integrals.hpp>  // horizon_clipping, integrate_polygon_light
#include <ltc/shading/shading_frame.hpp>            // shading_frame, make_shading_frame
#include <ltc/shading/lights/polygon_light.hpp>
#include <ltc/shading/lobes.hpp>
#include <ltc/shading/surface.hpp>

#include <ltc/config.hpp>
#include <ltc/core/edge_policy.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/tables/ltc_table.hpp>

#include <glm/glm.hpp>

#include <cstddef>

LTC_NAMESPACE_BEGIN

/// Specular and diffuse radiance reflected towards V (the name before ltc::shading_result).
template <typename T>
using polygon_light_result = shading_result<T>;

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
/// fresnel; e.g. from ltc::ltc_table::fetch(frame.cos_theta_v, roughness)). Deprecated: use
/// ltc::shade_lobes(shading_point, lobes::one{lobe}, light, options) (ltc/shading/lobes.hpp).
template <typename Policy = edge_policy::automatic, typename T>
LTC_HOST_DEVICE inline polygon_light_result<T> shade_polygon_light(
    const shading_frame<T>& frame, const ltc_coefficients<T>& lobe, const glm::vec<3, T>& P,
    const glm::vec<3, T>& F0, const glm::vec<3, T>& albedo, const glm::vec<3, T>& radiance,
    const glm::vec<3, T>* vertices, std::size_t n, sidedness side,
    horizon_clipping clip = horizon_clipping::ltc_space) {
    return shade_lobes<Policy>(shading_point<T>{frame, P, F0, albedo}, lobes::one<T>{lobe},
                               detail::polygon_light_access<T>::with_sidedness(vertices, n, side, radiance), shade_options{clip});
}

LTC_NAMESPACE_END
