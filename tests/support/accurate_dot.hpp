// Dot products and matrix-vector products accurate relative to their own result, for references
// whose inputs lie close to a plane (support/brute_force.hpp: heights just above the horizon).
#pragma once

#include <glm/glm.hpp>

#include <cmath>

namespace ltc_test {

/// a.b as accurate as if computed with twice the working precision, then rounded (Ogita, Rump
/// and Oishi's Dot2 with an FMA-based TwoProduct).
inline double accurate_dot(const glm::dvec3& a, const glm::dvec3& b) {
    double p = a.x * b.x;
    double e = std::fma(a.x, b.x, -p);
    for (int k = 1; k < 3; ++k) {
        const double q = a[k] * b[k];
        const double eq = std::fma(a[k], b[k], -q);
        const double sum = p + q;
        const double z = sum - p;
        e += ((p - (sum - z)) + (q - z)) + eq;  // TwoSum error + product error
        p = sum;
    }
    return p + e;
}

/// m * v with every component accurate relative to itself (see accurate_dot).
inline glm::dvec3 accurate_transform(const glm::dmat3& m, const glm::dvec3& v) {
    const glm::dmat3 t = glm::transpose(m);  // rows of m
    return {accurate_dot(t[0], v), accurate_dot(t[1], v), accurate_dot(t[2], v)};
}

}  // namespace ltc_test
