// ltc/detail/batch_walker.hpp -- the data-parallel horizon clipper of the batch kernels
// (ltc/shading/batch.hpp): one item's edges p -> q clipped to z >= 0 and summed (eq. 11) without
// a branch on the data, the horizon edges paired exit -> next entry (the file comment of
// batch.hpp says why this equals the scalar clipper's polygon).
#pragma once

#include <ltc/config.hpp>
#include <ltc/detail/batch_lanes.hpp>
#include <ltc/detail/math.hpp>

#include <cmath>
#include <cstddef>
#include <limits>

namespace ltc {
namespace batch {
namespace detail {

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

}  // namespace detail
}  // namespace batch
}  // namespace ltc
