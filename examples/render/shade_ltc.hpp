// render/shade_ltc.hpp -- the LTC render of one pixel (float, a renderer's path): the polygonal
// lights with ltc::shade_polygon_light (or a row of pixels at once with
// ltc::batch::shade_polygon_light; with --lobes 1 the _one_lobe functions, with --lobes 2 the
// _two_lobe ones), the textured light with ltc::shade_textured_quad_light
// (by default I_D I_L: the exact polygon integral times one fetch into the prefiltered texture,
// paper sections 5.2-5.4; or the cells of the texel-constant texture, --textured-method);
// specular and diffuse, Schlick's Fresnel through the table (Hill 2016).
#pragma once

#include "camera.hpp"
#include "lights.hpp"
#include "math.hpp"
#include "scene.hpp"

#include <ltc/shading/batch_shading.hpp>
#include <ltc/shading/batch_two_lobe.hpp>
#include <ltc/shading/cosine_lobe_polygon_light.hpp>
#include <ltc/shading/polygon_light.hpp>
#include <ltc/shading/textured_light.hpp>
#include <ltc/shading/two_lobe_polygon_light.hpp>

#include <cstddef>
#include <vector>

namespace render {

/// One polygonal light at a floor point by LTC with the table of --lobes: 3, the default table of
/// an LTC and the cosine (--lobes cosine: ltc::shade_polygon_light), 1, the one-lobe table
/// (ltc::shade_polygon_light_one_lobe), or 2, the two-lobe table (ltc::shade_polygon_light_two_lobe),
/// all taking the same arguments.
inline ltc::polygon_light_result<float> shade_ltc_light(const light& l, const material& m, const pixel_hit& hit,
                                                        int lobes) {
    const auto shade_with = [&](const auto& shading_function) {
        return shading_function(hit.p, vec3(0, 0, 1), hit.v, m.roughness, m.f0, m.albedo, l.radiance,
                                l.vertices.data(), l.vertices.size(), ltc::sidedness::one_sided);
    };
    // The two are overload sets of templates: each wrapped in a lambda to be passed as a value.
    if (lobes == 1) return shade_with([](const auto&... a) { return ltc::shade_polygon_light_one_lobe(a...); });
    return lobes == 2 ? shade_with([](const auto&... a) { return ltc::shade_polygon_light_two_lobe(a...); })
                      : shade_with([](const auto&... a) { return ltc::shade_polygon_light(a...); });
}

/// Radiance of one pixel from the polygonal lights (and their emitters): LTC with the table of
/// --lobes (float, the renderer's path).
inline vec3 shade_ltc(const scene& s, const pixel_hit& hit, int lobes = 3) {
    if (hit.kind == pixel_hit::emitter_front) return s.lights[static_cast<std::size_t>(hit.light)].radiance;
    if (hit.kind != pixel_hit::floor) return vec3(0.0f);
    const material& m = s.materials[static_cast<std::size_t>(hit.material)];
    vec3 sum(0.0f);
    for (const light& l : s.lights) {
        const ltc::polygon_light_result<float> r = shade_ltc_light(l, m, hit, lobes);
        sum += r.specular + r.diffuse;
    }
    return sum;
}

/// shade_ltc over count pixels at once, the way a renderer's pass over its G-buffer would: the
/// floor pixels gathered into structures of arrays, then each light over all of them with
/// ltc::batch::shade_polygon_light (one pixel per SIMD lane, the same values up to rounding), or
/// with --lobes 1 or 2 its _one_lobe or _two_lobe variant.
inline void shade_ltc_batch(const scene& s, const pixel_hit* hits, std::size_t count, vec3* out, int lobes = 3) {
    std::vector<float> in[16];  // px py pz nx ny nz vx vy vz roughness f0 rgb albedo rgb
    std::vector<std::size_t> where;
    for (std::size_t i = 0; i < count; ++i) {
        const pixel_hit& h = hits[i];
        if (h.kind != pixel_hit::floor) {
            out[i] = shade_ltc(s, h, lobes);
            continue;
        }
        const material& m = s.materials[static_cast<std::size_t>(h.material)];
        const float v[16] = {h.p.x, h.p.y, h.p.z, 0, 0, 1, h.v.x, h.v.y, h.v.z, m.roughness,
                             m.f0.x, m.f0.y, m.f0.z, m.albedo.x, m.albedo.y, m.albedo.z};
        for (int k = 0; k < 16; ++k) in[k].push_back(v[k]);
        where.push_back(i);
    }
    const std::size_t n = where.size();
    const float* columns[16];
    for (int k = 0; k < 16; ++k) columns[k] = in[k].data();
    const auto points = ltc::batch::shading_points<float>::from_columns(columns);
    std::vector<float> result[6];
    ltc::batch::shading_results<float> res;
    for (int c = 0; c < 3; ++c) {
        result[c].resize(n), result[3 + c].resize(n);
        res.specular[c] = result[c].data(), res.diffuse[c] = result[3 + c].data();
    }
    std::vector<vec3> sum(n, vec3(0.0f));
    for (const light& l : s.lights) {
        const auto side = ltc::sidedness::one_sided;
        if (lobes == 1)
            ltc::batch::shade_polygon_light_one_lobe(points, l.radiance, l.vertices.data(), l.vertices.size(), side, res, n);
        else if (lobes == 2)
            ltc::batch::shade_polygon_light_two_lobe(points, l.radiance, l.vertices.data(), l.vertices.size(), side, res, n);
        else
            ltc::batch::shade_polygon_light(points, l.radiance, l.vertices.data(), l.vertices.size(), side, res, n);
        for (std::size_t j = 0; j < n; ++j)
            for (int c = 0; c < 3; ++c) sum[j][c] += result[c][j] + result[3 + c][j];
    }
    for (std::size_t j = 0; j < n; ++j) out[where[j]] = sum[j];
}

/// Radiance of one pixel from the textured light (and its emitter): LTC by the policy's method
/// (float; the default policy is the paper's I_D I_L).
inline vec3 shade_ltc_textured(const scene& s, const pixel_hit& hit, const ltc::textured_policy& policy = {}) {
    const textured_light* t = s.textured.get();
    if (t == nullptr) return vec3(0.0f);
    if (hit.kind == pixel_hit::textured_front) return t->radiance(hit.uv.x, hit.uv.y);
    if (hit.kind != pixel_hit::floor) return vec3(0.0f);
    const material& m = s.materials[static_cast<std::size_t>(hit.material)];
    const ltc::textured_light_result<float> r = ltc::shade_textured_quad_light(
        hit.p, vec3(0, 0, 1), hit.v, m.roughness, m.f0, m.albedo, t->quad, *t->prefiltered, ltc::sidedness::one_sided,
        policy);
    return r.specular + r.diffuse;
}

}  // namespace render
