// ltc/detail/quad_lanes.hpp -- the float quad path on lanes: the quad's four edges in the four
// lanes of one 16-byte vector (SSE2 on x86-64, NEON on AArch64), each adding its part above the
// horizon, plus the horizon edge from the exit crossing to the entry crossing
// (ltc/detail/lanes.inc says why that is the clipped polygon's edge sum). It replaces the switch
// clipper and the five normalizations and edge terms of ltc/core/quad_path.hpp, which takes it for
// float and the symmetric fits (minimax_rational, the float default, and polynomial) where
// LTC_SIMD.
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/edge_policy.hpp>
#include <ltc/detail/lanes.hpp>
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <type_traits>

namespace ltc {
namespace detail {

/// Whether quad_form_factor runs on lanes for T and Policy.
template <typename T, typename Policy>
inline constexpr bool quad_on_lanes = LTC_SIMD && std::is_same_v<T, float> &&
                                      std::is_base_of_v<symmetric_fit<Policy>, Policy>;

#if LTC_SIMD
/// quad_form_factor's sum for the float quad q (M^-1 p of its vertices), or false where the
/// general path must take over: two runs above the horizon, and the lanes' own hand-backs (a
/// vertex or a crossing outside their range, an edge through the shading point: lanes.inc).
template <typename Policy>
LTC_INLINE bool quad_form_factor_lanes(const glm::vec3 (&q)[4], float& sum) {
    using namespace lanes::baseline;
    using VF = types<float>::vf;
    using VI = types<float>::vi;
    // Edge k runs from vertex k - 1 (a) to vertex k (b).
    const VF bx = {q[0].x, q[1].x, q[2].x, q[3].x}, by = {q[0].y, q[1].y, q[2].y, q[3].y};
    const VF bz = {q[0].z, q[1].z, q[2].z, q[3].z};
    const VF ax = __builtin_shufflevector(bx, bx, 3, 0, 1, 2), ay = __builtin_shufflevector(by, by, 3, 0, 1, 2);
    const VF az = __builtin_shufflevector(bz, bz, 3, 0, 1, 2);
    const VF lb = bx * bx + by * by + bz * bz, la = __builtin_shufflevector(lb, lb, 3, 0, 1, 2);
    const VI b_above = bz >= 0.0f, a_above = __builtin_shufflevector(b_above, b_above, 3, 0, 1, 2);
    const unsigned above = bits(b_above);
    sum = 0.0f;
    // All below: 0, unless a vertex is not finite (the general path decides then, as in
    // quad_path.hpp).
    if (above == 0u) return is_finite(q[0]) && is_finite(q[1]) && is_finite(q[2]) && is_finite(q[3]);
    VI fallback = ~((lb > 1e-16f) & (lb < 1e16f));
    VF xx, xy;
    const VF t = clipped_edge<Policy, float>(ax, ay, az, la, a_above, bx, by, bz, lb, b_above, xx, xy, fallback);
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
#endif

}  // namespace detail
}  // namespace ltc
