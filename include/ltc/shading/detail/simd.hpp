// ltc/shading/detail/simd.hpp -- the explicit SIMD layer of the batch kernels (ltc/shading/batch.hpp):
// vector types, the few primitives that need an instruction set (rsqrt, rcp, sqrt, bits, gather),
// and the run-time choice between instruction sets.
//
// The layer is the compiler's own vector extension (GCC and Clang: `vector_size`), the one that
// libstdc++'s <experimental/simd> is written in. Why not that, xsimd or Highway: the batch must
// run at AVX2 width in a build without -march (run-time dispatch) from headers alone.
//   - std::experimental::simd (GCC 12) fixes its ABI when the header is first included: inside a
//     function compiled for AVX2 by __attribute__((target)), fixed_size_simd<float, 8> still
//     compiles to pairs of 128-bit instructions (checked with GCC 12.2: no ymm register);
//   - xsimd enables its AVX2 batch only when the translation unit is compiled with -mavx2;
//   - Highway's run-time dispatch needs its library (libhwy) linked and the user's file
//     re-included once per target.
// Plain vector types, by contrast, compile to 256-bit instructions in any function compiled for
// AVX2, whatever the flags of the translation unit. Each instruction set has a namespace below
// (baseline: 16-byte vectors, SSE2 on x86-64; avx2: 32-byte vectors, AVX2 + FMA; avx512: 64-byte
// vectors, AVX-512) whose functions
// carry that instruction set's target attribute; the kernel (ltc/shading/detail/batch_simd_kernel.inc)
// is compiled once in each.
//
// LTC_SIMD is 1 where the layer is available (GCC or Clang, not CUDA device compilation, not
// disabled by defining LTC_NO_SIMD before including ltc); elsewhere the batch API runs its scalar
// path item by item. LTC_SIMD_AVX2 and LTC_SIMD_AVX512 are 1 where the AVX2 and AVX-512 kernels
// are compiled (x86-64).
#pragma once

#include <ltc/config.hpp>

#if !defined(LTC_NO_SIMD) && (defined(__GNUC__) || defined(__clang__)) && !defined(__CUDACC__)
#define LTC_SIMD 1
#else
#define LTC_SIMD 0
#endif

#if LTC_SIMD && defined(__x86_64__)
#define LTC_SIMD_AVX2 1
#define LTC_SIMD_AVX512 1
#include <immintrin.h>
#else
#define LTC_SIMD_AVX2 0
#define LTC_SIMD_AVX512 0
#endif

#if LTC_SIMD

#include <cmath>
#include <cstddef>
#include <cstdint>

// Functions of each instruction set's namespace: always inlined into the entry point compiled
// for that instruction set (ltc/shading/detail/batch_simd.hpp).
#define LTC_SIMD_BASELINE_FN inline __attribute__((always_inline))
#if LTC_SIMD_AVX2
#define LTC_SIMD_AVX2_TARGET __attribute__((target("avx2,fma")))
#define LTC_SIMD_AVX2_FN inline __attribute__((always_inline, target("avx2,fma")))
#endif
#if LTC_SIMD_AVX512
// x86-64-v4's AVX-512 subsets (F, CD, BW, DQ, VL), as Intel since Skylake-SP and AMD since Zen 4 have them.
#define LTC_SIMD_AVX512_TARGET __attribute__((target("avx2,fma,avx512f,avx512cd,avx512bw,avx512dq,avx512vl")))
#define LTC_SIMD_AVX512_FN \
    inline __attribute__((always_inline, target("avx2,fma,avx512f,avx512cd,avx512bw,avx512dq,avx512vl")))
#endif

