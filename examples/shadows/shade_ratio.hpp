// shadows/shade_ratio.hpp -- the methods' names, and the pixels of every method: (a), (a+), (b)
// and (d) (before its filter: denoise.hpp) here, (c) and (e) in shade_mis.hpp. (a), (a+) and (b):
// ltc::shade_shadowed<Model> (ltc/shading/shade_shadowed.hpp), the ratio estimator
// of Heitz, Hill and McGuire 2018: the analytic, unshadowed LTC shading times the ratio of two
// Monte Carlo estimates over the same K samples, of the shadowed and of the unshadowed integrand,
// per term (specular, diffuse); (d) keeps (a)'s estimates for its filter (each term's two sums
// and analytic value, and the specular term's for Schlick's part; with --filter-radius penumbra,
// its occluded samples' blocker distances: the result's `blockers`, from an ltc::first_hit callback).
//   (a)  the library's default plan: K samples in all, one shadow ray each, split between the LTC
//        lobe restricted to the polygon (specular share) and the light's area (diffuse share; the
//        exact cosine sampler, ltc::diffuse_sampler::cosine, costs ~8x more per sample) in
//        proportion to the specular and diffuse shares of the analytic result, combined by the
//        balance heuristic over the whole plan (every sample serves both terms): up to K rays.
//   (a+) (a) with an early stop: first K0 = min(K, adaptive_first) samples; where both terms'
//        ratios are exactly 0 or 1 (all samples agreed: umbra or fully lit), that result; else K
//        more with another rotation, and the two ratios averaged with weights K0 and K: up to
//        K0 + K rays (main.cpp's file comment: why the average, and the early stop's bias).
//   (b)  K points uniform over the light's area, shared by both terms: up to K rays.
// All on a rank-1 lattice shifted by a per-pixel rotation (Cranley-Patterson), so that the
// lattice's structured error becomes noise: by default screen-ordered (ltc::screen_point with
// shadow_sampling::stratified_rotation: neighbouring pixels' lattices stratified together;
// screen_order.hpp; (a+)'s second call random), with --pixel-points random independent per pixel.
// Visibility: Embree shadow rays (tracer::light_visible, the offsets of tracer.hpp); for (d) with
// --filter-radius penumbra, closest-hit queries that also give each occluded ray's blocker
// (tracer::first_occluder, wrapped in ltc::first_hit). The light is the scene's quad as an
// ltc::polygon_light, one-sided towards its front, built once per image (ltc_light).
#pragma once

#include "camera.hpp"
#include "scene.hpp"
#include "screen_order.hpp"
#include "shade_mis.hpp"  // shaded_pixel, uniform_float
#include "tracer.hpp"

#include <ltc/reference/splitmix64.hpp>
#include <ltc/shading/ggx_models.hpp>
#include <ltc/shading/lights/polygon_light.hpp>
#include <ltc/shading/shade_shadowed.hpp>
#include <ltc/shading/surface.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace shadows {

// The values seed the renders; (d) and (e) draw (a)'s and (c)'s random numbers (measure.hpp; (c)'s
// points are never screen-ordered).
enum class method { ratio_ltc, ratio_area, mis, ratio_ltc_adaptive, ratio_ltc_denoised, mis_denoised };

/// (d) and (e): a method whose pixels are filtered after shading (denoise.hpp).
inline bool denoised(method m) { return m == method::ratio_ltc_denoised || m == method::mis_denoised; }

inline const char* method_name(method m) {
    switch (m) {
        case method::ratio_ltc: return "ratio_ltc";
        case method::ratio_ltc_adaptive: return "ratio_ltc_adaptive";
        case method::ratio_area: return "ratio_area";
        case method::ratio_ltc_denoised: return "ratio_ltc_denoised";
        case method::mis_denoised: return "mis_denoised";
        default: return "mis";
    }
}

/// The tables' short names: (a), (a+), (b), (c).
inline const char* method_label(method m) {
    switch (m) {
        case method::ratio_ltc: return "(a)";
        case method::ratio_ltc_adaptive: return "(a+)";
        case method::ratio_area: return "(b)";
        case method::ratio_ltc_denoised: return "(d)";
        case method::mis_denoised: return "(e)";
        default: return "(c)";
    }
}

constexpr int adaptive_first = 4;  // (a+)'s K0 (at most K)

/// The library's light for the scene's quad, emitting towards its front: built once and shared by
/// every pixel; it refers to s.light_vertices (the scene must outlive it).
inline ltc::polygon_light<float> ltc_light(const scene& s) {
    return ltc::polygon_light<float>::one_sided(s.light_vertices, 4, s.light_front, s.light_radiance);
}

/// The material model of the ratio methods' analytic part (--lobes): ltc::ggx::one_lobe,
/// ltc::ggx::two_lobes or ltc::ggx::ltc_and_cosine.
enum class analytic_model { one_lobe, two_lobes, ltc_and_cosine };

