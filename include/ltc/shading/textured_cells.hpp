// ltc/shading/textured_cells.hpp -- the exact integral of an LTC times a piecewise-constant
// texture over a quad light: sum_k L_k I_D(cell_k), refined adaptively over a cell pyramid.
//
//   ltc::cell_pyramid<float> cells(width, height, rgb);          // or light_texture::cells()
//   ltc::cells_result<float> r = ltc::integrate_textured_cells(d, quad, cells, side, {64});
//   // r.value ~ int_quad L(w) D(w) dw, |r.value - exact| <= r.error_bound per channel
//
// With the texture constant on each texel, int L D = sum_t L_t I_D(t) exactly, each I_D(t) the
// closed form of eq. (11) over the texel's quad (transformed::integrate, horizon-clipped); a
// coarser cell c with the mean of its texels is off by at most range(c) I_D(c) per channel.
// Conventions: the texture mapping of ltc/shading/lights/textured_quad_light.hpp (uv on the
// parallelogram of corners 0, 1, 3). Degenerate cases: finite for finite input; 0 for a light
// below the horizon or a zero-area quad; a non-finite corner gives I_D times the texture's mean.
#pragma once

#include <ltc/config.hpp>

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/shading/cell_pyramid.hpp>
#include <ltc/shading/detail/cell_quadtree.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

LTC_NAMESPACE_BEGIN

/// How far integrate_textured_cells refines (integrate_textured_cells: the refinement).
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

/// Where cell_corners fails (a non-finite corner): no cell geometry. Like the fetch, whose
/// parameters are then invalid: I_D of the quad (0 if NaN) times the texture's mean, one cell.
template <typename T>
inline cells_result<T> whole_quad_result(const transformed<clamped_cosine<T>>& d, const glm::vec<3, T> quad[4],
                                         const cell_pyramid<T>& cells, sidedness side) {
    cells_result<T> r;
    const int top = cells.level_count() - 1;
    T i_d = d.integrate(quad, 4, side);
    if (!(i_d > T(0))) i_d = T(0);  // NaN from the non-finite corner: nothing (as the fetch)
    r.value = glm::vec<3, T>(double(i_d) * glm::dvec3(cells.mean(top, 0, 0)));
    r.error_bound = cells.range(top, 0, 0) * i_d;
    r.cells = 1, r.integrals = 1;
    return r;
}

}  // namespace detail

