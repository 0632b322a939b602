// ggx_error_report/grid.hpp -- the documented grid of configurations (main.cpp's file comment):
// view angles, roughnesses, light shapes, sizes and placements, the lights' vertices (front face
// towards the shading point), and a slot for each configuration's Monte Carlo ground truth.
#pragma once

#include <ltc/reference/ground_truth.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ggx_error_report {

using glm::dvec3;
constexpr double deg = 3.141592653589793 / 180.0;

// The documented grid (--grid on, the default) and one off it (--grid off): view angles and
// roughnesses between the first's, mostly between the tables' nodes (u = sqrt(1 - cos theta_v)
// and the roughness at t / (n - 1) for n = 32 and 64; in the 32 x 32 two-lobe table roughness
// 0.15 / 0.2 / 0.35 / 0.6 / 0.9 sit 0.65 / 0.2 / 0.85 / 0.6 / 0.9 of a cell above a node), so
// that a table is also measured where it interpolates. Index 3 is the grazing view of each.
inline constexpr double grid_thetas[2][4] = {{0, 30, 60, 80}, {15, 45, 65, 75}};
inline constexpr double grid_roughnesses[2][5] = {{0.1, 0.25, 0.5, 0.75, 1.0}, {0.15, 0.2, 0.35, 0.6, 0.9}};
inline const double* thetas = grid_thetas[0];            // set once by main (--grid)
inline const double* roughnesses = grid_roughnesses[0];
const char* const shape_names[] = {"rectangle", "triangle", "pentagon"};
const double sizes[] = {0.1, 0.5, 2.0};
const char* const placement_names[] = {"mirror", "zenith", "side", "low"};

struct config {
    int theta, rough, shape, size, placement;  // indices into the arrays above
    std::vector<dvec3> vertices;
    bool straddles = false;  // partly below the horizon
    ltc::ground_truth::estimate gt;
};

/// A light of the given shape, circumradius s, centred at distance 1 along c, facing the origin,
/// its vertices clockwise as seen from the origin (front face, polygon.hpp's convention).
inline std::vector<dvec3> make_light(int shape, double s, const dvec3& c) {
    std::vector<glm::dvec2> p;
    if (shape == 0) {  // 2:1 rectangle with circumradius s
        const double a = s * 2 / std::sqrt(5.0), b = s / std::sqrt(5.0);
        p = {{-a, -b}, {a, -b}, {a, b}, {-a, b}};
    } else {
        const int n = shape == 1 ? 3 : 5;
        for (int i = 0; i < n; ++i) {
            const double phi = 2 * 3.141592653589793 * i / n + 0.3;
            p.push_back({s * std::cos(phi), s * std::sin(phi)});
        }
    }
    // Tangent frame of the light plane: e1, e2 orthogonal to c.
    const dvec3 e1 = glm::normalize(std::abs(c.z) < 0.9 ? glm::cross(dvec3(0, 0, 1), c) : glm::cross(dvec3(1, 0, 0), c));
    const dvec3 e2 = glm::cross(c, e1);
    std::vector<dvec3> v;
    for (const auto& q : p) v.push_back(c + q.x * e1 + q.y * e2);
    // Front face (polygon.hpp): the right-hand normal points away from the origin.
    const dvec3 nrm = glm::cross(v[1] - v[0], v[2] - v[0]);
    if (glm::dot(v[0], nrm) < 0) std::reverse(v.begin(), v.end());
    return v;
}

inline dvec3 placement_direction(int placement, double theta) {
    const auto dir = [](double azimuth_deg, double elevation_deg) {
        const double a = azimuth_deg * deg, e = elevation_deg * deg;
        return dvec3(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
    };
    switch (placement) {
        case 0: return dvec3(-std::sin(theta * deg), 0, std::cos(theta * deg));
        case 1: return dvec3(0, 0, 1);
        case 2: return dir(90, 30);
        default: return dir(135, 5);
    }
}

inline std::vector<config> make_grid() {
    std::vector<config> grid;
    for (int t = 0; t < 4; ++t)
        for (int r = 0; r < 5; ++r)
            for (int sh = 0; sh < 3; ++sh)
                for (int sz = 0; sz < 3; ++sz)
                    for (int pl = 0; pl < 4; ++pl) {
                        config c{t, r, sh, sz, pl, {}, false, {}};
                        c.vertices = make_light(sh, sizes[sz], placement_direction(pl, thetas[t]));
                        for (const auto& v : c.vertices) c.straddles = c.straddles || v.z < 0;
                        grid.push_back(std::move(c));
                    }
    return grid;
}


}  // namespace ggx_error_report
