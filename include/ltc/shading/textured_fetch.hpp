// ltc/shading/textured_fetch.hpp -- the texture coordinates and filter width of the paper's
// fetch for textured quad lights (section 5.4, eq. 15): fetch_parameters; the file comment of
// ltc/shading/textured_light.hpp derives them and lists their robustness.
#pragma once

#include <ltc/config.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

LTC_NAMESPACE_BEGIN

/// The parameters of the prefiltered fetch (file comment).
template <typename T>
struct textured_fetch {
    glm::vec<2, T> uv{T(0.5), T(0.5)};          ///< texture coordinates of the foot point
    T sigma{std::numeric_limits<T>::infinity()}; ///< sqrt(r^2 / (2 A)), uv units
    T distance{0};  ///< |r| / sqrt(A): the distance to the plane in units of sqrt(area)
    bool valid{false};
};

/// Section 5.4: texture coordinates and filter width of the fetch for the quad quad[0..3]
/// (corners with uv (0,0), (1,0), (1,1), (0,1)), seen from the origin through the LTC whose
/// inverse matrix is m_inv (any scale; the identity for the clamped cosine itself).
template <typename T>
inline textured_fetch<T> fetch_parameters(const glm::mat<3, 3, T>& m_inv, const glm::vec<3, T> quad[4]) {
    using vec3 = glm::vec<3, double>;
    textured_fetch<T> out;
    double s = 0;
    for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 3; ++c) s = std::max(s, std::abs(static_cast<double>(quad[i][c])));
    if (!(s > 0) || !std::isfinite(s)) return out;
    const glm::dmat3 mi(m_inv);
    vec3 q[4];
    for (int i = 0; i < 4; ++i) q[i] = mi * (vec3(quad[i]) / s);
    const vec3 e1 = q[1] - q[0], e3 = q[3] - q[0];
    const vec3 n = glm::cross(q[2] - q[0], q[3] - q[1]);
    const double n_len = glm::length(n);
    const double area = 0.5 * n_len;
    const vec3 c13 = glm::cross(e1, e3);
    const double det = glm::dot(c13, c13);
    if (!(area > 0) || !(det > 0) || !std::isfinite(n_len) || !std::isfinite(det)) return out;
    const vec3 nh = n / n_len;
    const double r = glm::dot(nh, 0.25 * (q[0] + q[1] + q[2] + q[3]));
    const vec3 w = r * nh - q[0];
    const double u = glm::dot(glm::cross(w, e3), c13) / det;
    const double v = glm::dot(glm::cross(e1, w), c13) / det;
    const double sigma = std::abs(r) / std::sqrt(2.0 * area);
    if (!std::isfinite(u) || !std::isfinite(v) || !std::isfinite(sigma)) return out;
    constexpr double far = 1e6;  // far outside the texture: the lookup clamps anyway
    out.uv = glm::vec<2, T>(T(std::min(std::max(u, -far), far)), T(std::min(std::max(v, -far), far)));
    out.sigma = T(sigma);
    out.distance = T(std::abs(r) / std::sqrt(area));
    out.valid = true;
    return out;
}

LTC_NAMESPACE_END
