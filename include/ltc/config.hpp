// ltc/config.hpp -- version, ABI namespace and the host/device annotation shared by every header.
//
// LTC_HOST_DEVICE is empty for host compilers and `__host__ __device__` under CUDA, so the
// same evaluation and integration code runs in a renderer on either side (as pbrt-v4 does).
#pragma once

#define LTC_VERSION_MAJOR 0
#define LTC_VERSION_MINOR 2
#define LTC_VERSION_PATCH 0

// Every declaration of ltc lives in an inline namespace named after the version and the
// configuration (as nlohmann/json's json_abi_v3_11_x), so that translation units built with
// different settings never share an inline function by accident: a program whose files disagree
// on LTC_NO_SIMD gets two distinct sets of symbols, never one of them picked by the linker for
// both. No definition of ltc depends on -m flags (the batches' instruction sets are chosen by
// target attributes and a run-time CPU check), so they take no part in the name.
// User code names everything as ltc::x; the inline namespace appears only in mangled names.
#if defined(LTC_NO_SIMD)
#define LTC_ABI_TAG_SIMD _nosimd
#else
#define LTC_ABI_TAG_SIMD
#endif
#define LTC_ABI_CONCAT_(major, minor, patch, simd) abi_v##major##_##minor##_##patch##simd
#define LTC_ABI_CONCAT(major, minor, patch, simd) LTC_ABI_CONCAT_(major, minor, patch, simd)
#define LTC_ABI_NAMESPACE LTC_ABI_CONCAT(LTC_VERSION_MAJOR, LTC_VERSION_MINOR, LTC_VERSION_PATCH, LTC_ABI_TAG_SIMD)
#define LTC_NAMESPACE_BEGIN \
    namespace ltc {         \
    inline namespace LTC_ABI_NAMESPACE {
#define LTC_NAMESPACE_END \
    }                     \
    }

#if defined(__CUDACC__)
#define LTC_HOST_DEVICE __host__ __device__
#else
#define LTC_HOST_DEVICE
#endif

// LTC_INLINE marks the small functions of the integration hot path: GCC otherwise declines to
// inline some of them, and a call per vertex and per edge costs more than the math.
// LTC_NOINLINE keeps rare slow paths (rescaling of huge or tiny vectors) out of the hot code.
// LTC_NO_FORCE_INLINE makes LTC_INLINE a plain inline, for builds where compile time matters more
// than speed (the library's own unit tests): every call site of a forced-inline function gets its
// own copy of the whole integration. It changes no formula (ltc::ltc compiles without FP
// contraction, so inlining cannot fuse operations), so it takes no part in the ABI name.
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
#if defined(LTC_NO_FORCE_INLINE)
#undef LTC_INLINE
#define LTC_INLINE inline
#endif
