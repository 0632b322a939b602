// ltc/shading/batch_soa.hpp -- the structure-of-arrays input of the batch API
// (ltc/shading/batch.hpp): many polygons, vertex coordinates in one array per vertex and axis,
// and each item's inverse matrix M^-1 (eq. 11 is integrated over M^-1 P) in nine arrays or
// shared by all items.
#pragma once

#include <glm/glm.hpp>

#include <cstddef>

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
/// shading frame (any scale; see ltc/core/polygon.hpp for orientation and degenerate input).
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

}  // namespace batch
}  // namespace ltc
