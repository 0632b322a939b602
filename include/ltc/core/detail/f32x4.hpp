// ltc/core/detail/f32x4.hpp -- four float lanes for the core layer's lane algorithms (the float
// quad path, ltc/core/detail/quad_lanes.hpp), without intrinsics and without estimates: every
// operation is an elementwise IEEE 754 operation (+, -, *, /, sqrt, comparison, a choice between
// lanes, the sign bit cleared), so a lane holds the bits that the same operations give in scalar
// float code, whichever representation and instruction set computes it.
//
// Two representations of the same operations, in ltc::detail::lanes4: f32x4_portable (a plain
// struct, everywhere) and f32x4_vector (the GCC/Clang vector extension, where LTC_F32X4_VECTOR is
// 1); f32x4 and m32x4 name the one the build uses. Conventions: a mask (m32x4) holds -1 in a true
// lane, 0 in a false one; bitwise agreement with scalar code presumes -ffp-contract=off.
#pragma once

#include <ltc/config.hpp>

#include <cmath>
#include <cstdint>
#include <type_traits>

// Two representations of the same operations, in ltc::detail::lanes4:
//   - f32x4_portable, m32x4_portable: a plain struct of four lanes, the operators written out lane
//     by lane; defined everywhere (CUDA host and device code, MSVC, LTC_NO_SIMD);
//   - f32x4_vector, m32x4_vector: the GCC/Clang vector extension (`vector_size(16)`: one SSE or
//     NEON register), whose operators are the compiler's own; defined where LTC_F32X4_VECTOR is 1
//     (host GCC and Clang, unless LTC_NO_SIMD is defined).
#if !defined(LTC_NO_SIMD) && (defined(__GNUC__) || defined(__clang__)) && !defined(__CUDACC__)
#define LTC_F32X4_VECTOR 1
#else
#define LTC_F32X4_VECTOR 0
#endif

