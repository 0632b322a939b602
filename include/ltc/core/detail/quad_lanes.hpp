// ltc/core/detail/quad_lanes.hpp -- the float quad path on lanes: the quad's four edges in the four
// lanes of one 16-byte vector (SSE2 on x86-64, NEON on AArch64), each adding its part above the
// horizon, plus the horizon edge from the exit crossing to the entry crossing
// (ltc/shading/detail/lanes.inc says why that is the clipped polygon's edge sum). It replaces the switch
// clipper and the five normalizations and edge terms of ltc/core/quad_path.hpp, which takes it for
// float and the symmetric fits (minimax_rational, the float default, and polynomial) where
// LTC_SIMD.
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/edge_policy.hpp>
#include <ltc/shading/detail/lanes.hpp>
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <type_traits>
#include <utility>

LTC_NAMESPACE_BEGIN
namespace detail {

/// Whether quad_form_factor runs on lanes for T and Policy.
template <typename T, typename Policy>
inline constexpr bool quad_on_lanes = LTC_SIMD && std::is_same_v<T, float> &&
                                      std::is_base_of_v<symmetric_fit<Policy>, Policy>;

/// Whether vertices v are M^-1 p_i given as v.m_inv and v.v (transformed<>'s vertices): the lanes
/// then apply M^-1 themselves, four vertices at once.
template <typename Vertices, typename = void>
struct matrix_and_points : std::false_type {};
template <typename Vertices>
struct matrix_and_points<Vertices, std::void_t<decltype(std::declval<const Vertices&>().m_inv),
                                               decltype(std::declval<const Vertices&>().v)>> : std::true_type {};

#if LTC_SIMD
/// quad_form_factor's sum for the float quad whose vertices (M^-1 p, any scale: normalized here)
/// are in the lanes of bx, by, bz, or false where the general path must take over: two runs
/// above the horizon, and the lanes' own hand-backs (a vertex or a crossing outside their range,
/// an edge through the shading point: lanes.inc).
template <typename Policy, typename VF>
LTC_INLINE bool quad_form_factor_lanes(VF bx, VF by, VF bz, float& sum) {
    using namespace lanes::baseline;
    using VI = types<float>::vi;
    const VI b_above = bz >= 0.0f, a_above = __builtin_shufflevector(b_above, b_above, 3, 0, 1, 2);
    sum = 0.0f;
    // All below: 0, unless a vertex is not finite (|v|^2 - |v|^2 is then NaN, not 0): the general
    // path decides then, as in quad_path.hpp.
    if (bits(b_above) == 0u) {
        const VF l2 = bx * bx + by * by + bz * bz;
        return bits(l2 - l2 == 0.0f) == 0xfu;
    }
    VI fallback{};
    normalize_vertex(bx, by, bz, fallback);
    // Edge k runs from vertex k - 1 (a) to vertex k (b).
    const VF ax = __builtin_shufflevector(bx, bx, 3, 0, 1, 2), ay = __builtin_shufflevector(by, by, 3, 0, 1, 2);
    const VF az = __builtin_shufflevector(bz, bz, 3, 0, 1, 2);
    VF xx, xy;
    const VF t = clipped_edge<Policy, float>(ax, ay, az, a_above, bx, by, bz, b_above, xx, xy, fallback);
    const unsigned exits = bits(a_above & ~b_above), entries = bits(b_above & ~a_above);
    if (bits(fallback) != 0u || (exits & (exits - 1u)) != 0u) return false;  // a hand-back, or two exits
    float horizon = 0.0f;
    if (exits != 0u) {
        const int e = __builtin_ctz(exits), r = __builtin_ctz(entries);
        VI degenerate;
        const VF h = horizon_term<Policy, float>(splat(xx[e]), splat(xy[e]), splat(xx[r]), splat(xy[r]), degenerate);
        if (bits(degenerate) != 0u) return false;
        horizon = h[0];
    }
    sum = ((t[0] + t[1]) + (t[2] + t[3])) + horizon;
    return true;
}

/// The same from the quad's vertices: M^-1 p_i applied four at once (glm's order of operations)
/// where v gives M^-1 and the p_i, else the vertices as quad_form_factor reads them (q).
template <typename Policy, typename Vertices>
LTC_INLINE bool quad_form_factor_lanes(const Vertices& v, const glm::vec3 (&q)[4], float& sum) {
    using VF = lanes::baseline::types<float>::vf;
    if constexpr (matrix_and_points<Vertices>::value) {
        const glm::mat3& m = v.m_inv;
        const glm::vec3* p = v.v;
        const VF px = {p[0].x, p[1].x, p[2].x, p[3].x}, py = {p[0].y, p[1].y, p[2].y, p[3].y};
        const VF pz = {p[0].z, p[1].z, p[2].z, p[3].z};
        return quad_form_factor_lanes<Policy>(m[0][0] * px + m[1][0] * py + m[2][0] * pz,
                                              m[0][1] * px + m[1][1] * py + m[2][1] * pz,
                                              m[0][2] * px + m[1][2] * py + m[2][2] * pz, sum);
    } else {
        const VF bx = {q[0].x, q[1].x, q[2].x, q[3].x}, by = {q[0].y, q[1].y, q[2].y, q[3].y};
        const VF bz = {q[0].z, q[1].z, q[2].z, q[3].z};
        return quad_form_factor_lanes<Policy>(bx, by, bz, sum);
    }
}
#endif

}  // namespace detail
LTC_NAMESPACE_END
