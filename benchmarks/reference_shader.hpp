// A C++ port of the reference shader path for a quad light (Heitz et al. 2016's demo shader, as
// described by the production note in the sources): transform the four vertices by M^-1, clip
// the quad to the horizon with a 16-case switch on which vertices are above it, project to the
// sphere, and sum the edge terms with the shader's rational fit of theta / sin(theta) (plain
// cross product, 1 / (2 pi) folded into the fit). Used only as the benchmarks' baseline.
#pragma once

#include <glm/glm.hpp>

#include <cmath>

namespace reference_shader {

inline glm::vec3 integrate_edge_vec(const glm::vec3& v1, const glm::vec3& v2) {
    const float x = glm::dot(v1, v2);
    const float y = std::abs(x);
    const float a = 0.8543985f + (0.4965155f + 0.0145206f * y) * y;
    const float b = 3.4175940f + (4.1616724f + y) * y;
    const float v = a / b;
    const float theta_sintheta = x > 0.0f ? v : 0.5f / std::sqrt(std::max(1.0f - x * x, 1e-7f)) - v;
    return glm::cross(v1, v2) * theta_sintheta;
}

// Point where the edge from `in` (above) to `out` (below) meets z = 0, up to a positive factor.
inline glm::vec3 cut(const glm::vec3& in, const glm::vec3& out) { return -out.z * in + in.z * out; }

// Clips the quad L[0..3] to z > 0 in place; returns the vertex count (0, 3, 4 or 5) and closes
// the polygon by repeating L[0] after the last vertex, as the shader does.
inline int clip_quad_to_horizon(glm::vec3 L[5]) {
    const int config = (L[0].z > 0.0f ? 1 : 0) + (L[1].z > 0.0f ? 2 : 0) + (L[2].z > 0.0f ? 4 : 0) +
                       (L[3].z > 0.0f ? 8 : 0);
    int n = 0;
    switch (config) {
        case 0: break;  // all below
        case 1: n = 3; L[1] = cut(L[0], L[1]); L[2] = cut(L[0], L[3]); break;  // V1 up
        case 2: n = 3; L[0] = cut(L[1], L[0]); L[2] = cut(L[1], L[2]); break;  // V2 up
        case 3: n = 4; L[2] = cut(L[1], L[2]); L[3] = cut(L[0], L[3]); break;  // V1 V2 up
        case 4: n = 3; L[0] = cut(L[2], L[3]); L[1] = cut(L[2], L[1]); break;  // V3 up
        case 5: break;  // V1 V3 up: impossible for a planar convex quad
        case 6: n = 4; L[0] = cut(L[1], L[0]); L[3] = cut(L[2], L[3]); break;  // V2 V3 up
        case 7: n = 5; L[4] = cut(L[0], L[3]); L[3] = cut(L[2], L[3]); break;  // V1 V2 V3 up
        case 8: n = 3; L[0] = cut(L[3], L[0]); L[1] = cut(L[3], L[2]); L[2] = L[3]; break;  // V4 up
        case 9: n = 4; L[1] = cut(L[0], L[1]); L[2] = cut(L[3], L[2]); break;  // V1 V4 up
        case 10: break;  // V2 V4 up: impossible
        case 11: n = 5; L[4] = L[3]; L[3] = cut(L[3], L[2]); L[2] = cut(L[1], L[2]); break;  // V1 V2 V4 up
        case 12: n = 4; L[1] = cut(L[2], L[1]); L[0] = cut(L[3], L[0]); break;  // V3 V4 up
        case 13: n = 5; L[4] = L[3]; L[3] = L[2]; L[2] = cut(L[2], L[1]); L[1] = cut(L[0], L[1]); break;  // V1 V3 V4
        case 14: n = 5; L[4] = cut(L[3], L[0]); L[0] = cut(L[1], L[0]); break;  // V2 V3 V4 up
        case 15: n = 4; break;  // all up
    }
    if (n == 3) L[3] = L[0];
    if (n == 4) L[4] = L[0];
    return n;
}

// The shader's LTC_Evaluate for a quad given in the local frame, with m_inv applied here.
inline float ltc_evaluate(const glm::mat3& m_inv, const glm::vec3 points[4], bool two_sided) {
    glm::vec3 L[5];
    for (int i = 0; i < 4; ++i) L[i] = m_inv * points[i];
    L[4] = L[0];
    const int n = clip_quad_to_horizon(L);
    if (n == 0) return 0.0f;
    for (int i = 0; i < 5; ++i) L[i] = glm::normalize(L[i]);
    float sum = integrate_edge_vec(L[0], L[1]).z + integrate_edge_vec(L[1], L[2]).z + integrate_edge_vec(L[2], L[3]).z;
    if (n >= 4) sum += integrate_edge_vec(L[3], L[4]).z;
    if (n == 5) sum += integrate_edge_vec(L[4], L[0]).z;
    return two_sided ? std::abs(sum) : std::max(0.0f, sum);
}

}  // namespace reference_shader