LTC_NAMESPACE_BEGIN
namespace detail {
namespace lanes4 {

// A mask (m32x4, what a comparison returns) holds -1 (all bits set) in a true lane and 0 in a
// false one. Beyond the operators (+ - * / of lanes and of a lane and a float, += -= *= /=;
// >= > < == of lanes and against a float; & | ^ ~ of masks; [] for one lane): make4, splat,
// select, keep, bits, rotate, rotate_back, lane_sqrt, lane_abs below. f32x4 and m32x4 (after both
// representations) name the one the build uses.

// ---- The plain struct -------------------------------------------------------------------------

struct m32x4_portable {
    std::int32_t v[4];
    LTC_HOST_DEVICE LTC_INLINE std::int32_t operator[](int k) const { return v[k]; }
};

struct f32x4_portable {
    float v[4];
    LTC_HOST_DEVICE LTC_INLINE float& operator[](int k) { return v[k]; }
    LTC_HOST_DEVICE LTC_INLINE const float& operator[](int k) const { return v[k]; }
};

// The body of a lane-by-lane function: a R whose lane k is expr.
#define LTC_LANES4(R, expr)                         \
    R r;                                            \
    for (int k = 0; k < 4; ++k) r.v[k] = (expr);    \
    return r

#define LTC_LANES4_ARITHMETIC(op)                                                                  \
    LTC_HOST_DEVICE LTC_INLINE f32x4_portable operator op(const f32x4_portable& a,                 \
                                                          const f32x4_portable& b) {               \
        LTC_LANES4(f32x4_portable, a.v[k] op b.v[k]);                                              \
    }                                                                                              \
    LTC_HOST_DEVICE LTC_INLINE f32x4_portable operator op(const f32x4_portable& a, float b) {      \
        LTC_LANES4(f32x4_portable, a.v[k] op b);                                                   \
    }                                                                                              \
    LTC_HOST_DEVICE LTC_INLINE f32x4_portable operator op(float a, const f32x4_portable& b) {      \
        LTC_LANES4(f32x4_portable, a op b.v[k]);                                                   \
    }                                                                                              \
    LTC_HOST_DEVICE LTC_INLINE f32x4_portable& operator op##=(f32x4_portable & a,                  \
                                                              const f32x4_portable& b) {           \
        return a = a op b;                                                                         \
    }
LTC_LANES4_ARITHMETIC(+)
LTC_LANES4_ARITHMETIC(-)
LTC_LANES4_ARITHMETIC(*)
LTC_LANES4_ARITHMETIC(/)
#undef LTC_LANES4_ARITHMETIC

#define LTC_LANES4_COMPARISON(op)                                                                  \
    LTC_HOST_DEVICE LTC_INLINE m32x4_portable operator op(const f32x4_portable& a,                 \
                                                          const f32x4_portable& b) {               \
        LTC_LANES4(m32x4_portable, a.v[k] op b.v[k] ? -1 : 0);                                     \
    }                                                                                              \
    LTC_HOST_DEVICE LTC_INLINE m32x4_portable operator op(const f32x4_portable& a, float b) {      \
        LTC_LANES4(m32x4_portable, a.v[k] op b ? -1 : 0);                                          \
    }
LTC_LANES4_COMPARISON(>=)
LTC_LANES4_COMPARISON(>)
LTC_LANES4_COMPARISON(<)
LTC_LANES4_COMPARISON(==)
#undef LTC_LANES4_COMPARISON

#define LTC_LANES4_LOGIC(op)                                                                       \
    LTC_HOST_DEVICE LTC_INLINE m32x4_portable operator op(const m32x4_portable& a,                 \
                                                          const m32x4_portable& b) {               \
        LTC_LANES4(m32x4_portable, a.v[k] op b.v[k]);                                              \
    }
LTC_LANES4_LOGIC(&)
LTC_LANES4_LOGIC(|)
LTC_LANES4_LOGIC(^)
#undef LTC_LANES4_LOGIC

LTC_HOST_DEVICE LTC_INLINE m32x4_portable operator~(const m32x4_portable& a) { LTC_LANES4(m32x4_portable, ~a.v[k]); }

/// a where m, else b.
LTC_HOST_DEVICE LTC_INLINE f32x4_portable select(const m32x4_portable& m, const f32x4_portable& a,
                                                 const f32x4_portable& b) {
    LTC_LANES4(f32x4_portable, m.v[k] ? a.v[k] : b.v[k]);
}

/// a where m, else +0.
LTC_HOST_DEVICE LTC_INLINE f32x4_portable keep(const m32x4_portable& m, const f32x4_portable& a) {
    LTC_LANES4(f32x4_portable, m.v[k] ? a.v[k] : 0.0f);
}

/// Bit k set where lane k of m is true.
LTC_HOST_DEVICE LTC_INLINE unsigned bits(const m32x4_portable& m) {
    return (m.v[0] ? 1u : 0u) | (m.v[1] ? 2u : 0u) | (m.v[2] ? 4u : 0u) | (m.v[3] ? 8u : 0u);
}

/// Lane k takes lane k - 1, lane 0 lane 3.
LTC_HOST_DEVICE LTC_INLINE f32x4_portable rotate(const f32x4_portable& a) {
    LTC_LANES4(f32x4_portable, a.v[(k + 3) % 4]);
}
LTC_HOST_DEVICE LTC_INLINE m32x4_portable rotate(const m32x4_portable& a) {
    LTC_LANES4(m32x4_portable, a.v[(k + 3) % 4]);
}
/// Lane k takes lane k + 1, lane 3 lane 0 (rotate's inverse).
LTC_HOST_DEVICE LTC_INLINE f32x4_portable rotate_back(const f32x4_portable& a) {
    LTC_LANES4(f32x4_portable, a.v[(k + 1) % 4]);
}
LTC_HOST_DEVICE LTC_INLINE m32x4_portable rotate_back(const m32x4_portable& a) {
    LTC_LANES4(m32x4_portable, a.v[(k + 1) % 4]);
}

/// The correctly rounded square root of each lane.
///
/// In both representations (std::sqrt, or SSE's sqrtps through the builtin GCC and Clang share).
/// Bitwise agreement with scalar code presumes that neither contracts a * b + c into a fused
/// multiply-add (-ffp-contract=off): a compiler may contract vector and scalar expressions
/// differently.
LTC_HOST_DEVICE LTC_INLINE f32x4_portable lane_sqrt(const f32x4_portable& a) {
    LTC_LANES4(f32x4_portable, std::sqrt(a.v[k]));
}

/// Each lane with its sign bit cleared.
LTC_HOST_DEVICE LTC_INLINE f32x4_portable lane_abs(const f32x4_portable& a) {
    LTC_LANES4(f32x4_portable, std::fabs(a.v[k]));
}

#undef LTC_LANES4

// ---- The vector extension ---------------------------------------------------------------------

#if LTC_F32X4_VECTOR
typedef float f32x4_vector __attribute__((vector_size(16)));
typedef std::int32_t m32x4_vector __attribute__((vector_size(16)));

#if defined(__clang__) || __GNUC__ >= 12
#define LTC_LANES4_SHUFFLE(a, i, j, k, l) __builtin_shufflevector(a, a, i, j, k, l)
#else
#define LTC_LANES4_SHUFFLE(a, i, j, k, l) __builtin_shuffle(a, m32x4_vector{i, j, k, l})
#endif

LTC_INLINE f32x4_vector select(m32x4_vector m, f32x4_vector a, f32x4_vector b) { return m ? a : b; }
LTC_INLINE f32x4_vector keep(m32x4_vector m, f32x4_vector a) { return m ? a : f32x4_vector{}; }

/// The lanes' weights 1, 2, 4, 8 where true, OR-ed together across the register by two shuffles.
LTC_INLINE unsigned bits(m32x4_vector m) {
    const m32x4_vector w = m & m32x4_vector{1, 2, 4, 8};
    const m32x4_vector h = w | LTC_LANES4_SHUFFLE(w, 2, 3, 0, 1);
    return unsigned((h | LTC_LANES4_SHUFFLE(h, 1, 0, 3, 2))[0]);
}

LTC_INLINE f32x4_vector rotate(f32x4_vector a) { return LTC_LANES4_SHUFFLE(a, 3, 0, 1, 2); }
LTC_INLINE m32x4_vector rotate(m32x4_vector a) { return LTC_LANES4_SHUFFLE(a, 3, 0, 1, 2); }
LTC_INLINE f32x4_vector rotate_back(f32x4_vector a) { return LTC_LANES4_SHUFFLE(a, 1, 2, 3, 0); }
LTC_INLINE m32x4_vector rotate_back(m32x4_vector a) { return LTC_LANES4_SHUFFLE(a, 1, 2, 3, 0); }
#undef LTC_LANES4_SHUFFLE

LTC_INLINE f32x4_vector lane_sqrt(f32x4_vector a) {
#if defined(__SSE__)
    // sqrtps: the correctly rounded square root of every lane, the same bits as std::sqrt (IEEE 754
    // requires it), without the errno check that GCC adds to each scalar std::sqrt by default.
    // A compiler builtin that GCC and Clang share, not an <immintrin.h> intrinsic.
    return __builtin_ia32_sqrtps(a);
#else
    return f32x4_vector{std::sqrt(a[0]), std::sqrt(a[1]), std::sqrt(a[2]), std::sqrt(a[3])};
#endif
}

LTC_INLINE f32x4_vector lane_abs(f32x4_vector a) {
    constexpr std::int32_t magnitude = 0x7fffffff;
    return (f32x4_vector)((m32x4_vector)a & m32x4_vector{magnitude, magnitude, magnitude, magnitude});
}

using f32x4 = f32x4_vector;
using m32x4 = m32x4_vector;
#else
using f32x4 = f32x4_portable;
using m32x4 = m32x4_portable;
#endif

/// The lanes a, b, c, d of F (either representation).
template <typename F>
LTC_HOST_DEVICE LTC_INLINE F make4(float a, float b, float c, float d) {
    if constexpr (std::is_class_v<F>)
        return F{{a, b, c, d}};
    else
        return F{a, b, c, d};
}

/// s in every lane.
template <typename F>
LTC_HOST_DEVICE LTC_INLINE F splat(float s) {
    return make4<F>(s, s, s, s);
}

}  // namespace lanes4
}  // namespace detail
LTC_NAMESPACE_END
