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
#pragma once

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/core/polygon.hpp>
#include <ltc/core/transformed.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <type_traits>
#include <utility>

namespace ltc {
namespace batch {

/// Where each item's inverse matrix M^-1 comes from: nine arrays (one per entry, indexed like
/// glm: entry[c][r][i] = (M^-1 of item i)[c][r], column c, row r), or one matrix shared by all.
template <typename T>
struct matrices {
    const T* entry[3][3] = {};    ///< per-item arrays; all null: `shared` is used for every item
    glm::mat<3, 3, T> shared{T(1)};

    static matrices per_item(const T* const (&e)[3][3]) {
        matrices m;
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) m.entry[c][r] = e[c][r];
        return m;
    }
    static matrices same_for_all(const glm::mat<3, 3, T>& m_inv) {
        matrices m;
        m.shared = m_inv;
        return m;
    }
    bool is_shared() const { return entry[0][0] == nullptr; }
};

/// count polygons of N vertices each: vertex k of item i is (x[k][i], y[k][i], z[k][i]), in the
/// shading frame (any scale; see polygon.hpp for orientation and degenerate input).
template <typename T, std::size_t N>
struct polygon_soa {
    matrices<T> m_inv;
    const T* x[N] = {};
    const T* y[N] = {};
    const T* z[N] = {};
};

template <typename T>
using quad_soa = polygon_soa<T, 4>;

/// The same with n known at run time only: x[k] (k < n) points to the x coordinates of vertex k.
template <typename T>
struct ngon_soa {
    matrices<T> m_inv;
    std::size_t n = 0;
    const T* const* x = nullptr;
    const T* const* y = nullptr;
    const T* const* z = nullptr;
};

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

/// z component of the edge term of unit vectors a -> b (edge_integral_z of polygon.hpp).
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

/// Unit vector of M^-1 p (transformed_vertices of transformed.hpp, fast path); flags an item whose
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

/// The data-parallel horizon clipper and edge sum of one item, one input edge p -> q at a time.
/// The horizon edges (exit E -> next entry R) are evaluated at each entry (S = 0: any n, state of
/// fixed size), or, with S = n / 2 >= the number of entries, recorded in S slots and evaluated
/// once each at the end (fewer edge terms: S instead of n + 1).
template <typename T, std::size_t S = 0>
struct walker {
    T px, py, pz;     // previous unit vertex
    T ex, ey;         // last exit crossing (z = 0)
    T rx, ry;         // S = 0: first entry crossing, when no exit preceded it
    T sum;            // sum of edge terms (times 2 pi)
    bool has_exit, has_first, fallback;
    // S > 0: slot k holds the k-th entry R and the exit E before it (slot 0: E pending if no exit
    // preceded the first entry; it is then the last exit, set at the end).
    T sex[S ? S : 1], sey[S ? S : 1], srx[S ? S : 1], sry[S ? S : 1];
    mask_t<T> entries;

    template <typename Policy>
    LTC_INLINE void edge(T qx, T qy, T qz) {
        const bool pin = pz >= T(0), qin = qz >= T(0);
        const bool crossing = pin != qin, entry = !pin & qin, exit = pin & !qin;
        // Crossing point: horizon_crossing_direction(in, out), normalized.
        const T ix = select(pin, px, qx), iy = select(pin, py, qy), iz = select(pin, pz, qz);
        const T ox = select(pin, qx, px), oy = select(pin, qy, py), oz = select(pin, qz, pz);
        T xx = ix * (-oz) + ox * iz, xy = iy * (-oz) + oy * iz;
        const T xl2 = xx * xx + xy * xy;
        const T inv = rsqrt(xl2);
        xx *= inv, xy *= inv;
        // The clipped part of the edge.
        const bool valid = pin | qin;
        const T ax = select(pin, px, xx), ay = select(pin, py, xy), az = select(pin, pz, T(0));
        const T bx = select(qin, qx, xx), by = select(qin, qy, xy), bz = select(qin, qz, T(0));
        bool f_edge = false;
        const T t = edge_z<Policy>(ax, ay, az, bx, by, bz, f_edge);
        sum += select(valid, t, T(0));
        fallback = fallback | (crossing & !(xl2 > T(1e-30))) | (valid & f_edge);
        if constexpr (S == 0) {
            // At an entry after an exit: the horizon edge from that exit to this entry.
            bool f_close = false;
            const bool close = entry & has_exit;
            const T h = horizon_edge_z<Policy>(ex, ey, xx, xy, f_close);
            sum += select(close, h, T(0));
            fallback = fallback | (close & f_close);
            const bool first = entry & !has_exit;
            rx = select(first, xx, rx), ry = select(first, xy, ry);
            has_first = has_first | first;
        } else {
            for (std::size_t k = 0; k < S; ++k) {
                const bool here = entry & (entries == mask_t<T>(k));
                sex[k] = select(here, ex, sex[k]), sey[k] = select(here, ey, sey[k]);
                srx[k] = select(here, xx, srx[k]), sry[k] = select(here, xy, sry[k]);
            }
            has_first = has_first | (entry & !has_exit);  // slot 0's exit is pending
            entries += mask_t<T>(entry);
        }
        ex = select(exit, xx, ex), ey = select(exit, xy, ey);
        has_exit = has_exit | exit;
        px = qx, py = qy, pz = qz;
    }

