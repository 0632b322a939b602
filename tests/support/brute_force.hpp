// Brute-force reference integration over spherical polygons, independent of the library.
//
// The integral of a direction function f over the spherical polygon subtended by a planar
// polygon P is computed exactly as the supplement (section 2.3) does, as an integral over the
// planar polygon with the Jacobian of the spherical projection:
//
//     int_P f(p / |p|) |<p / |p|, n>| / |p|^2 dp      (n: unit normal of the plane),
//
// but with a converging rule instead of the supplement's fixed grid:
//   - P is split into the triangles (c, p_i, p_i+1) around a kernel point c of the star-shaped
//     polygon (a genuine partition, all of one orientation); each triangle uses its own plane,
//     so vertices rounded off the exact plane are still handled exactly (every planar triangle
//     projects onto the spherical triangle bounded by great arcs, and the arcs c -> p_i are
//     shared, so the union is the spherical polygon the closed forms integrate);
//   - every triangle is split by the plane <w, h> = 0 across which f may have a kink or a jump
//     (h = (0, 0, 1) for the clamped densities D_o; for D over P, h = the third row of M^-1),
//     so that f is analytic on each piece;
//   - each piece is integrated with a product Gauss-Legendre rule through the Duffy (collapsed)
//     map (u, v) in [0, 1]^2 -> A + u ((B - A) + v (C - B)), Jacobian 2 area u, with N and 2N
//     points per direction; pieces are subdivided into four (midpoints) while the estimate
//     sum |Q_N - Q_2N| over the leaves exceeds the requested relative tolerance.
//
// Accuracy near the plane h. A piece next to the plane can be a sliver whose integral is tiny
// compared with the coordinates that define it (a vertex just above the horizon); computed
// naively, the rounding of the crossing points and of <p, h> at the nodes would then dominate.
// So the geometry is carried in barycentric coordinates of each triangle (c, p_i, p_i+1), and
// s = <p, h> is carried along with every vertex: computed with a compensated dot product at the
// polygon's vertices, exactly 0 at crossing points, and interpolated with non-negative weights
// elsewhere (s has one sign on a piece, so no cancellation). f receives s / |p| = <w, h>, and
// every quantity is accurate relative to itself; only the node positions p (used for |p| and
// the direction w) carry errors relative to the coordinates, bounded through `rho` below.
//
// Error estimate. The value is Q_2N; the estimate is e = e_quad + e_round with
//   e_quad  = sum over the leaves of |Q_N - Q_2N|: for an integrand analytic on each leaf the GL
//             error falls geometrically with N, so this (essentially the error of Q_N) bounds
//             the error of Q_2N with a wide margin;
//   e_round = u sum over the leaves of S_leaf (4N + 12 + evaluation_error + 3 rho (3 +
//             direction_condition)) + L u sum |Q_leaf|: first-order rounding of the double
//             computation, with S_leaf the sum of |terms| of the 2N rule, 4N for the two nested
//             sums of 2N terms, 12 for one term (the Duffy weights 3, |p| 2.5, 1 / |p|^3 and d 4,
//             the area factors 3) plus evaluation_error for f itself, rho = max |vertex| / d
//             for the position error 3u rho |p| of a node (3 operations on coordinates up to
//             max |vertex|, relative to |p| >= d, the plane's distance) amplified by 3 through
//             1 / |p|^3 and by `direction_condition` through f's dependence on w, and L u for
//             the sum of the L leaves.
// The integrand is vector-valued (std::array<double, K>) so that several densities share the
// same nodes; refinement continues until every component meets the tolerance.
#pragma once

#include "support/accurate_dot.hpp"
#include "support/gauss_legendre.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace ltc_test {

template <std::size_t K>
struct brute_force_result {
    std::array<double, K> value{};             // Q_2N summed over the leaves
    std::array<double, K> error{};             // e_quad + e_round (see the header comment)
    std::array<double, K> quadrature_error{};  // e_quad alone
    std::size_t leaves = 0;                    // leaf triangles after refinement
    bool converged = true;                     // false when max_leaves stopped the refinement
};

