// ltc/config.hpp -- version and the host/device annotation shared by every header.
//
// LTC_HOST_DEVICE is empty for host compilers and `__host__ __device__` under CUDA, so the
// same evaluation and integration code runs in a renderer on either side (as pbrt-v4 does).
#pragma once

#define LTC_VERSION_MAJOR 0
#define LTC_VERSION_MINOR 2
#define LTC_VERSION_PATCH 0

#if defined(__CUDACC__)
#define LTC_HOST_DEVICE __host__ __device__
#else
#define LTC_HOST_DEVICE
#endif

// LTC_INLINE marks the small functions of the integration hot path: GCC otherwise declines to
// inline some of them (measured: a call per vertex and per edge costs more than the math).
// LTC_NOINLINE keeps rare slow paths (rescaling of huge or tiny vectors) out of the hot code.
#if defined(__GNUC__) || defined(__clang__)
#define LTC_INLINE inline __attribute__((always_inline))
#define LTC_NOINLINE __attribute__((noinline))
#elif defined(_MSC_VER)
#define LTC_INLINE __forceinline
#define LTC_NOINLINE __declspec(noinline)
#else
#define LTC_INLINE inline
#define LTC_NOINLINE
#endif