/// One call of the library at the pixel: K samples by `sampler`, the lattice rotated at random or,
/// given screen-ordered points, by the pixel's point of stream 0 with stratified_rotation (the
/// neighbours' lattices stratified together: ltc/shading/shade_shadowed.hpp), the analytic part
/// by `model`; `light`: ltc_light(s).
inline ltc::shadowed_polygon_light_result<float> shade_shadowed_at(const scene& s,
                                                                  const ltc::polygon_light<float>& light,
                                                                  const tracer& tr, const pixel_hit& h,
                                                                  ltc::shadow_sampler sampler, int K, analytic_model model,
                                                                  ltc::ground_truth::splitmix64& rng,
                                                                  const pixel_points* points = nullptr,
                                                                  bool record_blockers = false) {
    const material& m = s.materials[static_cast<std::size_t>(h.material)];
    ltc::shadow_sampling<float> options;
    options.samples = static_cast<std::size_t>(K);
    const float rx = uniform_float(rng), ry = uniform_float(rng);
    options.rotation = glm::vec2(rx, ry);
    if (points != nullptr && points->screen) {
        options.rotation = points->at(0);
        options.stratified_rotation = true;
    }
    options.sampler = sampler;
    const vec3 N = h.n;
    const ltc::surface<float> surface{h.p, h.n, h.v, m.roughness, m.f0, m.albedo};
    const auto shade_with = [&](const auto& callback) {
        switch (model) {
            case analytic_model::two_lobes:
                return ltc::shade_shadowed<ltc::ggx::two_lobes>(surface, light, callback, options);
            case analytic_model::ltc_and_cosine:
                return ltc::shade_shadowed<ltc::ggx::ltc_and_cosine>(surface, light, callback, options);
            default:
                return ltc::shade_shadowed<ltc::ggx::one_lobe>(surface, light, callback, options);
        }
    };
    // Recording blockers: a first-hit callback (ltc::first_hit: one closest-hit query per ray instead
    // of an any-hit one), whose distances the library sums into the result's `blockers`.
    if (record_blockers)
        return shade_with(ltc::first_hit([&tr, N](const vec3& origin, const vec3& unit_direction, float distance) {
            return tr.first_occluder(origin, N, unit_direction, distance);
        }));
    return shade_with([&tr, N](const vec3& origin, const vec3& unit_direction, float distance) {
        return tr.light_visible(origin, N, unit_direction, distance);
    });
}

/// Whether a term's ratio is exactly 0 or 1: its result is 0 or the unshadowed one. (A ratio
/// within a float's rounding of 1, where an occluded sample's weight is below 2^-24 of the
/// others', passes too: its difference from 1 is below the result's own rounding.)
inline bool agreed(const glm::vec3& ratio, const glm::vec3& unshadowed) {
    return ratio == glm::vec3(0.0f) || ratio == unshadowed;
}

/// Radiance towards the camera at one pixel by (a), (a+) or (b) with K = spp samples.
inline shaded_pixel shade_ratio(const scene& s, const ltc::polygon_light<float>& light, const tracer& tr,
                                const pixel_hit& h, method which, int spp, std::uint64_t seed, analytic_model lobes,
                                const pixel_points& points, bool record_blockers = false) {
    shaded_pixel out;
    if (h.kind == pixel_hit::emitter_front) out.radiance = dvec3(s.light_radiance);
    if (!h.shaded() || spp <= 0) return out;
    ltc::ground_truth::splitmix64 rng(seed);
    const auto sampler = which == method::ratio_area ? ltc::shadow_sampler::light_area : ltc::shadow_sampler::ltc_polygon;
    const int first = which == method::ratio_ltc_adaptive ? std::min(spp, adaptive_first) : spp;
    const ltc::shadowed_polygon_light_result<float> r =
        shade_shadowed_at(s, light, tr, h, sampler, first, lobes, rng, &points, record_blockers);
    out.radiance = dvec3(r.ratio.specular + r.ratio.diffuse);
    out.rays = r.rays;
    out.analytic = {dvec3(r.unshadowed.specular), dvec3(r.unshadowed.diffuse)};
    const auto to_double = [](const ltc::ratio_estimates<float>& e) {
        return ltc::ratio_estimates<double>{e.visible, e.total, e.analytic};
    };
    out.specular_estimates = to_double(r.specular_estimates);
    out.specular_fresnel_estimates = to_double(r.specular_fresnel_estimates);
    out.diffuse_estimates = to_double(r.diffuse_estimates);
    out.blockers = {r.blockers.ratio_sum, r.blockers.occluded};
    if (which != method::ratio_ltc_adaptive || (agreed(r.ratio.specular, r.unshadowed.specular) &&
                                                agreed(r.ratio.diffuse, r.unshadowed.diffuse)))
        return out;
    const ltc::shadowed_polygon_light_result<float> more = shade_shadowed_at(s, light, tr, h, sampler, spp, lobes, rng);
    const double w = static_cast<double>(first) / static_cast<double>(first + spp);
    out.radiance = w * out.radiance + (1.0 - w) * dvec3(more.ratio.specular + more.ratio.diffuse);
    out.rays += more.rays;
    return out;
}

/// One pixel by any method, before (d)'s and (e)'s filter: K = spp samples for (a), (a+), (b) and
/// (d), spp MIS iterations (one BRDF and one light sample each) for (c) and (e); `light`:
/// ltc_light(s), for the ratio methods.
inline shaded_pixel shade(const scene& s, const ltc::polygon_light<float>& light, const tracer& tr, const pixel_hit& h,
                          method which, int spp, std::uint64_t seed, analytic_model lobes, const pixel_points& points,
                          bool record_blockers = false) {
    if (which == method::mis || which == method::mis_denoised) return shade_mis(s, tr, h, spp, seed, points);
    return shade_ratio(s, light, tr, h, which == method::ratio_ltc_denoised ? method::ratio_ltc : which, spp, seed,
                       lobes, points, record_blockers && which == method::ratio_ltc_denoised);
}

}  // namespace shadows
