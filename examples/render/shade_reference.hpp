// render/shade_reference.hpp -- the Monte Carlo reference of one pixel (double): the same GGX BRDF
// with Schlick's Fresnel integrated without approximation (ltc::ground_truth::integrate for the
// polygonal lights, the diffuse term in closed form; ltc::textured_ground_truth::integrate of the
// texel-constant texture, textured_light::radiance, for the textured light), with the variance of
// its luminance. The method is described in main.cpp's file comment (reference.png).
#pragma once

#include "camera.hpp"
#include "common/colour.hpp"
#include "common/random.hpp"
#include "lights.hpp"
#include "math.hpp"
#include "scene.hpp"

#include <ltc/brdf/ggx.hpp>
#include <ltc/core/form_factor.hpp>
#include <ltc/core/polygon.hpp>
#include <ltc/reference/ground_truth.hpp>
#include <ltc/reference/textured_ground_truth.hpp>
#include <ltc/shading/shading_frame.hpp>

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace render {

/// The GGX model of ltc/brdf/ggx.hpp weighted by Schlick's (1 - V.H)^5: the integrand of the
/// LTC table's "fresnel" channel. Same sampling and density as GGX (the weight is in [0, 1]).
struct ggx_schlick_weight {
    using model = ltc::brdf::ggx<double>;
    static double eval(const dvec3& V, const dvec3& L, double alpha) {
        const double f = model::eval(V, L, alpha);
        if (!(f > 0)) return 0.0;
        const dvec3 H = glm::normalize(V + L);
        const double c = 1.0 - glm::clamp(glm::dot(V, H), 0.0, 1.0);
        const double c2 = c * c;
        return f * c2 * c2 * c;
    }
    static double pdf(const dvec3& V, const dvec3& L, double alpha) { return model::pdf(V, L, alpha); }
    static dvec3 sample(const dvec3& V, const glm::dvec2& u, double alpha) { return model::sample(V, u, alpha); }
};

struct reference_pixel {
    dvec3 radiance{0.0};  // the polygonal lights (and their emitters)
    double luminance_variance = 0.0;  // of the Monte Carlo estimate of the luminance
    dvec3 textured{0.0};  // the textured light (and its emitter)
    double textured_variance = 0.0;  // of the estimate of its luminance
};

/// The textured light's contribution to the reference (main.cpp's file comment): S + albedo D,
/// both Monte Carlo integrals of the texel-constant texture, and the variance of the luminance of that
/// sum. Each iteration is one call of the estimator with its own seed (so the luminance of every
/// iteration's RGB value is known and its variance exact).
inline void shade_reference_textured(const textured_light& t, const dvec3& P, const ltc::shading_frame<double>& frame,
                                     const dvec3& V, double alpha, const dvec3& F0, const dvec3& albedo,
                                     std::uint64_t seed_specular, std::uint64_t seed_diffuse, int spp,
                                     reference_pixel& out) {
    dvec3 q[4];
    for (int i = 0; i < 4; ++i) q[i] = frame.to_local(dvec3(t.quad[i]) - P);
    // One-sided: lit only where its front face is seen (the estimator is two-sided).
    const dvec3 rh_normal = glm::cross(q[1] - q[0], q[2] - q[0]);
    if (!(glm::dot(q[0], rh_normal) > 0) || spp <= 0) return;
    const dvec3 e1 = q[1] - q[0], e3 = q[3] - q[0];
    // L(u, v) times Schlick's Fresnel of the direction towards (u, v) on the quad.
    const auto specular_radiance = [&](double u, double v) {
        const dvec3 w = glm::normalize(q[0] + u * e1 + v * e3);
        const dvec3 h = V + w;
        const double hl = glm::length(h);
        const double c = hl > 0 ? 1.0 - glm::clamp(glm::dot(V, h) / hl, 0.0, 1.0) : 1.0;
        const double c2 = c * c;
        return dvec3(t.radiance(u, v)) * (F0 + (dvec3(1.0) - F0) * (c2 * c2 * c));
    };
    const auto diffuse_radiance = [&](double u, double v) { return dvec3(t.radiance(u, v)); };
    const ltc::textured_ground_truth::brdf_lobe<ltc::brdf::ggx<double>> ggx_lobe{V, alpha};
    const ltc::textured_ground_truth::ltc_lobe cosine_lobe{};  // M = I: max(0, z) / pi
    const bool diffuse = albedo.r > 0 || albedo.g > 0 || albedo.b > 0;
    ltc::textured_ground_truth::options opt;
    opt.samples = 1;
    dvec3 sum(0.0);
    double y_mean = 0, y_m2 = 0;  // Welford on the luminance of each iteration's value
    for (int i = 0; i < spp; ++i) {
        opt.seed = mix_seed(seed_specular, static_cast<std::uint64_t>(i));
        dvec3 value = ltc::textured_ground_truth::integrate(ggx_lobe, q, specular_radiance, opt, t.area_density.get()).mean;
        if (diffuse) {
            opt.seed = mix_seed(seed_diffuse, static_cast<std::uint64_t>(i));
            value += albedo *
                     ltc::textured_ground_truth::integrate(cosine_lobe, q, diffuse_radiance, opt, t.area_density.get()).mean;
        }
        sum += value;
        const double y = luminance(value), delta = y - y_mean;
        y_mean += delta / (i + 1);
        y_m2 += delta * (y - y_mean);
    }
    out.textured += sum / static_cast<double>(spp);
    if (spp > 1) out.textured_variance += y_m2 / (static_cast<double>(spp - 1) * spp);
}

/// Radiance of one pixel: the Monte Carlo reference (double).
inline reference_pixel shade_reference(const scene& s, const pixel_hit& hit, std::uint64_t pixel_seed, int spp) {
    reference_pixel out;
    if (hit.kind == pixel_hit::emitter_front) {
        out.radiance = dvec3(s.lights[static_cast<std::size_t>(hit.light)].radiance);
        return out;
    }
    if (hit.kind == pixel_hit::textured_front) {
        out.textured = dvec3(s.textured->radiance(hit.uv.x, hit.uv.y));
        return out;
    }
    if (hit.kind != pixel_hit::floor) return out;
    const material& m = s.materials[static_cast<std::size_t>(hit.material)];
    const dvec3 P(hit.p), N(0, 0, 1), F0(m.f0), albedo(m.albedo);
    const ltc::shading_frame<double> frame = ltc::make_shading_frame(N, dvec3(hit.v));
    const dvec3 V = frame.to_local(glm::normalize(dvec3(hit.v)));
    // alpha = roughness^2, the table's convention (the model clamps it to [alpha_min, alpha_max]
    // as the fit did).
    const double alpha = double(m.roughness) * double(m.roughness);
    std::vector<dvec3> local;
    for (std::size_t k = 0; k < s.lights.size(); ++k) {
        const light& l = s.lights[k];
        const std::size_t n = l.vertices.size();
        local.resize(n);
        for (std::size_t i = 0; i < n; ++i) local[i] = frame.to_local(dvec3(l.vertices[i]) - P);
        // One-sided light: lit only where its front face is seen (polygon.hpp's orientation);
        // the ground truth integrates over the set of directions, whatever the winding.
        const dvec3 rh_normal = glm::cross(local[1] - local[0], local[2] - local[0]);
        if (!(glm::dot(local[0], rh_normal) > 0)) continue;
        const dvec3 Le(l.radiance);
        // Diffuse: closed form (the LTC render computes the same exact integral).
        const double E = ltc::form_factor(local.data(), n, ltc::sidedness::one_sided);
        out.radiance += albedo * Le * E;
        // Specular: F0 A + (1 - F0) B, each a Monte Carlo integral with its own seed.
        ltc::ground_truth::options opt;
        opt.samples = static_cast<std::uint64_t>(spp);
        opt.seed = mix_seed(pixel_seed, 2 * k);
        const ltc::ground_truth::estimate A =
            ltc::ground_truth::integrate(ltc::brdf::ggx<double>{}, V, alpha, local.data(), n, opt);
        opt.seed = mix_seed(pixel_seed, 2 * k + 1);
        const ltc::ground_truth::estimate B =
            ltc::ground_truth::integrate(ggx_schlick_weight{}, V, alpha, local.data(), n, opt);
        out.radiance += Le * (F0 * A.mean + (dvec3(1.0) - F0) * B.mean);
        // Luminance = a A + b B + const; independent estimates: variances add.
        const double a = luminance(Le * F0), b = luminance(Le * (dvec3(1.0) - F0));
        const double sa = a * A.standard_error, sb = b * B.standard_error;
        out.luminance_variance += sa * sa + sb * sb;
    }
    if (s.textured) {
        const std::uint64_t k = 2 * s.lights.size();  // after the polygonal lights' seeds
        shade_reference_textured(*s.textured, P, frame, V, alpha, F0, albedo, mix_seed(pixel_seed, k),
                                 mix_seed(pixel_seed, k + 1), spp, out);
    }
    return out;
}

}  // namespace render
