// render/camera.hpp -- the pinhole camera: one ray through each pixel centre and what it hits (the
// floor, with its material, point and view direction; a light's front or back; the textured
// light's front, with its texture coordinates; or nothing).
#pragma once

#include "common/pinhole.hpp"
#include "lights.hpp"
#include "math.hpp"
#include "scene.hpp"

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace render {

/// What the camera ray of a pixel sees.
struct pixel_hit {
    enum kind_t : std::uint8_t { background, floor, emitter_front, emitter_back, textured_front } kind = background;
    int material = -1;
    int light = -1;  // emitter_front / emitter_back: index in scene::lights; -1 for the textured light
    vec3 p{0.0f};  // floor point
    vec3 v{0.0f};  // unit direction towards the eye
    glm::vec2 uv{0.0f};  // textured_front: texture coordinates of the hit
};

inline bool inside_polygon(const std::vector<glm::vec2>& poly, glm::vec2 q) {  // even-odd rule
    bool in = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const glm::vec2 a = poly[i], b = poly[j];
        if ((a.y > q.y) != (b.y > q.y) && q.x < (b.x - a.x) * (q.y - a.y) / (b.y - a.y) + a.x) in = !in;
    }
    return in;
}

inline std::vector<pixel_hit> trace_camera(const scene& s, int width, int height) {
    std::vector<pixel_hit> hits(static_cast<std::size_t>(width) * height);
    const pinhole camera(s.eye, s.target, s.vfov_deg, width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const vec3 d = camera.direction(x, y);
            pixel_hit& hit = hits[static_cast<std::size_t>(y) * width + x];
            float t_best = INFINITY;
            if (d.z < 0) {
                const float t = -s.eye.z / d.z;
                const vec3 p = s.eye + t * d;
                const int m = s.material_at(p.x, p.y);
                if (m >= 0) {
                    t_best = t;
                    hit.kind = pixel_hit::floor;
                    hit.material = m;
                    hit.p = vec3(p.x, p.y, 0.0f);
                    hit.v = -d;
                }
            }
            for (std::size_t k = 0; k < s.lights.size(); ++k) {
                const light& l = s.lights[k];
                const float dn = glm::dot(d, l.front);
                if (dn == 0) continue;
                const float t = glm::dot(l.centre - s.eye, l.front) / dn;
                if (!(t > 0 && t < t_best)) continue;
                const vec3 q = s.eye + t * d - l.centre;
                if (!inside_polygon(l.outline, glm::vec2(glm::dot(q, l.axis_u), glm::dot(q, l.axis_v)))) continue;
                t_best = t;
                hit.kind = dn < 0 ? pixel_hit::emitter_front : pixel_hit::emitter_back;
                hit.light = static_cast<int>(k);
                hit.material = -1;
            }
            if (const textured_light* l = s.textured.get()) {
                const float dn = glm::dot(d, l->front);
                const float t = dn != 0 ? glm::dot(l->centre - s.eye, l->front) / dn : -1.0f;
                if (t > 0 && t < t_best) {
                    // uv from the top-left corner along the (orthogonal) edges.
                    const vec3 q = s.eye + t * d - l->quad[0];
                    const float u = glm::dot(q, l->axis_u) / (2.0f * l->half_width);
                    const float v = -glm::dot(q, l->axis_v) / (2.0f * l->half_height);
                    if (u >= 0 && u <= 1 && v >= 0 && v <= 1) {
                        hit.kind = dn < 0 ? pixel_hit::textured_front : pixel_hit::emitter_back;
                        hit.light = -1;
                        hit.material = -1;
                        hit.uv = glm::vec2(u, v);
                    }
                }
            }
        }
    return hits;
}

}  // namespace render
