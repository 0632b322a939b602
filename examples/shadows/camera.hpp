// shadows/camera.hpp -- the pinhole camera (common/pinhole.hpp): one Embree ray through each
// pixel centre (no antialiasing: every method shades the same points) and what it sees: a floor
// or occluder point with its material, unit normal (facing the camera) and view direction, the
// light's emitting front or its dark back, or nothing.
#pragma once

#include "common/pinhole.hpp"
#include "scene.hpp"
#include "tracer.hpp"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace shadows {

struct pixel_hit {
    enum kind_t : std::uint8_t { background, floor, occluder, emitter_front, emitter_back } kind = background;
    int material = -1;
    vec3 p{0.0f};  // shading point
    vec3 n{0.0f};  // unit normal on the camera's side
    vec3 v{0.0f};  // unit direction towards the eye

    bool shaded() const { return kind == floor || kind == occluder; }
};

inline std::vector<pixel_hit> trace_camera(const scene& s, const tracer& tr, int width, int height) {
    std::vector<pixel_hit> hits(static_cast<std::size_t>(width) * height);
    const ltc_examples::pinhole camera(s.eye, s.target, s.vfov_deg, width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const vec3 d = camera.direction(x, y);
            pixel_hit& hit = hits[static_cast<std::size_t>(y) * width + x];
            const ray_hit r = tr.intersect(s.eye, d);
            if (r.kind == ray_hit::none) continue;
            hit.v = -d;
            if (r.kind == ray_hit::light) {
                hit.kind = glm::dot(d, s.light_front) < 0 ? pixel_hit::emitter_front : pixel_hit::emitter_back;
                continue;
            }
            hit.p = s.eye + r.t * d;
            hit.n = glm::dot(r.ng, d) < 0 ? r.ng : -r.ng;
            if (r.kind == ray_hit::floor) {
                hit.kind = pixel_hit::floor;
                hit.p.z = 0.0f;  // exactly on the plane
                hit.n = vec3(0, 0, 1);
                hit.material = s.floor_material(hit.p.x, hit.p.y);
            } else {
                hit.kind = pixel_hit::occluder;
                hit.material = scene::occluder_material;
            }
        }
    return hits;
}

}  // namespace shadows
