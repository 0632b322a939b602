// ltc/core/polygon.hpp -- exact integrals over spherical polygons, and horizon clipping.
//
// The polygon machinery of the library, usable on its own:
//   - clip_to_horizon:        Sutherland-Hodgman clipping of an n-gon to the half-space z >= 0;
//   - edge_integral:          the exact edge term of the paper's eq. (11) (Baum et al. 1989);
//   - vector_form_factor:     F = 1/(2 pi) sum of edge terms, the "vector irradiance" of the
//                             unclipped polygon (input of the horizon-clipping approximations);
//   - form_factor:            the clamped-cosine integral of the clipped polygon, eq. (11),
//                             signed, one-sided (max(0, sum)) or two-sided (abs(sum));
//   - solid_angle / clipped_solid_angle: signed solid angles (Van Oosterom & Strackee 1983).
//
// Speed. The clamped-cosine integral of a quad (the common light shape) takes a path of its own:
// clipped before normalization by a switch on the vertices above the horizon, as the paper's
// shader does, then five edge terms without a branch on the vertex count; other polygons, and
// the quads whose degenerate cases need care, take a streaming clipper on unit vertices. The
// edge policies (edge_policy) trade the exact atan2 for float-accurate fits.
//
// Conventions. A polygon is given by n >= 3 vertices (any scale, not necessarily unit) of a
// simple planar polygon, seen from the shading point at the origin; z is the normal of the
// shading frame. Signed results are positive when the vertices turn clockwise as seen from the
// origin, i.e. when dot(p, sum_i p_i x p_i+1) > 0 for any point p of the polygon's plane: the
// polygon's vector area points away from the shading point (for a convex polygon,
// dot(p0, (p1 - p0) x (p2 - p0)) > 0 says the same). Non-convex polygons are handled: every
// result integrates over the winding number of the boundary, which is the polygon's indicator
// for a simple polygon.
//
// Degenerate input never yields NaN or Inf for finite vertices:
//   - n < 3, or a vertex exactly at the origin (then the polygon's plane contains the shading
//     point and the polygon is seen edge-on): every integral is 0;
//   - repeated or collinear vertices: zero-length edges contribute exactly 0;
//   - an edge whose line passes through the origin has no defined great circle: it contributes 0;
//   - a polygon entirely below the horizon clips to nothing: clipped integrals are 0.
#pragma once

#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

namespace ltc {

/// How a one-sided or two-sided emitter turns a signed integral into a non-negative one:
/// one_sided = max(0, signed), two_sided = |signed| (the paper's shader code).
enum class sidedness { one_sided, two_sided };

template <typename T>
LTC_HOST_DEVICE LTC_INLINE T apply_sidedness(T signed_value, sidedness s) {
    return s == sidedness::two_sided ? std::abs(signed_value)
                                     : (signed_value > T(0) ? signed_value : T(0));
}

/// Largest vertex count that clipping an n-gon to a half-space can produce: every run of
/// vertices outside is replaced by two crossing points, and there are at most n/2 such runs.
LTC_HOST_DEVICE constexpr std::size_t clipped_capacity(std::size_t n) { return n + n / 2; }

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
    vec3 u[small_polygon];
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

/// theta / sin(theta) for theta = atan2(s, c), s = sin(theta) >= 0 computed accurately.
/// Where s is too small for the quotient to be representable, the edge has (almost) no
/// length (c > 0: the limit is 1) or passes through the shading point (c < 0: no great circle;
/// its cross product is ~0 and we return 0 so that the product stays finite).
template <typename T>
LTC_HOST_DEVICE LTC_INLINE T theta_over_sin(T s, T c) {
    if (s > min_normal<T>()) return std::atan2(s, c) / s;
    return c > T(0) ? T(1) : T(0);
}

/// theta / sin(theta) from p = f(|c|), a fit of f on c >= 0: p itself for c >= 0, and
/// f(c) = pi / s - f(-c) for c < 0 (theta = pi - theta', same sine), s = |a x b|.
template <typename T>
LTC_HOST_DEVICE LTC_INLINE T symmetric_extension(T c, const glm::vec<3, T>& axb, T p) {
    if (c >= T(0)) return p;
    const T s = glm::length(axb);
    return s > min_normal<T>() ? pi<T>() / s - p : T(0);  // s = 0, c < 0: see theta_over_sin
}

/// Whether Policy fits f on c >= 0 alone (Policy::positive_branch(1 - c)): edge_integral_z then
/// needs only the z component of a x b there.
template <typename Policy, typename T, typename = void>
struct has_positive_branch : std::false_type {};
template <typename Policy, typename T>
struct has_positive_branch<Policy, T, std::void_t<decltype(Policy::template positive_branch<T>(T(0)))>>
    : std::true_type {};

}  // namespace detail