struct brute_force_options {
    std::size_t order = 8;          // N: Q_N and Q_2N per direction of the product rule
    double rel_tol = 1e-13;         // target for sum |Q_N - Q_2N| relative to int |f|
    double abs_floor = 1e-18;       // ... or absolute (integrals of normalized densities are <= 1)
    std::size_t max_leaves = 6000;  // safety stop (reported through `converged`)
    /// Bound on |grad_w f| |w| / |f| through f's dependence on w other than through s = <w, h>
    /// (0 for a function of s only, such as D_o with h = z); used for e_round.
    double direction_condition = 0;
    /// Relative rounding error of one evaluation of f, in units of u; used for e_round.
    double evaluation_error = 4;
};

namespace detail {

/// A vertex of a piece: barycentric coordinates l in its triangle (c, p_i, p_i+1) and
/// s = <p, h>, both accurate relative to themselves.
struct bary_vertex {
    glm::dvec3 l;
    double s;
};

struct fan_triangle {
    glm::dvec3 k, a, b;  // kernel point and the edge p_i -> p_i+1
    double area2;        // 2 area
    double d;            // distance of its plane to the origin
    double rho;          // max |vertex| / d
};

template <std::size_t K>
struct bf_leaf {
    std::size_t fan;
    bary_vertex v[3];
    std::array<double, K> lo, hi, abs_terms;
};

inline const quadrature_rule& cached_rule(std::size_t n) {
    // Rules for N = 1..64, computed once each (the tests are single-threaded).
    static std::vector<quadrature_rule> rules(65);
    if (n == 0 || n >= rules.size()) n = 64;
    if (rules[n].x.empty()) rules[n] = gauss_legendre(n);
    return rules[n];
}

/// Twice the area of the piece in barycentric coordinates (1 for the whole triangle). Any two
/// of the three coordinates give it (the projections are area-preserving); the two used are
/// those other than the one that is largest all over the piece, so that the differences of
/// coordinates are accurate for slivers at a vertex or along an edge.
inline double bary_area2(const bary_vertex v[3]) {
    int skip = 0;
    double best = -1;
    for (int m = 0; m < 3; ++m) {
        const double lo = std::min({v[0].l[m], v[1].l[m], v[2].l[m]});
        const double hi = std::max({v[0].l[m], v[1].l[m], v[2].l[m]});
        if (lo + hi > best) best = lo + hi, skip = m;
    }
    const int c1 = (skip + 1) % 3, c2 = (skip + 2) % 3;
    const double e1x = v[1].l[c1] - v[0].l[c1], e1y = v[1].l[c2] - v[0].l[c2];
    const double e2x = v[2].l[c1] - v[0].l[c1], e2y = v[2].l[c2] - v[0].l[c2];
    return std::abs(e1x * e2y - e1y * e2x);
}

/// Duffy-map product rule of order r.x.size() on the piece. f(w, s) with s = <w, h>.
template <std::size_t K, typename F>
void duffy_rule(const fan_triangle& t, const bary_vertex v[3], const quadrature_rule& r, const F& f,
                std::array<double, K>& q, std::array<double, K>* abs_terms) {
    q.fill(0);
    if (abs_terms) abs_terms->fill(0);
    const double jac = t.area2 * bary_area2(v);
    if (!(jac > 0)) return;
    for (std::size_t i = 0; i < r.x.size(); ++i) {
        const double x = r.x[i];
        std::array<double, K> row{}, row_abs{};
        for (std::size_t j = 0; j < r.x.size(); ++j) {
            const double y = r.x[j];
            // (1 - x) A + x (1 - y) B + x y C: non-negative weights
            const double wa = 1 - x, wb = x * (1 - y), wc = x * y;
            const glm::dvec3 l = wa * v[0].l + wb * v[1].l + wc * v[2].l;
            const double s = wa * v[0].s + wb * v[1].s + wc * v[2].s;
            const glm::dvec3 p = l.x * t.k + l.y * t.a + l.z * t.b;
            const double r2 = glm::dot(p, p);
            const double len = std::sqrt(r2);
            const std::array<double, K> fv = f(p / len, s / len);
            const double g = r.w[j] * t.d / (r2 * len);
            for (std::size_t k = 0; k < K; ++k) row[k] += fv[k] * g, row_abs[k] += std::abs(fv[k] * g);
        }
        for (std::size_t k = 0; k < K; ++k) {
            q[k] += r.w[i] * x * jac * row[k];
            if (abs_terms) (*abs_terms)[k] += r.w[i] * x * jac * row_abs[k];
        }
    }
}

template <std::size_t K, typename F>
bf_leaf<K> evaluate_leaf(const std::vector<fan_triangle>& fans, std::size_t fan, const bary_vertex& a,
                         const bary_vertex& b, const bary_vertex& c, const brute_force_options& o, const F& f) {
    bf_leaf<K> l{fan, {a, b, c}, {}, {}, {}};
    duffy_rule<K>(fans[fan], l.v, cached_rule(o.order), f, l.lo, nullptr);
    duffy_rule<K>(fans[fan], l.v, cached_rule(2 * o.order), f, l.hi, &l.abs_terms);
    return l;
}

/// Splits the triangle (in barycentric coordinates, with s) by s = 0 into at most three
/// triangles, each with s >= 0 or s <= 0 at its vertices, appended to `out`.
inline void split_by_sign(const bary_vertex v[3], std::vector<std::array<bary_vertex, 3>>& out) {
    const bool any_pos = v[0].s > 0 || v[1].s > 0 || v[2].s > 0;
    const bool any_neg = v[0].s < 0 || v[1].s < 0 || v[2].s < 0;
    if (!(any_pos && any_neg)) {
        out.push_back({v[0], v[1], v[2]});
        return;
    }
    // Sutherland-Hodgman against sign * s >= 0 for both signs, then a fan of the (convex)
    // result: a triangle and a quadrilateral, or two triangles when the plane goes through a
    // vertex. Both sides compute each crossing point identically (a genuine partition).
    for (const double sign : {1.0, -1.0}) {
        bary_vertex poly[4];
        std::size_t m = 0;
        for (std::size_t i = 0; i < 3; ++i) {
            const std::size_t j = (i + 1) % 3;
            const double si = sign * v[i].s, sj = sign * v[j].s;
            if (si >= 0) poly[m++] = v[i];
            if ((si > 0 && sj < 0) || (si < 0 && sj > 0)) {
                const double den = v[i].s - v[j].s;                  // no cancellation: opposite signs
                const double wi = -v[j].s / den, wj = v[i].s / den;  // both in (0, 1)
                poly[m++] = {wi * v[i].l + wj * v[j].l, 0.0};
            }
        }
        for (std::size_t k = 1; k + 1 < m; ++k) out.push_back({poly[0], poly[k], poly[k + 1]});
    }
}

}  // namespace detail

