// ltc/core/solid_angle.hpp -- signed solid angles of spherical triangles and polygons, unclipped
// and clipped to the horizon (Van Oosterom and Strackee 1983): the integrals of the uniform
// sphere and hemisphere (supplement 1.1, 1.2).
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/horizon_clip.hpp>
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>

LTC_NAMESPACE_BEGIN

/// Signed solid angle of the spherical triangle (q, a, b) of unit vectors, by Van Oosterom and
/// Strackee (1983): tan(Omega / 2) = q.(a x b) / (1 + q.a + q.b + a.b). The triple product is
/// evaluated as (q - a).(a x (b -+ a)), which is exact in exact arithmetic and keeps full
/// relative accuracy for tiny triangles.
template <typename T>
LTC_HOST_DEVICE LTC_INLINE T triangle_solid_angle(const glm::vec<3, T>& q, const glm::vec<3, T>& a,
                                              const glm::vec<3, T>& b) {
    const T ab = glm::dot(a, b);
    const T triple = glm::dot(q - a, detail::stable_cross(a, b, ab));
    return T(2) * std::atan2(triple, T(1) + glm::dot(q, a) + glm::dot(q, b) + ab);
}

namespace detail {

template <typename T, typename Vertices>
LTC_HOST_DEVICE LTC_INLINE T solid_angle(const Vertices& v, std::size_t n) {
    T omega(0);
    // Fan from the first vertex: each triangle is the projection of a planar one, so it lies
    // in an open hemisphere and Van Oosterom's formula applies.
    const bool ok = for_each_unit_edge<T, false>(
        v, n, [&](const glm::vec<3, T>& a, const glm::vec<3, T>& b, const glm::vec<3, T>& q) {
            omega += triangle_solid_angle(q, a, b);
        });
    return ok ? omega : T(0);
}

/// Signed solid angle of the triangle (z, a, b) for unit a, b with a.z, b.z >= 0: Van Oosterom
/// and Strackee with the pole as apex. Every clipped polygon lies in the upper hemisphere, so a
/// fan from the pole is valid and turns the solid angle into a sum of edge terms, as stable as
/// eq. (11) itself, even for polygons close to or in the horizon plane where a fan from one of
/// their own vertices would be made of nearly flat, nearly hemispherical triangles.
template <typename T>
LTC_HOST_DEVICE LTC_INLINE T pole_triangle_solid_angle(const glm::vec<3, T>& a, const glm::vec<3, T>& b) {
    const T ab = glm::dot(a, b);
    return T(2) * std::atan2(stable_cross(a, b, ab).z, T(1) + a.z + b.z + ab);
}

template <typename T, typename Vertices>
LTC_HOST_DEVICE LTC_INLINE T clipped_solid_angle(const Vertices& v, std::size_t n) {
    T omega(0);
    const bool ok = for_each_unit_edge<T, true>(
        v, n, [&](const glm::vec<3, T>& a, const glm::vec<3, T>& b, const glm::vec<3, T>&) {
            omega += pole_triangle_solid_angle(a, b);
        });
    return ok ? omega : T(0);
}

}  // namespace detail

/// Signed solid angle subtended by the polygon (no clipping), in (-2 pi, 2 pi).
template <typename T>
LTC_HOST_DEVICE LTC_INLINE T solid_angle(const glm::vec<3, T>* v, std::size_t n) {
    return detail::solid_angle<T>(v, n);
}

/// Signed solid angle of the part of the polygon above the horizon z >= 0, in (-2 pi, 2 pi).
template <typename T>
LTC_HOST_DEVICE LTC_INLINE T clipped_solid_angle(const glm::vec<3, T>* v, std::size_t n) {
    return detail::clipped_solid_angle<T>(v, n);
}

LTC_NAMESPACE_END
