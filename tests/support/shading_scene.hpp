// A random shading point for world-space shading tests (tests/test_shape_lights.cpp,
// tests/test_tube_light.cpp): P, a random normal N with its tangents, and V at theta_v from N in
// the (t1, N) plane, so that local coordinates (the frame of the LTC tables) map to world space.
#pragma once

#include "support/rng.hpp"

#include <ltc/shading/shading_frame.hpp>

#include <glm/glm.hpp>

#include <cmath>

namespace ltc_test {

struct shading_scene {
    glm::dvec3 P, N, V, t1, t2;
    glm::dvec3 direction(const glm::dvec3& l) const { return l.x * t1 + l.y * t2 + l.z * N; }
    glm::dvec3 world(const glm::dvec3& l) const { return P + direction(l); }
};

inline shading_scene random_shading_scene(rng& r, double cos_theta_v) {
    shading_scene s;
    for (int k = 0; k < 3; ++k) s.P[k] = r.uniform(-1, 1);
    s.N = r.direction(), s.t1 = ltc::orthonormal_tangent(s.N), s.t2 = glm::cross(s.N, s.t1);
    s.V = s.direction(glm::dvec3(std::sqrt(1 - cos_theta_v * cos_theta_v), 0, cos_theta_v));
    return s;
}

}  // namespace ltc_test
