// ltc/shading/textured_cells.hpp -- the exact integral of an LTC times a piecewise-constant
// texture over a quad light: sum_k L_k I_D(cell_k), refined adaptively over a cell pyramid.
//
//   ltc::cell_pyramid<float> cells(width, height, rgb);          // or light_texture::cells()
//   ltc::cells_result<float> r = ltc::integrate_textured_cells(d, quad, cells, side, {64});
//   // r.value ~ int_quad L(w) D(w) dw, |r.value - exact| <= r.error_bound per channel
//
// With the texture constant on each texel (ltc/shading/cell_pyramid.hpp), the integral of L D
// over the light is exactly sum_t L_t I_D(t) over the texels t, each I_D(t) the closed form of
// eq. (11) over the texel's quad (transformed::integrate, horizon-clipped). A coarser cell c
// with the mean of its texels gives mean(c) I_D(c), off by sum_t (L_t - mean) I_D(t), at most
// range(c) I_D(c) per channel (every I_D(t) >= 0: the cells share the light's orientation).
//
// Refinement (a quadtree over the pyramid): start from the one cell of the last level; while the
// budget allows, replace the leaf with the largest bound range(c) I_D(c) by its children (four
// polygon integrals); leaves of level 0 or of range 0 are exact and never refined. Stops when
// the leaves would exceed budget.max_cells, or when the summed bound is at most budget.tolerance
// times the value (largest channel). The result converges to the texel-constant integral as the
// budget grows and equals it (to rounding) once every leaf is exact: at most width x height
// leaves, about (4/3) width height integrals. Cost: one integral for the root and four per
// refinement: (max_cells - 1) / 3 refinements at most.
//
// Texture mapping: as ltc/shading/textured_light.hpp and the ground truth
// (ltc/reference/textured_ground_truth.hpp), the texture covers the parallelogram q_0 + u (q_1 -
// q_0) + v (q_3 - q_0), uv in [0, 1]^2 (exact for rectangles and parallelograms; corner 2 is not
// used). The cells are that parallelogram's sub-parallelograms, with the quad's orientation.
//
// Robustness: finite for finite input (each integral is); a light entirely below the horizon or
// a zero-area quad gives 0 after one integral.
#pragma once

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/shading/cell_pyramid.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cstddef>
#include <queue>
#include <vector>

namespace ltc {

/// How far integrate_textured_cells refines (file comment).
struct cell_budget {
    std::size_t max_cells = 64;  ///< leaves of the quadtree at most (0 is taken as 1)
    double tolerance = 0;        ///< stop once the bound <= tolerance * value (0: the whole budget)
};

template <typename T>
struct cells_result {
    glm::vec<3, T> value{T(0)};  ///< ~ int_quad L D (RGB)
    T error_bound{0};            ///< per channel, against the texel-constant integral, up to rounding
    std::size_t cells = 0;       ///< leaves summed
    std::size_t integrals = 0;   ///< polygon integrals evaluated
};

namespace detail {

/// A leaf of the quadtree: cell (i, j) of level k, its I_D and its bound range I_D.
template <typename T>
struct cell_leaf {
    T bound, i_d;
    int k, i, j;
    bool operator<(const cell_leaf& o) const { return bound < o.bound; }
};

}  // namespace detail

/// The integral of the texel-constant texture times D over the quad, adaptively (file comment).
/// Two-sided by default, like transformed::integrate.
template <typename T>
inline cells_result<T> integrate_textured_cells(const transformed<clamped_cosine<T>>& d, const glm::vec<3, T> quad[4],
                                                const cell_pyramid<T>& cells, sidedness side = sidedness::two_sided,
                                                const cell_budget& budget = cell_budget()) {
    using vec3 = glm::vec<3, T>;
    using leaf = detail::cell_leaf<T>;
    cells_result<T> r;
    const vec3 q0 = quad[0], e1 = quad[1] - quad[0], e3 = quad[3] - quad[0];
    const T du = T(1) / T(cells.width()), dv = T(1) / T(cells.height());
    const auto integral = [&](int k, int i, int j) {
        int x0, y0, x1, y1;
        cells.texels(k, i, j, x0, y0, x1, y1);
        // Corners from the texel indices, so that neighbours share them bit for bit.
        const T u0 = T(x0) * du, u1 = T(x1) * du, v0 = T(y0) * dv, v1 = T(y1) * dv;
        const vec3 c[4] = {q0 + u0 * e1 + v0 * e3, q0 + u1 * e1 + v0 * e3, q0 + u1 * e1 + v1 * e3,
                           q0 + u0 * e1 + v1 * e3};
        ++r.integrals;
        return d.integrate(c, 4, side);
    };
    const auto make = [&](int k, int i, int j, T i_d) {
        const T bound = k == 0 ? T(0) : cells.range(k, i, j) * i_d;
        return leaf{bound, i_d, k, i, j};
    };
    const int top = cells.level_count() - 1;
    std::priority_queue<leaf> open;  // leaves that may be refined, largest bound first
    std::vector<leaf> done;          // exact leaves
    const leaf root = make(top, 0, 0, integral(top, 0, 0));
    (root.bound > T(0) ? open.push(root) : done.push_back(root));
    std::size_t leaves = 1;
    const std::size_t max_cells = std::max<std::size_t>(budget.max_cells, 1);
    const auto contribution = [&](const leaf& l) { return double(l.i_d) * glm::dvec3(cells.mean(l.k, l.i, l.j)); };
    double bound_sum = double(root.bound);
    glm::dvec3 running = contribution(root);  // the value of the current leaves (for the tolerance)
    while (!open.empty()) {
        const leaf c = open.top();
        const double value = std::max(running.x, std::max(running.y, running.z));
        if (budget.tolerance > 0 && bound_sum <= budget.tolerance * value) break;
        // The children: the cells of level k - 1 inside c.
        leaf child[4];
        int n = 0;
        for (int b = 0; b < 2; ++b)
            for (int a = 0; a < 2; ++a) {
                const int ci = 2 * c.i + a, cj = 2 * c.j + b;
                if (ci < cells.cells_x(c.k - 1) && cj < cells.cells_y(c.k - 1)) child[n++] = leaf{T(0), T(0), c.k - 1, ci, cj};
            }
        if (n > 1 && leaves - 1 + std::size_t(n) > max_cells) break;
        open.pop();
        bound_sum -= double(c.bound);
        running -= contribution(c);
        for (int m = 0; m < n; ++m) {
            // One child covers the same texels: its integral is the parent's.
            const T i_d = n == 1 ? c.i_d : integral(child[m].k, child[m].i, child[m].j);
            const leaf l = make(child[m].k, child[m].i, child[m].j, i_d);
            bound_sum += double(l.bound);
            running += contribution(l);
            (l.bound > T(0) ? open.push(l) : done.push_back(l));
        }
        leaves += std::size_t(n) - 1;
    }
    glm::dvec3 sum(0.0);  // summed afresh: the running value drifts by its subtractions
    double bound = 0;
    const auto add = [&](const leaf& l) {
        sum += contribution(l);
        bound += double(l.bound);
    };
    for (const leaf& l : done) add(l);
    for (; !open.empty(); open.pop()) add(open.top());
    r.value = vec3(sum);
    r.error_bound = T(bound);
    r.cells = leaves;
    return r;
}

}  // namespace ltc