LTC_NAMESPACE_BEGIN
namespace simd {

/// The vector of W lanes of T, and the integer vector of the same lanes that comparisons return
/// (all bits set where true).
template <typename T, std::size_t Bytes>
struct vector_types;
template <std::size_t Bytes>
struct vector_types<float, Bytes> {
    typedef float vf __attribute__((vector_size(Bytes)));
    typedef std::int32_t vi __attribute__((vector_size(Bytes)));
    static constexpr std::size_t width = Bytes / sizeof(float);
};
template <std::size_t Bytes>
struct vector_types<double, Bytes> {
    typedef double vf __attribute__((vector_size(Bytes)));
    typedef std::int64_t vi __attribute__((vector_size(Bytes)));
    static constexpr std::size_t width = Bytes / sizeof(double);
};

namespace baseline {

template <typename T>
using types = vector_types<T, 16>;

/// 1 / sqrt(x) for normal x > 0 (callers mask the other lanes). float on x86-64: the hardware
/// estimate (relative error <= 1.5 * 2^-12) and one Newton step y (3/2 - x y^2 / 2), which
/// squares the error (measured in tests/test_batch.cpp); double, and other targets: 1 / sqrt.
template <typename V>
LTC_SIMD_BASELINE_FN V rsqrt(V x) {
#if defined(__SSE2__)
    if constexpr (sizeof(x[0]) == 4) {
        const V y = (V)_mm_rsqrt_ps((__m128)x);
        return y * (1.5f - (0.5f * x) * (y * y));
    } else {
        return 1.0 / (V)_mm_sqrt_pd((__m128d)x);
    }
#else
    V r;
    for (std::size_t k = 0; k < sizeof(V) / sizeof(x[0]); ++k) r[k] = 1 / std::sqrt(x[k]);
    return r;
#endif
}

/// A positive number within 1.5 * 2^-12 of 1 / x (float on x86-64) or 1 / x itself, for x != 0:
/// used where only the direction of the scaled vector matters.
template <typename V>
LTC_SIMD_BASELINE_FN V rcp_estimate(V x) {
#if defined(__SSE2__)
    if constexpr (sizeof(x[0]) == 4) return (V)_mm_rcp_ps((__m128)x);
#endif
    return 1 / x;
}

/// sqrt(x), correctly rounded.
template <typename V>
LTC_SIMD_BASELINE_FN V sqrt(V x) {
#if defined(__SSE2__)
    if constexpr (sizeof(x[0]) == 4) return (V)_mm_sqrt_ps((__m128)x);
    else return (V)_mm_sqrt_pd((__m128d)x);
#else
    V r;
    for (std::size_t k = 0; k < sizeof(V) / sizeof(x[0]); ++k) r[k] = std::sqrt(x[k]);
    return r;
#endif
}

/// Bit k set where lane k of the comparison result m is true.
template <typename VI>
LTC_SIMD_BASELINE_FN unsigned bits(VI m) {
#if defined(__SSE2__)
    if constexpr (sizeof(m[0]) == 4) return unsigned(_mm_movemask_ps((__m128)m));
    else return unsigned(_mm_movemask_pd((__m128d)m));
#else
    unsigned b = 0;
    for (std::size_t k = 0; k < sizeof(VI) / sizeof(m[0]); ++k) b |= (m[k] ? 1u : 0u) << k;
    return b;
#endif
}

/// Whether every lane of the comparison result m is true.
template <typename VI>
LTC_SIMD_BASELINE_FN bool all(VI m) {
    return bits(m) == (1u << (sizeof(VI) / sizeof(m[0]))) - 1;
}

/// Lane k: base[index[k]], widened to the lane type of V (float or double); index has V's lanes.
/// SSE2 and NEON have no gather instruction: one load per lane.
template <typename V, typename VI>
LTC_SIMD_BASELINE_FN V gather(const float* base, VI index) {
    V r;
    for (std::size_t k = 0; k < sizeof(V) / sizeof(r[0]); ++k) r[k] = base[index[k]];
    return r;
}

}  // namespace baseline

#if LTC_SIMD_AVX2
namespace avx2 {

template <typename T>
using types = vector_types<T, 32>;

template <typename V>
LTC_SIMD_AVX2_FN V rsqrt(V x) {
    if constexpr (sizeof(x[0]) == 4) {
        const V y = (V)_mm256_rsqrt_ps((__m256)x);
        return y * (1.5f - (0.5f * x) * (y * y));
    } else {
        return 1.0 / (V)_mm256_sqrt_pd((__m256d)x);
    }
}

template <typename V>
LTC_SIMD_AVX2_FN V rcp_estimate(V x) {
    if constexpr (sizeof(x[0]) == 4) return (V)_mm256_rcp_ps((__m256)x);
    return 1 / x;
}

template <typename V>
LTC_SIMD_AVX2_FN V sqrt(V x) {
    if constexpr (sizeof(x[0]) == 4) return (V)_mm256_sqrt_ps((__m256)x);
    else return (V)_mm256_sqrt_pd((__m256d)x);
}

template <typename VI>
LTC_SIMD_AVX2_FN unsigned bits(VI m) {
    if constexpr (sizeof(m[0]) == 4) return unsigned(_mm256_movemask_ps((__m256)m));
    else return unsigned(_mm256_movemask_pd((__m256d)m));
}

template <typename VI>
LTC_SIMD_AVX2_FN bool all(VI m) {
    return bits(m) == (1u << (sizeof(VI) / sizeof(m[0]))) - 1;
}

/// Lane k: base[index[k]] (vgatherdps; double lanes: vgatherqps, then widened).
template <typename V, typename VI>
LTC_SIMD_AVX2_FN V gather(const float* base, VI index) {
    if constexpr (sizeof(V) / sizeof(index[0]) == 8)
        return (V)_mm256_i32gather_ps(base, (__m256i)index, 4);
    else
        return (V)_mm256_cvtps_pd(_mm256_i64gather_ps(base, (__m256i)index, 4));
}

/// Whether this CPU runs the AVX2 kernel (AVX2 and FMA), checked once at run time in every build
/// (never from -m flags: the body must be the same in every translation unit).
inline bool supported() {
    static const bool yes = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    }();
    return yes;
}

}  // namespace avx2
#endif

