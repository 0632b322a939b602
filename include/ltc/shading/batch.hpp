// ltc/shading/batch.hpp -- the clamped-cosine integral over many polygons at once, from
// structure-of-arrays input, one item per SIMD lane (docs/batches.md).
//
//   ltc::batch::quad_soa<float> in;
//   in.m_inv = ltc::batch::matrices<float>::per_item(m);  // m[c][r][i]: (M^-1 of item i)[c][r]
//   for (int k = 0; k < 4; ++k) in.x[k] = ..., in.y[k] = ..., in.z[k] = ...;  // vertex k of item i
//   ltc::batch::integrate_quads(in, out, count, ltc::sidedness::two_sided);
//
// out[i] is the value of
//   ltc::transformed<ltc::clamped_cosine<T, Policy>>::from_inverse(m_inv_i).integrate(p_i, n, s)
// up to rounding: the clamped-cosine integral of M^-1 P, clipped to the horizon (eq. 11); the
// items the SIMD kernel declines, and the tail, are that scalar path's (integrate_polygons).
// Policy: edge_policy::automatic (minimax_rational in float; exact in double, which has no SIMD
// kernel). Instruction sets: isa, chosen at run time. Degenerate cases: N < 3 gives 0.
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/edge_policy.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/shading/detail/batch_scalar.hpp>
#include <ltc/shading/detail/batch_simd.hpp>
#include <ltc/shading/detail/simd.hpp>
#include <ltc/shading/batch_soa.hpp>  // matrices, polygon_soa, quad_soa, ngon_soa

#include <cstddef>

