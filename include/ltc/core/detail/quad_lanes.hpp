// ltc/core/detail/quad_lanes.hpp -- the float quad path on four lanes (ltc/core/detail/f32x4.hpp),
// one edge of the quad per lane: the clamped-cosine edge sum of eq. (11), times 2 pi, over the
// quad clipped to the horizon z >= 0. quad_path.hpp takes it for float and the symmetric fits
// (minimax_rational, the float default, and polynomial) in every build, in place of its switch
// clipper, and the result has the same bits in every build: the lanes use only correctly rounded
// operations (1 / sqrt, exact division; no estimate instruction, no fused multiply-add), in an
// order fixed by the source, whether they are a vector register or a plain struct (LTC_NO_SIMD,
// CUDA, MSVC) (f32x4.hpp: built with -ffp-contract=off).
//
// Conventions: vertices M^-1 p_k of any scale, z = 0 counting as above (as in clip_to_horizon).
// Degenerate cases: the path declines (false, sum 0) where the general path's special cases
// arise (quad_sum lists them); a quad wholly below the horizon gives 0.
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/detail/f32x4.hpp>
#include <ltc/core/detail/vertices.hpp>
#include <ltc/core/edge_policy.hpp>
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <type_traits>
#include <utility>

LTC_NAMESPACE_BEGIN
namespace detail {

/// Whether quad_form_factor runs on lanes for T and Policy: float with a symmetric fit, in every
/// build.
template <typename T, typename Policy>
inline constexpr bool quad_on_lanes = std::is_same_v<T, float> && std::is_base_of_v<symmetric_fit<Policy>, Policy>;

/// Whether vertices v are M^-1 p_i given as v.m_inv and v.v (transformed<>'s vertices): the lanes
/// then apply M^-1 themselves, four vertices at once, in glm's order of operations.
template <typename Vertices, typename = void>
struct matrix_and_points : std::false_type {};
template <typename Vertices>
struct matrix_and_points<Vertices, std::void_t<decltype(std::declval<const Vertices&>().m_inv),
                                               decltype(std::declval<const Vertices&>().v)>> : std::true_type {};

namespace lanes4 {

/// The index of the lowest set bit of b, for b in [1, 15].
LTC_HOST_DEVICE LTC_INLINE int lowest_lane(unsigned b) { return (b & 1u) ? 0 : (b & 2u) ? 1 : (b & 4u) ? 2 : 3; }

/// theta n_z of the edge p -> q of unit vectors, lane by lane (quad_sum); `degenerate` marks
/// the lanes with c < 0 and sin(theta)^2 <= 1e-30.
template <typename Policy, typename F, typename M>
LTC_HOST_DEVICE LTC_INLINE F edge_terms(const F& px, const F& py, const F& pz, const F& qx, const F& qy, const F& qz,
                                        M& degenerate) {
    const F c = px * qx + py * qy + pz * qz;
    const M positive = c >= 0.0f;
    // q - p where c >= 0, q + p where c < 0 (stable_cross).
    const F sp = select(positive, splat<F>(-1.0f), splat<F>(1.0f));
    const F dx = qx + sp * px, dy = qy + sp * py, dz = qz + sp * pz;
    const F cz = px * dy - py * dx;
    F f;
    Policy::evaluate_positive_branch(F(1.0f - lane_abs(c)), f);
    const F t = f * cz;
    degenerate = M{};
    if (bits(positive) == 0xfu) return t;  // most edges of most lights (c < 0: longer than 90 degrees)
    const F s2 = (1.0f - c) * (dx * dx + dy * dy + dz * dz) * 0.5f;
    degenerate = ~positive & ~(s2 > 1e-30f);
    return select(positive, t, pi<float>() * cz / lane_sqrt(s2) - t);
}

/// The same for the horizon edge p -> q (unit vectors in the plane z = 0), in scalar code: the
/// operations of edge_terms with p.z = q.z = 0, and pi / sin(theta) (p x q).z as pi with the sign
/// of (p x q).z. `degenerate`: c < 0 and (p x q).z^2 <= 1e-30.
template <typename Policy>
LTC_HOST_DEVICE LTC_INLINE float horizon_term(float px, float py, float qx, float qy, bool& degenerate) {
    const float c = px * qx + py * qy;
    const bool positive = c >= 0.0f;
    const float sp = positive ? -1.0f : 1.0f;
    const float cz = px * (qy + sp * py) - py * (qx + sp * px);
    float f;
    Policy::evaluate_positive_branch(1.0f - std::fabs(c), f);
    const float t = f * cz;
    degenerate = !positive && !(cz * cz > 1e-30f);
    return positive ? t : std::copysign(pi<float>(), cz) - t;
}

/// quad_form_factor's sum for the float quad whose vertices (M^-1 p, any scale) are in the lanes
/// of bx, by, bz, or false (sum 0) where the general path must take over (below).
///
/// The clamped-cosine edge sum of eq. (11), times 2 pi, over the quad clipped to the horizon
/// z >= 0 (vertices with z = 0 count as above, as in clip_to_horizon). Lane k holds edge k, from
/// v_{k-1} = a to v_k = b (v_k = M^-1 p_k, any scale):
///   - the edge contributes its part above the horizon, [a or X, b or X] (0 where both ends are
///     below), X its unit horizon crossing; the clipped polygon's horizon edge runs from the
///     crossing of the edge that exits (a above, b below) to that of the edge that enters (in a
///     quad with one run of vertices above the horizon there is one of each);
///   - the vertices above the horizon are normalized, u = v * (1 / sqrt(|v|^2));
///   - the crossing comes from the raw vertices, x = a.z b - b.z a, which is (a.z - b.z) |a| |b|
///     times the chord's point on the horizon between the unit vertices (the crossing of the
///     great circle, z = 0): X = x * (+-1 / sqrt(|x|^2)), + for the exit (a.z - b.z > 0), - for
///     the entry. It needs neither the unit vertices nor a division, so the crossings and the
///     vertices are normalized together, one square root per lane: a vertex below the horizon is
///     never normalized and lends its lane to the crossing next to it (with one vertex below, the
///     entry's crossing is normalized apart). Where |x|^2 <= 1e-36 (tiny vertices, or an edge
///     whose ends are both within about 1e-18 |v| of the horizon) the square would lose precision:
///     those quads take X = (a.z b - b.z a) / (a.z - b.z) from the unit vertices, whose length is
///     at least the chord's distance to the origin;
///   - each edge term is theta n_z = f(c) (p x q).z of edge_integral_z, for unit p, q and
///     c = p . q: f the policy's fit of theta / sin(theta) on c >= 0, evaluated at 1 - |c|, and
///     the cancellation-free cross product p x (q - p) (c >= 0) or p x (q + p) (c < 0); for c < 0,
///     theta / sin(theta) = pi / sin(theta) - f(-c) (symmetric_extension) with
///     sin(theta)^2 = (1 - c) |q + p|^2 / 2 (no cancellation: 1 + c = |q + p|^2 / 2 for unit
///     vectors), and for the horizon edge, whose p x q is along z, (pi / sin(theta)) (p x q).z is
///     pi with the sign of (p x q).z (computed in scalar code, the same operations);
///   - the sum is ((e_0 + e_1) + (e_2 + e_3)) + h, h the horizon edge's term (no h without a
///     crossing).
///
/// The path declines (returns false, sum 0: form_factor takes the general path, whose special
/// cases these are) where a vertex has |M^-1 p|^2 outside (1e-16, 1e16) (a vertex at the origin,
/// tiny, huge or not finite: the general path rescales), a crossing of the unit vertices has
/// |X|^2 <= 1e-16 (an edge passing within about 1e-8 of the shading point; tested as
/// |x|^2 <= 1e-16 (a.z^2 |b|^2 + b.z^2 |a|^2), which is |X|^2 <= 1e-16 to within a factor 2), the
/// quad has two runs of vertices above the horizon (two exits: only a non-convex quad has them),
/// or an edge above the horizon has c < 0 and sin(theta)^2 <= 1e-30 (endpoints nearly opposite:
/// the edge passes by the shading point, where the general path's theta / sin(theta) takes its own
/// limit), the horizon edge likewise with (p x q).z^2 <= 1e-30. A quad wholly below the horizon
/// gives 0, unless a vertex is not finite (|v|^2 - |v|^2 is then NaN): the general path decides
/// then.
template <typename Policy, typename F>
LTC_HOST_DEVICE LTC_INLINE bool quad_sum(const F& bx, const F& by, const F& bz, float& sum) {
    using M = decltype(bz >= 0.0f);
    sum = 0.0f;
    const M b_above = bz >= 0.0f;
    const unsigned above = bits(b_above);
    const F l2 = bx * bx + by * by + bz * bz;
    if (above == 0u) return bits(l2 - l2 == 0.0f) == 0xfu;
    // Lane k holds edge k, from vertex k - 1 (a) to vertex k (b).
    const unsigned a_bits = ((above << 1) | (above >> 3)) & 0xfu;
    const unsigned exits = a_bits & ~above, entries = above & ~a_bits;
    if ((exits & (exits - 1u)) != 0u) return false;  // two runs above the horizon
    if (bits((l2 > 1e-16f) & (l2 < 1e16f)) != 0xfu) return false;
    M degenerate;
    if (exits == 0u) {  // all above
        const F r = 1.0f / lane_sqrt(l2);
        const F ux = bx * r, uy = by * r, uz = bz * r;
        const F t = edge_terms<Policy>(rotate(ux), rotate(uy), rotate(uz), ux, uy, uz, degenerate);
        if (bits(degenerate) != 0u) return false;
        sum = (t[0] + t[1]) + (t[2] + t[3]);
        return true;
    }
    const M a_above = rotate(b_above), exiting = a_above & ~b_above, entering = b_above & ~a_above;
    const M crossing = exiting | entering;
    const int e = lowest_lane(exits), n = lowest_lane(entries);
    const F ax = rotate(bx), ay = rotate(by), az = rotate(bz);
    // The crossings from the raw vertices, a.z b - b.z a: (a.z - b.z) |a| |b| times the crossing
    // of the unit vertices, so the exit's (a.z - b.z > 0) has its direction and the entry's the
    // opposite one.
    F xx = az * bx - bz * ax, xy = az * by - bz * ay;
    F lx = xx * xx + xy * xy;
    F r, rx;  // 1 / |v| (lanes of the vertices above), +-1 / |x| (lanes of the crossings)
    if (bits(crossing & ~(lx > 1e-36f)) == 0u) {
        // |x|^2 > 1e-16 (a.z^2 |b|^2 + b.z^2 |a|^2): the crossing of the unit vertices has
        // |X|^2 > 1e-16 (a.z^2 + b.z^2) / (|a.z| + |b.z|)^2, between 0.5e-16 and 1e-16.
        if (bits(crossing & ~(lx > 1e-16f * (az * az * l2 + bz * bz * rotate(l2)))) != 0u) return false;
        // One square root per lane: a vertex below (never normalized) lends its lane to the
        // crossing of the exit (lane e, vertex e below) or of the entry (lane n - 1, vertex
        // n - 1 below); with one vertex below (e = n - 1) the entry's is taken apart.
        const M entry_next = rotate_back(entering);
        r = 1.0f / lane_sqrt(select(exiting, lx, select(entry_next, rotate_back(lx), l2)));
        rx = select(exiting, r, rotate(r));
        if (bits(entry_next & exiting) != 0u) rx = select(entering, splat<F>(1.0f / std::sqrt(lx[n])), rx);
        rx = select(exiting, rx, 0.0f - rx);
    } else {
        // A crossing too small for its square (tiny vertices, or an edge with both ends within
        // about 1e-18 of the horizon relative to their lengths): from the unit vertices, as
        // X = (a.z b - b.z a) / (a.z - b.z) itself, at least the chord's distance to the origin.
        r = 1.0f / lane_sqrt(l2);
        const F ux = bx * r, uy = by * r, uz = bz * r, vx = rotate(ux), vy = rotate(uy), vz = rotate(uz);
        const F scale = 1.0f / (vz - uz);
        xx = (vz * ux - uz * vx) * scale, xy = (vz * uy - uz * vy) * scale;
        lx = xx * xx + xy * xy;
        if (bits(crossing & ~(lx > 1e-16f)) != 0u) return false;
        rx = 1.0f / lane_sqrt(select(crossing, lx, splat<F>(1.0f)));
    }
    const F cx = xx * rx, cy = xy * rx;  // the unit crossings (z = 0)
    const F ux = bx * r, uy = by * r, uz = bz * r;
    const F t = edge_terms<Policy>(select(a_above, rotate(ux), cx), select(a_above, rotate(uy), cy),
                                   keep(a_above, rotate(uz)), select(b_above, ux, cx), select(b_above, uy, cy),
                                   keep(b_above, uz), degenerate);
    const M part = a_above | b_above;  // the edges with a part above the horizon
    if (bits(part & degenerate) != 0u) return false;
    bool horizon_degenerate;
    const float h = horizon_term<Policy>(cx[e], cy[e], cx[n], cy[n], horizon_degenerate);
    if (horizon_degenerate) return false;
    const F kept = keep(part, t);
    sum = ((kept[0] + kept[1]) + (kept[2] + kept[3])) + h;
    return true;
}

}  // namespace lanes4

/// quad_sum from the quad's vertices: M^-1 p_i applied four at once (glm's order of operations:
/// the bits of transformed<>'s raw()) where v gives M^-1 and the p_i, else raw_vertex(v, i). F: the
/// lane representation (the build's own by default).
template <typename Policy, typename F = lanes4::f32x4, typename Vertices>
LTC_HOST_DEVICE LTC_INLINE bool quad_form_factor_lanes(const Vertices& v, float& sum) {
    using lanes4::make4;
    if constexpr (matrix_and_points<Vertices>::value) {
        const glm::mat3& m = v.m_inv;
        const glm::vec3* p = v.v;
        const F px = make4<F>(p[0].x, p[1].x, p[2].x, p[3].x), py = make4<F>(p[0].y, p[1].y, p[2].y, p[3].y);
        const F pz = make4<F>(p[0].z, p[1].z, p[2].z, p[3].z);
        return lanes4::quad_sum<Policy>(F(m[0][0] * px + m[1][0] * py + m[2][0] * pz),
                                        F(m[0][1] * px + m[1][1] * py + m[2][1] * pz),
                                        F(m[0][2] * px + m[1][2] * py + m[2][2] * pz), sum);
    } else {
        glm::vec3 q[4];
        for (unsigned i = 0; i < 4; ++i) q[i] = raw_vertex<float>(v, i);
        return lanes4::quad_sum<Policy>(make4<F>(q[0].x, q[1].x, q[2].x, q[3].x),
                                        make4<F>(q[0].y, q[1].y, q[2].y, q[3].y),
                                        make4<F>(q[0].z, q[1].z, q[2].z, q[3].z), sum);
    }
}

}  // namespace detail
LTC_NAMESPACE_END
