// A C++ port of the reference shader's shading of a quad light (Heitz et al. 2016's demo
// fragment shader, ltc.frag): the frame T1 = normalize(V - N (V.N)), T2 = N x T1; two bilinear
// fetches of the 64 x 64 table (the shader's ltc_1 texture: the four M^-1 entries; ltc_2:
// magnitude and Fresnel) at uv = (roughness, sqrt(1 - N.V)) * LUT_SCALE + LUT_BIAS; then
// LTC_Evaluate twice, for the specular lobe (M^-1 from ltc_1) and the diffuse one (M^-1 = I):
// M^-1 times the frame's transpose applied to each vertex minus P, the 16-case clipper and the
// rational edge fit of reference_shader.hpp. Used only as the benchmarks' baseline.
#pragma once

#include "reference_shader.hpp"

#include <ltc/shading/ggx_fetch.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace reference_shading {

// texture(lut, uv) of an RGBA32F texture with linear filtering and clamp-to-edge addressing:
// `first` channels of the table from channel c0 at texel coordinates uv (in [0, 1]).
inline void texture(const ltc::ltc_table& lut, glm::vec2 uv, int c0, int count, float* out) {
    const int w = lut.width(), h = lut.height();
    const float x = uv.x * float(w) - 0.5f, y = uv.y * float(h) - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y);
    const float ax = x - fx, ay = y - fy;
    const int x0 = std::clamp(int(fx), 0, w - 1), x1 = std::clamp(int(fx) + 1, 0, w - 1);
    const int y0 = std::clamp(int(fy), 0, h - 1), y1 = std::clamp(int(fy) + 1, 0, h - 1);
    for (int c = 0; c < count; ++c) {
        const float lo = lut.node(x0, y0, c0 + c) * (1 - ax) + lut.node(x1, y0, c0 + c) * ax;
        const float hi = lut.node(x0, y1, c0 + c) * (1 - ax) + lut.node(x1, y1, c0 + c) * ax;
        out[c] = lo * (1 - ay) + hi * ay;
    }
}

// LTC_Evaluate(N, V, P, Minv, points, twoSided) for a quad.
inline float ltc_evaluate(const glm::vec3& N, const glm::vec3& V, const glm::vec3& P, glm::mat3 m_inv,
                          const glm::vec3 points[4], bool two_sided) {
    const glm::vec3 T1 = glm::normalize(V - N * glm::dot(V, N));
    const glm::vec3 T2 = glm::cross(N, T1);
    m_inv = m_inv * glm::transpose(glm::mat3(T1, T2, N));
    glm::vec3 L[4];
    for (int i = 0; i < 4; ++i) L[i] = points[i] - P;
    return reference_shader::ltc_evaluate(m_inv, L, two_sided);
}

struct result {
    glm::vec3 specular, diffuse;
};

// The shader's main() for one quad light: table coordinates along u = sqrt(1 - cos theta_v)
// (the table's first axis) and roughness.
inline result shade(const glm::vec3& P, const glm::vec3& N, const glm::vec3& V, float roughness, const glm::vec3& F0,
                    const glm::vec3& albedo, const glm::vec3& radiance, const glm::vec3 points[4], bool two_sided) {
    const ltc::ltc_table& lut = ltc::ggx::table;
    const float scale = float(lut.width() - 1) / float(lut.width()), bias = 0.5f / float(lut.width());
    const float ct = std::clamp(glm::dot(N, V), 0.0f, 1.0f);
    const glm::vec2 uv = glm::vec2(std::sqrt(1 - ct), roughness) * scale + bias;
    float t1[4], t2[2];
    texture(lut, uv, 0, 4, t1);
    texture(lut, uv, 4, 2, t2);
    const glm::mat3 m_inv(glm::vec3(t1[0], 0, t1[1]), glm::vec3(0, 1, 0), glm::vec3(t1[2], 0, t1[3]));
    result r;
    r.specular = radiance * (F0 * t2[0] + (1.0f - F0) * t2[1]) * ltc_evaluate(N, V, P, m_inv, points, two_sided);
    r.diffuse = albedo * radiance * ltc_evaluate(N, V, P, glm::mat3(1.0f), points, two_sided);
    return r;
}

}  // namespace reference_shading
