// brushed/shade.hpp -- one floor pixel, both ways, with F0 = 1 (no Fresnel: the quantity both
// sides compute exactly alike): the LTC's L * magnitude * I and the Monte Carlo L * int rho cos dL.
#pragma once

#include "scene.hpp"

#include <ltc/brdf/ggx_anisotropic.hpp>
#include <ltc/ltc.hpp>
#include <ltc/reference/ground_truth.hpp>
#include <ltc/shading/ggx_anisotropic_model.hpp>

#include <glm/glm.hpp>

#include <cstdint>

namespace brushed {

/// ltc::shade<Model> of the quad light at a floor point, F0 = 1 and albedo 0: the specular
/// radiance L * magnitude * I (paper eq. 3 through the fitted M^-1), one channel of it.
template <typename Model>
double shade_ltc(const pixel_hit& h, const material& m, const quad_light& light) {
    const ltc::surface<float> s{h.p, vec3(0, 0, 1), h.v, m.roughness, vec3(1.0f), vec3(0.0f), tangent,
                                m.roughness_bitangent};
    const auto quad = ltc::polygon_light<float>::one_sided(light.vertices, 4, light.normal, vec3(light.radiance));
    return double(ltc::shade<Model>(s, quad).specular.x);
}

struct reference_value {
    double radiance = 0, standard_error = 0;
};

/// The reference: L times the Monte Carlo integral of rho(V, L) cos theta_L over the quad
/// (ltc::ground_truth::integrate: BRDF sampling of visible normals and uniform spherical-polygon
/// sampling, balance heuristic) in the frame the model uses (make_tangent_frame: N = +z, tangent
/// = +x); 0 where the point sees the back of the one-sided light (the estimator is two-sided).
inline reference_value shade_reference(const pixel_hit& h, const material& m, const quad_light& light, int samples,
                                       std::uint64_t seed) {
    const dvec3 P(h.p);
    if (!light.faces(P)) return {};
    const ltc::shading_frame<double> f = ltc::make_tangent_frame(dvec3(0, 0, 1), dvec3(h.v), dvec3(tangent));
    dvec3 local[4];
    for (int i = 0; i < 4; ++i) local[i] = f.to_local(dvec3(light.vertices[i]) - P);
    const double ax = double(m.roughness) * m.roughness, ay = double(m.roughness_bitangent) * m.roughness_bitangent;
    ltc::ground_truth::options opt;
    opt.samples = static_cast<std::uint64_t>(samples);
    opt.seed = seed;
    const ltc::ground_truth::estimate e =
        ltc::ground_truth::integrate(ltc::brdf::ggx_anisotropic<double>{}, f.to_local(glm::normalize(dvec3(h.v))),
                                     ltc::brdf::anisotropic_alpha<double>{ax, ay}, local, 4, opt);
    return {light.radiance * e.mean, light.radiance * e.standard_error};
}

}  // namespace brushed
