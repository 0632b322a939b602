// Shared pieces of the textured light tests (test_textured.cpp, test_textured_ground_truth.cpp):
// GGX lobes from the shipped table and random rectangles in front of the shading point.
#pragma once

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/shading/ggx_fetch.hpp>

#include "support/rng.hpp"

#include <glm/glm.hpp>

#include <cmath>

namespace ltc_test::textured_checks {

using dvec3 = glm::dvec3;

template <typename T>
ltc::transformed<ltc::clamped_cosine<T>> ggx_lobe(T cos_theta_v, T roughness) {
    return ltc::transformed<ltc::clamped_cosine<T>>::from_inverse(ltc::ggx::fetch<T>(cos_theta_v, roughness).m_inv);
}

/// A random rectangle in front of the shading point (above the horizon on average).
inline void random_quad(ltc_test::rng& r, dvec3 q[4]) {
    const dvec3 c(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(0.5, 2));
    dvec3 a = r.direction(), b = r.direction();
    b = glm::normalize(b - a * glm::dot(a, b));
    a *= r.uniform(0.2, 1.5);
    b *= r.uniform(0.2, 1.5);
    q[0] = c - a - b;
    q[1] = c + a - b;
    q[2] = c + a + b;
    q[3] = c - a + b;
}

inline bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
inline bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace ltc_test::textured_checks
