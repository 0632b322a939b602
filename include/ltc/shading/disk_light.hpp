// ltc/shading/disk_light.hpp -- shading a point with a constant-radiance disk light and GGX: the
// LTC of the GGX table (paper section 4) integrated exactly over the disk (Heitz and Hill 2017's
// disk lights, with ltc/core/ellipse_integral.hpp's exact clipped ellipse in place of their
// sphere approximation, which integrate_disk_2017 keeps for comparison).
//
//   ltc::polygon_light_result<float> r = ltc::shade_disk_light(
//       P, N, V, roughness, F0, albedo, radiance, centre, normal, radius, ltc::sidedness::one_sided);
//
// World space, as shade_polygon_light (ltc/shading/polygon_light.hpp): the shading point P, the
// normal N, the direction V towards the eye (N and V normalized here), roughness (alpha =
// roughness^2), the specular colour F0, the diffuse albedo, the light's radiance; the disk's
// centre, normal (any length) and radius. One-sided disks emit towards +normal.
//
//   diffuse  = albedo * radiance * E,   E = int_disk cos / pi        (integrate_disk, M = I)
//   specular = radiance * (F0 magnitude + (1 - F0) fresnel) * I_ltc  (integrate_disk, the GGX LTC)
//
// Both integrals are exact to rounding (the horizon clipped exactly); the shading's error is the
// GGX fit's (examples/shape_error_report measures it against Monte Carlo of the real GGX).
// Degenerate input gives finite results: radius <= 0, N = 0, the point in the disk's plane
// (edge-on) give 0; see ltc/core/ellipse_integral.hpp.
#pragma once

#include <ltc/config.hpp>

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/ellipse_integral.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/shading/polygon_light_radiance.hpp>  // polygon_light_result, shade_polygon_light(frame, lobe, ...)
#include <ltc/shading/shading_frame.hpp>

#include <glm/glm.hpp>

LTC_NAMESPACE_BEGIN

/// The disk light (file comment) with explicit LTC coefficients in the local frame of `frame`.
template <typename T>
inline polygon_light_result<T> shade_disk_light(const shading_frame<T>& frame, const ltc_coefficients<T>& lobe,
                                                const glm::vec<3, T>& P, const glm::vec<3, T>& F0,
                                                const glm::vec<3, T>& albedo, const glm::vec<3, T>& radiance,
                                                const glm::vec<3, T>& centre, const glm::vec<3, T>& normal, T radius,
                                                sidedness side) {
    polygon_light_result<T> r;
    if (!frame.valid) return r;
    const glm::vec<3, T> c = frame.to_local(centre - P), n = frame.to_local(normal);
    const auto spec = transformed<clamped_cosine<T>>::from_inverse(lobe.m_inv);
    const auto cosine = transformed<clamped_cosine<T>>::from_inverse(glm::mat<3, 3, T>(T(1)));
    const glm::vec<3, T> specular_scale = brdf_scale(F0, lobe);
    r.specular = radiance * specular_scale * integrate_disk(spec, c, n, radius, side);
    r.diffuse = albedo * radiance * integrate_disk(cosine, c, n, radius, side);
    return r;
}

/// The disk light (file comment) with the library's one-lobe GGX table (ltc::ggx::fetch).
template <typename T>
inline polygon_light_result<T> shade_disk_light(const glm::vec<3, T>& P, const glm::vec<3, T>& N,
                                                const glm::vec<3, T>& V, T roughness, const glm::vec<3, T>& F0,
                                                const glm::vec<3, T>& albedo, const glm::vec<3, T>& radiance,
                                                const glm::vec<3, T>& centre, const glm::vec<3, T>& normal, T radius,
                                                sidedness side) {
    const shading_frame<T> frame = make_shading_frame(N, V);
    return shade_disk_light(frame, ggx::fetch<T>(frame.cos_theta_v, roughness), P, F0, albedo, radiance, centre,
                            normal, radius, side);
}

LTC_NAMESPACE_END
