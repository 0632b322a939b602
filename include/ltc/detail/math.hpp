// ltc/detail/math.hpp -- scalar helpers shared by the headers (not part of the public API).
//
// Domain-safe functions in the spirit of pbrt-v4's SafeSqrt/SafeASin: they clamp the tiny
// excursions that rounding produces instead of returning NaN.
#pragma once

#include <ltc/config.hpp>

#include <glm/glm.hpp>

#include <cfloat>
#include <cmath>
#include <limits>
#include <type_traits>

LTC_NAMESPACE_BEGIN

/// pi in the precision of T.
template <typename T>
LTC_HOST_DEVICE constexpr T pi() {
    return static_cast<T>(3.141592653589793238462643383279502884L);
}

namespace detail {

/// Smallest positive normal number and machine epsilon of T, usable in CUDA device code
/// (std::numeric_limits members are host-only constexpr functions there).
template <typename T>
LTC_HOST_DEVICE constexpr T min_normal() {
    if constexpr (std::is_same_v<T, float>) return FLT_MIN;
    else if constexpr (std::is_same_v<T, double>) return DBL_MIN;
    else return std::numeric_limits<T>::min();
}
/// The largest finite T (CUDA-safe, as min_normal).
template <typename T>
LTC_HOST_DEVICE constexpr T largest_finite() {
    if constexpr (std::is_same_v<T, float>) return FLT_MAX;
    else if constexpr (std::is_same_v<T, double>) return DBL_MAX;
    else return std::numeric_limits<T>::max();
}
template <typename T>
LTC_HOST_DEVICE constexpr T epsilon() {
    if constexpr (std::is_same_v<T, float>) return FLT_EPSILON;
    else if constexpr (std::is_same_v<T, double>) return DBL_EPSILON;
    else return std::numeric_limits<T>::epsilon();
}

template <typename T>
LTC_HOST_DEVICE LTC_INLINE T safe_sqrt(T x) {
    return std::sqrt(x > T(0) ? x : T(0));
}

template <typename T>
LTC_HOST_DEVICE inline bool is_finite(const glm::vec<3, T>& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// v times the power of two that brings its largest component into [1, 2): exact (no rounding,
/// even from or to subnormals), so directions computed from the result are those of v itself.
/// Returns 0 for v = 0.
template <typename T>
LTC_HOST_DEVICE inline glm::vec<3, T> rescale_pow2(const glm::vec<3, T>& v) {
    const T m = glm::max(glm::max(std::abs(v.x), std::abs(v.y)), std::abs(v.z));
    if (!(m > T(0))) return glm::vec<3, T>(T(0));
    const int e = std::ilogb(m);
    return glm::vec<3, T>(std::ldexp(v.x, -e), std::ldexp(v.y, -e), std::ldexp(v.z, -e));
}

/// v times 2^e, exactly (barring over- or underflow of the result).
template <typename T>
LTC_HOST_DEVICE inline glm::vec<3, T> rescale_by(const glm::vec<3, T>& v, int e) {
    return glm::vec<3, T>(std::ldexp(v.x, e), std::ldexp(v.y, e), std::ldexp(v.z, e));
}

/// m times the power of two that brings its largest entry into [1, 2): exact, as rescale_pow2 of a
/// vector (m * v then has the direction of the original product, without its overflow).
template <typename T>
LTC_HOST_DEVICE inline glm::mat<3, 3, T> rescale_pow2(const glm::mat<3, 3, T>& m) {
    T big = T(0);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) big = glm::max(big, std::abs(m[c][r]));
    if (!(big > T(0)) || !std::isfinite(big)) return m;  // zero, or not finite
    const int e = std::ilogb(big);
    glm::mat<3, 3, T> s;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) s[c][r] = std::ldexp(m[c][r], -e);
    return s;
}

/// safe_normalize's slow path, kept out of line: an exact power-of-two rescale first, so that the
/// result is bitwise the one of the rescaled polygon (integrals are invariant under power-of-two
/// scaling).
template <typename T>
LTC_HOST_DEVICE LTC_NOINLINE glm::vec<3, T> safe_normalize_rescaled(const glm::vec<3, T>& v) {
    const glm::vec<3, T> s = rescale_pow2(v);
    const T s2 = glm::dot(s, s);
    return s2 > T(0) ? s * (T(1) / std::sqrt(s2)) : s;
}

/// Unit vector along v, or the zero vector when v is zero (a vertex at the shading point),
/// without overflow of |v|^2 for huge inputs nor underflow for tiny (even subnormal) ones.
template <typename T>
LTC_HOST_DEVICE LTC_INLINE glm::vec<3, T> safe_normalize(const glm::vec<3, T>& v) {
    const T l2 = glm::dot(v, v);
    // Fast path: |v|^2 neither overflowed nor lost precision to underflow (a well-predicted
    // branch).
    if (l2 > T(1e-30) && l2 < T(1e30)) return v * (T(1) / std::sqrt(l2));
    return safe_normalize_rescaled(v);
}

/// a x b for unit vectors, accurate to a few ulps *relative to |a x b|* even when a and b are
/// nearly parallel or nearly opposite: a x b = a x (b - a) = a x (b + a), and the difference
/// (or sum) of two nearly equal vectors is computed almost exactly (Sterbenz), so the
/// cancellation that a plain cross product suffers never happens.
template <typename T>
LTC_HOST_DEVICE LTC_INLINE glm::vec<3, T> stable_cross(const glm::vec<3, T>& a, const glm::vec<3, T>& b,
                                                   T a_dot_b) {
    return glm::cross(a, a_dot_b >= T(0) ? b - a : b + a);
}

/// a*b - c*d with one rounding error (Kahan's algorithm with FMA, as pbrt-v4's
/// DifferenceOfProducts): used for determinants and inverses of M.
template <typename T>
LTC_HOST_DEVICE inline T difference_of_products(T a, T b, T c, T d) {
    const T cd = c * d;
    const T err = std::fma(-c, d, cd);
    const T dop = std::fma(a, b, -cd);
    return dop + err;
}

}  // namespace detail
LTC_NAMESPACE_END

LTC_NAMESPACE_BEGIN
namespace detail {

/// (sin t cos phi, sin t sin phi, cos t): the supplement's spherical parameterization.
template <typename T>
LTC_HOST_DEVICE inline glm::vec<3, T> spherical_direction(T cos_theta, T sin_theta, T phi) {
    return glm::vec<3, T>(std::cos(phi) * sin_theta, std::sin(phi) * sin_theta, cos_theta);
}

/// Azimuth 2 pi u, shared by every sampler of the library.
template <typename T>
LTC_HOST_DEVICE inline T azimuth(T u) {
    return T(2) * pi<T>() * u;
}

}  // namespace detail
LTC_NAMESPACE_END
