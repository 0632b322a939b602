// ltc/shading/detail/simd.hpp -- the explicit SIMD layer of the batch kernels (ltc/shading/batch.hpp):
// vector types, the few primitives that need an instruction set (rsqrt, rcp, sqrt, bits, gather),
// and the run-time choice between instruction sets. Internal: ltc/shading/batch.hpp includes it.
//
// The layer is the compiler's own vector extension (GCC and Clang: `vector_size`). Its primitives
// call the compiler's x86 builtins (`__builtin_ia32_*`, which GCC's and Clang's <immintrin.h>
// intrinsics are defined with, compiling to the same instructions) and generic vector operations
// (`__builtin_convertvector`), so that no intrinsic header is included: the builtins need no
// declaration. Where GCC and Clang name a builtin differently, `__clang__` chooses. Each
// instruction set has a namespace below (baseline: 16-byte vectors, SSE2 on x86-64; avx2: 32-byte
// vectors, AVX2 + FMA; avx512: 64-byte vectors, AVX-512) whose functions carry that instruction
// set's target attribute; the kernel (ltc/shading/detail/batch_simd_kernel.inc) is compiled once
// in each. Why not std::experimental::simd, xsimd or Highway: docs/design_notes.md.
#pragma once

#include <ltc/config.hpp>

// LTC_SIMD is 1 where the layer is available (GCC or Clang, not CUDA device compilation, not
// disabled by defining LTC_NO_SIMD before including ltc); elsewhere the batch API runs its scalar
// path item by item. LTC_SIMD_AVX2 and LTC_SIMD_AVX512 are 1 where the AVX2 and AVX-512 kernels
// are compiled (x86-64).
#if !defined(LTC_NO_SIMD) && (defined(__GNUC__) || defined(__clang__)) && !defined(__CUDACC__)
#define LTC_SIMD 1
#else
#define LTC_SIMD 0
#endif

#if LTC_SIMD && defined(__x86_64__)
#define LTC_SIMD_AVX2 1
#define LTC_SIMD_AVX512 1
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

/// The operand types of the x86 builtins below (GCC's and Clang's __v4sf, __v4di, ... of
/// <immintrin.h>, which is not included). Casts between vector types of the same size keep the
/// bits: vector_types<double, 32>::vi (lanes of std::int64_t, which is long) to v4di (long long).
namespace x86 {
typedef float v4sf __attribute__((vector_size(16)));
typedef float v8sf __attribute__((vector_size(32)));
typedef float v16sf __attribute__((vector_size(64)));
typedef double v2df __attribute__((vector_size(16)));
typedef double v4df __attribute__((vector_size(32)));
typedef double v8df __attribute__((vector_size(64)));
typedef int v4si __attribute__((vector_size(16)));
typedef int v8si __attribute__((vector_size(32)));
typedef int v16si __attribute__((vector_size(64)));
typedef long long v4di __attribute__((vector_size(32)));
typedef long long v8di __attribute__((vector_size(64)));
}  // namespace x86

