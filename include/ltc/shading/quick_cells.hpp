// ltc/shading/quick_cells.hpp -- textured_method::quick_cells (ltc/shading/lights/textured_quad_light.hpp):
// the real-time improvement on the paper's fetch, at a fixed cost of at most two calls of the
// float batch kernel.
//
//   ltc::cells_result<float> r = ltc::integrate_quick_cells(d, quad, tex, ltc::sidedness::two_sided);
//   // r.value ~ int_quad L(w) D(w) dw (RGB); r.cells leaves, r.integrals polygon integrals
//
// int L D ~= sum over at most 22 leaves of I_D(leaf) (eq. 11, exact) times the leaf's texel mean,
// or the paper's fetch (section 5.4) clamped into the leaf in the (at most) two leaves of largest
// I_D that are wider than the lobe. Conventions: the texture mapping of textured_quad_light.hpp.
// Degenerate cases: as integrate_textured_cells (corners near the largest finite value scaled by
// 2^-4; a non-finite corner gives I_D of the quad times the texture's mean; 0 below the horizon).
#pragma once

#include <ltc/config.hpp>

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/shading/detail/cell_quadtree.hpp>
#include <ltc/shading/cell_pyramid.hpp>
#include <ltc/shading/light_texture.hpp>
#include <ltc/shading/textured_cells.hpp>
#include <ltc/shading/textured_fetch.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cstddef>

LTC_NAMESPACE_BEGIN

