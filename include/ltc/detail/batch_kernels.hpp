// ltc/detail/batch_kernels.hpp -- the loops over items of the batch API (ltc/shading/batch.hpp):
// the fixed-n kernel (a walker per item, edges unrolled), the runtime-n blocked kernel (vertex
// loop outside, item loop inside), and the scalar path (transformed<clamped_cosine>, eq. 11)
// that recomputes the items the loops flagged.
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/detail/batch_lanes.hpp>
#include <ltc/detail/batch_walker.hpp>
#include <ltc/shading/batch_soa.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <memory>
#include <utility>

namespace ltc {
namespace batch {
namespace detail {

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
}  // namespace batch
}  // namespace ltc