#if LTC_SIMD_AVX512
namespace avx512 {

template <typename T>
using types = vector_types<T, 64>;

/// float: the AVX-512 estimate (relative error <= 2^-14) and one Newton step, as in baseline.
/// (The masked forms: GCC 12 warns that the unmasked ones read an uninitialized register.)
template <typename V>
LTC_SIMD_AVX512_FN V rsqrt(V x) {
    if constexpr (sizeof(x[0]) == 4) {
        const V y = (V)_mm512_maskz_rsqrt14_ps(__mmask16(0xffff), (__m512)x);
        return y * (1.5f - (0.5f * x) * (y * y));
    } else {
        return 1.0 / (V)_mm512_maskz_sqrt_pd(__mmask8(0xff), (__m512d)x);
    }
}

/// Within 2^-14 of 1 / x (float), or 1 / x itself.
template <typename V>
LTC_SIMD_AVX512_FN V rcp_estimate(V x) {
    if constexpr (sizeof(x[0]) == 4) return (V)_mm512_maskz_rcp14_ps(__mmask16(0xffff), (__m512)x);
    return 1 / x;
}

template <typename V>
LTC_SIMD_AVX512_FN V sqrt(V x) {
    if constexpr (sizeof(x[0]) == 4) return (V)_mm512_maskz_sqrt_ps(__mmask16(0xffff), (__m512)x);
    else return (V)_mm512_maskz_sqrt_pd(__mmask8(0xff), (__m512d)x);
}

template <typename VI>
LTC_SIMD_AVX512_FN unsigned bits(VI m) {
    if constexpr (sizeof(m[0]) == 4) return unsigned(_mm512_movepi32_mask((__m512i)m));
    else return unsigned(_mm512_movepi64_mask((__m512i)m));
}

template <typename VI>
LTC_SIMD_AVX512_FN bool all(VI m) {
    return bits(m) == (1u << (sizeof(VI) / sizeof(m[0]))) - 1;
}

/// Lane k: base[index[k]] (vgatherdps; double lanes: vgatherqps, then widened). The masked forms
/// with a zero source: GCC 12's unmasked ones start from an undefined register
/// (_mm512_undefined_ps), which it then warns of as uninitialized.
template <typename V, typename VI>
LTC_SIMD_AVX512_FN V gather(const float* base, VI index) {
    if constexpr (sizeof(V) / sizeof(index[0]) == 16) {
        return (V)_mm512_mask_i32gather_ps(_mm512_setzero_ps(), __mmask16(0xffff), (__m512i)index, base, 4);
    } else {
        return (V)_mm512_maskz_cvtps_pd(
            __mmask8(0xff), _mm512_mask_i64gather_ps(_mm256_setzero_ps(), __mmask8(0xff), (__m512i)index, base, 4));
    }
}

/// Whether this CPU (and its operating system, which must save the 512-bit registers: the
/// compiler's check includes it) runs the AVX-512 kernel, checked once.
inline bool supported() {
    static const bool yes = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512cd") &&
               __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") &&
               __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    }();
    return yes;
}

}  // namespace avx512
#endif

}  // namespace simd
LTC_NAMESPACE_END

#endif  // LTC_SIMD
