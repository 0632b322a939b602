// ltc/core/quad_path.hpp -- the fast path of the clamped-cosine integral of a quad, the common
// light shape: clipped before normalization by a switch on the vertices above the horizon (as the
// paper's shader does), then five edge terms without a branch on the vertex count. form_factor
// (ltc/core/form_factor.hpp) takes it for n = 4 and falls back to the general path where it
// declines. In float with the symmetric fits (minimax_rational, the float default, and
// polynomial) it runs on four lanes instead, one edge per lane (ltc/core/detail/quad_lanes.hpp),
// in every build (with or without LTC_NO_SIMD, in CUDA device code), with the same bits in each.
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/edge_integral.hpp>
#include <ltc/core/horizon_clip.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/core/detail/quad_lanes.hpp>
#include <ltc/core/detail/vertices.hpp>

#include <glm/glm.hpp>

#include <cmath>

LTC_NAMESPACE_BEGIN

namespace detail {

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
/// z = 0 count as above, as in clip_to_horizon. For float and the symmetric fits
/// (quad_on_lanes) the lanes of quad_lanes.hpp compute the sum instead, with hand-backs of their
/// own (quad_sum there).
template <typename T, typename Policy, typename Vertices>
LTC_HOST_DEVICE LTC_INLINE bool quad_form_factor(const Vertices& v, T& sum) {
    using vec3 = glm::vec<3, T>;
    if constexpr (quad_on_lanes<T, Policy>) return quad_form_factor_lanes<Policy>(v, sum);
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

}  // namespace detail

LTC_NAMESPACE_END
