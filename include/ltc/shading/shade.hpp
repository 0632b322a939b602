// ltc/shading/shade.hpp -- one entry point for every light and every material model:
//
//   ltc::surface<float> s{P, N, V, roughness, F0, albedo};
//   auto quad = ltc::polygon_light<float>::one_sided(vertices, 4, emission_normal, radiance);
//   ltc::shading_result<float> r = ltc::shade(s, quad);          // ltc::ggx::ltc_and_cosine
//   r = ltc::shade<ltc::ggx::two_lobes>(s, quad, {ltc::horizon_clipping::shading_first});
//
// shade<Model>(s, light, options) reads the model's lobes at (cos theta_v, roughness) in the frame
// of the tables and shades them against the light (ltc/shading/lobes.hpp: the equations, paper
// eq. 3 and 11). Conventions: world space; the lights and models of shade's comment.
// Bad input, the same for every light and model: a zero or non-finite normal or view vector
// gives 0 (specular and diffuse); the roughness is clamped to [0, 1], NaN read as 0 (the table's
// domain); lights check their own construction (ltc/shading/lights/light_error.hpp).
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/edge_policy.hpp>
#include <ltc/shading/ggx_models.hpp>
#include <ltc/shading/lobes.hpp>
#include <ltc/shading/shading_frame.hpp>
#include <ltc/shading/surface.hpp>

#include <glm/glm.hpp>

#include <type_traits>
#include <utility>

LTC_NAMESPACE_BEGIN

/// The shading point of s in the frame of the tables (invalid frame: N or V zero or not finite).
template <typename T>
LTC_HOST_DEVICE LTC_INLINE shading_point<T> make_shading_point(const surface<T>& s) {
    return {make_shading_frame(s.normal, s.view), s.position, s.f0, s.albedo};
}

/// The shading point of s in the frame of the anisotropic tables (make_tangent_frame: T1 along
/// s.tangent).
template <typename T>
LTC_HOST_DEVICE LTC_INLINE shading_point<T> make_tangent_shading_point(const surface<T>& s) {
    return {make_tangent_frame(s.normal, s.view, s.tangent), s.position, s.f0, s.albedo};
}

namespace detail {
/// Whether Model is anisotropic: its fetch takes (cos theta_v, phi_v, roughness, roughness_bitangent).
template <typename Model, typename T, typename = void>
struct takes_tangent : std::false_type {};
template <typename Model, typename T>
struct takes_tangent<Model, T,
                     std::void_t<decltype(std::declval<const Model&>().template fetch<T>(T(0), T(0), T(0), T(0)))>>
    : std::true_type {};

/// The shading point of s in the frame of Model's tables.
template <typename Model, typename T>
LTC_HOST_DEVICE LTC_INLINE shading_point<T> model_shading_point(const surface<T>& s) {
    if constexpr (takes_tangent<Model, T>::value)
        return make_tangent_shading_point(s);
    else
        return make_shading_point(s);
}

/// Model's lobes at s, p its model_shading_point.
template <typename Model, typename T>
LTC_HOST_DEVICE LTC_INLINE auto fetch_lobes(const Model& model, const shading_point<T>& p, const surface<T>& s) {
    if constexpr (takes_tangent<Model, T>::value)
        return model.template fetch<T>(p.frame.cos_theta_v, view_azimuth(p.frame, s.view), s.roughness,
                                       s.roughness_bitangent);
    else
        return model.template fetch<T>(p.frame.cos_theta_v, s.roughness);
}

/// shade's steps with a model object (static fetch or not: batch::shade's models with state).
template <typename Policy, typename Model, typename T, typename Light>
LTC_HOST_DEVICE LTC_INLINE shading_result<T> shade_model(const Model& model, const surface<T>& s, const Light& light,
                                         const shade_options& options) {
    // x - x is 0 for finite x, NaN for an infinity or NaN: one test for the nine coordinates.
    const glm::vec<3, T> z = (s.position - s.position) + (s.normal - s.normal) + (s.view - s.view);
    if (!(z.x + z.y + z.z == T(0)) || s.view == glm::vec<3, T>(T(0)))
        return {};
    const shading_point<T> p = model_shading_point<Model>(s);
    if (!p.frame.valid) return {};
    return shade_lobes<Policy>(p, fetch_lobes(model, p, s), light, options);
}
}  // namespace detail

/// Radiance reflected towards s.view from `light`, with the lobes of Model. shade<Model>(s,
/// light, options) builds the frame of the tables at s.position (N = +z, V in the xz-plane:
/// make_shading_frame; anisotropic models: the tangent along +x, make_tangent_frame), reads the
/// model's lobes at (cos theta_v, roughness) (anisotropic: at (cos theta_v, phi_v, roughness,
/// roughness_bitangent)) and shades them against the light (ltc/shading/lobes.hpp: the
/// equations). Lights: polygon_light, disk_light, sphere_light, line_light, tube_light and
/// textured_quad_light (ltc/shading/lights/). Models: ltc::ggx::one_lobe, ltc_and_cosine (the
/// default), two_lobes (ltc/shading/ggx_models.hpp), ltc::ggx::anisotropic
/// (ltc/shading/ggx_anisotropic_model.hpp), the sheen ltc::sheen::charlie
/// (ltc/shading/sheen_models.hpp), or a user's own (the model interface in ggx_models.hpp). Bad
/// input: the file's first comment. Policy: the edge terms of the polygon integrals
/// (ltc/core/edge_policy.hpp). CUDA: __host__ __device__ where Model's fetch and the light's
/// shading are (the shipped tables are host data; on the device, shade(model, s, light) below
/// with a model over a table in device memory).
template <typename Model = ggx::ltc_and_cosine, typename Policy = edge_policy::automatic, typename T, typename Light>
LTC_HOST_DEVICE LTC_INLINE shading_result<T> shade(const surface<T>& s, const Light& light,
                                                   const shade_options& options = {}) {
    return detail::shade_model<Policy>(Model{}, s, light, options);
}

/// shade<Model>(s, light, options) with a model object: a model with state, e.g. one over a
/// user's own table, ltc::shade(ltc::ggx::one_lobe_of{table}, s, light) (ltc/shading/ggx_models.hpp),
/// which is how a CUDA kernel shades with a table in device memory. The same steps and bits as
/// shade<Model> for a model whose fetch is static.
template <typename Policy = edge_policy::automatic, typename Model, typename T, typename Light>
LTC_HOST_DEVICE LTC_INLINE shading_result<T> shade(const Model& model, const surface<T>& s, const Light& light,
                                                   const shade_options& options = {}) {
    return detail::shade_model<Policy>(model, s, light, options);
}

LTC_NAMESPACE_END
