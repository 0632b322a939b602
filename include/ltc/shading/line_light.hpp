// ltc/shading/line_light.hpp -- deprecated shading functions of the line light: one-line wrappers over
// ltc::shade<ltc::ggx::one_lobe>(surface, ltc::line_light<T>{p0, p1, radius, radiance})
// (ltc/shading/lights/line_light.hpp: the light, its equations and degenerate cases), kept with the
// same results. The one-lobe GGX table (ltc::ggx::one_lobe) throughout, as before.
#pragma once

#include <ltc/config.hpp>

#include <ltc/core/sidedness.hpp>
#include <ltc/shading/lights/line_light.hpp>
#include <ltc/shading/polygon_light_radiance.hpp>  // polygon_light_result
#include <ltc/shading/shade.hpp>
#include <ltc/shading/shading_frame.hpp>

#include <glm/glm.hpp>

LTC_NAMESPACE_BEGIN

/// Deprecated: ltc::shade_lobes with lobes::one (ltc/shading/lobes.hpp).
/// The tube light with explicit LTC coefficients in the local frame of `frame`.
template <typename T>
inline polygon_light_result<T> shade_line_light(const shading_frame<T>& frame, const ltc_coefficients<T>& lobe,
                                                const glm::vec<3, T>& P, const glm::vec<3, T>& F0,
                                                const glm::vec<3, T>& albedo, const glm::vec<3, T>& radiance,
                                                const glm::vec<3, T>& p0, const glm::vec<3, T>& p1, T radius) {
    return shade_lobes<edge_policy::automatic>(shading_point<T>{frame, P, F0, albedo}, lobes::one<T>{lobe},
                                               line_light<T>{p0, p1, radius, radiance}, shade_options{});
}

/// Deprecated: ltc::shade<ltc::ggx::one_lobe>(surface, light) (ltc/shading/shade.hpp).
/// The tube light with the library\'s one-lobe GGX table (ltc::ggx::fetch).
template <typename T>
inline polygon_light_result<T> shade_line_light(const glm::vec<3, T>& P, const glm::vec<3, T>& N,
                                                const glm::vec<3, T>& V, T roughness, const glm::vec<3, T>& F0,
                                                const glm::vec<3, T>& albedo, const glm::vec<3, T>& radiance,
                                                const glm::vec<3, T>& p0, const glm::vec<3, T>& p1, T radius) {
    return shade<ggx::one_lobe>(surface<T>{P, N, V, roughness, F0, albedo}, line_light<T>{p0, p1, radius, radiance});
}

LTC_NAMESPACE_END
