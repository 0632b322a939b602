// ltc/detail/cell_quadtree.hpp -- the pieces of the quadtree of ltc/shading/textured_cells.hpp:
// its leaves, the set of leaves still to refine, and the integrals of a group of cells.
#pragma once

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/shading/batch.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cstddef>
#include <type_traits>

namespace ltc {
namespace detail {

/// A leaf of the quadtree: cell (i, j) of level k, its I_D and its bound range I_D.
template <typename T>
struct cell_leaf {
    T bound, i_d;
    int k, i, j;
    bool operator<(const cell_leaf& o) const { return bound < o.bound; }
};

/// I_D of the cells (k, i, j)[0..count), count <= 16: float through the batch kernel
/// (ltc/shading/batch.hpp) of the widest instruction set that the count fills, double one by
/// one (its default policy, exact, has no kernel). One call for all: a call of 8 costs about as
/// much as one of 4 (measured), so the number of calls matters more than the number of cells.
template <typename T, typename Corners>
inline void cell_integrals(const transformed<clamped_cosine<T>>& d, sidedness side, const Corners& corners,
                           const int* k, const int* i, const int* j, int count, T* out, std::size_t& integrals) {
    using vec3 = glm::vec<3, T>;
    integrals += std::size_t(count);
    if constexpr (std::is_same_v<T, float>) {
        T x[4][16], y[4][16], z[4][16];
        for (int m = 0; m < count; ++m) {
            vec3 c[4];
            corners(k[m], i[m], j[m], c);
            for (int v = 0; v < 4; ++v) x[v][m] = c[v].x, y[v][m] = c[v].y, z[v][m] = c[v].z;
        }
        batch::quad_soa<T> soa;
        soa.m_inv = batch::matrices<T>::same_for_all(d.inverse_matrix());
        for (int v = 0; v < 4; ++v) soa.x[v] = x[v], soa.y[v] = y[v], soa.z[v] = z[v];
        batch::isa which = batch::isa::scalar;
        for (const batch::isa candidate : batch::instruction_sets)
            if (batch::available(candidate) && batch::lane_count<T>(candidate) <= std::size_t(count)) which = candidate;
        batch::integrate_quads(soa, out, std::size_t(count), side, which);
    } else {
        for (int m = 0; m < count; ++m) {
            vec3 c[4];
            corners(k[m], i[m], j[m], c);
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
    void push(const cell_leaf<T>& l) {
        data_[count_++] = l;
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

}  // namespace ltc
