// ltc/shading/sheen_models.hpp -- the sheen material model of ltc::shade (ltc/shading/shade.hpp):
// KHR_materials_sheen's Charlie sheen (ltc::brdf::charlie) through its one-lobe table
// (ltc::charlie::fetch), for every light shape, and the spec's albedo scaling of the base layer.
//
//   ltc::surface<float> sheen_layer{P, N, V, sheen_roughness, sheen_colour, glm::vec3(0)};
//   glm::vec3 sheen = ltc::shade<ltc::sheen::charlie>(sheen_layer, light).specular;
//   float k = ltc::sheen::albedo_scaling(sheen_colour, cos_theta_v, sheen_roughness);
//   glm::vec3 colour = sheen + k * (base.specular + base.diffuse);   // base: any model's shade
//
// Conventions: surface::f0 carries the sheen colour and surface::roughness the sheen roughness
// (alpha = roughness^2); albedo 0 leaves the diffuse term 0. Degenerate cases: those of ltc::shade;
// albedo_scaling is in [0, 1] for any input (NaN colour or roughness read as 0).
#pragma once

#include <ltc/config.hpp>
#include <ltc/shading/charlie_fetch.hpp>
#include <ltc/shading/lobes.hpp>

#include <glm/glm.hpp>

LTC_NAMESPACE_BEGIN
namespace sheen {

/// The Charlie sheen as a model of ltc::shade: one LTC (lobes::one), from ltc::charlie::fetch.
/// shade<sheen::charlie>(s, light).specular = L s.f0 magnitude I_ltc (the fetch's fresnel is 0):
/// the spec's sheenColor * f_sheen integrated over the light, with s.f0 the sheen colour.
struct charlie {
    template <typename T>
    using coefficients = lobes::one<T>;
    template <typename T>
    static coefficients<T> fetch(T cos_theta_v, T roughness) {
        return {::ltc::charlie::fetch<T>(cos_theta_v, roughness)};
    }
};

/// KHR_materials_sheen's albedo scaling of the base layer in its simplified form ("Albedo-scaling
/// technique": the view term only, which the spec allows for direct and indirect light alike):
/// 1 - max(sheenColor.r, .g, .b) E(cos theta_v), E the directional albedo of the Charlie sheen
/// (charlie::fetch's magnitude), clamped to [0, 1] (E exceeds 1 at grazing views of the smoothest
/// sheens; colour channels outside [0, 1] or NaN are clamped, NaN read as 0).
template <typename T>
inline T albedo_scaling(const glm::vec<3, T>& sheen_colour, T cos_theta_v, T roughness) {
    T m = T(0);
    for (int i = 0; i < 3; ++i) m = sheen_colour[i] > m ? sheen_colour[i] : m;  // NaN: not taken
    m = m < T(1) ? m : T(1);
    const T k = T(1) - m * ::ltc::charlie::fetch<T>(cos_theta_v, roughness).magnitude;
    return k > T(0) ? (k < T(1) ? k : T(1)) : T(0);
}

}  // namespace sheen
LTC_NAMESPACE_END