/// How the factor theta / sin(theta) of the edge term is evaluated, from c = cos(theta) and
/// the cross product a x b of the edge's unit vertices (|a x b| = sin(theta), accurate: it comes
/// from a cancellation-free cross product; a policy takes its length only where it needs it).
/// Selected at compile time; every integral of the library defaults to `exact`. A policy may also
/// expose positive_branch(y), its fit of theta / sin(theta) at c = 1 - y >= 0: edge_integral_z
/// then skips the x and y components of a x b there. Measured maximum relative errors of the
/// factor over c in [-1, 1] are in the README and tests/test_edge_policies.cpp.
namespace edge_policy {

/// atan2(s, c) / s: correct to a few ulps at every angle.
struct exact {
    template <typename T>
    LTC_HOST_DEVICE LTC_INLINE static T theta_over_sin(T c, const glm::vec<3, T>& axb) {
        return detail::theta_over_sin(glm::length(axb), c);
    }
};

/// Degree-9 polynomial in y = 1 - c, interpolating f(c) = acos(c) / sqrt(1 - c^2) at the
/// Chebyshev nodes of [0, 1] (near-minimax: 1.3e-8 relative error in exact arithmetic, below
/// float rounding), extended to c < 0 by the symmetry f(c) = pi / s - f(-c).
struct polynomial {
    /// f(|c|) for y = 1 - |c|, branch-free (shared with the vectorized batch path).
    /// Estrin's scheme: four levels of independent multiply-adds instead of a chain of nine.
    template <typename T>
    LTC_HOST_DEVICE LTC_INLINE static T positive_branch(T y) {
        const T y2 = y * y, y4 = y2 * y2;
        const T a01 = T(0.99999999) + T(0.333335381) * y, a23 = T(0.133266572) + T(0.0579778015) * y;
        const T a45 = T(0.0201634898) + T(0.030059176) * y, a67 = T(-0.0335529978) + T(0.0509757585) * y;
        const T a89 = T(-0.0325916887) + T(0.0111628242) * y;
        return (a01 + a23 * y2) + ((a45 + a67 * y2) + a89 * y4) * y4;
    }

    template <typename T>
    LTC_HOST_DEVICE LTC_INLINE static T theta_over_sin(T c, const glm::vec<3, T>& axb) {
        return detail::symmetric_extension(c, axb, positive_branch(T(1) - glm::abs(c)));
    }
};

/// A (3, 2) rational function of y = 1 - c, the relative-error minimax fit of
/// f(c) = acos(c) / sqrt(1 - c^2) on c in [0, 1] (linearized Loeb iteration on 400 Chebyshev
/// points, checked on 4001 points: 4.1e-8 in exact arithmetic, below float's half ulp of 6e-8),
/// extended to c < 0 by f(c) = pi / s - f(-c). Five multiply-adds and one division per edge,
/// against the degree-9 polynomial's nine multiply-adds and two products: the fastest
/// float-accurate policy.
struct minimax_rational {
    template <typename T>
    LTC_HOST_DEVICE LTC_INLINE static T positive_branch(T y) {
        const T p = T(0.999999965867) + y * (T(-0.44145776482) + y * (T(0.0170912151505) + y * T(0.00123519700345)));
        const T q = T(1) + y * (T(-0.774792977409) + y * T(0.142038957683));
        return p / q;
    }

