// ltc/shading/equivalent_sphere.hpp -- the sphere that stands in for a polygon in the clipless
// approximation (ltc/shading/clipless.hpp; Hill and Heitz 2016): the polygon's unclipped vector
// form factor F (ltc/core/form_factor.hpp) gives f = |F| = sin^2(sigma) and the direction of the
// sphere's centre; the polygon's orientation gives the side it is seen from.
//
//   #include <ltc/shading/equivalent_sphere.hpp>
//   ltc::clipless::equivalent_sphere<float> s = ltc::clipless::sphere_of_polygon(vertices, n);
//
// Conventions: signed like every integral of the library, positive for a front face (the vertices
// turning clockwise as seen from the origin: equivalent_sphere, "Orientation"). Degenerate cases:
// the polygon must be planar; for non-planar input the sign test is meaningless.
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/form_factor.hpp>  // vector_form_factor

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>

LTC_NAMESPACE_BEGIN
namespace clipless {

/// The sphere that stands in for a polygon: f = sin^2(sigma) = |F| and cos(omega) = u.z with u
/// the unit direction of F, flipped for a back-facing polygon.
///
/// Orientation. The sphere forgets which side of the polygon faces the shading point (Hill
/// 2016 tests the light's plane equation in the shader). Here the polygon is oriented by the
/// sign of p0 . sum_i p_i x p_i+1 (Newell's normal: positive when the vertices turn clockwise
/// as seen from the origin, the convention of polygon.hpp), in the space where the vertices are
/// given, times the sign of |M^-1|. For a front-facing polygon F points towards it; for a
/// back-facing one F is flipped before the lookup. The result is signed like every integral of
/// the library (positive for a front face) and sidedness applies as usual: one_sided gives 0 for
/// a back face, two_sided the same value for both faces. The polygon must be planar (true for
/// any light and its image under M^-1); for non-planar input the sign test is meaningless.
template <typename T>
struct equivalent_sphere {
    T f;          // |F|, in [0, 1]
    T cos_omega;  // cosine of the angle between the sphere's centre and the normal
    T sign;       // +1 front face, -1 back face, 0 degenerate (F = 0 or not a polygon)
};

namespace detail {

/// +1 when the planar polygon at(0..n) turns clockwise as seen from the origin (polygon.hpp's
/// positive orientation), -1 when counter-clockwise, 0 when degenerate: the sign of
/// p0 . sum p_i x p_i+1, on vertices divided by their largest coordinate (one common factor,
/// so that the polygon stays planar and nothing overflows).
template <typename T, typename VertexAt>
LTC_HOST_DEVICE inline T orientation(const VertexAt& at, std::size_t n) {
    using vec3 = glm::vec<3, T>;
    if (n < 3) return T(0);
    T scale(0);
    for (std::size_t i = 0; i < n; ++i) {
        const vec3 p = at(i);
        scale = glm::max(scale, glm::max(glm::max(std::abs(p.x), std::abs(p.y)), std::abs(p.z)));
    }
    if (!(scale > T(0))) return T(0);
    const vec3 p0 = at(0) / scale;
    vec3 normal(T(0));
    vec3 prev = at(n - 1) / scale;
    for (std::size_t i = 0; i < n; ++i) {
        const vec3 p = at(i) / scale;
        normal += glm::cross(prev - p0, p - p0);  // = sum p_i x p_i+1 over the closed loop
        prev = p;
    }
    const T d = glm::dot(p0, normal);
    return d > T(0) ? T(1) : (d < T(0) ? T(-1) : T(0));
}

template <typename T>
LTC_HOST_DEVICE inline equivalent_sphere<T> sphere_of(const glm::vec<3, T>& F, T facing) {
    const T len = glm::length(F);
    if (!(len > T(0)) || facing == T(0)) return {T(0), T(0), T(0)};
    return {glm::min(len, T(1)), glm::clamp(facing * F.z / len, T(-1), T(1)), facing};
}

}  // namespace detail

/// The equivalent sphere of a polygon (no transformation): its unclipped vector form factor
/// and its orientation.
template <typename T>
LTC_HOST_DEVICE inline equivalent_sphere<T> sphere_of_polygon(const glm::vec<3, T>* vertices, std::size_t n) {
    const auto at = [&](std::size_t i) { return glm::vec<3, T>(vertices[i]); };
    return detail::sphere_of(ltc::vector_form_factor(vertices, n), detail::orientation<T>(at, n));
}

}  // namespace clipless
LTC_NAMESPACE_END