/// Integral of f over the spherical polygon subtended by the star-shaped polygon `p` with kernel
/// point `kernel`. f(w, s) receives the unit direction w and s = <w, h> accurately; it must be
/// analytic on each side of the plane <w, h> = 0 (h = 0: analytic everywhere, s = 0). The
/// polygon's winding does not matter (the integral is unsigned, as the supplement's).
template <std::size_t K, typename F>
brute_force_result<K> integrate_polygon(const std::vector<glm::dvec3>& p, const glm::dvec3& kernel, const glm::dvec3& h,
                                        const F& f, const brute_force_options& o = brute_force_options()) {
    using detail::bary_vertex;
    std::vector<detail::fan_triangle> fans;
    std::vector<detail::bf_leaf<K>> leaves;
    const double s_kernel = accurate_dot(kernel, h);
    for (std::size_t i = 0; i < p.size(); ++i) {
        const glm::dvec3 a = p[i], b = p[(i + 1) % p.size()];
        const glm::dvec3 cr = glm::cross(a - kernel, b - kernel);
        const double area2 = std::sqrt(glm::dot(cr, cr));
        if (!(area2 > 0)) continue;
        const double d = std::abs(glm::dot(kernel, cr)) / area2;
        const double vmax = std::max({glm::length(kernel), glm::length(a), glm::length(b)});
        fans.push_back({kernel, a, b, area2, d, vmax / d});
        const bary_vertex v[3] = {
            {{1, 0, 0}, s_kernel}, {{0, 1, 0}, accurate_dot(a, h)}, {{0, 0, 1}, accurate_dot(b, h)}};
        std::vector<std::array<bary_vertex, 3>> pieces;
        detail::split_by_sign(v, pieces);
        for (const auto& t : pieces)
            leaves.push_back(detail::evaluate_leaf<K>(fans, fans.size() - 1, t[0], t[1], t[2], o, f));
    }

    brute_force_result<K> res;
    for (;;) {
        std::array<double, K> q{}, e{}, q_abs{};
        for (const auto& l : leaves)
            for (std::size_t k = 0; k < K; ++k)
                q[k] += l.hi[k], q_abs[k] += l.abs_terms[k], e[k] += std::abs(l.lo[k] - l.hi[k]);
        // Worst component relative to its target (relative to int |f|, the sum of |terms|).
        std::size_t worst = 0;
        double worst_ratio = 0;
        for (std::size_t k = 0; k < K; ++k) {
            const double target = std::max(o.rel_tol * q_abs[k], o.abs_floor);
            if (e[k] / target > worst_ratio) worst_ratio = e[k] / target, worst = k;
        }
        if (worst_ratio <= 1 || leaves.size() >= o.max_leaves) {
            const double u = std::numeric_limits<double>::epsilon() / 2;
            res.converged = worst_ratio <= 1;
            res.leaves = leaves.size();
            for (std::size_t k = 0; k < K; ++k) {
                double round = double(leaves.size()) * u * q_abs[k];
                for (const auto& l : leaves)
                    round += u * l.abs_terms[k] *
                             (4.0 * double(o.order) + 12 + o.evaluation_error +
                              3 * fans[l.fan].rho * (3 + o.direction_condition));
                res.value[k] = q[k];
                res.quadrature_error[k] = e[k];
                res.error[k] = e[k] + round;
            }
            return res;
        }
        // Refine every leaf whose estimate for the worst component is within a factor 4 of the
        // largest one.
        double largest = 0;
        for (const auto& l : leaves) largest = std::max(largest, std::abs(l.lo[worst] - l.hi[worst]));
        const std::size_t count = leaves.size();
        for (std::size_t i = 0; i < count; ++i) {
            if (!(std::abs(leaves[i].lo[worst] - leaves[i].hi[worst]) >= 0.25 * largest)) continue;
            const std::size_t fan = leaves[i].fan;
            const bary_vertex a = leaves[i].v[0], b = leaves[i].v[1], c = leaves[i].v[2];
            const auto mid = [](const bary_vertex& x, const bary_vertex& y) {
                return bary_vertex{0.5 * (x.l + y.l), 0.5 * (x.s + y.s)};
            };
            const bary_vertex ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
            leaves[i] = detail::evaluate_leaf<K>(fans, fan, a, ab, ca, o, f);
            leaves.push_back(detail::evaluate_leaf<K>(fans, fan, ab, b, bc, o, f));
            leaves.push_back(detail::evaluate_leaf<K>(fans, fan, ca, bc, c, o, f));
            leaves.push_back(detail::evaluate_leaf<K>(fans, fan, ab, bc, ca, o, f));
        }
    }
}

}  // namespace ltc_test