    /// The value of the item, or NaN where the scalar path must recompute it.
    template <typename Policy>
    LTC_INLINE T finish(bool negative_det, bool two_sided) {
        T total = sum;
        bool fb = fallback;
        if constexpr (S == 0) {
            bool f_close = false;
            const bool close = has_first & has_exit;  // last exit -> first entry, cyclically
            const T h = horizon_edge_z<Policy>(ex, ey, rx, ry, f_close);
            total += select(close, h, T(0));
            fb = fb | (close & f_close);
        } else {
            sex[0] = select(has_first, ex, sex[0]), sey[0] = select(has_first, ey, sey[0]);
            for (std::size_t k = 0; k < S; ++k) {
                bool f_close = false;
                const bool used = entries > mask_t<T>(k);
                const T h = horizon_edge_z<Policy>(sex[k], sey[k], srx[k], sry[k], f_close);
                total += select(used, h, T(0));
                fb = fb | (used & f_close);
            }
        }
        const T v = total / (T(2) * pi<T>());
        const T sv = v * (negative_det ? T(-1) : T(1));
        const T r = two_sided ? std::abs(sv) : select(sv > T(0), sv, T(0));
        return select(fb, std::numeric_limits<T>::quiet_NaN(), r);
    }

    LTC_INLINE void start(T ux, T uy, T uz) {
        px = ux, py = uy, pz = uz;
        ex = ey = rx = ry = sum = T(0);
        has_exit = has_first = false;
        for (std::size_t k = 0; k < (S ? S : 1); ++k) sex[k] = sey[k] = srx[k] = sry[k] = T(0);
        entries = 0;
    }
};

template <typename Policy, typename T, std::size_t S, typename M>
LTC_INLINE void fixed_step(walker<T, S>& w, const M& m, std::size_t i, T px, T py, T pz) {
    T qx, qy, qz;
    unit_vertex(m, i, px, py, pz, qx, qy, qz, w.fallback);
    w.template edge<Policy>(qx, qy, qz);
}

/// Fixed n: the whole item in registers, edges unrolled at compile time.
template <typename Policy, bool two_sided, typename T, std::size_t N, typename M, std::size_t... K>
inline void kernel_fixed(const M m, const T* const (&x)[N], const T* const (&y)[N], const T* const (&z)[N],
                         T* __restrict out, std::size_t count, std::index_sequence<K...>) {
    for (std::size_t i = 0; i < count; ++i) {
        walker<T, N / 2> w;
        w.fallback = false;
        T ux, uy, uz;
        unit_vertex(m, i, x[N - 1][i], y[N - 1][i], z[N - 1][i], ux, uy, uz, w.fallback);
        w.start(ux, uy, uz);
        // Edges (n-1 -> 0), (0 -> 1), ..., (n-2 -> n-1); vertex n-1 is transformed again at the
        // end rather than kept live across the item (same value).
        (fixed_step<Policy>(w, m, i, x[K][i], y[K][i], z[K][i]), ...);
        out[i] = w.template finish<Policy>(negative_determinant<T>(m, i), two_sided);
    }
}

/// Runtime n: blocks of B items, the vertex loop outside, the item loop inside (vectorized), the
/// walkers' state in arrays.
template <typename Policy, bool two_sided, typename T, typename M>
inline void kernel_blocked(const M m, std::size_t n, const T* const* x, const T* const* y, const T* const* z,
                           T* __restrict out, std::size_t count) {
    constexpr std::size_t B = 64;
    using mask = mask_t<T>;
    T px[B], py[B], pz[B], ex[B], ey[B], rx[B], ry[B], sum[B];
    mask has_exit[B], has_first[B], fb[B];
    for (std::size_t base = 0; base < count; base += B) {
        const std::size_t b = count - base < B ? count - base : B;
        const T *xs = x[n - 1] + base, *ys = y[n - 1] + base, *zs = z[n - 1] + base;
        for (std::size_t j = 0; j < b; ++j) {
            bool f = false;
            T ux, uy, uz;
            unit_vertex(m, base + j, xs[j], ys[j], zs[j], ux, uy, uz, f);
            px[j] = ux, py[j] = uy, pz[j] = uz;
            ex[j] = ey[j] = rx[j] = ry[j] = sum[j] = T(0);
            has_exit[j] = has_first[j] = 0;
            fb[j] = f;
        }
        for (std::size_t k = 0; k < n; ++k) {  // edges (n-1 -> 0), (0 -> 1), ..., (n-2 -> n-1)
            xs = x[k] + base, ys = y[k] + base, zs = z[k] + base;
            for (std::size_t j = 0; j < b; ++j) {
                walker<T> w;
                w.px = px[j], w.py = py[j], w.pz = pz[j], w.ex = ex[j], w.ey = ey[j], w.rx = rx[j], w.ry = ry[j];
                w.sum = sum[j], w.has_exit = has_exit[j] != 0, w.has_first = has_first[j] != 0, w.fallback = fb[j] != 0;
                T qx, qy, qz;
                unit_vertex(m, base + j, xs[j], ys[j], zs[j], qx, qy, qz, w.fallback);
                w.template edge<Policy>(qx, qy, qz);
                px[j] = w.px, py[j] = w.py, pz[j] = w.pz, ex[j] = w.ex, ey[j] = w.ey, rx[j] = w.rx, ry[j] = w.ry;
                sum[j] = w.sum, has_exit[j] = w.has_exit, has_first[j] = w.has_first, fb[j] = w.fallback;
            }
        }
        for (std::size_t j = 0; j < b; ++j) {
            walker<T> w;
            w.px = px[j], w.py = py[j], w.pz = pz[j], w.ex = ex[j], w.ey = ey[j], w.rx = rx[j], w.ry = ry[j];
            w.sum = sum[j], w.has_exit = has_exit[j] != 0, w.has_first = has_first[j] != 0, w.fallback = fb[j] != 0;
            out[base + j] = w.template finish<Policy>(negative_determinant<T>(m, base + j), two_sided);
        }
    }
}

/// The scalar path for item i (used where the vector loop flagged it).
template <typename Policy, typename T, typename M, typename Vertex>
inline T scalar_item(const M& m, std::size_t i, std::size_t n, const Vertex& vertex, sidedness s) {
    glm::mat<3, 3, T> mi;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) mi[c][r] = m.at(c, r, i);
    constexpr std::size_t stack = 16;
    glm::vec<3, T> buf[stack];
    T value(0);
    const auto eval = [&](glm::vec<3, T>* v) {
        for (std::size_t k = 0; k < n; ++k) v[k] = vertex(k, i);
        value = transformed<clamped_cosine<T, Policy>>::from_inverse(mi).integrate(v, n, s);
    };
    if (n <= stack) {
        eval(buf);
    } else {
        std::unique_ptr<glm::vec<3, T>[]> heap(new glm::vec<3, T>[n]);
        eval(heap.get());
    }
    return value;
}

template <typename Policy, typename T, typename M, typename Vertex>
inline void fix_up(const M& m, std::size_t n, const Vertex& vertex, T* out, std::size_t count, sidedness s) {
    for (std::size_t i = 0; i < count; ++i)
        if (std::isnan(out[i])) out[i] = scalar_item<Policy, T>(m, i, n, vertex, s);
}

template <typename Policy, typename T, typename Run>
inline void with_matrix(const matrices<T>& mats, const Run& run) {
    if (mats.is_shared()) {
        shared_matrix<T> m;
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) m.e[c][r] = mats.shared[c][r];
        run(m);
    } else {
        per_item_matrix<T> m;
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) m.e[c][r] = mats.entry[c][r];
        run(m);
    }
}

}  // namespace detail

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