    template <typename T>
    LTC_HOST_DEVICE LTC_INLINE static T theta_over_sin(T c, const glm::vec<3, T>& axb) {
        return detail::symmetric_extension(c, axb, positive_branch(T(1) - glm::abs(c)));
    }
};

/// The rational fit of the paper's reference shader code (Heitz et al. 2016, ltc.glsl,
/// IntegrateEdgeVec), times 2 pi (the shader folds 1 / (2 pi) into it); for c < 0 it uses
/// 1 / sqrt(max(1 - c^2, 1e-7)) as the shader does.
struct rational {
    template <typename T>
    LTC_HOST_DEVICE LTC_INLINE static T theta_over_sin(T c, const glm::vec<3, T>&) {
        const T y = glm::abs(c);
        const T a = T(0.8543985) + (T(0.4965155) + T(0.0145206) * y) * y;
        const T b = T(3.4175940) + (T(4.1616724) + y) * y;
        const T v = a / b;
        const T r = c > T(0) ? v : T(0.5) / std::sqrt(glm::max(T(1) - c * c, T(1e-7))) - v;
        return T(2) * pi<T>() * r;
    }
};

/// The FP16-friendly quadratic of the production note (Chinese note in the sources):
/// 0.33735186 c^2 - 0.89665001 c + pi / 2 for c >= 0, extended to c < 0 by
/// pi / sqrt(1 - c^2) - f(-c). Every operation fits in half precision.
/// Instantiable with T = _Float16 (real half-precision arithmetic; sqrt through float).
struct fp16_quadratic {
    template <typename T>
    LTC_HOST_DEVICE LTC_INLINE static T theta_over_sin(T c, const glm::vec<3, T>&) {
        const T x = c < T(0) ? -c : c;
        const T v = (T(0.33735186f) * x - T(0.89665001f)) * x + T(1.5707963f);
        if (c >= T(0)) return v;
        const T one_minus_c2 = T(1) - c * c;
        return T(3.1415927f) / T(std::sqrt(static_cast<float>(one_minus_c2 > T(1e-4f) ? one_minus_c2 : T(1e-4f)))) - v;
    }
};

}  // namespace edge_policy

/// Exact edge term of eq. (11) for unit vectors a, b: theta * (a x b) / |a x b|, theta the angle
/// between them. With the default policy, computed as atan2(|a x b|, a.b) with a
/// cancellation-free cross product, so it is accurate for nearly parallel and nearly opposite
/// vertices (no acos of a dot product near +-1, no division by a vanishing sine).
template <typename Policy = edge_policy::exact, typename T>
LTC_HOST_DEVICE LTC_INLINE glm::vec<3, T> edge_integral(const glm::vec<3, T>& a, const glm::vec<3, T>& b) {
    const T c = glm::dot(a, b);
    const glm::vec<3, T> axb = detail::stable_cross(a, b, c);
    return axb * Policy::theta_over_sin(c, axb);
}

/// z component of edge_integral(a, b): the edge's contribution to the clamped-cosine integral
/// (times 2 pi).
template <typename Policy = edge_policy::exact, typename T>
LTC_HOST_DEVICE LTC_INLINE T edge_integral_z(const glm::vec<3, T>& a, const glm::vec<3, T>& b) {
    const T c = glm::dot(a, b);
    if constexpr (detail::has_positive_branch<Policy, T>::value) {
        // c >= 0: the z component of a x b = a x (b - a) alone (what stable_cross computes).
        if (c >= T(0)) return (a.x * (b.y - a.y) - a.y * (b.x - a.x)) * Policy::positive_branch(T(1) - c);
    }
    const glm::vec<3, T> axb = detail::stable_cross(a, b, c);
    return axb.z * Policy::theta_over_sin(c, axb);
}

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

namespace detail {

/// vector_form_factor for any Vertices (a pointer, or a callable i -> unit vector).
template <typename T, typename Policy, typename Vertices>
LTC_HOST_DEVICE LTC_INLINE glm::vec<3, T> vector_form_factor(const Vertices& v, std::size_t n) {
    glm::vec<3, T> f(T(0));
    const bool ok = for_each_unit_edge<T, false>(
        v, n, [&](const glm::vec<3, T>& a, const glm::vec<3, T>& b, const glm::vec<3, T>&) {
            f += edge_integral<Policy>(a, b);
        });
    return ok ? f / (T(2) * pi<T>()) : glm::vec<3, T>(T(0));
}

}  // namespace detail

