// ltc/detail/batch_lanes.hpp -- the branch-free arithmetic of one item in one vector lane, for
// the batch kernels (ltc/shading/batch.hpp): bitwise select, a Newton rsqrt without sqrt or
// division, the edge term of eq. (11) for the library's edge policies, and M^-1 p normalized.
// Each mirrors a scalar function of the library (named at each) in its order of operations, and
// raises a fallback flag where that scalar function takes a path of its own.
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/edge_policy.hpp>
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace ltc {
namespace batch {
namespace detail {

// The loop bodies must be inlined whole into the loops over items, or nothing vectorizes:
// every helper below is LTC_INLINE (config.hpp).

/// Integer type of the width of T: flags live in it so that they share T's vector lanes.
template <typename T>
using mask_t = std::conditional_t<sizeof(T) == 4, std::int32_t, std::int64_t>;

/// c ? a : b through the bits: both operands are computed unconditionally. A C++ conditional
/// operator whose operands are only used there lets GCC sink their computation into a branch,
/// which it then refuses to if-convert (the default -ftrapping-math forbids speculating a
/// floating-point operation), and the loop is not vectorized.
template <typename T>
LTC_INLINE T select(bool c, T a, T b) {
    using U = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
    U ua, ub;
    std::memcpy(&ua, &a, sizeof ua);
    std::memcpy(&ub, &b, sizeof ub);
    const U m = U(0) - U(c);
    const U r = (ua & m) | (ub & ~m);
    T t;
    std::memcpy(&t, &r, sizeof t);
    return t;
}

/// 1 / sqrt(x) for normal x > 0 (other x give garbage, possibly NaN or Inf: callers select such
/// lanes away or flag them), without sqrt or division (unless -fno-math-errno, see below): the
/// classical integer first guess (relative error < 3.5e-2), then Newton steps
/// y (3/2 - x y^2 / 2), each squaring the error (1.7e-3, 4.3e-6, then float rounding: measured
/// <= 2.2 ulps over [1e-30, 1e30]). Double takes one more.
template <typename T>
LTC_INLINE T rsqrt(T x) {
    static_assert(std::is_same_v<T, float> || std::is_same_v<T, double>, "float or double");
#if defined(__NO_MATH_ERRNO__)
    // Under -fno-math-errno (GCC and Clang define __NO_MATH_ERRNO__) std::sqrt vectorizes:
    // sqrtps and divps, correctly rounded like the scalar path (measured: +20% throughput, SSE2).
    return T(1) / std::sqrt(x);
#endif
    T y;
    if constexpr (std::is_same_v<T, float>) {
        std::uint32_t u;
        std::memcpy(&u, &x, sizeof u);
        u = 0x5f375a86u - (u >> 1);
        std::memcpy(&y, &u, sizeof y);
    } else {
        std::uint64_t u;
        std::memcpy(&u, &x, sizeof u);
        u = 0x5fe6eb50c7b537a9ull - (u >> 1);
        std::memcpy(&y, &u, sizeof y);
    }
    const T h = T(0.5) * x;
    y = y * (T(1.5) - h * y * y);
    y = y * (T(1.5) - h * y * y);
    y = y * (T(1.5) - h * y * y);
    if constexpr (std::is_same_v<T, double>) y = y * (T(1.5) - h * y * y);
    return y;
}

/// theta / sin(theta) of the edge policy, from c = cos(theta), s2 = |a x b|^2 and a x b, without
/// branches for the library's approximate policies. Sets `fallback` where the scalar path must
/// take over (polynomial, minimax_rational: c < 0 with |a x b|^2 <= 1e-30).
template <typename Policy, typename T>
LTC_INLINE T theta_over_sin(T c, T s2, T cx, T cy, T cz, bool& fallback) {
    if constexpr (std::is_same_v<Policy, edge_policy::polynomial> ||
                  std::is_same_v<Policy, edge_policy::minimax_rational>) {
        // The scalar policy's own fit, in the same order (its division vectorizes).
        const T p = Policy::positive_branch(T(1) - std::abs(c));
        const bool pos = c >= T(0);
        fallback = !pos & !(s2 > T(1e-30));
        const T neg = pi<T>() * rsqrt(s2) - p;  // pi / s - p
        return select(pos, p, neg);
    } else if constexpr (std::is_same_v<Policy, edge_policy::rational>) {
        fallback = false;
        const T y = std::abs(c);
        const T a = T(0.8543985) + (T(0.4965155) + T(0.0145206) * y) * y;
        const T b = T(3.4175940) + (T(4.1616724) + y) * y;
        const T v = a / b;
        const T d = T(1) - c * c;
        const T neg = T(0.5) * rsqrt(select(d > T(1e-7), d, T(1e-7))) - v;  // 0.5 / sqrt(max(d, 1e-7)) - v
        const T r = select(c > T(0), v, neg);
        return T(2) * pi<T>() * r;
    } else if constexpr (std::is_same_v<Policy, edge_policy::fp16_quadratic> && std::is_same_v<T, float>) {
        fallback = false;
        const T x = std::abs(c);
        const T v = (T(0.33735186f) * x - T(0.89665001f)) * x + T(1.5707963f);
        const T d = T(1) - c * c;
        const T neg = T(3.1415927f) * rsqrt(select(d > T(1e-4f), d, T(1e-4f))) - v;
        return select(c >= T(0), v, neg);
    } else {
        // edge_policy::exact (atan2: not vectorized) and user policies: the scalar evaluation.
        (void)s2;
        fallback = false;
        return Policy::theta_over_sin(c, glm::vec<3, T>(cx, cy, cz));
    }
}

/// z component of the edge term of unit vectors a -> b (edge_integral_z of ltc/core/edge_integral.hpp).
template <typename Policy, typename T>
LTC_INLINE T edge_z(T ax, T ay, T az, T bx, T by, T bz, bool& fallback) {
    const T c = ax * bx + ay * by + az * bz;
    // stable_cross: a x (b - a) or a x (b + a); b + (-1) a is b - a exactly.
    const T sa = c >= T(0) ? T(-1) : T(1);
    const T dx = bx + sa * ax, dy = by + sa * ay, dz = bz + sa * az;
    const T cx = ay * dz - dy * az, cy = az * dx - dz * ax, cz = ax * dy - dx * ay;
    return cz * theta_over_sin<Policy>(c, cx * cx + cy * cy + cz * cz, cx, cy, cz, fallback);
}

/// The same for a -> b both on the horizon (z = 0): only a x b's z component is non-zero.
template <typename Policy, typename T>
LTC_INLINE T horizon_edge_z(T ax, T ay, T bx, T by, bool& fallback) {
    const T c = ax * bx + ay * by;
    const T sa = c >= T(0) ? T(-1) : T(1);
    const T dx = bx + sa * ax, dy = by + sa * ay;
    const T cz = ax * dy - dx * ay;
    return cz * theta_over_sin<Policy>(c, cz * cz, T(0), T(0), cz, fallback);
}

/// M^-1 as a per-item accessor: nine arrays, or one shared matrix (a broadcast).
template <typename T>
struct per_item_matrix {
    const T* e[3][3];
    LTC_INLINE T at(int c, int r, std::size_t i) const { return e[c][r][i]; }
};
template <typename T>
struct shared_matrix {
    T e[3][3];
    LTC_INLINE T at(int c, int r, std::size_t) const { return e[c][r]; }
};

/// Unit vector of M^-1 p (transformed_vertices of ltc/core/transformed.hpp, fast path); flags an item whose
/// |M^-1 p|^2 is outside the fast path's range (origin, tiny, huge, NaN).
template <typename T, typename M>
LTC_INLINE void unit_vertex(const M& m, std::size_t i, T px, T py, T pz, T& ux, T& uy, T& uz, bool& fallback) {
    // glm's mat3 * vec3, in its order of operations.
    const T qx = m.at(0, 0, i) * px + m.at(1, 0, i) * py + m.at(2, 0, i) * pz;
    const T qy = m.at(0, 1, i) * px + m.at(1, 1, i) * py + m.at(2, 1, i) * pz;
    const T qz = m.at(0, 2, i) * px + m.at(1, 2, i) * py + m.at(2, 2, i) * pz;
    const T l2 = qx * qx + qy * qy + qz * qz;
    fallback = fallback | !(l2 > T(1e-30)) | !(l2 < T(1e30));
    const T inv = rsqrt(l2);
    ux = qx * inv, uy = qy * inv, uz = qz * inv;
}

/// Sign of |M^-1| (transformed::from_inverse's determinant, in glm's order of operations).
template <typename T, typename M>
LTC_INLINE bool negative_determinant(const M& m, std::size_t i) {
    const T c1x = m.at(1, 0, i), c1y = m.at(1, 1, i), c1z = m.at(1, 2, i);
    const T c2x = m.at(2, 0, i), c2y = m.at(2, 1, i), c2z = m.at(2, 2, i);
    const T kx = c1y * c2z - c2y * c1z, ky = c1z * c2x - c2z * c1x, kz = c1x * c2y - c2x * c1y;
    return m.at(0, 0, i) * kx + m.at(0, 1, i) * ky + m.at(0, 2, i) * kz < T(0);
}

}  // namespace detail
}  // namespace batch
}  // namespace ltc
