// ltc/core/detail/vertices.hpp -- how the polygon machinery reads vertex i: from a pointer to glm
// vectors, or from a callable (transformed<> applies M^-1 on the fly, without a vertex buffer),
// as a unit vector (the general path) or as a raw direction of any scale (the quad path).
#pragma once

#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <cstddef>
#include <type_traits>
#include <utility>

LTC_NAMESPACE_BEGIN

namespace detail {

/// Vertex i of a polygon as a unit vector (0 for a vertex at the origin), from either a pointer
/// to glm vectors or a callable i -> unit vec3 (the latter lets transformed<> apply M^-1 on the
/// fly, without a vertex buffer).
template <typename T, typename Vertices>
LTC_HOST_DEVICE LTC_INLINE glm::vec<3, T> unit_vertex(const Vertices& v, std::size_t i) {
    if constexpr (std::is_pointer_v<Vertices>)
        return safe_normalize(glm::vec<3, T>(v[i]));
    else
        return v(i);
}

/// Vertex i before normalization: p_i itself, M^-1 p_i for transformed<> (its raw()), or what
/// another callable returns (any positive multiple of the direction).
template <typename T, typename Vertices, typename = void>
struct has_raw : std::false_type {};
template <typename T, typename Vertices>
struct has_raw<T, Vertices, std::void_t<decltype(std::declval<const Vertices&>().raw(std::size_t(0)))>>
    : std::true_type {};

/// Vertices from a callable raw_at(i) returning directions of any scale: unit vectors for the
/// general path, the raw directions for the quad path, which normalizes after clipping (so that
/// neither normalizes twice).
template <typename RawAt>
struct directions {
    RawAt raw_at;
    LTC_HOST_DEVICE LTC_INLINE auto raw(std::size_t i) const { return raw_at(i); }
    LTC_HOST_DEVICE LTC_INLINE auto operator()(std::size_t i) const { return safe_normalize(raw_at(i)); }
};
template <typename RawAt>
LTC_HOST_DEVICE LTC_INLINE directions<RawAt> make_directions(const RawAt& raw_at) {
    return {raw_at};
}

template <typename T, typename Vertices>
LTC_HOST_DEVICE LTC_INLINE glm::vec<3, T> raw_vertex(const Vertices& v, std::size_t i) {
    if constexpr (std::is_pointer_v<Vertices>)
        return glm::vec<3, T>(v[i]);
    else if constexpr (has_raw<T, Vertices>::value)
        return v.raw(i);
    else
        return v(i);
}

}  // namespace detail

LTC_NAMESPACE_END