/// The quick_cells integral of D times the texture over the quad. Two-sided by default, like
/// transformed::integrate.
///
/// The light's texture as constant cells (ltc/shading/cell_pyramid.hpp): the cells of the level
/// two below the last (at most 4 x 4) with I_D of each exact (eq. 11, one kernel call); then the
/// cell of largest bound range I_D (ltc/shading/textured_cells.hpp) is split into its children,
/// and either the cell of second largest bound or the split cell's child of largest range too
/// (a second call of up to 8 cells): at most 22 leaves and 24 polygon integrals. Each call's
/// latency, not its width, sets the cost (cell_integrals in ltc/shading/detail/cell_quadtree.hpp), so
/// the number of calls is fixed, where the adaptive quadtree of textured_cells.hpp needs one per
/// level below its first.
///
/// Each leaf contributes I_D(leaf) times a radiance: its texels' mean, or the paper's fetch
/// (section 5.4) at the foot point clamped into the leaf, in the (at most) two leaves of largest
/// I_D that hold at least 1/64 of the light's and are wider than about 4 sigma of the lobe (2^k
/// texels against sigma = 2^(lod - 1) texels), once some leaf holds a quarter of I_D (a lobe
/// that none does is wider than the leaves: the means serve, and the fetch's parameters, which
/// cost as much as the fetch, are skipped). The lobe is sharper than those leaves, so the mean
/// would weight their texels wrongly, most of all in a leaf that takes only the lobe's tail next
/// to its border (docs/design_notes.md: why the fetch is not kept to the leaves that hold a
/// quarter of I_D). Its error against Monte Carlo and its cost against the fetch:
/// docs/design_notes.md, "Textured polygonal lights" (tools/textured_error_report,
/// benchmarks/bench_textured.cpp).
template <typename T>
inline cells_result<T> integrate_quick_cells(const transformed<clamped_cosine<T>>& d, const glm::vec<3, T> quad[4],
                                             const light_texture<T>& tex, sidedness side = sidedness::two_sided,
                                             bool use_fetch = true) {
    using vec3 = glm::vec<3, T>;
    const cell_pyramid<T>& cells = tex.cells();
    const int top = cells.level_count() - 1;
    cells_result<T> r;
    vec3 q[4];
    if (!detail::cell_corners(quad, q)) return detail::whole_quad_result(d, quad, cells, side);
    const detail::cell_geometry<T> geometry = detail::make_cell_geometry(q, cells);
    // The leaves: the base cells, then the children of those split (split[m]: not a leaf).
    constexpr int most = 16 + 8;
    int k[most] = {}, i[most] = {}, j[most] = {}, n = 0;
    T i_d[most];
    bool split[most] = {};
    const int base = std::max(top - 2, 0);
    for (int b = 0; b < cells.cells_y(base); ++b)
        for (int a = 0; a < cells.cells_x(base); ++a) k[n] = base, i[n] = a, j[n] = b, ++n;
    detail::cell_integrals(d, side, geometry, cells, k, i, j, n, i_d, r.integrals);
    T total(0);
    for (int m = 0; m < n; ++m) total += i_d[m];
    r.cells = std::size_t(n);
    if (!(total > T(0))) return r;
    if (base > 0) {
        int best[2] = {-1, -1};
        T bound[2] = {T(0), T(0)};
        for (int m = 0; m < n; ++m) {
            const T b = cells.range(k[m], i[m], j[m]) * i_d[m];
            if (b > bound[0]) bound[1] = bound[0], best[1] = best[0], bound[0] = b, best[0] = m;
            else if (b > bound[1]) bound[1] = b, best[1] = m;
        }
        // The 8 lanes of the second call: the children of the best cell, then either those of
        // the second best or those of the best's child of largest range, whichever bound is
        // larger (the child's I_D taken as a quarter of its parent's): a small bright detail
        // refines one cell two levels deep, a smooth texture two cells one level deep.
        const int first = n;
        const auto add_children = [&](int p) {
            int children = 0;
            for (int b = 0; b < 2; ++b)
                for (int a = 0; a < 2; ++a)
                    if (2 * i[p] + a < cells.cells_x(k[p] - 1) && 2 * j[p] + b < cells.cells_y(k[p] - 1))
                        k[n] = k[p] - 1, i[n] = 2 * i[p] + a, j[n] = 2 * j[p] + b, ++n, ++children;
            if (children > 1) split[p] = true;
            else n -= children;  // one child: the same texels
        };
        if (best[0] >= 0) {
            add_children(best[0]);
            int widest = -1;
            for (int m = first; m < n; ++m)
                if (k[m] > 0 && (widest < 0 || cells.range(k[m], i[m], j[m]) > cells.range(k[widest], i[widest], j[widest])))
                    widest = m;
            const T deeper = widest < 0 ? T(0) : cells.range(k[widest], i[widest], j[widest]) * i_d[best[0]] / T(4);
            if (best[1] >= 0 && bound[1] >= deeper) add_children(best[1]);
            else if (deeper > T(0)) add_children(widest);
        }
        if (n > first) detail::cell_integrals(d, side, geometry, cells, k + first, i + first, j + first, n - first, i_d + first, r.integrals);
    }
    // The fetch goes to the (at most) two inexact leaves of largest I_D that hold at least
    // 1/64 of it, where they are wider than the lobe.
    constexpr int fetches = 2;
    int fetch_leaf[fetches] = {-1, -1};
    for (int m = 0; use_fetch && m < n; ++m) {
        if (split[m] || k[m] == 0 || !(i_d[m] >= total / T(64)) || !(cells.range(k[m], i[m], j[m]) > T(0))) continue;
        int at = fetches;
        while (at > 0 && (fetch_leaf[at - 1] < 0 || i_d[fetch_leaf[at - 1]] < i_d[m])) --at;
        if (at == fetches) continue;
        for (int c = fetches - 1; c > at; --c) fetch_leaf[c] = fetch_leaf[c - 1];
        fetch_leaf[at] = m;
    }
    textured_fetch<T> f;
    double lod = 0;
    // A lobe that no leaf holds a quarter of is wider than the leaves: no fetch (nor its
    // parameters, as costly as the fetch itself) where the means serve.
    if (fetch_leaf[0] >= 0 && i_d[fetch_leaf[0]] >= total / T(4))
        f = fetch_parameters(d.inverse_matrix(), quad), lod = double(tex.lod_for_sigma(f.sigma));
    glm::dvec3 sum(0.0);
    double bound = 0;
    r.cells = 0;
    for (int m = 0; m < n; ++m) {
        if (split[m]) continue;
        ++r.cells;
        if (k[m] > 0) bound += double(cells.range(k[m], i[m], j[m])) * double(i_d[m]);
        const bool fetch = f.valid && double(k[m]) > lod + 1 &&
                           (m == fetch_leaf[0] || m == fetch_leaf[1]);
        glm::dvec3 value(cells.mean(k[m], i[m], j[m]));
        if (fetch) {
            int x0, y0, x1, y1;
            cells.texels(k[m], i[m], j[m], x0, y0, x1, y1);
            const double u = std::min(std::max(double(f.uv.x), double(x0) / cells.width()), double(x1) / cells.width());
            const double v = std::min(std::max(double(f.uv.y), double(y0) / cells.height()), double(y1) / cells.height());
            value = glm::dvec3(tex.lookup(glm::vec<2, T>(T(u), T(v)), T(lod)));
        }
        sum += double(i_d[m]) * value;
    }
    r.value = vec3(sum);
    r.error_bound = T(bound);
    return r;
}

LTC_NAMESPACE_END
