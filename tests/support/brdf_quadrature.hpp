// Adaptive product quadrature on the sphere, for the microfacet BRDF tests.
//
// Parameterization. w(beta, psi) = cos(beta) p + sin(beta) (cos(psi) a + sin(psi) b) for an
// orthonormal frame (a, b, p), dw = sin(beta) dbeta dpsi. Two frames are used:
//   - p = z (beta = theta, psi = phi): the usual polar angles of L;
//   - p = y, a = x, b = z: the "lune" frame. For V in the xz-plane, the great circles h.z = 0 and
//     V.h = 0 both contain the y axis, so they are the lines psi = 0 and psi = pi - theta_v, and
//     the lune {h.z > 0, V.h > 0} is the rectangle [0, pi] x [0, pi - theta_v]: the kink of
//     max(0, V.h) lies on the boundary of the domain instead of cutting through it.
//
// Rule. The caller gives a coarse grid of breakpoints in (beta, psi) that puts every jump or kink
// of the integrand on a cell boundary (and every point singularity at a cell corner). Each cell
// is integrated with a product Gauss-Legendre rule of n and of 2n points per direction; the cells
// are then split into four (quadtree) while the summed estimate |Q_n - Q_2n| exceeds the target,
// refining every leaf whose estimate is within a factor 4 of the largest one (as
// support/brute_force.hpp does on triangles). On a cell where the integrand is analytic the
// Gauss-Legendre error falls geometrically with n, so |Q_n - Q_2n| bounds the error of Q_2n with
// a wide margin; the refinement isolates peaks (the lobe of a small alpha) and corner
// singularities (an integrable 1/r at a corner contributes O(cell size), which the estimate sees).
//
// Only the first `drive` components of the vector integrand steer the refinement: the others
// (the same model in float) ride along on the same cells, and their |Q_n - Q_2n| includes their
// rounding noise, which no refinement removes.
//
// The leaves (numbered depth-first, so that consecutive leaves are neighbours) are the cells of
// the chi-square test of the sampler: locate() maps a direction's (beta, psi) to its leaf.
#pragma once

#include "support/gauss_legendre.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace ltc_test {

struct polar_frame {
    glm::dvec3 a{1, 0, 0}, b{0, 1, 0}, p{0, 0, 1};
};

/// beta = theta, psi = phi.
inline polar_frame z_frame() { return polar_frame(); }
/// The lune frame of the file comment: p = y, a = x, b = z.
inline polar_frame lune_frame() {
    polar_frame f;
    f.a = {1, 0, 0};
    f.b = {0, 0, 1};
    f.p = {0, 1, 0};
    return f;
}

/// Sorted breakpoints lo, ..., hi: the given points inside (lo, hi), and a uniform subdivision
/// with spacing <= max_len; points closer than 1e-12 (hi - lo) are merged.
inline std::vector<double> breakpoints(double lo, double hi, std::vector<double> pts, double max_len) {
    const int m = static_cast<int>(std::ceil((hi - lo) / max_len));
    for (int i = 1; i < m; ++i) pts.push_back(lo + (hi - lo) * i / m);
    std::sort(pts.begin(), pts.end());
    std::vector<double> out{lo};
    for (const double v : pts)
        if (v - out.back() > 1e-12 * (hi - lo) && hi - v > 1e-12 * (hi - lo)) out.push_back(v);
    out.push_back(hi);
    return out;
}

template <std::size_t K>
struct quadtree_integral {
    struct node {
        double b0, b1, p0, p1;
        std::array<double, K> value{}, error{};  // Q_2n and |Q_n - Q_2n| on the cell
        long child = -1;                         // first of the four children, -1 for a leaf
        long leaf = -1;                          // depth-first number of a leaf
    };
    std::vector<double> beta, psi;      // the coarse grid
    std::vector<node> nodes;            // the coarse cells first, row-major
    std::vector<std::size_t> leaves;    // node index of each leaf, depth-first
    std::array<double, K> value{}, error{};  // sums over the leaves
    bool converged = false;

    /// The leaf that contains (b, p) (clamped into the grid).
    std::size_t locate(double b, double p) const {
        const auto index = [](const std::vector<double>& x, double v) {
            const std::size_t i = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), v) - x.begin());
            return std::min(std::max<std::size_t>(i, 1), x.size() - 1) - 1;
        };
        std::size_t k = index(beta, b) * (psi.size() - 1) + index(psi, p);
        while (nodes[k].child >= 0) {
            const node& c = nodes[k];
            const std::size_t q = (b >= 0.5 * (c.b0 + c.b1) ? 2 : 0) + (p >= 0.5 * (c.p0 + c.p1) ? 1 : 0);
            k = static_cast<std::size_t>(c.child) + q;
        }
        return static_cast<std::size_t>(nodes[k].leaf);
    }
};