/// integrate_textured_cells with the radiance of the leaves that remain inexact (range > 0,
/// above level 0) given by open_value(k, i, j) -> glm::dvec3 instead of their mean (e.g. a
/// fetch, as ltc/shading/quick_cells.hpp does in its own leaves); error_bound then bounds the
/// means' version only.
template <typename T, typename OpenValue>
inline cells_result<T> integrate_textured_cells_with(const transformed<clamped_cosine<T>>& d, const glm::vec<3, T> quad[4],
                                                     const cell_pyramid<T>& cells, sidedness side,
                                                     const cell_budget& budget, const OpenValue& open_value) {
    using vec3 = glm::vec<3, T>;
    using leaf = detail::cell_leaf<T>;
    cells_result<T> r;
    vec3 q[4];
    if (!detail::cell_corners(quad, q)) return detail::whole_quad_result(d, quad, cells, side);
    const detail::cell_geometry<T> geometry = detail::make_cell_geometry(q, cells);
    const auto bound_of = [&](int k, int i, int j, T i_d) { return k == 0 ? T(0) : cells.range(k, i, j) * i_d; };
    const auto contribution = [&](int k, int i, int j, T i_d) { return double(i_d) * glm::dvec3(cells.mean(k, i, j)); };
    const int top = cells.level_count() - 1;
    const std::size_t max_cells = std::max<std::size_t>(budget.max_cells, 1);
    // The leaves that may still be refined: on the stack for the usual budgets (no allocation
    // per shading). Exact leaves are only summed.
    constexpr std::size_t stack_leaves = 64;
    leaf stack[stack_leaves];
    std::vector<leaf> heap_storage(max_cells > stack_leaves ? max_cells : 0);
    detail::open_leaves<T> open(max_cells > stack_leaves ? heap_storage.data() : stack, max_cells > stack_leaves);
    glm::dvec3 exact_sum(0.0);
    // The summed bound and the value of the current leaves, kept for the tolerance only.
    const bool tolerance = budget.tolerance > 0;
    double bound_sum = 0;
    glm::dvec3 running(0.0);
    const auto add = [&](int k, int i, int j, T i_d) {
        const T bound = bound_of(k, i, j, i_d);
        if (tolerance) bound_sum += double(bound), running += contribution(k, i, j, i_d);
        if (bound > T(0)) open.push(bound, i_d, k, i, j);
        else exact_sum += contribution(k, i, j, i_d);
    };
    // The cells of level base = top - 2 (at most 4 x 4) in one call; the I_D of the levels above
    // are their sums (I_D adds up over cells of one orientation), so the root and the first two
    // refinements need no integral of their own.
    const int base = std::max(top - 2, 0);
    T known[3][16];  // I_D of levels base, base + 1, base + 2, cell (i, j) at [j * 4 + i]
    {
        int k[16] = {}, i[16] = {}, j[16] = {}, n = 0;
        for (int b = 0; b < cells.cells_y(base); ++b)
            for (int a = 0; a < cells.cells_x(base); ++a) k[n] = base, i[n] = a, j[n] = b, ++n;
        T packed[16];
        detail::cell_integrals(d, side, geometry, cells, k, i, j, n, packed, r.integrals);
        for (int m = 0; m < n; ++m) known[0][j[m] * 4 + i[m]] = packed[m];
        for (int l = 1; l <= top - base; ++l)
            for (int b = 0; b < cells.cells_y(base + l); ++b)
                for (int a = 0; a < cells.cells_x(base + l); ++a) {
                    T sum(0);
                    for (int y = 2 * b; y < std::min(2 * b + 2, cells.cells_y(base + l - 1)); ++y)
                        for (int x = 2 * a; x < std::min(2 * a + 2, cells.cells_x(base + l - 1)); ++x)
                            sum += known[l - 1][y * 4 + x];
                    known[l][b * 4 + a] = sum;
                }
    }
    add(top, 0, 0, known[top - base][0]);
    std::size_t leaves = 1;
    // Each step refines the two leaves of largest bound (one if the budget allows only one), so
    // that their up to 8 children are integrated together: 8 lanes of the float batch kernel.
    while (open.size() > 0) {
        if (tolerance && bound_sum <= budget.tolerance * std::max(running.x, std::max(running.y, running.z))) break;
        T parent_i_d[2];
        int child_k[8] = {}, child_i[8] = {}, child_j[8] = {}, child_of[8] = {};
        int parents = 0, children = 0;
        while (parents < 2 && open.size() > 0) {
            const std::size_t at = open.best();
            const leaf& c = open[at];
            int n = 0;
            for (int b = 0; b < 2; ++b)
                for (int a = 0; a < 2; ++a)
                    if (2 * c.i + a < cells.cells_x(c.k - 1) && 2 * c.j + b < cells.cells_y(c.k - 1)) {
                        child_k[children + n] = c.k - 1, child_i[children + n] = 2 * c.i + a;
                        child_j[children + n] = 2 * c.j + b, child_of[children + n] = parents;
                        ++n;
                    }
            if (n > 1 && leaves - 1 + std::size_t(n) > max_cells) break;
            const leaf popped = open.take(at);
            if (tolerance) bound_sum -= double(popped.bound), running -= contribution(popped.k, popped.i, popped.j, popped.i_d);
            leaves += std::size_t(n) - 1;
            parent_i_d[parents++] = popped.i_d;
            children += n;
        }
        if (parents == 0) break;
        // A parent's only child (the same texels) takes the parent's integral; children on the
        // base level or above are known; the others are integrated together.
        T i_d[8], fresh[8];
        bool needed[8] = {};
        int uk[8] = {}, ui[8] = {}, uj[8] = {}, unknown = 0;
        for (int m = 0; m < children; ++m) {
            const bool only = (m == 0 || child_of[m - 1] != child_of[m]) &&
                              (m + 1 == children || child_of[m + 1] != child_of[m]);
            if (only) {
                i_d[m] = parent_i_d[child_of[m]];
            } else if (child_k[m] >= base) {
                i_d[m] = known[child_k[m] - base][child_j[m] * 4 + child_i[m]];
            } else {
                needed[m] = true;
                uk[unknown] = child_k[m], ui[unknown] = child_i[m], uj[unknown] = child_j[m], ++unknown;
            }
        }
        if (unknown > 0) {
            detail::cell_integrals(d, side, geometry, cells, uk, ui, uj, unknown, fresh, r.integrals);
            for (int m = 0, u = 0; m < children; ++m)
                if (needed[m]) i_d[m] = fresh[u++];
        }
        for (int m = 0; m < children; ++m) add(child_k[m], child_i[m], child_j[m], i_d[m]);
    }
    // Summed afresh: the running value drifts by its subtractions.
    glm::dvec3 sum = exact_sum;
    double bound = 0;
    for (std::size_t m = 0; m < open.size(); ++m) {
        const leaf& l = open[m];
        sum += double(l.i_d) * glm::dvec3(open_value(l.k, l.i, l.j));
        bound += double(open[m].bound);
    }
    r.value = vec3(sum);
    r.error_bound = T(bound);
    r.cells = leaves;
    return r;
}

