// ltc/shading/batch.hpp -- the clamped-cosine integral over many polygons at once, from
// structure-of-arrays input, written so that the compiler vectorizes the loop over items.
//
//   ltc::batch::quad_soa<float> in;
//   in.m_inv = ltc::batch::matrices<float>::per_item(m);  // m[c][r][i]: (M^-1 of item i)[c][r]
//   for (int k = 0; k < 4; ++k) in.x[k] = ..., in.y[k] = ..., in.z[k] = ...;  // vertex k of item i
//   ltc::batch::integrate_quads(in, out, count, ltc::sidedness::two_sided);
//
// out[i] is the value of
//   ltc::transformed<ltc::clamped_cosine<T, Policy>>::from_inverse(m_inv_i).integrate(p_i, n, s)
// up to rounding: the clamped-cosine integral of M^-1 P, clipped to the horizon (eq. 11).
//
// How it differs from the scalar path (polygon.hpp), and why the results agree:
//   - The scalar path's clippers (the streaming Sutherland-Hodgman clipper, and for quads a switch
//     on the vertices above the horizon) emit a variable number of vertices. Here each
//     edge p -> q becomes, with X its (unit) horizon crossing, the segment
//     [p_in ? p : X, q_in ? q : X], masked by p_in || q_in; the clipped polygon's edges along the
//     horizon, from an exit E to the next entry R, are added when R is met (paired with the last
//     exit), and the first entry, if no exit precedes it, is paired at the end with the last exit
//     (cyclically). Entries and exits alternate along the boundary, so this pairs every entry
//     with the previous exit, also for non-convex polygons: the clipped polygon has the same edges
//     as the scalar path's, summed in another order.
//   - No branch depends on the data. Vertices and crossings are normalized by x * rsqrt(|x|^2),
//     rsqrt by an integer first guess and Newton steps (a few ulps; the length of a unit vector is
//     off by as much, its direction is that of x up to the rounding of the products). This avoids
//     std::sqrt, which GCC does not vectorize under its default -fmath-errno (the call may set
//     errno; a guard branch blocks vectorization), and divisions under a select, which it does
//     not speculate under the default -ftrapping-math. Both policies' branches are evaluated
//     and selected. Compiled with -fno-math-errno, the loops use std::sqrt instead, which then
//     vectorizes.
//   - Items that the scalar path treats specially are detected in the loop (a branch-free flag)
//     and recomputed by the scalar path afterwards, so their results are the scalar path's: a
//     vertex with |M^-1 p|^2 outside (1e-30, 1e30) (a vertex at the origin, tiny, huge or
//     non-finite vertices: rescaling and the origin test live in the scalar path), a horizon
//     crossing direction with |x|^2 <= 1e-30 (an edge through, or within 1e-15 of, the shading
//     point), and, for the polynomial and minimax_rational policies, a nearly antipodal edge with
//     |a x b|^2 <= 1e-30.
//     Such items are rare in rendering; a batch made only of them runs at the scalar speed.
//
// Policies: polynomial (default), minimax_rational and rational are evaluated branch-free and
// vectorize, and so is fp16_quadratic in float. edge_policy::exact needs atan2, which GCC does not vectorize without -ffast-math
// and a vector math library: the batch API accepts it and returns the same values, but its loop
// stays scalar. Any other policy is called through Policy::theta_over_sin (scalar unless the
// compiler manages to if-convert it).
//
// Vectorization (GCC 12, checked with -fopt-info-vec-optimized): the loops over items of the
// fixed-n kernel (integrate_polygons / integrate_quads, and integrate_ngons for 3 <= n <= 8) and
// of the runtime-n kernel are vectorized at 16 bytes (SSE2, 4 floats) with plain -O3 and at 32
// bytes (8 floats) with -march=x86-64-v3. No OpenMP pragma is needed.
//
// The pieces: ltc/shading/batch_soa.hpp (the input layout), ltc/detail/batch_lanes.hpp (the
// branch-free arithmetic of one item per lane), ltc/detail/batch_walker.hpp (the clipper and
// edge sum above), ltc/detail/batch_kernels.hpp (the loops over items and the scalar fix-up).
#pragma once

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/core/polygon.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/shading/batch_soa.hpp>      // matrices, polygon_soa, quad_soa, ngon_soa
#include <ltc/detail/batch_lanes.hpp>     // select, rsqrt, theta_over_sin, edge_z, unit_vertex, ...
#include <ltc/detail/batch_walker.hpp>    // walker: the data-parallel horizon clipper
#include <ltc/detail/batch_kernels.hpp>   // kernel_fixed, kernel_blocked, fix_up (scalar path)

