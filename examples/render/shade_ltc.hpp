// render/shade_ltc.hpp -- the LTC render of one pixel (float, a renderer's path): the polygonal
// lights with ltc::shade_polygon_light, the textured light with ltc::shade_textured_quad_light
// (I_D I_L: the exact polygon integral times one fetch into the prefiltered texture, paper
// sections 5.2-5.4); specular and diffuse, Schlick's Fresnel through the table (Hill 2016).
#pragma once

#include "camera.hpp"
#include "lights.hpp"
#include "math.hpp"
#include "scene.hpp"

#include <ltc/shading/polygon_light.hpp>
#include <ltc/shading/textured_light.hpp>

#include <cstddef>

namespace render {

/// Radiance of one pixel from the polygonal lights (and their emitters): LTC (float, the
/// renderer's path).
inline vec3 shade_ltc(const scene& s, const pixel_hit& hit) {
    if (hit.kind == pixel_hit::emitter_front) return s.lights[static_cast<std::size_t>(hit.light)].radiance;
    if (hit.kind != pixel_hit::floor) return vec3(0.0f);
    const material& m = s.materials[static_cast<std::size_t>(hit.material)];
    vec3 sum(0.0f);
    for (const light& l : s.lights) {
        const ltc::polygon_light_result<float> r =
            ltc::shade_polygon_light(hit.p, vec3(0, 0, 1), hit.v, m.roughness, m.f0, m.albedo, l.radiance,
                                     l.vertices.data(), l.vertices.size(), ltc::sidedness::one_sided);
        sum += r.specular + r.diffuse;
    }
    return sum;
}

/// Radiance of one pixel from the textured light (and its emitter): LTC, I_D I_L (float).
inline vec3 shade_ltc_textured(const scene& s, const pixel_hit& hit) {
    const textured_light* t = s.textured.get();
    if (t == nullptr) return vec3(0.0f);
    if (hit.kind == pixel_hit::textured_front) return t->radiance(hit.uv.x, hit.uv.y);
    if (hit.kind != pixel_hit::floor) return vec3(0.0f);
    const material& m = s.materials[static_cast<std::size_t>(hit.material)];
    const ltc::textured_light_result<float> r = ltc::shade_textured_quad_light(
        hit.p, vec3(0, 0, 1), hit.v, m.roughness, m.f0, m.albedo, t->quad, *t->prefiltered, ltc::sidedness::one_sided);
    return r.specular + r.diffuse;
}

}  // namespace render
