// ltc/core/horizon_clip.hpp -- clipping a polygon to the horizon z >= 0 (Sutherland-Hodgman),
// as the paper's section 5.1 requires before eq. (11): clip_to_horizon writes the clipped polygon;
// the integrals stream its edges as unit vectors (detail::for_each_unit_edge), with no vertex
// buffer for any n.
#pragma once

#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/core/detail/vertices.hpp>

#include <glm/glm.hpp>

#include <cstddef>

LTC_NAMESPACE_BEGIN

/// Largest vertex count that clipping an n-gon to a half-space can produce: every run of
/// vertices outside is replaced by two crossing points, and there are at most n/2 such runs.
LTC_HOST_DEVICE constexpr std::size_t clipped_capacity(std::size_t n) { return n + n / 2; }

namespace detail {

/// The point where the segment from `in` (z >= 0) to `out` (z < 0) meets the plane z = 0, up to
/// a positive factor: in * (-out.z) + out * in.z needs no division, and z is set to exactly 0.
template <typename T>
LTC_HOST_DEVICE LTC_INLINE glm::vec<3, T> horizon_crossing_direction(const glm::vec<3, T>& in,
                                                                 const glm::vec<3, T>& out) {
    glm::vec<3, T> x = in * (-out.z) + out * in.z;
    x.z = T(0);
    return x;
}

/// Sutherland-Hodgman against z >= 0, with the crossing point computed by `crossing(in, out)`.
/// Calls emit(p) for each vertex of the clipped polygon, in order.
template <typename T, typename VertexAt, typename Crossing, typename Emit>
LTC_HOST_DEVICE LTC_INLINE void clip_horizon(const VertexAt& at, std::size_t n, const Crossing& crossing,
                                         Emit&& emit) {
    // Start with the closing edge (n-1 -> 0) so that an unclipped polygon comes out unchanged.
    glm::vec<3, T> p = at(n - 1);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec<3, T> q = at(i);
        const bool p_in = p.z >= T(0);
        const bool q_in = q.z >= T(0);
        if (p_in != q_in) emit(p_in ? crossing(p, q) : crossing(q, p));
        if (q_in) emit(q);
        p = q;
    }
}

/// Calls edge(last, p, first) for each edge of the polygon whose unit vertices at(i) are given,
/// clipped to z >= 0 first when clip is true (Sutherland-Hodgman, streaming: no vertex buffer).
template <typename T, bool clip, typename VertexAt, typename EdgeFn>
LTC_HOST_DEVICE LTC_INLINE void stream_unit_edges(const VertexAt& at, std::size_t n, EdgeFn& edge) {
    using vec3 = glm::vec<3, T>;
    vec3 first(T(0)), last(T(0));
    bool started = false;
    const auto emit = [&](const vec3& p) {
        if (started)
            edge(last, p, first);
        else
            first = p, started = true;
        last = p;
    };
    if constexpr (clip) {
        const auto crossing = [](const vec3& in, const vec3& out) {
            return safe_normalize(horizon_crossing_direction(in, out));
        };
        clip_horizon<T>(at, n, crossing, emit);
    } else {
        for (std::size_t i = 0; i < n; ++i) emit(at(i));
    }
    if (started) edge(last, first, first);
}

/// Largest vertex count of the small-polygon path below.
inline constexpr std::size_t small_polygon = 8;