#include <glm/glm.hpp>

#include <cstddef>
#include <type_traits>
#include <utility>

namespace ltc {
namespace batch {

/// out[i] = the horizon-clipped clamped-cosine integral of M_i^-1 P_i for count polygons of N
/// vertices (N >= 3; N < 3 gives 0 like the scalar path), seen by a one- or two-sided emitter.
template <typename Policy = edge_policy::polynomial, typename T, std::size_t N>
void integrate_polygons(const polygon_soa<T, N>& in, T* out, std::size_t count, sidedness s) {
    if constexpr (N < 3) {
        for (std::size_t i = 0; i < count; ++i) out[i] = T(0);
    } else {
        detail::with_matrix<Policy>(in.m_inv, [&](const auto& m) {
            if (s == sidedness::two_sided)
                detail::kernel_fixed<Policy, true>(m, in.x, in.y, in.z, out, count, std::make_index_sequence<N>{});
            else
                detail::kernel_fixed<Policy, false>(m, in.x, in.y, in.z, out, count, std::make_index_sequence<N>{});
            const auto vertex = [&](std::size_t k, std::size_t i) {
                return glm::vec<3, T>(in.x[k][i], in.y[k][i], in.z[k][i]);
            };
            detail::fix_up<Policy>(m, N, vertex, out, count, s);
        });
    }
}

/// integrate_polygons for quads.
template <typename Policy = edge_policy::polynomial, typename T>
void integrate_quads(const quad_soa<T>& in, T* out, std::size_t count, sidedness s) {
    integrate_polygons<Policy>(in, out, count, s);
}

/// Runtime-n blocked kernel for any n >= 3 (what integrate_ngons uses above n = 8); exposed so
/// that tests and benchmarks can compare it with the fixed-n kernel.
template <typename Policy = edge_policy::polynomial, typename T>
void integrate_ngons_blocked(const ngon_soa<T>& in, T* out, std::size_t count, sidedness s) {
    const std::size_t n = in.n;
    if (n < 3) {
        for (std::size_t i = 0; i < count; ++i) out[i] = T(0);
        return;
    }
    detail::with_matrix<Policy>(in.m_inv, [&](const auto& m) {
        if (s == sidedness::two_sided)
            detail::kernel_blocked<Policy, true>(m, n, in.x, in.y, in.z, out, count);
        else
            detail::kernel_blocked<Policy, false>(m, n, in.x, in.y, in.z, out, count);
        const auto vertex = [&](std::size_t k, std::size_t i) {
            return glm::vec<3, T>(in.x[k][i], in.y[k][i], in.z[k][i]);
        };
        detail::fix_up<Policy>(m, n, vertex, out, count, s);
    });
}

/// The same with the vertex count known at run time only (the same for every item). n from 3 to 8
/// runs the fixed-n kernel; other n a blocked kernel (vertex loop outside, item loop inside).
template <typename Policy = edge_policy::polynomial, typename T>
void integrate_ngons(const ngon_soa<T>& in, T* out, std::size_t count, sidedness s) {
    const std::size_t n = in.n;
    if (n < 3) {
        for (std::size_t i = 0; i < count; ++i) out[i] = T(0);
        return;
    }
    const auto fixed = [&](auto n_constant) {
        constexpr std::size_t N = decltype(n_constant)::value;
        polygon_soa<T, N> p;
        p.m_inv = in.m_inv;
        for (std::size_t k = 0; k < N; ++k) p.x[k] = in.x[k], p.y[k] = in.y[k], p.z[k] = in.z[k];
        integrate_polygons<Policy>(p, out, count, s);
    };
    switch (n) {
        case 3: return fixed(std::integral_constant<std::size_t, 3>{});
        case 4: return fixed(std::integral_constant<std::size_t, 4>{});
        case 5: return fixed(std::integral_constant<std::size_t, 5>{});
        case 6: return fixed(std::integral_constant<std::size_t, 6>{});
        case 7: return fixed(std::integral_constant<std::size_t, 7>{});
        case 8: return fixed(std::integral_constant<std::size_t, 8>{});
        default: break;
    }
    integrate_ngons_blocked<Policy>(in, out, count, s);
}

}  // namespace batch
}  // namespace ltc