namespace baseline {

template <typename T>
using types = vector_types<T, 16>;

/// 1 / sqrt(x) for normal x > 0 (callers mask the other lanes). float on x86-64: the hardware
/// estimate (relative error <= 1.5 * 2^-12) and one Newton step y (3/2 - x y^2 / 2), which
/// squares the error (tests/test_batch.cpp checks it); double, and other targets: 1 / sqrt.
template <typename V>
LTC_SIMD_BASELINE_FN V rsqrt(V x) {
#if defined(__SSE2__)
    if constexpr (sizeof(x[0]) == 4) {
        const V y = (V)__builtin_ia32_rsqrtps((x86::v4sf)x);  // rsqrtps
        return y * (1.5f - (0.5f * x) * (y * y));
    } else {
        return 1.0 / (V)__builtin_ia32_sqrtpd((x86::v2df)x);  // sqrtpd
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
    if constexpr (sizeof(x[0]) == 4) return (V)__builtin_ia32_rcpps((x86::v4sf)x);  // rcpps
#endif
    return 1 / x;
}

/// sqrt(x), correctly rounded.
template <typename V>
LTC_SIMD_BASELINE_FN V sqrt(V x) {
#if defined(__SSE2__)
    if constexpr (sizeof(x[0]) == 4) return (V)__builtin_ia32_sqrtps((x86::v4sf)x);  // sqrtps
    else return (V)__builtin_ia32_sqrtpd((x86::v2df)x);                            // sqrtpd
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
    if constexpr (sizeof(m[0]) == 4) return unsigned(__builtin_ia32_movmskps((x86::v4sf)m));  // movmskps
    else return unsigned(__builtin_ia32_movmskpd((x86::v2df)m));                            // movmskpd
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
    V r{};
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
        const V y = (V)__builtin_ia32_rsqrtps256((x86::v8sf)x);  // vrsqrtps ymm
        return y * (1.5f - (0.5f * x) * (y * y));
    } else {
        return 1.0 / (V)__builtin_ia32_sqrtpd256((x86::v4df)x);  // vsqrtpd ymm
    }
}

template <typename V>
LTC_SIMD_AVX2_FN V rcp_estimate(V x) {
    if constexpr (sizeof(x[0]) == 4) return (V)__builtin_ia32_rcpps256((x86::v8sf)x);  // vrcpps ymm
    return 1 / x;
}

template <typename V>
LTC_SIMD_AVX2_FN V sqrt(V x) {
    if constexpr (sizeof(x[0]) == 4) return (V)__builtin_ia32_sqrtps256((x86::v8sf)x);  // vsqrtps ymm
    else return (V)__builtin_ia32_sqrtpd256((x86::v4df)x);                            // vsqrtpd ymm
}

template <typename VI>
LTC_SIMD_AVX2_FN unsigned bits(VI m) {
    if constexpr (sizeof(m[0]) == 4) return unsigned(__builtin_ia32_movmskps256((x86::v8sf)m));  // vmovmskps ymm
    else return unsigned(__builtin_ia32_movmskpd256((x86::v4df)m));                            // vmovmskpd ymm
}

template <typename VI>
LTC_SIMD_AVX2_FN bool all(VI m) {
    return bits(m) == (1u << (sizeof(VI) / sizeof(m[0]))) - 1;
}

/// Lane k: base[index[k]] (vgatherdps; double lanes: vgatherqps, then widened by vcvtps2pd). The
/// builtins take a source (zero), the base, the indices, a mask (every lane: its sign bit set)
/// and the scale, a constant.
template <typename V, typename VI>
LTC_SIMD_AVX2_FN V gather(const float* base, VI index) {
    if constexpr (sizeof(V) / sizeof(index[0]) == 8) {
        const x86::v8sf every = (x86::v8sf)~x86::v8si{};
#if defined(__clang__)
        return (V)__builtin_ia32_gatherd_ps256(x86::v8sf{}, base, (x86::v8si)index, every, 4);
#else
        return (V)__builtin_ia32_gathersiv8sf(x86::v8sf{}, base, (x86::v8si)index, every, 4);
#endif
    } else {
        const x86::v4sf every = (x86::v4sf)~x86::v4si{};
#if defined(__clang__)
        const x86::v4sf f = __builtin_ia32_gatherq_ps256(x86::v4sf{}, base, (x86::v4di)index, every, 4);
        return __builtin_convertvector(f, V);
#else
        // GCC 12 lowers __builtin_convertvector here to two 128-bit conversions.
        const x86::v4sf f = __builtin_ia32_gatherdiv4sf256(x86::v4sf{}, base, (x86::v4di)index, every, 4);
        return (V)__builtin_ia32_cvtps2pd256(f);
#endif
    }
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

// The masks of the builtins' masked forms (__mmask16, __mmask8) that select every lane.
inline constexpr unsigned short every16 = 0xffff;
inline constexpr unsigned char every8 = 0xff;
// The rounding argument of the 512-bit builtins: the current rounding mode (MXCSR), as in the
// instructions without embedded rounding (_MM_FROUND_CUR_DIRECTION).
inline constexpr int current_rounding = 4;

/// Correctly rounded sqrt of the 512-bit vector x (vsqrtps zmm, vsqrtpd zmm): GCC's builtin has a
/// source and a mask (every lane), Clang's not.
LTC_SIMD_AVX512_FN x86::v16sf sqrt_lanes(x86::v16sf x) {
#if defined(__clang__)
    return __builtin_ia32_sqrtps512(x, current_rounding);
#else
    return __builtin_ia32_sqrtps512_mask(x, x86::v16sf{}, every16, current_rounding);
#endif
}
LTC_SIMD_AVX512_FN x86::v8df sqrt_lanes(x86::v8df x) {
#if defined(__clang__)
    return __builtin_ia32_sqrtpd512(x, current_rounding);
#else
    return __builtin_ia32_sqrtpd512_mask(x, x86::v8df{}, every8, current_rounding);
#endif
}

/// float: the AVX-512 estimate (vrsqrt14ps, relative error <= 2^-14) and one Newton step, as in
/// baseline. (The builtin is the masked form: source zero, every lane.)
template <typename V>
LTC_SIMD_AVX512_FN V rsqrt(V x) {
    if constexpr (sizeof(x[0]) == 4) {
        const V y = (V)__builtin_ia32_rsqrt14ps512_mask((x86::v16sf)x, x86::v16sf{}, every16);
        return y * (1.5f - (0.5f * x) * (y * y));
    } else {
        return 1.0 / (V)sqrt_lanes((x86::v8df)x);
    }
}

/// Within 2^-14 of 1 / x (float: vrcp14ps, the masked builtin as in rsqrt), or 1 / x itself.
template <typename V>
LTC_SIMD_AVX512_FN V rcp_estimate(V x) {
    if constexpr (sizeof(x[0]) == 4) return (V)__builtin_ia32_rcp14ps512_mask((x86::v16sf)x, x86::v16sf{}, every16);
    return 1 / x;
}

template <typename V>
LTC_SIMD_AVX512_FN V sqrt(V x) {
    if constexpr (sizeof(x[0]) == 4) return (V)sqrt_lanes((x86::v16sf)x);
    else return (V)sqrt_lanes((x86::v8df)x);
}

template <typename VI>
LTC_SIMD_AVX512_FN unsigned bits(VI m) {
    if constexpr (sizeof(m[0]) == 4) return unsigned(__builtin_ia32_cvtd2mask512((x86::v16si)m));  // vpmovd2m
    else return unsigned(__builtin_ia32_cvtq2mask512((x86::v8di)m));                            // vpmovq2m
}

template <typename VI>
LTC_SIMD_AVX512_FN bool all(VI m) {
    return bits(m) == (1u << (sizeof(VI) / sizeof(m[0]))) - 1;
}

/// Lane k: base[index[k]] (vgatherdps; double lanes: vgatherqps, then widened by vcvtps2pd). The
/// builtins (GCC's and Clang's alike) take a source (zero), the base, the indices, a mask (every
/// lane) and the scale, a constant.
template <typename V, typename VI>
LTC_SIMD_AVX512_FN V gather(const float* base, VI index) {
    if constexpr (sizeof(V) / sizeof(index[0]) == 16) {
        return (V)__builtin_ia32_gathersiv16sf(x86::v16sf{}, base, (x86::v16si)index, every16, 4);
    } else {
        const x86::v8sf f = __builtin_ia32_gatherdiv16sf(x86::v8sf{}, base, (x86::v8di)index, every8, 4);
#if defined(__clang__)
        return __builtin_convertvector(f, V);
#else
        // GCC 12 lowers __builtin_convertvector here to two 256-bit conversions.
        return (V)__builtin_ia32_cvtps2pd512_mask(f, x86::v8df{}, every8, current_rounding);
#endif
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
