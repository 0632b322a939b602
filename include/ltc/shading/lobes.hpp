// ltc/shading/lobes.hpp -- how a material model's lobes form the specular and diffuse terms of
// ltc::shade (ltc/shading/shade.hpp), for any light.
//
// A model's table gives, at (cos theta_v, roughness), one of three lobe sets, typed so that one
// cannot stand for another:
//   lobes::one<T>             one LTC (the paper's single lobe, section 4)
//   lobes::ltc_and_cosine<T>  an LTC plus the clamped cosine about the normal, whose integral is
//                             the form factor the diffuse term needs anyway (one LTC integral)
//   lobes::two<T>             two LTCs (two LTC integrals)
// and each is shaded (Hill and Heitz 2016's Fresnel split for every lobe; shade_lobes) as
//
//   specular = sum over lobes  L (F0 magnitude + (1 - F0) fresnel) I_lobe
//   diffuse  = L albedo E                                     (Lambert: E = int cos / pi)
//
// I_lobe: the lobe's integral (eq. 3 through M^-1), E the cosine's (eq. 11), facing applied.
#pragma once

#include <ltc/config.hpp>
#include <ltc/shading/shading_frame.hpp>
#include <ltc/shading/surface.hpp>
#include <ltc/tables/ltc_table.hpp>

#include <glm/glm.hpp>

LTC_NAMESPACE_BEGIN
namespace lobes {

template <typename T>
struct one {
    ltc_coefficients<T> ltc;
};

template <typename T>
struct ltc_and_cosine {
    ltc_coefficients<T> ltc;
    ltc_coefficients<T> cosine;  ///< its magnitude and fresnel; m_inv unused (the identity)
};

template <typename T>
struct two {
    ltc_coefficients<T> first;
    ltc_coefficients<T> second;
};

}  // namespace lobes

/// A shading point in its frame: what shade_lobes needs of a surface once the table is read.
template <typename T>
struct shading_point {
    shading_frame<T> frame;
    glm::vec<3, T> position{T(0)};
    glm::vec<3, T> f0{T(0)};
    glm::vec<3, T> albedo{T(0)};
};

namespace detail {
/// One LTC's specular term and the diffuse term: shade_lobes of lobes::one, the first lobe of lobes::two.
template <typename Policy, typename T, typename Light>
LTC_HOST_DEVICE inline shading_result<T> shade_ltc(const shading_point<T>& p, const ltc_coefficients<T>& c, const Light& light,
                                                   const shade_options& o) {
    const auto I = light.template integrals<Policy>(p.frame, p.position, c.m_inv, o);
    shading_result<T> r;
    r.specular = light.emitted(brdf_scale(p.f0, c), I.ltc);
    r.diffuse = light.emitted(p.albedo, I.form_factor);
    return r;
}
}  // namespace detail

/// The shading of a lobe set (one overload per set): the specular and diffuse terms of the file's
/// first comment, with I_lobe the lobe's integral over the light (eq. 3 through the LTC's M^-1)
/// and E the clamped cosine's (eq. 11), both with the light's facing applied, and L the light's
/// radiance.
///
/// The light interface. A light type (ltc/shading/lights/) provides, in the shading frame at P:
///   integrals<Policy>(frame, P, m_inv, options)  -> {form_factor, ltc}: E and the LTC integral
///   ltc_integral<Policy>(frame, P, m_inv, options) -> the LTC integral alone (a further lobe)
///   emitted(scale, integral)                      -> the radiance that scale x integral stands for
/// (constant lights: radiance * scale * integral; textured ones integrate the colour themselves).
/// Policy is the edge_policy of the polygon integrals (ltc/core/edge_policy.hpp).
template <typename Policy, typename T, typename Light>
LTC_HOST_DEVICE inline shading_result<T> shade_lobes(const shading_point<T>& p, const lobes::one<T>& c, const Light& light,
                                     const shade_options& o) {
    return detail::shade_ltc<Policy>(p, c.ltc, light, o);
}

template <typename Policy, typename T, typename Light>
LTC_HOST_DEVICE inline shading_result<T> shade_lobes(const shading_point<T>& p, const lobes::ltc_and_cosine<T>& c, const Light& light,
                                     const shade_options& o) {
    const auto I = light.template integrals<Policy>(p.frame, p.position, c.ltc.m_inv, o);
    shading_result<T> r;
    r.specular = light.emitted(brdf_scale(p.f0, c.ltc), I.ltc);
    r.diffuse = light.emitted(p.albedo, I.form_factor);
    r.specular += light.emitted(brdf_scale(p.f0, c.cosine), I.form_factor);
    return r;
}

template <typename Policy, typename T, typename Light>
LTC_HOST_DEVICE inline shading_result<T> shade_lobes(const shading_point<T>& p, const lobes::two<T>& c, const Light& light,
                                     const shade_options& o) {
    shading_result<T> r = detail::shade_ltc<Policy>(p, c.first, light, o);
    const auto second = light.template ltc_integral<Policy>(p.frame, p.position, c.second.m_inv, o);
    r.specular += light.emitted(brdf_scale(p.f0, c.second), second);
    return r;
}

LTC_NAMESPACE_END
