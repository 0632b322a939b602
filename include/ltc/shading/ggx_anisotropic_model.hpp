// ltc/shading/ggx_anisotropic_model.hpp -- anisotropic GGX as a material model of ltc::shade
// (ltc/shading/shade.hpp): one full-matrix LTC per node of the 4D table (ltc::ggx_anisotropic::
// fetch, after Kt, Heitz, Dupuy and Narayanan 2022), for every light shape, scalar and batch.
//
//   ltc::surface<float> s{P, N, V, roughness, F0, albedo};
//   s.tangent = T;                     // the direction of `roughness` (brushing direction)
//   s.roughness_bitangent = 0.6f;      // the roughness along N x T
//   ltc::shading_result<float> r = ltc::shade<ltc::ggx::anisotropic>(s, light);
//
// Conventions: alpha_x = roughness^2 along the tangent, alpha_y = roughness_bitangent^2 along
// N x tangent; the frame of the table is make_tangent_frame(N, V, tangent) and phi_v V's azimuth
// in it (view_azimuth). Degenerate cases: those of ltc::shade; a tangent zero, not finite or
// parallel to N takes a fixed direction of N's plane (make_tangent_frame); both roughnesses are
// clamped to [0, 1], NaN read as 0. At roughness == roughness_bitangent the model is isotropic
// GGX through the 4D table (close to ggx::one_lobe, within the 8^4 grid's interpolation).
#pragma once

#include <ltc/config.hpp>
#include <ltc/shading/ggx_anisotropic_fetch.hpp>
#include <ltc/shading/lobes.hpp>

LTC_NAMESPACE_BEGIN
namespace ggx {

/// Anisotropic GGX (ltc::brdf::ggx_anisotropic: Heitz 2014's height-correlated Smith, no Fresnel)
/// through ltc::ggx_anisotropic::fetch: one LTC (lobes::one) whose m_inv is a full matrix in the
/// tangent frame. The anisotropic model interface: fetch(cos theta_v, phi_v, roughness,
/// roughness_bitangent), which ltc::shade calls in make_tangent_frame's frame.
struct anisotropic {
    template <typename T>
    using coefficients = lobes::one<T>;
    template <typename T>
    static coefficients<T> fetch(T cos_theta_v, T phi_v, T roughness, T roughness_bitangent) {
        const T rx = detail::saturate(roughness), ry = detail::saturate(roughness_bitangent);
        return {ggx_anisotropic::fetch<T>(cos_theta_v, phi_v, rx * rx, ry * ry)};
    }
};

}  // namespace ggx
LTC_NAMESPACE_END