/// The integral of the texel-constant texture times D over the quad, adaptively. Two-sided by
/// default, like transformed::integrate.
///
/// With the texture constant on each texel (ltc/shading/cell_pyramid.hpp), the integral of L D
/// over the light is exactly sum_t L_t I_D(t) over the texels t, each I_D(t) the closed form of
/// eq. (11) over the texel's quad (transformed::integrate, horizon-clipped). A coarser cell c
/// with the mean of its texels gives mean(c) I_D(c), off by sum_t (L_t - mean) I_D(t), at most
/// range(c) I_D(c) per channel (every I_D(t) >= 0: the cells share the light's orientation).
///
/// Refinement (a quadtree over the pyramid): start from the one cell of the last level; while the
/// budget allows, replace the leaf with the largest bound range(c) I_D(c) by its children; leaves
/// of level 0 or of range 0 are exact and never refined. Stops when the leaves would exceed
/// budget.max_cells, or when the summed bound is at most budget.tolerance times the value
/// (largest channel). The result converges to the texel-constant integral as the budget grows and
/// equals it (to rounding) once every leaf is exact: at most width x height leaves.
///
/// Cost: the cells of the level two below the last (at most 4 x 4) are integrated first, in one
/// call of the float batch kernel (ltc/shading/batch.hpp), and the levels above take their sums
/// (I_D adds up over cells of one orientation); below that, each step refines the two leaves of
/// largest bound, integrating their up to 8 children in one call (tools/textured_error_report
/// prints the integrals per method). Double integrates cell by cell (its default policy, exact,
/// has no SIMD kernel).
///
/// Texture mapping: as ltc/shading/lights/textured_quad_light.hpp and the ground truth
/// (ltc/reference/textured_ground_truth.hpp), the texture covers the parallelogram q_0 + u (q_1 -
/// q_0) + v (q_3 - q_0), uv in [0, 1]^2 (exact for rectangles and parallelograms; corner 2 is not
/// used). The cells are that parallelogram's sub-parallelograms, with the quad's orientation.
///
/// Robustness: finite for finite input (each integral is; corners beyond a eighth of the largest
/// finite value are first scaled by 2^-4, exactly); a light entirely below the horizon or a
/// zero-area quad gives 0. A non-finite corner (an overflow upstream) gives I_D of the quad times
/// the texture's mean, as the fetch does there.
template <typename T>
inline cells_result<T> integrate_textured_cells(const transformed<clamped_cosine<T>>& d, const glm::vec<3, T> quad[4],
                                                const cell_pyramid<T>& cells, sidedness side = sidedness::two_sided,
                                                const cell_budget& budget = cell_budget()) {
    return integrate_textured_cells_with(d, quad, cells, side, budget,
                                         [&](int k, int i, int j) { return cells.mean(k, i, j); });
}

LTC_NAMESPACE_END
