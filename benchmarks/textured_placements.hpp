// The light placements and textures of bench_textured.cpp: the grid of the textured error
// report (tools/textured_error_report/), see bench_textured.cpp's file comment.
#pragma once

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/shading/light_texture.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

namespace bench_textured {

inline constexpr double kPi = 3.141592653589793;
inline constexpr int kSize = 64;                      // texture width and height
inline constexpr std::size_t kFullBudget = 64 * 64;   // leaves >= texels: full refinement

enum texture_id { smooth = 0, bright = 1 };

inline std::vector<glm::dvec3> texels(texture_id which) {
    std::vector<glm::dvec3> px(std::size_t(kSize) * kSize);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double u = (x + 0.5) / kSize, v = (y + 0.5) / kSize;
            glm::dvec3 c(0.02);
            if (which == smooth)
                c = glm::dvec3(u, v, 1 - u * v);
            else if (x >= 44 && x < 47 && y >= 21 && y < 24)
                c = glm::dvec3(100.0, 80.0, 60.0);
            px[std::size_t(y) * kSize + x] = c;
        }
    return px;
}

template <typename T>
ltc::light_texture<T> make_texture(texture_id which) {
    const std::vector<glm::dvec3> px = texels(which);
    const std::vector<glm::vec<3, T>> rgb(px.begin(), px.end());
    return ltc::light_texture<T>(kSize, kSize, rgb.data());
}

template <typename T>
const ltc::light_texture<T>& texture(texture_id which) {
    static const ltc::light_texture<T> tex[2] = {make_texture<T>(smooth), make_texture<T>(bright)};
    return tex[which];
}

// One light placement of the report, in double.
struct placement {
    double roughness;  // < 0: the diffuse lobe (M = I)
    double theta_v;    // radians
    glm::dvec3 quad[4];
};

inline std::vector<placement> placements() {
    std::vector<placement> out;
    const double roughs[] = {-1, 0.1, 0.25, 0.5, 1.0};
    const double views[] = {0, 30, 60, 80};
    const double dists[] = {0.5, 1.5, 4};
    for (double r : roughs)
        for (double view : views)
            for (double dist : dists)
                for (int oi = 0; oi < 3; ++oi) {
                    placement p;
                    p.roughness = r;
                    p.theta_v = view * kPi / 180;
                    const double el = 45 * kPi / 180;
                    const glm::dvec3 dir(-std::cos(el), 0, std::sin(el));
                    const glm::dvec3 C = dist * dir;
                    glm::dvec3 n = -dir;
                    if (oi == 1) {
                        const double a = 60 * kPi / 180;
                        n = glm::dvec3(n.x * std::cos(a) + n.z * std::sin(a), 0, -n.x * std::sin(a) + n.z * std::cos(a));
                    } else if (oi == 2) {
                        n = glm::dvec3(1, 0, 0);
                    }
                    const glm::dvec3 t(0, 1, 0);
                    const glm::dvec3 b = glm::normalize(glm::cross(n, t));
                    p.quad[0] = C - 0.5 * t - 0.5 * b, p.quad[1] = C + 0.5 * t - 0.5 * b;
                    p.quad[2] = C + 0.5 * t + 0.5 * b, p.quad[3] = C - 0.5 * t + 0.5 * b;
                    out.push_back(p);
                }
    return out;
}

template <typename T>
ltc::transformed<ltc::clamped_cosine<T>> lobe(const placement& p) {
    const glm::mat<3, 3, T> m_inv = p.roughness < 0 ? glm::mat<3, 3, T>(T(1))
                                                    : ltc::ggx::fetch<T>(T(std::cos(p.theta_v)), T(p.roughness)).m_inv;
    return ltc::transformed<ltc::clamped_cosine<T>>::from_inverse(m_inv);
}

}  // namespace bench_textured
