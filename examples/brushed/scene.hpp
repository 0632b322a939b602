// brushed/scene.hpp -- the scene (z up): the floor z = 0, the camera looking along the brushing
// direction +x, the one-sided quad light in front of it, the two materials, and what each pixel sees.
#pragma once

#include "common/math.hpp"
#include "common/pinhole.hpp"

#include <glm/glm.hpp>

#include <cstddef>
#include <vector>

namespace brushed {

using ltc_examples::dvec3;
using ltc_examples::vec3;

/// A floor material: roughness along the tangent (+x) and across it (alpha = roughness^2).
struct material {
    const char* name;
    float roughness, roughness_bitangent;
};

const vec3 metal_f0(0.95f, 0.64f, 0.54f);  // copper-like; applied for display only (main.cpp)
const vec3 tangent(1, 0, 0);               // the brushing direction on the floor

/// The light: a 1.0 x 1.2 rectangle centred 2 above the floor, 6 ahead of the camera, facing back
/// towards it and 59 degrees down: its mirror image falls in the middle of the view, and every
/// floor point in view sees its front (its plane meets the floor at x = 9.33, beyond the view).
struct quad_light {
    vec3 centre{6.0f, 0.0f, 2.0f};
    vec3 normal = glm::normalize(vec3(-0.6f, 0.0f, -1.0f));  // emission normal
    vec3 across{0.0f, 1.0f, 0.0f};                           // in-plane axes
    vec3 up = glm::normalize(glm::cross(normal, across));
    float half_across = 0.5f, half_up = 0.6f;
    float radiance = 4.0f;
    vec3 vertices[4];

    quad_light() {
        const vec3 a = half_across * across, b = half_up * up;
        vertices[0] = centre - a - b, vertices[1] = centre + a - b;
        vertices[2] = centre + a + b, vertices[3] = centre - a + b;
    }

    /// Whether the floor point P sees the front face (the one-sided light is dark from behind).
    bool faces(const dvec3& P) const { return glm::dot(dvec3(centre) - P, dvec3(normal)) < 0; }
};

/// What one pixel's ray meets: the floor (or sky; the light is above the view).
struct pixel_hit {
    bool floor = false;
    vec3 p{0.0f};  // the floor point
    vec3 v{0.0f};  // towards the eye (unit)
};

/// Camera 2.5 above the floor looking along +x at (3.3, 0, 0), the light's mirror point, 40 degrees
/// of vertical field: the floor from x = 1.6 to 8.1 ahead, theta_v 33 to 73 degrees down the middle.
const vec3 eye(0.0f, 0.0f, 2.5f);
inline ltc_examples::pinhole make_camera(int width, int height) {
    return {eye, vec3(3.3f, 0.0f, 0.0f), 40.0f, width, height};
}

/// The floor point of every pixel's ray (row 0 at the top).
inline std::vector<pixel_hit> trace_camera(int width, int height) {
    const ltc_examples::pinhole cam = make_camera(width, height);
    std::vector<pixel_hit> hits(static_cast<std::size_t>(width) * height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            pixel_hit& h = hits[static_cast<std::size_t>(y) * width + x];
            const vec3 d = cam.direction(x, y);
            if (!(d.z < 0)) continue;
            h.floor = true;
            h.p = eye - (eye.z / d.z) * d;
            h.p.z = 0.0f;
            h.v = -d;
        }
    return hits;
}

}  // namespace brushed
