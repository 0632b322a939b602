// render/shade_ltc.hpp -- the LTC render of one pixel (float, a renderer's path): each polygonal
// light as an ltc::polygon_light, one-sided towards its front, built once for the whole render
// (ltc_lights) and shaded by ltc::shade<Model> (or a row of pixels at once by
// ltc::batch::shade<Model>), with the model --lobes names (1: ltc::ggx::one_lobe, the paper's
// single LTC; 2: ltc::ggx::two_lobes, two LTCs; cosine or 3: ltc::ggx::ltc_and_cosine, an LTC and
// the cosine, the default); the textured light as an ltc::textured_quad_light, built once per
// method (ltc_textured_light), shaded by ltc::shade<ltc::ggx::one_lobe> (by default I_D I_L: the
// exact polygon integral times one fetch into the prefiltered texture, paper sections 5.2-5.4; or
// the cells of the texel-constant texture, --textured-method). Specular and diffuse, Schlick's
// Fresnel through the table (Hill 2016).
#pragma once

#include "camera.hpp"
#include "lights.hpp"
#include "math.hpp"
#include "scene.hpp"

#include <ltc/ltc.hpp>

#include <cstddef>
#include <vector>

namespace render {

/// The library's lights for the scene's polygonal lights, in the order of scene::lights, built
/// once: each refers to its light's vertices (the scene must outlive them) and emits towards its
/// front.
inline std::vector<ltc::polygon_light<float>> ltc_lights(const scene& s) {
    std::vector<ltc::polygon_light<float>> lights;
    for (const light& l : s.lights)
        lights.push_back(
            ltc::polygon_light<float>::one_sided(l.vertices.data(), l.vertices.size(), l.front, l.radiance));
    return lights;
}

/// Calls f with the model --lobes names (a value of its type).
template <typename F>
inline auto with_model(int lobes, F&& f) {
    if (lobes == 1) return f(ltc::ggx::one_lobe{});
    if (lobes == 2) return f(ltc::ggx::two_lobes{});
    return f(ltc::ggx::ltc_and_cosine{});
}

/// Radiance of one pixel from the polygonal lights (and their emitters): LTC with the model of
/// --lobes (float, the renderer's path); `lights`: ltc_lights(s).
inline vec3 shade_ltc(const scene& s, const std::vector<ltc::polygon_light<float>>& lights, const pixel_hit& hit,
                      int lobes = 3) {
    if (hit.kind == pixel_hit::emitter_front) return s.lights[static_cast<std::size_t>(hit.light)].radiance;
    if (hit.kind != pixel_hit::floor) return vec3(0.0f);
    const material& m = s.materials[static_cast<std::size_t>(hit.material)];
    const ltc::surface<float> point{hit.p, vec3(0, 0, 1), hit.v, m.roughness, m.f0, m.albedo};
    return with_model(lobes, [&](auto model) {
        vec3 sum(0.0f);
        for (const ltc::polygon_light<float>& l : lights) {
            const ltc::shading_result<float> r = ltc::shade<decltype(model)>(point, l);
            sum += r.specular + r.diffuse;
        }
        return sum;
    });
}

/// shade_ltc over count pixels at once, the way a renderer's pass over its G-buffer would: the
/// floor pixels gathered into structures of arrays (the normal uniform), then each light over all
/// of them with ltc::batch::shade<Model> (one pixel per SIMD lane, the same values up to rounding).
inline void shade_ltc_batch(const scene& s, const std::vector<ltc::polygon_light<float>>& lights, const pixel_hit* hits,
                            std::size_t count, vec3* out, int lobes = 3) {
    std::vector<float> in[13];  // px py pz vx vy vz roughness f0 rgb albedo rgb
    std::vector<std::size_t> where;
    for (std::size_t i = 0; i < count; ++i) {
        const pixel_hit& h = hits[i];
        if (h.kind != pixel_hit::floor) {
            out[i] = shade_ltc(s, lights, h, lobes);
            continue;
        }
        const material& m = s.materials[static_cast<std::size_t>(h.material)];
        const float v[13] = {h.p.x, h.p.y, h.p.z, h.v.x, h.v.y, h.v.z, m.roughness,
                             m.f0.x, m.f0.y, m.f0.z, m.albedo.x, m.albedo.y, m.albedo.z};
        for (int k = 0; k < 13; ++k) in[k].push_back(v[k]);
        where.push_back(i);
    }
    const std::size_t n = where.size();
    ltc::batch::surfaces<float> points;
    points.count = n;
    points.position = {in[0].data(), in[1].data(), in[2].data()};
    points.normal = ltc::batch::uniform(vec3(0, 0, 1));
    points.view = {in[3].data(), in[4].data(), in[5].data()};
    points.roughness = in[6].data();
    points.f0 = {in[7].data(), in[8].data(), in[9].data()};
    points.albedo = {in[10].data(), in[11].data(), in[12].data()};
    std::vector<float> result[6];
    ltc::batch::shading_results<float> res;
    for (int c = 0; c < 3; ++c) {
        result[c].resize(n), result[3 + c].resize(n);
        res.specular[c] = result[c].data(), res.diffuse[c] = result[3 + c].data();
    }
    std::vector<vec3> sum(n, vec3(0.0f));
    for (const ltc::polygon_light<float>& l : lights) {
        with_model(lobes, [&](auto model) {
            ltc::batch::shade<decltype(model)>(points, l, res);
            return 0;
        });
        for (std::size_t j = 0; j < n; ++j)
            for (int c = 0; c < 3; ++c) sum[j][c] += result[c][j] + result[3 + c][j];
    }
    for (std::size_t j = 0; j < n; ++j) out[where[j]] = sum[j];
}

/// The library's light for the scene's textured light (which must exist and outlive it: the light
/// refers to its prefiltered texture), one-sided towards its front, integrated by the policy's
/// method (the default policy is the paper's I_D I_L); built once per method.
inline ltc::textured_quad_light<float> ltc_textured_light(const textured_light& t,
                                                          const ltc::textured_policy& policy = {}) {
    return ltc::textured_quad_light<float>::one_sided(t.quad, t.front, *t.prefiltered, policy);
}

/// Radiance of one pixel from the textured light (and its emitter): LTC (float, the one-lobe
/// table); `light`: ltc_textured_light(*s.textured, policy).
inline vec3 shade_ltc_textured(const scene& s, const ltc::textured_quad_light<float>& light, const pixel_hit& hit) {
    const textured_light* t = s.textured.get();
    if (t == nullptr) return vec3(0.0f);
    if (hit.kind == pixel_hit::textured_front) return t->radiance(hit.uv.x, hit.uv.y);
    if (hit.kind != pixel_hit::floor) return vec3(0.0f);
    const material& m = s.materials[static_cast<std::size_t>(hit.material)];
    const ltc::surface<float> point{hit.p, vec3(0, 0, 1), hit.v, m.roughness, m.f0, m.albedo};
    const ltc::shading_result<float> r = ltc::shade<ltc::ggx::one_lobe>(point, light);
    return r.specular + r.diffuse;
}

}  // namespace render