/// Vector form factor F = 1/(2 pi) sum_i edge_integral(p_i, p_i+1) of the unclipped polygon
/// (eq. 11 before the dot with z; Snyder 1996 / Hill 2016). Its z component is the cosine
/// integral without horizon clipping; |F| and its direction define the equivalent sphere of the
/// horizon-clipping approximation.
template <typename Policy = edge_policy::exact, typename T>
LTC_HOST_DEVICE LTC_INLINE glm::vec<3, T> vector_form_factor(const glm::vec<3, T>* v, std::size_t n) {
    return detail::vector_form_factor<T, Policy>(v, n);
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

/// Whether every squared length is in (1e-30, 1e30), the range where normalizing by 1 / sqrt
/// neither overflows nor loses precision: the sum bounds each term from above (and is NaN if one
/// is), the minimum from below; both tests together take fewer instructions than one per length.
template <typename T, typename... Ts>
LTC_HOST_DEVICE LTC_INLINE bool in_range_all(T first, Ts... rest) {
    T lo = first, sum = first;
    ((lo = rest < lo ? rest : lo, sum += rest), ...);
    return sum < T(1e30) && lo > T(1e-30);
}

/// The clamped-cosine edge sum (times 2 pi) of a quad, the common light shape, along the lines of
/// the reference shader: the quad is clipped before normalization by a switch on which vertices
/// are above the horizon, the clipped polygon (3 to 5 vertices) is padded to 5 with repeats of
/// its first vertex (a zero-length edge adds exactly 0 with the library's policies), and 5 edge
/// terms are
/// summed without a branch on the vertex count. Returns false, for form_factor to take the
/// general path, where that path's special cases arise: a vertex of the clipped polygon, or an
/// unnormalized horizon crossing, with |p|^2 outside (1e-30, 1e30) (a vertex at the origin, tiny,
/// huge or not finite, an edge through or near the shading point; also, harmlessly, quads of
/// |M^-1 p| beyond about 1e-7 or 1e7, whose crossings' squared lengths scale as |M^-1 p|^4, and
/// five vertices whose |p|^2 sum to 1e30 or more), a non-finite vertex anywhere, or two separate
/// runs of vertices above the horizon (only a non-convex quad has them). Vertices on the plane
/// z = 0 count as above, as in clip_to_horizon.
template <typename T, typename Policy, typename Vertices>
LTC_HOST_DEVICE LTC_INLINE bool quad_form_factor(const Vertices& v, T& sum) {
    using vec3 = glm::vec<3, T>;
    vec3 q[5];
    unsigned above = 0;
    for (unsigned i = 0; i < 4; ++i) {
        q[i] = raw_vertex<T>(v, i);
        above |= (q[i].z >= T(0) ? 1u : 0u) << i;
    }
    if (above == 5u || above == 10u) return false;
    sum = T(0);
    // All below: 0, unless a vertex is not finite (M^-1 p may overflow to NaN, which counts as
    // below, where the general path's rescaled M^-1 p is above): the general path decides then.
    if (above == 0u) return is_finite(q[0]) && is_finite(q[1]) && is_finite(q[2]) && is_finite(q[3]);
    // X(i, j): where the edge between q_i (above) and q_j (below) meets the horizon.
    const auto X = [&](unsigned i, unsigned j) { return horizon_crossing_direction(q[i], q[j]); };
    // Clipped in place, in the quad's cyclic order (up to a rotation): the vertices above stay,
    // each run of vertices below gives way to the crossing where the boundary leaves and the one
    // where it re-enters. Crossings are computed from the original vertices before any is
    // overwritten; the last slots repeat q[0].
    switch (above) {
        // One vertex above: the opposite one enters no crossing, so the range test below does not
        // see it; a non-finite one sends the quad to the general path, as any other would.
        case 1u:  // [V0, X01, X03]
            if (!is_finite(q[2])) return false;
            q[1] = X(0, 1), q[2] = X(0, 3), q[3] = q[4] = q[0];
            break;
        case 2u:  // [X10, V1, X12]
            if (!is_finite(q[3])) return false;
            q[0] = X(1, 0), q[2] = X(1, 2), q[3] = q[4] = q[0];
            break;
        case 4u:  // [X23, X21, V2]
            if (!is_finite(q[0])) return false;
            q[0] = X(2, 3), q[1] = X(2, 1), q[3] = q[4] = q[0];
            break;
        case 8u: {  // [X30, X32, V3]
            if (!is_finite(q[1])) return false;
            const vec3 x30 = X(3, 0), x32 = X(3, 2);
            q[2] = q[3], q[0] = x30, q[1] = x32, q[3] = q[4] = x30;
            break;
        }
        case 3u: q[2] = X(1, 2), q[3] = X(0, 3), q[4] = q[0]; break;   // [V0, V1, X12, X03]
        case 6u: q[0] = X(1, 0), q[3] = X(2, 3), q[4] = q[0]; break;   // [X10, V1, V2, X23]
        case 9u: q[1] = X(0, 1), q[2] = X(3, 2), q[4] = q[0]; break;   // [V0, X01, X32, V3]
        case 12u: q[0] = X(3, 0), q[1] = X(2, 1), q[4] = q[0]; break;  // [X30, X21, V2, V3]
        case 7u: q[4] = X(0, 3), q[3] = X(2, 3); break;                // [V0, V1, V2, X23, X03]
        case 11u: {                                                    // [V0, V1, X12, X32, V3]
            const vec3 x12 = X(1, 2), x32 = X(3, 2);
            q[4] = q[3], q[2] = x12, q[3] = x32;
            break;
        }
        case 13u: {  // [V0, X01, X21, V2, V3]
            const vec3 x01 = X(0, 1), x21 = X(2, 1);
            q[4] = q[3], q[3] = q[2], q[1] = x01, q[2] = x21;
            break;
        }
        case 14u: q[4] = X(3, 0), q[0] = X(1, 0); break;  // [X10, V1, V2, V3, X30]
        default: q[4] = q[0]; break;                      // 15: [V0, V1, V2, V3]
    }
    // Only the clipped polygon's vertices need the range test: the vertices above are among them,
    // a vertex below that is not finite makes its crossing NaN or infinite (or is the opposite
    // vertex, tested above), and a vertex at the origin has z = 0 and counts as above. A finite
    // vertex below of extreme size still gives an accurate crossing direction.
    T l2[5];
    for (unsigned i = 0; i < 5; ++i) l2[i] = glm::dot(q[i], q[i]);
    if (!in_range_all(l2[0], l2[1], l2[2], l2[3], l2[4])) return false;
    vec3 u[5];
    for (unsigned i = 0; i < 5; ++i) u[i] = q[i] * (T(1) / std::sqrt(l2[i]));
    // Written out: GCC does not unroll a loop over 5 edges once the policy is inlined in it.
    sum = (edge_integral_z<Policy>(u[0], u[1]) + edge_integral_z<Policy>(u[1], u[2])) +
          (edge_integral_z<Policy>(u[2], u[3]) + edge_integral_z<Policy>(u[3], u[4])) +
          edge_integral_z<Policy>(u[4], u[0]);
    return true;
}

template <typename T, typename Policy = edge_policy::exact, typename Vertices>
LTC_HOST_DEVICE LTC_INLINE T form_factor(const Vertices& v, std::size_t n) {
    T sum(0);
    if (n == 4 && quad_form_factor<T, Policy>(v, sum)) return sum / (T(2) * pi<T>());
    const bool ok = for_each_unit_edge<T, true>(
        v, n, [&](const glm::vec<3, T>& a, const glm::vec<3, T>& b, const glm::vec<3, T>&) {
            sum += edge_integral_z<Policy>(a, b);
        });
    return ok ? sum / (T(2) * pi<T>()) : T(0);
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

/// Signed integral of cos(theta) / pi over the horizon-clipped polygon: eq. (11) of the paper,
/// E = 1/(2 pi) sum_i theta_i (p_i x p_j / |p_i x p_j|).z, on the clipped polygon.
/// Policy selects the evaluation of theta / sin(theta) (see edge_policy).
template <typename Policy = edge_policy::exact, typename T>
LTC_HOST_DEVICE LTC_INLINE T form_factor_signed(const glm::vec<3, T>* v, std::size_t n) {
    return detail::form_factor<T, Policy>(v, n);
}

/// form_factor_signed made non-negative for a one-sided or two-sided emitter.
template <typename Policy = edge_policy::exact, typename T>
LTC_HOST_DEVICE LTC_INLINE T form_factor(const glm::vec<3, T>* v, std::size_t n, sidedness s) {
    return apply_sidedness(form_factor_signed<Policy>(v, n), s);
}

}  // namespace ltc
