// ltc/shading/batch_soa.hpp -- the structure-of-arrays inputs and outputs of the batch API:
// many polygons for ltc/shading/batch.hpp (vertex coordinates in one array per vertex and axis,
// and each item's inverse matrix M^-1, eq. 11 being integrated over M^-1 P, in nine arrays or
// shared by all items), and many shading points for ltc/shading/batch_shading.hpp.
#pragma once

#include <ltc/config.hpp>

#include <glm/glm.hpp>

#include <cstddef>

LTC_NAMESPACE_BEGIN
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

/// Shading points for ltc::batch::shade_polygon_light (ltc/shading/batch_shading.hpp): point i is
/// P = (px[i], py[i], pz[i]), its normal N, its direction towards the eye V (neither needs to be
/// normalized), its roughness (alpha = roughness^2), its specular colour F0 = (f0[0][i], f0[1][i],
/// f0[2][i]) and diffuse albedo, all in world space, as for ltc::shade_polygon_light.
template <typename T>
struct shading_points {
    const T* px = nullptr;
    const T* py = nullptr;
    const T* pz = nullptr;
    const T* nx = nullptr;
    const T* ny = nullptr;
    const T* nz = nullptr;
    const T* vx = nullptr;
    const T* vy = nullptr;
    const T* vz = nullptr;
    const T* roughness = nullptr;
    const T* f0[3] = {};
    const T* albedo[3] = {};

    /// The view of 16 arrays in the order px, py, pz, nx, ny, nz, vx, vy, vz, roughness, f0 r g b,
    /// albedo r g b.
    static shading_points from_columns(const T* const (&c)[16]) {
        shading_points p;
        p.px = c[0], p.py = c[1], p.pz = c[2], p.nx = c[3], p.ny = c[4], p.nz = c[5];
        p.vx = c[6], p.vy = c[7], p.vz = c[8], p.roughness = c[9];
        for (int k = 0; k < 3; ++k) p.f0[k] = c[10 + k], p.albedo[k] = c[13 + k];
        return p;
    }
};

/// Where the shading batches write: specular[c][i] and diffuse[c][i], channel c of item i.
template <typename T>
struct shading_results {
    T* specular[3] = {};
    T* diffuse[3] = {};
};

}  // namespace batch
LTC_NAMESPACE_END
