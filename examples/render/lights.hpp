// render/lights.hpp -- the scene's lights: one-sided, constant-radiance planar polygons
// (make_light places an outline in a plane, in the library's one-sided orientation) and the
// one-sided textured quad light, with its prefiltered texture (ltc::light_texture, for the LTC
// render, paper sections 5.2-5.4) and its texel-luminance sampling density (for the reference).
#pragma once

#include "common/image.hpp"
#include "math.hpp"

#include <ltc/reference/textured_ground_truth.hpp>
#include <ltc/shading/light_texture.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace render {

struct light {
    const char* name;
    std::vector<vec3> vertices;  // front face: clockwise as seen from the lit side
    vec3 radiance;
    vec3 centre, front;  // front: unit normal of the emitting side
    vec3 axis_u, axis_v;  // orthonormal axes of the light's plane (hit test)
    std::vector<glm::vec2> outline;  // the vertices in (axis_u, axis_v) coordinates
};

/// A planar light: outline points (in its plane, around the centre) placed on the plane through
/// `centre` with unit normal `front` (the emitting side), "up" in the plane towards `up`.
inline light make_light(const char* name, const std::vector<glm::vec2>& outline, vec3 centre, vec3 front, vec3 up,
                        vec3 radiance) {
    light l;
    l.name = name;
    l.radiance = radiance;
    l.centre = centre;
    l.front = glm::normalize(front);
    l.axis_v = glm::normalize(up - glm::dot(up, l.front) * l.front);
    l.axis_u = glm::cross(l.axis_v, l.front);
    l.outline = outline;
    for (const auto& p : outline) l.vertices.push_back(centre + p.x * l.axis_u + p.y * l.axis_v);
    // One-sided convention of the library (polygon.hpp): the right-hand normal
    // (p1 - p0) x (p2 - p0) points away from the lit points, i.e. against `front`.
    const vec3 n = glm::cross(l.vertices[1] - l.vertices[0], l.vertices[2] - l.vertices[0]);
    if (glm::dot(n, l.front) > 0) {
        std::reverse(l.vertices.begin(), l.vertices.end());
        std::reverse(l.outline.begin(), l.outline.end());
    }
    return l;
}

inline std::vector<glm::vec2> rotated(std::vector<glm::vec2> p, double angle_deg) {
    const float c = static_cast<float>(std::cos(angle_deg * deg)), s = static_cast<float>(std::sin(angle_deg * deg));
    for (auto& q : p) q = glm::vec2(c * q.x - s * q.y, s * q.x + c * q.y);
    return p;
}

/// A one-sided textured quad light: a rectangle with texture coordinates (0,0) at its top left,
/// (1,0) top right, (1,1) bottom right, (0,1) bottom left as seen from the front (the image's
/// first row at the top, not mirrored). In this order the corners turn clockwise as seen from
/// the front: the library's one-sided orientation.
struct textured_light {
    const char* name = "textured quad";
    vec3 quad[4];
    vec3 centre, front, axis_u, axis_v;  // axis_u: right, axis_v: up, as seen from the front
    float half_width = 0, half_height = 0;
    image picture;  // linear radiance (the texture times the light's radiance scale)
    std::unique_ptr<ltc::light_texture<float>> prefiltered;  // the LTC render's levels
    std::unique_ptr<ltc::textured_ground_truth::texel_distribution> area_density;  // reference
    /// The radiance at uv: the texel-constant texture, each texel's colour over its whole square
    /// (ltc::nearest_image_lookup; what both renders draw where the camera sees the light, and what
    /// the reference integrates: the texture whose integral the exact cell methods compute; see
    /// main.cpp's file comment).
    vec3 radiance(double u, double v) const {
        return ltc::nearest_image_lookup(picture.width, picture.height, picture.texels.data(), u, v);
    }
};

}  // namespace render