namespace brdf_quadrature_detail {

template <std::size_t K, typename F>
std::array<double, K> product_rule(const F& f, const polar_frame& fr, double b0, double b1, double p0,
                                   double p1, const quadrature_rule& r) {
    std::array<double, K> q{};
    const double db = b1 - b0, dp = p1 - p0;
    for (std::size_t i = 0; i < r.x.size(); ++i) {
        const double beta = b0 + db * r.x[i];
        const double sb = std::sin(beta), cb = std::cos(beta);
        std::array<double, K> row{};
        for (std::size_t j = 0; j < r.x.size(); ++j) {
            const double psi = p0 + dp * r.x[j];
            const glm::dvec3 w = cb * fr.p + sb * (std::cos(psi) * fr.a + std::sin(psi) * fr.b);
            const std::array<double, K> v = f(w);
            for (std::size_t k = 0; k < K; ++k) row[k] += r.w[j] * v[k];
        }
        for (std::size_t k = 0; k < K; ++k) q[k] += r.w[i] * sb * row[k];
    }
    for (std::size_t k = 0; k < K; ++k) q[k] *= db * dp;
    return q;
}

}  // namespace brdf_quadrature_detail

/// Integral of f (unit direction -> std::array<double, K>) over [beta0, betaN] x [psi0, psiM]
/// of the coarse grid (beta, psi), refined until the summed |Q_n - Q_2n| of each of the first
/// `drive` components is <= tol (or max_leaves is reached: converged = false).
template <std::size_t K, typename F>
quadtree_integral<K> integrate_adaptive(const F& f, const polar_frame& fr, const std::vector<double>& beta,
                                        const std::vector<double>& psi, std::size_t n, std::size_t drive,
                                        double tol, std::size_t max_leaves = 40000) {
    using node = typename quadtree_integral<K>::node;
    const quadrature_rule lo = gauss_legendre(n), hi = gauss_legendre(2 * n);
    quadtree_integral<K> t;
    t.beta = beta;
    t.psi = psi;
    const auto evaluate = [&](double b0, double b1, double p0, double p1) {
        using brdf_quadrature_detail::product_rule;
        node c;
        c.b0 = b0, c.b1 = b1, c.p0 = p0, c.p1 = p1;
        const auto ql = product_rule<K>(f, fr, b0, b1, p0, p1, lo);
        const auto qh = product_rule<K>(f, fr, b0, b1, p0, p1, hi);
        for (std::size_t k = 0; k < K; ++k) c.value[k] = qh[k], c.error[k] = std::abs(qh[k] - ql[k]);
        return c;
    };
    for (std::size_t i = 0; i + 1 < beta.size(); ++i)
        for (std::size_t j = 0; j + 1 < psi.size(); ++j)
            t.nodes.push_back(evaluate(beta[i], beta[i + 1], psi[j], psi[j + 1]));
    std::vector<std::size_t> open(t.nodes.size());
    for (std::size_t i = 0; i < open.size(); ++i) open[i] = i;
    for (;;) {
        std::array<double, K> err{};
        for (const std::size_t i : open)
            for (std::size_t k = 0; k < K; ++k) err[k] += t.nodes[i].error[k];
        std::size_t worst = 0;
        for (std::size_t k = 1; k < drive; ++k)
            if (err[k] > err[worst]) worst = k;
        t.converged = err[worst] <= tol;
        if (t.converged || open.size() >= max_leaves) break;
        double largest = 0;
        for (const std::size_t i : open) largest = std::max(largest, t.nodes[i].error[worst]);
        std::vector<std::size_t> next;
        for (const std::size_t i : open) {
            if (!(t.nodes[i].error[worst] >= 0.25 * largest)) {
                next.push_back(i);
                continue;
            }
            const node c = t.nodes[i];
            const double bm = 0.5 * (c.b0 + c.b1), pm = 0.5 * (c.p0 + c.p1);
            t.nodes[i].child = static_cast<long>(t.nodes.size());
            // children in the order of locate(): (beta half, psi half) = 00, 01, 10, 11
            const double b[3] = {c.b0, bm, c.b1}, p[3] = {c.p0, pm, c.p1};
            for (std::size_t q = 0; q < 4; ++q) {
                next.push_back(t.nodes.size());
                t.nodes.push_back(evaluate(b[q / 2], b[q / 2 + 1], p[q % 2], p[q % 2 + 1]));
            }
        }
        open.swap(next);
    }
    // Depth-first numbering of the leaves, and the sums.
    const std::size_t coarse = (beta.size() - 1) * (psi.size() - 1);
    std::vector<std::size_t> stack;
    for (std::size_t r = coarse; r-- > 0;) stack.push_back(r);
    while (!stack.empty()) {
        const std::size_t i = stack.back();
        stack.pop_back();
        node& c = t.nodes[i];
        if (c.child >= 0) {
            for (std::size_t q = 4; q-- > 0;) stack.push_back(static_cast<std::size_t>(c.child) + q);
            continue;
        }
        c.leaf = static_cast<long>(t.leaves.size());
        t.leaves.push_back(i);
        for (std::size_t k = 0; k < K; ++k) t.value[k] += c.value[k], t.error[k] += c.error[k];
    }
    return t;
}

}  // namespace ltc_test
