// ltc/shading/detail/cell_quadtree.hpp -- the pieces of the quadtree of ltc/shading/textured_cells.hpp:
// its leaves, the set of leaves still to refine, and the integrals of a group of cells.
#pragma once

#include <ltc/config.hpp>

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/shading/batch.hpp>
#include <ltc/shading/cell_pyramid.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

LTC_NAMESPACE_BEGIN
namespace detail {

/// A leaf of the quadtree: cell (i, j) of level k, its I_D and its bound range I_D.
template <typename T>
struct cell_leaf {
    T bound, i_d;
    int k, i, j;
    bool operator<(const cell_leaf& o) const { return bound < o.bound; }
};

/// Where the cells lie: texel corner (x, y) at q0 + (x du) e1 + (y dv) e3 (neighbours share
/// their corners: the same expression of the same texel indices).
template <typename T>
struct cell_geometry {
    glm::vec<3, T> q0, e1, e3;
    T du, dv;
};

/// The quad's corners for the cells: only directions matter, so corners near the largest finite
/// value are scaled by 2^-4 (exactly) so that the parallelogram's fourth corner q0 + e1 + e3
/// cannot overflow. False for a non-finite coordinate, NaN included, in any corner (a caller's
/// overflow, e.g. world to local): there is no cell geometry then.
template <typename T>
inline bool cell_corners(const glm::vec<3, T> quad[4], glm::vec<3, T> (&q)[4]) {
    T largest(0);
    bool finite = true;
    for (int c = 0; c < 4; ++c) {
        q[c] = quad[c];
        for (int a = 0; a < 3; ++a) {
            finite = finite && std::isfinite(q[c][a]);  // NaN too: std::max would drop it
            largest = std::max(largest, std::abs(q[c][a]));
        }
    }
    if (largest > std::numeric_limits<T>::max() / T(8))
        for (glm::vec<3, T>& p : q) p *= T(0.0625);
    return finite;
}

template <typename T>
inline cell_geometry<T> make_cell_geometry(const glm::vec<3, T> (&q)[4], const cell_pyramid<T>& cells) {
    return {q[0], q[1] - q[0], q[3] - q[0], T(1) / T(cells.width()), T(1) / T(cells.height())};
}

/// The instruction set cell_integrals runs and its lanes: the narrowest with at least 8 lanes
/// that the CPU runs (the widest available otherwise); double: one cell at a time.
template <typename T>
struct cell_lanes {
    batch::isa which = batch::isa::scalar;
    int lanes = 1;
    cell_lanes() {
        if constexpr (std::is_same_v<T, float>)
            for (const batch::isa candidate : batch::instruction_sets) {
                if (!batch::available(candidate)) continue;
                which = candidate, lanes = int(batch::lane_count<T>(candidate));
                if (lanes >= 8) break;
            }
    }
};

/// I_D of the cells (k, i, j)[0..count), count <= 16: float through the batch kernel
/// (ltc/shading/batch.hpp) of cell_lanes, the lanes beyond count filled with copies of the last
/// cell, so that no cell takes the scalar tail; double one by one (its default policy, exact,
/// has no kernel). The corners are computed coordinate by coordinate over arrays, which the
/// compiler vectorizes. (Why 8 lanes, no tail and the corners by coordinate: docs/design_notes.md.)
template <typename T>
inline void cell_integrals(const transformed<clamped_cosine<T>>& d, sidedness side, const cell_geometry<T>& g,
                           const cell_pyramid<T>& cells, const int* k, const int* i, const int* j, int count, T* out,
                           std::size_t& integrals) {
    constexpr int most = 16;
    integrals += std::size_t(count);
    const cell_lanes<T> group;
    const int lanes = group.lanes;
    const int padded = std::min((count + lanes - 1) / lanes * lanes, most);
    // u, v of the corners 0..3 ((u0, v0), (u1, v0), (u1, v1), (u0, v1)); all 16 lanes filled
    // (copies of the last cell), so that the loops below have a constant count (vectorized at -O2).
    T u[2][most], v[2][most];
    for (int m = 0; m < most; ++m) {
        const int c = std::min(m, count - 1);
        int x0, y0, x1, y1;
        cells.texels(k[c], i[c], j[c], x0, y0, x1, y1);
        u[0][m] = T(x0) * g.du, u[1][m] = T(x1) * g.du, v[0][m] = T(y0) * g.dv, v[1][m] = T(y1) * g.dv;
    }
    constexpr int corner_u[4] = {0, 1, 1, 0}, corner_v[4] = {0, 0, 1, 1};
    const T q0[3] = {g.q0.x, g.q0.y, g.q0.z}, e1[3] = {g.e1.x, g.e1.y, g.e1.z}, e3[3] = {g.e3.x, g.e3.y, g.e3.z};
    T xyz[3][4][most];
    for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 4; ++c) {
            const T* uc = u[corner_u[c]];
            const T* vc = v[corner_v[c]];
            for (int m = 0; m < most; ++m) xyz[a][c][m] = q0[a] + uc[m] * e1[a] + vc[m] * e3[a];
        }
    if constexpr (std::is_same_v<T, float>) {
        batch::quad_soa<T> soa;
        soa.m_inv = batch::matrices<T>::same_for_all(d.inverse_matrix());
        for (int c = 0; c < 4; ++c) soa.x[c] = xyz[0][c], soa.y[c] = xyz[1][c], soa.z[c] = xyz[2][c];
        T result[most];
        batch::integrate_quads(soa, result, std::size_t(padded), side, group.which);
        for (int m = 0; m < count; ++m) out[m] = result[m];
    } else {
        for (int m = 0; m < count; ++m) {
            glm::vec<3, T> c[4];
            for (int n = 0; n < 4; ++n) c[n] = glm::vec<3, T>(xyz[0][n][m], xyz[1][n][m], xyz[2][n][m]);
            out[m] = d.integrate(c, 4, side);
        }
    }
}

/// The leaves that may still be refined, largest bound first: a linear scan for the usual small
/// budgets (cheaper than a heap's moves), a binary heap for large ones.
template <typename T>
class open_leaves {
  public:
    open_leaves(cell_leaf<T>* storage, bool heap) : data_(storage), heap_(heap) {}
    std::size_t size() const { return count_; }
    const cell_leaf<T>& operator[](std::size_t m) const { return data_[m]; }
    /// Field by field: a leaf just computed and copied whole would be read back in one wide load
    /// from narrow stores (a store-forwarding stall; its cost: docs/design_notes.md).
    void push(T bound, T i_d, int k, int i, int j) {
        cell_leaf<T>& l = data_[count_++];
        l.bound = bound, l.i_d = i_d, l.k = k, l.i = i, l.j = j;
        if (heap_) std::push_heap(data_, data_ + count_);
    }
    /// The index of the leaf of largest bound (0 in a heap).
    std::size_t best() const {
        std::size_t at = 0;
        if (!heap_)
            for (std::size_t m = 1; m < count_; ++m)
                if (data_[at].bound < data_[m].bound) at = m;
        return at;
    }
    /// Removes and returns the leaf at best().
    cell_leaf<T> take(std::size_t at) {
        if (heap_) {
            std::pop_heap(data_, data_ + count_);
            return data_[--count_];
        }
        const cell_leaf<T> l = data_[at];
        data_[at] = data_[--count_];
        return l;
    }

  private:
    cell_leaf<T>* data_;
    bool heap_;
    std::size_t count_ = 0;
};

}  // namespace detail

LTC_NAMESPACE_END