LTC_NAMESPACE_BEGIN
namespace batch {

/// The instruction set a batch runs with. How (ltc/shading/detail/batch_simd_kernel.inc): explicit
/// SIMD through the compiler's vector types (ltc/shading/detail/simd.hpp; docs/design_notes.md says
/// why not a SIMD library), one kernel compiled for three instruction sets and chosen at run time,
/// so that a build without -march runs 8 or 16 floats wide on an AVX2 or AVX-512 CPU:
///   isa::baseline  16-byte vectors: 4 floats (SSE2 on x86-64, NEON on AArch64), 2 doubles;
///   isa::avx2      32-byte vectors with FMA: 8 floats, 4 doubles (x86-64 with AVX2 and FMA);
///   isa::avx512    64-byte vectors: 16 floats, 8 doubles (x86-64 with AVX-512 F, CD, BW, DQ and
///                  VL, x86-64-v4: Intel since Skylake-SP, AMD since Zen 4);
///   isa::scalar    the scalar path, item by item.
/// isa::automatic (the default) takes the widest the CPU runs; an unavailable request falls back
/// to the next narrower one. Defining LTC_NO_SIMD before including ltc (or compiling with a
/// compiler without GCC's vector extensions, or for CUDA) leaves only the scalar path.
enum class isa { automatic, scalar, baseline, avx2, avx512 };

/// Every instruction set but automatic, narrowest first.
inline constexpr isa instruction_sets[] = {isa::scalar, isa::baseline, isa::avx2, isa::avx512};

/// Whether this build and this CPU run `which` (automatic and scalar: always).
inline bool available(isa which) {
    switch (which) {
        case isa::automatic:
        case isa::scalar: return true;
        case isa::baseline: return LTC_SIMD != 0;
        case isa::avx2:
#if LTC_SIMD_AVX2
            return simd::avx2::supported();
#else
            return false;
#endif
        case isa::avx512:
#if LTC_SIMD_AVX512
            return simd::avx512::supported();
#else
            return false;
#endif
    }
    return false;
}

/// The instruction set that `which` runs with here: itself if available, else the next narrower
/// one that is (automatic: the widest available).
inline isa resolve(isa which) {
    if (which == isa::automatic) which = isa::avx512;
    for (std::size_t k = sizeof(instruction_sets) / sizeof(instruction_sets[0]); k-- > 0;)
        if (instruction_sets[k] == which) {
            while (!available(instruction_sets[k])) --k;  // scalar is always available
            return instruction_sets[k];
        }
    return isa::scalar;
}

/// How many items of T one vector of `which` holds (1 for scalar; automatic: resolved first).
template <typename T>
std::size_t lane_count(isa which) {
    switch (resolve(which)) {
        case isa::baseline: return 16 / sizeof(T);
        case isa::avx2: return 32 / sizeof(T);
        case isa::avx512: return 64 / sizeof(T);
        default: return 1;
    }
}

namespace detail {

/// The SIMD kernel of `which` over the full vectors of items (EdgePolicy resolved, n >= 3):
/// returns how many it wrote, NaN where it hands an item back; 0 where `which` resolves to
/// scalar or EdgePolicy has no SIMD kernel. N > 0: the vertex count as a constant.
template <typename EdgePolicy, std::size_t N, typename T>
std::size_t integrate_vectorized(const matrices<T>& mats, std::size_t n, const T* const* x, const T* const* y,
                                 const T* const* z, T* out, std::size_t count, bool two_sided, isa which) {
    std::size_t vectorized = 0;
    if constexpr (simd_policy<EdgePolicy, T>) {
#if LTC_SIMD
        switch (resolve(which)) {
            case isa::baseline: vectorized = run_baseline<EdgePolicy, N>(mats, n, x, y, z, out, count, two_sided); break;
#if LTC_SIMD_AVX2
            case isa::avx2: vectorized = run_avx2<EdgePolicy, N>(mats, n, x, y, z, out, count, two_sided); break;
#endif
#if LTC_SIMD_AVX512
            case isa::avx512: vectorized = run_avx512<EdgePolicy, N>(mats, n, x, y, z, out, count, two_sided); break;
#endif
            default: break;
        }
#endif
    }
    (void)mats, (void)n, (void)x, (void)y, (void)z, (void)out, (void)count, (void)two_sided, (void)which;
    return vectorized;
}

/// Every item: the SIMD kernel over full vectors, then the scalar path where it handed back and
/// for the tail. N > 0: the vertex count as a constant.
template <typename Policy, std::size_t N, typename T>
void integrate(const matrices<T>& mats, std::size_t n, const T* const* x, const T* const* y, const T* const* z, T* out,
               std::size_t count, sidedness s, isa which) {
    using EdgePolicy = edge_policy::resolve_t<Policy, T>;
    if (n < 3) {
        for (std::size_t i = 0; i < count; ++i) out[i] = T(0);
        return;
    }
    const std::size_t vectorized =
        integrate_vectorized<EdgePolicy, N>(mats, n, x, y, z, out, count, s == sidedness::two_sided, which);
    scalar_items<EdgePolicy>(mats, x, y, z, n, out, vectorized, count, s);
}

}  // namespace detail

/// out[i] = the horizon-clipped clamped-cosine integral of M_i^-1 P_i for count polygons of N
/// vertices (N >= 3; N < 3 gives 0 like the scalar path), seen by a one- or two-sided emitter.
///
/// The default policy is edge_policy::automatic, as for the scalar integrals: minimax_rational in
/// float (float-accurate, the fastest), exact in double (which has no SIMD kernel: pass
/// minimax_rational or polynomial for double lanes at float accuracy). Policies other than
/// minimax_rational, polynomial and user fits built on ltc::detail::symmetric_fit run the scalar
/// path.
///
/// The kernel needs no clipped polygon: every edge adds its part above the horizon, and the one
/// horizon edge runs from the crossing of the edge that exits to that of the edge that enters.
/// Items it does not take (a vertex at the origin, tiny, huge or non-finite vertices, an edge
/// through the shading point, a non-convex polygon with several runs above the horizon: see the
/// kernel's file comment) and the last count % width items go through the scalar path, so every
/// result is the scalar path's up to rounding (tests/test_batch.cpp derives the tolerance).
template <typename Policy = edge_policy::automatic, typename T, std::size_t N>
void integrate_polygons(const polygon_soa<T, N>& in, T* out, std::size_t count, sidedness s, isa which = isa::automatic) {
    detail::integrate<Policy, N>(in.m_inv, N, in.x, in.y, in.z, out, count, s, which);
}

/// integrate_polygons for quads.
template <typename Policy = edge_policy::automatic, typename T>
void integrate_quads(const quad_soa<T>& in, T* out, std::size_t count, sidedness s, isa which = isa::automatic) {
    integrate_polygons<Policy>(in, out, count, s, which);
}

/// The same with the vertex count known at run time only (the same for every item).
template <typename Policy = edge_policy::automatic, typename T>
void integrate_ngons(const ngon_soa<T>& in, T* out, std::size_t count, sidedness s, isa which = isa::automatic) {
    detail::integrate<Policy, 0>(in.m_inv, in.n, in.x, in.y, in.z, out, count, s, which);
}

/// integrate_ngons (the one kernel serves every n; kept from 0.1).
template <typename Policy = edge_policy::automatic, typename T>
void integrate_ngons_blocked(const ngon_soa<T>& in, T* out, std::size_t count, sidedness s, isa which = isa::automatic) {
    integrate_ngons<Policy>(in, out, count, s, which);
}

}  // namespace batch
LTC_NAMESPACE_END
