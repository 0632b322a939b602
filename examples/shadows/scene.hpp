// shadows/scene.hpp -- the scene as triangles (z up): a tiled GGX floor, a one-sided quad light
// above and behind it, and two grey occluders between them (a box standing on the floor, a
// slanted panel with a square hole); the materials and the camera (main.cpp's file comment).
#pragma once

#include "common/math.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace shadows {

using ltc_examples::dvec3;
using ltc_examples::vec3;

struct material {
    float roughness;  // alpha = roughness^2, the convention of the LTC table
    vec3 f0;
    vec3 albedo;
};

/// A triangle mesh: one Embree geometry.
struct mesh {
    std::vector<vec3> vertices;
    std::vector<std::uint32_t> indices;  // three per triangle

    void quad(vec3 a, vec3 b, vec3 c, vec3 d) {  // a b c d around the quad
        const auto base = static_cast<std::uint32_t>(vertices.size());
        vertices.insert(vertices.end(), {a, b, c, d});
        indices.insert(indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
};

struct scene {
    // Camera: a pinhole 3 units above the floor, looking down 20 degrees.
    vec3 eye{0.0f, -6.0f, 3.0f};
    vec3 target{0.0f, 1.0f, 0.45f};
    float vfov_deg = 46.0f;

    // Floor z = 0, x in [x0, x1], y in [y0, y1]: unit tiles, three dielectric roughnesses in
    // diagonals (so that every penumbra crosses all three) and one gold column, x in [0, 1],
    // under the highlight and the panel's penumbra.
    float x0 = -6.0f, x1 = 6.0f, y0 = -3.5f, y1 = 5.0f;
    static constexpr float roughness[3] = {0.15f, 0.3f, 0.6f};
    std::vector<material> materials;  // 0..2 dielectric, 3..5 gold, by roughness; 6 occluders
    static constexpr int gold_material = 3, occluder_material = 6;
    static bool is_gold(int material) { return material >= gold_material && material < occluder_material; }

    // The light: a one-sided 2.6 x 1.0 rectangle 3 units up, behind the occluders, facing the
    // camera and the floor. vertices: the library's one-sided orientation (clockwise seen from
    // the lit side: the right-hand normal points away from it).
    vec3 light_vertices[4];
    vec3 light_front;  // unit normal of the emitting side
    vec3 light_radiance = vec3(1.0f, 0.9f, 0.75f) * 30.0f;

    mesh floor, occluders, emitter;

    scene() {
        const vec3 gold(1.000f, 0.766f, 0.336f);  // F0, linear sRGB
        for (float r : roughness) materials.push_back({r, vec3(0.04f), vec3(0.5f)});
        for (float r : roughness) materials.push_back({r, gold, vec3(0.0f)});
        materials.push_back({0.5f, vec3(0.04f), vec3(0.45f)});  // the occluders: rough grey

        floor.quad({x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0}, {x0, y1, 0});

        // The light, tilted so that its normal points 42 degrees below the horizontal.
        light_front = glm::normalize(vec3(0.0f, -1.0f, -0.9f));
        const vec3 centre(0.0f, 4.2f, 3.0f), u(1.3f, 0.0f, 0.0f);
        const vec3 v = 0.5f * glm::normalize(glm::cross(light_front, u));
        light_vertices[0] = centre - u - v, light_vertices[1] = centre + u - v;
        light_vertices[2] = centre + u + v, light_vertices[3] = centre - u + v;
        const vec3 rh = glm::cross(light_vertices[1] - light_vertices[0], light_vertices[2] - light_vertices[0]);
        if (glm::dot(rh, light_front) > 0) std::reverse(light_vertices, light_vertices + 4);
        emitter.quad(light_vertices[0], light_vertices[1], light_vertices[2], light_vertices[3]);

        // A unit box on the floor: a contact shadow, hard at its base, softening away from it.
        const float bx0 = -2.1f, bx1 = -1.1f, by0 = 0.0f, by1 = 1.0f, bz = 1.0f;
        const vec3 b[8] = {{bx0, by0, 0}, {bx1, by0, 0}, {bx1, by1, 0}, {bx0, by1, 0},
                           {bx0, by0, bz}, {bx1, by0, bz}, {bx1, by1, bz}, {bx0, by1, bz}};
        occluders.quad(b[4], b[5], b[6], b[7]);  // top
        occluders.quad(b[0], b[1], b[5], b[4]);  // front (towards the camera)
        occluders.quad(b[1], b[2], b[6], b[5]);
        occluders.quad(b[2], b[3], b[7], b[6]);
        occluders.quad(b[3], b[0], b[4], b[7]);

        // A 1.8 x 1.4 panel with a 0.5 x 0.5 hole, slanted 30 degrees sideways (its normal
        // towards the light) and 15 degrees towards the camera, its low corner 0.5 units up and its
        // high one 1.7: a narrower penumbra from the low edge, a wide one from the high edge, a
        // soft spot of light through the hole. Four strips around the hole.
        const float slant = 30.0f * static_cast<float>(ltc_examples::deg), tilt = 15.0f * static_cast<float>(ltc_examples::deg);
        const vec3 pc(1.2f, 1.0f, 1.1f), pu(std::cos(slant), 0.0f, std::sin(slant));
        const vec3 pw(0.0f, std::cos(tilt), std::sin(tilt));
        const auto at = [&](float a, float c) { return pc + a * pu + c * pw; };
        const float U0 = -0.9f, U1 = 0.9f, W0 = -0.7f, W1 = 0.7f;  // outline
        const float h0 = -0.15f, h1 = 0.35f, k0 = -0.2f, k1 = 0.3f;  // hole
        occluders.quad(at(U0, W0), at(U1, W0), at(U1, k0), at(U0, k0));
        occluders.quad(at(U0, k1), at(U1, k1), at(U1, W1), at(U0, W1));
        occluders.quad(at(U0, k0), at(h0, k0), at(h0, k1), at(U0, k1));
        occluders.quad(at(h1, k0), at(U1, k0), at(U1, k1), at(h1, k1));
    }

    /// Material index of the floor point (x, y).
    int floor_material(float x, float y) const {
        const int i = static_cast<int>(std::floor(x)), j = static_cast<int>(std::floor(y));
        const int r = ((i + j) % 3 + 3) % 3;
        return i == 0 ? 3 + r : r;
    }

    float light_area() const {
        return glm::length(glm::cross(light_vertices[1] - light_vertices[0], light_vertices[3] - light_vertices[0]));
    }
};

}  // namespace shadows
