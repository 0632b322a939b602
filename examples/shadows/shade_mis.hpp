// shadows/shade_mis.hpp -- method (c) and the reference: plain Monte Carlo of the direct light at a
// shading point with multiple importance sampling. Each iteration draws one direction from the
// BRDF and one point on the light (uniform in area), weights each by the balance heuristic
// f / (p_brdf + p_light) and casts one ray for each through Embree (tracer.hpp): the light sample
// a shadow ray to the point (rtcOccluded1), the BRDF sample a closest-hit ray that counts if the
// first thing it meets is the light's front. The BRDF is the one the LTC shading approximates
// (render/shade_reference.hpp): GGX (ltc::brdf::ggx<float>, alpha = roughness^2, height-
// correlated masking) times Schlick's F0 + (1 - F0)(1 - V.H)^5, plus Lambert albedo / pi. The
// BRDF technique picks GGX's visible normals or, with probability 1/2 where albedo > 0, the
// cosine (GGX alone would leave the rough diffuse term to the light samples only). Independent
// uniform random numbers (SplitMix64), seeded per pixel, or with screen-ordered points
// (screen_order.hpp) each iteration's light point, lobe choice and lobe point from their own
// streams of them.
#pragma once

#include "camera.hpp"
#include "common/colour.hpp"
#include "common/random.hpp"
#include "scene.hpp"
#include "screen_order.hpp"
#include "tracer.hpp"