/// for_each_unit_edge for polygons of n <= small_polygon vertices: the unit vertices are computed
/// up front, on the stack, so that all normalizations are independent (they overlap in the
/// pipeline), and the common cases, a polygon wholly above or wholly below the horizon, skip the
/// clipper's per-vertex branches. The edges, their order and their values are those of the
/// streaming path.
template <typename T, bool clip, typename Vertices, typename EdgeFn>
LTC_HOST_DEVICE LTC_INLINE bool for_each_small_unit_edge(const Vertices& vertices, std::size_t n, EdgeFn& edge) {
    using vec3 = glm::vec<3, T>;
    vec3 u[small_polygon]{};  // all written below for i < n; zeroed so that GCC -O2 sees it (-Wmaybe-uninitialized)
    bool at_origin = false;
    std::size_t above = 0;
    for (std::size_t i = 0; i < n; ++i) {
        u[i] = unit_vertex<T>(vertices, i);
        at_origin = at_origin || u[i] == vec3(T(0));
        above += u[i].z >= T(0) ? 1 : 0;
    }
    if (!clip || above == n) {
        for (std::size_t i = 0; i + 1 < n; ++i) edge(u[i], u[i + 1], u[0]);
        edge(u[n - 1], u[0], u[0]);
    } else if (above > 0) {
        stream_unit_edges<T, clip>([&](std::size_t i) { return u[i]; }, n, edge);
    }
    return !at_origin;
}

/// Calls edge(a, b, first) for each edge a -> b of the polygon as unit vectors, where `first`
/// is the polygon's first unit vertex (an apex for fan triangulations). With clip = true the
/// polygon is first clipped to z >= 0. Returns false when a vertex is at the
/// origin (the polygon is seen edge-on; the edges seen so far have then been called with a zero
/// vertex, which every edge term maps to a finite value) or n < 3: callers discard the sum.
template <typename T, bool clip, typename Vertices, typename EdgeFn>
LTC_HOST_DEVICE LTC_INLINE bool for_each_unit_edge(const Vertices& vertices, std::size_t n, EdgeFn&& edge) {
    using vec3 = glm::vec<3, T>;
    if (n < 3) return false;
    if (n <= small_polygon) return for_each_small_unit_edge<T, clip>(vertices, n, edge);
    bool at_origin = false;
    const auto unit_at = [&](std::size_t i) {
        const vec3 u = unit_vertex<T>(vertices, i);
        at_origin = at_origin || u == vec3(T(0));
        return u;
    };
    stream_unit_edges<T, clip>(unit_at, n, edge);
    return !at_origin;
}

}  // namespace detail

/// Clips the polygon to the upper half-space z >= 0 (Sutherland-Hodgman). Writes the clipped
/// polygon to `out`, which must hold clipped_capacity(n) vertices, and returns its vertex
/// count (0 when nothing is above the horizon or n < 3). Vertices keep their positions and their
/// order (a polygon entirely above the horizon is copied unchanged); a vertex exactly on z = 0
/// followed by one below is written twice (as itself and as the crossing point); points
/// on the plane z = 0 count as inside and crossing points have z exactly 0. For a non-convex
/// polygon the result may contain edges that run back and forth along z = 0: they cancel in
/// every integral of this library (the winding number is unchanged).
template <typename T>
LTC_HOST_DEVICE LTC_INLINE std::size_t clip_to_horizon(const glm::vec<3, T>* in, std::size_t n,
                                                   glm::vec<3, T>* out) {
    if (n < 3) return 0;
    std::size_t m = 0;
    const auto at = [&](std::size_t i) { return in[i]; };
    const auto crossing = [](const glm::vec<3, T>& a, const glm::vec<3, T>& b) {
        // a.z >= 0 > b.z. Dividing both heights by the larger one keeps a.z - b.z in [1, 2]
        // (no overflow for huge, no 0/0 for subnormal heights); the convex combination
        // a (1 - t) + b t does not overflow where b - a would.
        const T s = glm::max(a.z, -b.z);
        const T t = (a.z / s) / (a.z / s - b.z / s);
        // Clamping to the segment's bounding box keeps the rounding of a (1 - t) + b t from
        // stepping past FLT_MAX when a and b are both near it.
        glm::vec<3, T> x = glm::clamp(a * (T(1) - t) + b * t, glm::min(a, b), glm::max(a, b));
        x.z = T(0);
        return x;
    };
    detail::clip_horizon<T>(at, n, crossing, [&](const glm::vec<3, T>& p) { out[m++] = p; });
    return m;
}

LTC_NAMESPACE_END
