// ltc/shading/textured_fetch.hpp -- the texture coordinates and filter width of the paper's
// fetch for textured quad lights (section 5.4, eq. 15): fetch_parameters, which derives them and
// lists their degenerate cases; ltc/shading/lights/textured_quad_light.hpp uses them.
#pragma once

#include <ltc/config.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

LTC_NAMESPACE_BEGIN

/// The parameters of the prefiltered fetch (fetch_parameters).
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
///
/// Eq. 15. In the cosine configuration (the quad's corners mapped by M^-1, where D becomes the
/// clamped cosine D_o around +z and the shading point stays at the origin), the shading point is
/// projected orthogonally onto the plane of the quad:
///
///   q_i = M^-1 p_i,  n = (q_2 - q_0) x (q_3 - q_1)  (twice the vector area),  A = |n| / 2,
///   r = n^ . (q_0 + q_1 + q_2 + q_3) / 4   (signed distance of the plane; |r| is used),
///   f = r n^  (the foot of the perpendicular from the origin),
///   (u, v): f = q_0 + u (q_1 - q_0) + v (q_3 - q_0)  (least squares in the plane),
///   sigma = sqrt(r^2 / (2 A))   (texture-space standard deviation, uv units),
///   lod = tex.lod_for_sigma(sigma).
///
/// (u, v) and sigma are invariant to the scale of M^-1 and of the quad (r^2 / A is scale-free),
/// so the quad is first divided by its largest coordinate (no overflow of M^-1 p for huge
/// input). A linear map keeps planes planar and parallelograms parallelograms, and maps the
/// affine texture parameterization q_0 + u e_1 + v e_3 onto the world one, so (u, v) is the
/// texture coordinate of the world-space point whose image is f. Texture mapping: the quad is
/// taken as the parallelogram spanned from corner 0 by corners 1 and 3 (exact for rectangles
/// and parallelograms; corner 2 only enters the area vector), the same mapping as the ground
/// truth of ltc/reference/textured_ground_truth.hpp.
///
/// Robustness (never NaN or Inf for finite input):
///   - plane behind the shading point, or light below the horizon: |r| is used.
///   - grazing (shading point in or near the light plane): r -> 0, sigma -> 0, the sharpest
///     level at the foot point, which is where the light is (I_D -> 0 there too).
///   - a foot point far outside the texture: uv outside [0, 1]; the lookup clamps it to the
///     margin of the prefiltered levels (light_texture.hpp), where the filter is wide and smooth.
///   - degenerate quad (zero area, coincident corners) or non-finite intermediate values:
///     `valid` is false, uv = (0.5, 0.5) and sigma = +inf (the last, widest level: about the
///     texture's average).
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