#include <ltc/brdf/ggx.hpp>
#include <ltc/reference/splitmix64.hpp>
#include <ltc/shading/shading_frame.hpp>
#include <ltc/shading/shade_shadowed.hpp>  // ratio_estimates, blocker_estimates
#include <ltc/shading/surface.hpp>         // shading_result

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace shadows {

using ltc_examples::mix_seed;  // independent seeds per run, pixel and iteration

/// Uniform float in [0, 1): the top 24 bits (a double rounded to float could give 1).
inline float uniform_float(ltc::ground_truth::splitmix64& rng) {
    return static_cast<float>(rng.next() >> 40) * 0x1.0p-24f;
}

struct shaded_pixel {
    dvec3 radiance{0.0};
    double luminance_variance = 0;  // of the estimate (the mean over the iterations)
    std::size_t rays = 0;           // visibility queries made
    // The ratio methods' analytic terms and their estimates (each term's two sums and analytic
    // value; the specular term's also for Schlick's part), of the first call for (a+) (read by
    // (d)'s filter only: denoise.hpp).
    ltc::shading_result<double> analytic;
    ltc::ratio_estimates<double> specular_estimates, diffuse_estimates, specular_fresnel_estimates;
    // (d) with --filter-radius penumbra: its occluded samples' blockers, the library's sums of
    // t_b / (t_l - t_b) and their count (denoise.hpp's penumbra_radii).
    ltc::blocker_estimates<double> blockers;
};

/// Radiance towards the camera at one pixel by `iterations` MIS iterations (file comment).
inline shaded_pixel shade_mis(const scene& s, const tracer& tr, const pixel_hit& h, int iterations,
                              std::uint64_t seed, const pixel_points& points) {
    using ggx = ltc::brdf::ggx<float>;
    shaded_pixel out;
    if (h.kind == pixel_hit::emitter_front) out.radiance = dvec3(s.light_radiance);
    if (!h.shaded() || iterations <= 0) return out;
    const material& m = s.materials[static_cast<std::size_t>(h.material)];
    const ltc::shading_frame<float> frame = ltc::make_shading_frame(h.n, h.v);
    const vec3 V = frame.to_local(h.v);
    const float alpha = m.roughness * m.roughness;
    const float inv_pi = static_cast<float>(1.0 / ltc_examples::pi);
    const float p_ggx = m.albedo == vec3(0.0f) ? 1.0f : 0.5f;  // BRDF technique: lobe choice
    const vec3 O = h.p + surface_offset * h.n;  // every ray's origin (tracer.hpp)
    const vec3 q0 = s.light_vertices[0], e1 = s.light_vertices[1] - q0, e3 = s.light_vertices[3] - q0;
    const float area = s.light_area();

    const auto brdf_cos = [&](const vec3& L) {  // f(V, L) cos theta_L, RGB
        if (!(L.z > 0)) return vec3(0.0f);
        const vec3 H = glm::normalize(V + L);
        const float c = 1.0f - glm::clamp(glm::dot(V, H), 0.0f, 1.0f), c2 = c * c;
        return ggx::eval(V, L, alpha) * (m.f0 + (vec3(1.0f) - m.f0) * (c2 * c2 * c)) + m.albedo * (L.z * inv_pi);
    };
    const auto brdf_pdf = [&](const vec3& L) {
        return p_ggx * ggx::pdf(V, L, alpha) + (1.0f - p_ggx) * glm::max(L.z, 0.0f) * inv_pi;
    };
    const auto light_pdf = [&](const vec3& w, float distance) {  // per steradian; 0 from behind
        const float cos_l = -glm::dot(w, s.light_front);
        return cos_l > 0 ? distance * distance / (area * cos_l) : 0.0f;
    };

    ltc::ground_truth::splitmix64 rng(seed);
    dvec3 sum(0.0);
    double y_mean = 0, y_m2 = 0;  // Welford on the luminance of each iteration's value
    for (int i = 0; i < iterations; ++i) {
        vec3 value(0.0f);
        // Light sample: a uniform point on the quad.
        float u = uniform_float(rng), v = uniform_float(rng);
        if (points.screen) {  // iteration i's three streams: the light's point, the lobe's choice, the lobe's point
            const glm::vec2 p = points.at(3 * static_cast<std::uint64_t>(i) + 1);
            u = p.x, v = p.y;
        }
        const vec3 to_light = q0 + u * e1 + v * e3 - O;
        const float distance = glm::length(to_light);
        const vec3 w = to_light / distance;
        const vec3 f = brdf_cos(frame.to_local(w));
        const float pl = light_pdf(w, distance);
        if (pl > 0 && f != vec3(0.0f)) {
            ++out.rays;
            if (tr.unoccluded(O, w, distance - light_margin))
                value += s.light_radiance * f / (pl + brdf_pdf(frame.to_local(w)));
        }
        // BRDF sample.
        float pick = uniform_float(rng), a = uniform_float(rng), b = uniform_float(rng);
        if (points.screen) {
            const glm::vec2 p = points.at(3 * static_cast<std::uint64_t>(i) + 3);
            pick = points.at(3 * static_cast<std::uint64_t>(i) + 2).x, a = p.x, b = p.y;
        }
        vec3 L;
        if (pick < p_ggx) {
            L = ggx::sample(V, glm::vec2(a, b), alpha);
        } else {  // cosine: Malley's method
            const float r = std::sqrt(a), phi = 2.0f * static_cast<float>(ltc_examples::pi) * b;
            L = vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(glm::max(0.0f, 1.0f - a)));
        }
        if (L.z > 0) {
            const vec3 wb = L.x * frame.t1 + L.y * frame.t2 + L.z * frame.n;
            ++out.rays;
            const ray_hit hit = tr.intersect(O, wb);
            const float pl_b = hit.kind == ray_hit::light ? light_pdf(wb, hit.t) : 0.0f;
            if (pl_b > 0) value += s.light_radiance * brdf_cos(L) / (pl_b + brdf_pdf(L));
        }
        const dvec3 dv(value);
        sum += dv;
        const double y = ltc_examples::luminance(dv), delta = y - y_mean;
        y_mean += delta / (i + 1);
        y_m2 += delta * (y - y_mean);
    }
    out.radiance = sum / static_cast<double>(iterations);
    if (iterations > 1) out.luminance_variance = y_m2 / (static_cast<double>(iterations - 1) * iterations);
    return out;
}

}  // namespace shadows
