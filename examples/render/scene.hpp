// render/scene.hpp -- the scene: the floor's materials (dielectric, gold and copper stripes
// crossed by bands of roughness, grout lines), the camera's placement, the two polygonal lights
// and, optionally, the textured light (see main.cpp's file comment for the layout).
#pragma once

#include "common/image.hpp"
#include "lights.hpp"
#include "math.hpp"

#include <ltc/reference/textured_ground_truth.hpp>
#include <ltc/shading/light_texture.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace render {

struct material {
    float roughness;
    vec3 f0;
    vec3 albedo;
};


struct scene {
    // Camera.
    vec3 eye{0.0f, -6.5f, 2.8f};
    vec3 target{0.0f, 2.0f, 0.3f};
    float vfov_deg = 48.0f;
    // Floor: x in [x0, x1], y in [y0, y1], z = 0: `columns` material stripes along y, crossed
    // by `bands` of roughness (the lights' reflections run along the stripes, across the bands).
    static constexpr int columns = 4, bands = 5;
    float x0 = -4.0f, x1 = 4.0f;
    // Band edges along y, spaced to look about equally tall from the camera.
    float band_edges[bands + 1] = {-3.3f, -2.5f, -1.6f, -0.4f, 1.4f, 4.5f};
    float y0 = band_edges[0], y1 = band_edges[bands];
    float grout = 0.02f;  // half width of the grout lines
    float roughness[bands] = {0.9f, 0.7f, 0.5f, 0.3f, 0.1f};  // near to far
    const char* column_names[columns] = {"dielectric", "gold", "dielectric", "copper"};
    std::vector<material> materials;  // [band * columns + column], then the grout
    std::vector<light> lights;
    std::unique_ptr<textured_light> textured;  // null without the textured light

    scene() {
        const vec3 gold(1.000f, 0.766f, 0.336f), copper(0.955f, 0.638f, 0.538f);  // F0, linear sRGB
        for (float r : roughness)
            for (int c = 0; c < columns; ++c)
                if (c % 2 == 0)
                    materials.push_back({r, vec3(0.04f), vec3(0.5f)});
                else
                    materials.push_back({r, c == 1 ? gold : copper, vec3(0.0f)});
        materials.push_back({0.8f, vec3(0.04f), vec3(0.02f)});  // grout

        // Two tall lights standing behind the floor, facing the camera and tilted 10 degrees
        // towards the floor, each above the boundary between a dielectric and a metal stripe:
        // a 1.2 x 3.4 rectangle leaning 20 degrees, and an irregular pentagon.
        const vec3 front = glm::normalize(vec3(0.0f, -1.0f, -0.18f));
        const vec3 up(0.0f, 0.0f, 1.0f);
        const std::vector<glm::vec2> rect = {{-0.6f, -1.7f}, {0.6f, -1.7f}, {0.6f, 1.7f}, {-0.6f, 1.7f}};
        lights.push_back(make_light("rectangle", rotated(rect, 20.0), vec3(-3.0f, 5.0f, 1.9f), front, up,
                                    vec3(1.00f, 0.78f, 0.50f) * 6.0f));
        const std::vector<glm::vec2> pentagon = {
            {0.0f, 1.8f}, {0.9f, 0.5f}, {0.6f, -1.6f}, {-0.7f, -1.6f}, {-0.9f, 0.6f}};
        lights.push_back(make_light("pentagon", pentagon, vec3(3.0f, 5.0f, 1.9f), front, up,
                                    vec3(0.50f, 0.72f, 1.00f) * 6.0f));
    }

    /// Adds the textured light: the picture (linear, white = 1) times `radiance`, on a quad in
    /// the plane of the other lights (the same tilt), centred between them, with the picture's
    /// aspect ratio, as large as fits in 2.6 x 3.2 units.
    void add_textured_light(image picture, float radiance) {
        auto t = std::make_unique<textured_light>();
        for (auto& c : picture.texels) c *= radiance;
        const float aspect = static_cast<float>(picture.width) / static_cast<float>(picture.height);
        const float max_w = 2.6f, max_h = 3.2f;
        float w = max_w, h = max_w / aspect;
        if (h > max_h) h = max_h, w = max_h * aspect;
        t->half_width = 0.5f * w;
        t->half_height = 0.5f * h;
        t->centre = vec3(0.0f, 5.0f, 1.9f);
        t->front = glm::normalize(vec3(0.0f, -1.0f, -0.18f));
        const vec3 up(0.0f, 0.0f, 1.0f);
        t->axis_v = glm::normalize(up - glm::dot(up, t->front) * t->front);
        t->axis_u = glm::cross(t->axis_v, t->front);  // right, as seen from the front
        const vec3 U = t->half_width * t->axis_u, V = t->half_height * t->axis_v;
        t->quad[0] = t->centre - U + V;  // uv (0, 0): top left
        t->quad[1] = t->centre + U + V;  // (1, 0): top right
        t->quad[2] = t->centre + U - V;  // (1, 1): bottom right
        t->quad[3] = t->centre - U - V;  // (0, 1): bottom left
        t->prefiltered = std::make_unique<ltc::light_texture<float>>(picture.width, picture.height,
                                                                    picture.texels.data());
        std::vector<double> weights(picture.texels.size());
        for (std::size_t i = 0; i < weights.size(); ++i)
            weights[i] = 0.2126 * picture.texels[i].r + 0.7152 * picture.texels[i].g + 0.0722 * picture.texels[i].b;
        t->area_density = std::make_unique<ltc::textured_ground_truth::texel_distribution>(
            picture.width, picture.height, weights.data());
        t->picture = std::move(picture);
        textured = std::move(t);
    }

    /// Material index at the floor point (x, y), or -1 outside the floor.
    int material_at(float x, float y) const {
        if (!(x >= x0 && x <= x1 && y >= y0 && y <= y1)) return -1;
        const float u = (x - x0) / (x1 - x0) * columns;
        if (std::abs(u - std::round(u)) * (x1 - x0) / columns < grout) return columns * bands;
        int b = 0;
        while (b + 1 < bands && y >= band_edges[b + 1]) ++b;
        if (y - band_edges[b] < grout || band_edges[b + 1] - y < grout) return columns * bands;
        return b * columns + std::min(columns - 1, static_cast<int>(u));
    }
};

}  // namespace render
