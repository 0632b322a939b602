// Shared pieces of the polygon-sampler tests (test_projected_sampling*.cpp,
// test_ltc_polygon_sampling*.cpp, test_polygon_area_sampling.cpp): the test polygons, clipping a
// planar polygon by a plane through the origin (with the crossing points' direction errors), the
// first-order rounding bound of the projected sampler's E, a grid of great-circle wedges over a
// polygon (the chi-square bins), a great-circle containment test with a margin, and the
// chi-square statistic.
//
// Wedge grid. For a planar polygon P that does not contain the origin, c is its plane's unit
// normal oriented towards the plane (c.p = d > 0 for every p of the plane, so every direction of
// P has w.c > 0) and (t, b, c) an orthonormal frame. A direction w has the angles
// x = atan2(w.t, w.c) and y = atan2(w.b, w.c) in (-pi/2, pi/2), i.e. the equi-angular coordinates
// of a cube-map face facing P. The grid cuts [x0, x1] x [y0, y1] (the range of the vertices of P
// clipped to z >= 0, which bounds the whole convex polygon: the central projection onto the
// plane maps great circles to lines) into k x k cells. Cell (i, j) is bounded by four great
// circles: x >= x_i is w.(cos x_i t - sin x_i c) >= 0 (that dot is |w| cos x_w sin(x_w - x_i)),
// and likewise for the three other sides. P intersected with a cell is P clipped by these four
// planes through the origin: a convex planar polygon whose closed-form integral gives the cell's
// exact probability.
#pragma once

#include "support/chi_square.hpp"
#include "support/rounding_bound.hpp"

#include <ltc/core/polygon.hpp>
#include <ltc/core/projected_solid_angle_sampling.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace ltc_test::polygon_sampling {

using glm::dvec3;
using poly = std::vector<dvec3>;
inline constexpr double kPi = 3.141592653589793238462643383279502884;

/// P clipped to the half-space w.n >= 0 (Sutherland-Hodgman; n through the origin). A crossing
/// point is a + t (b - a) with t = da / (da - db): its direction is off the exact one by at most
/// crossing_error(a, b, x) units of u (see below), the other vertices are copied exactly.
struct clipped {
    poly v;
    std::vector<double> delta;  // direction error of each vertex in units of u
};

/// The direction error, in units of u, of a crossing point x = a + t (b - a) (here) or
/// a (1 - t) + b t (ltc::clip_to_horizon, t from the heights rescaled by the larger one): t
/// carries <= 4u relative (two dots or rescalings, a difference without cancellation since da
/// and db have opposite signs, a division), i.e. <= 4u |b - a| <= 4u (|a| + |b|) in x; the
/// products and the sum add 3u (|a| + |b|): <= 7u (|a| + |b|) absolute, so <= 7 (|a| + |b|) / |x|
/// radians, rounded up to 8.
inline double crossing_error(const dvec3& a, const dvec3& b, const dvec3& x) {
    return 8 * (glm::length(a) + glm::length(b)) / glm::length(x);
}

inline clipped clip(const clipped& p, const dvec3& n) {
    // In ltc::clip_to_horizon's order (the closing edge first), so that clipping to z >= 0 gives
    // the sampler's vertices in the sampler's order (its fan apex first).
    clipped out;
    const std::size_t m = p.v.size();
    for (std::size_t i = 0; i < m; ++i) {
        const std::size_t j = (i + m - 1) % m;
        const dvec3 &a = p.v[j], &b = p.v[i];
        const double da = glm::dot(a, n), db = glm::dot(b, n);
        if ((da >= 0) != (db >= 0)) {
            const dvec3 x = a + (da / (da - db)) * (b - a);
            out.v.push_back(x);
            out.delta.push_back(std::max(p.delta[i], p.delta[j]) + crossing_error(a, b, x));
        }
        if (db >= 0) out.v.push_back(b), out.delta.push_back(p.delta[i]);
    }
    return out;
}

inline clipped exact(const poly& p) { return {p, std::vector<double>(p.size(), 0.0)}; }

/// Unit normal of the plane of P (Newell), oriented so that c.p0 > 0.
inline dvec3 facing_normal(const poly& p) {
    dvec3 a(0);
    for (std::size_t i = 0; i < p.size(); ++i) a += glm::cross(p[i], p[(i + 1) % p.size()]);
    a = glm::normalize(a);
    return glm::dot(a, p[0]) > 0 ? a : -a;
}

/// w inside the convex spherical polygon P (either winding) by at least `margin` radians from
/// every edge's great circle (a negative margin accepts directions that far outside).
inline bool inside(const poly& p, const dvec3& w, double margin) {
    const dvec3 c = facing_normal(p);
    if (!(glm::dot(w, c) > 0)) return false;
    for (std::size_t i = 0; i < p.size(); ++i) {
        // p_i x (p_i+1 - p_i): the difference is exact to u |p_i+1 - p_i|, so the normal of a
        // short edge keeps its accuracy (p_i x p_i+1 would lose it to cancellation)
        dvec3 n = glm::cross(p[i], p[(i + 1) % p.size()] - p[i]);
        const double l = glm::length(n);
        if (!(l > 0)) continue;
        n /= l;
        if (glm::dot(n, p[(i + 2) % p.size()]) < 0) n = -n;  // towards the polygon (convex)
        if (glm::dot(n, w) < margin * glm::length(w)) return false;
    }
    return true;
}

/// First-order bound on |E - E_exact| for the projected solid angle E that
/// projected_polygon_sampler<T> computes from the vertices p (exact in T), in units of T's u
/// (multiply by u). The sampler clips p to z >= 0 in T (crossing points off by crossing_error),
/// normalizes (2u more per vertex), and sums the masses of the fan triangles (v0, vi, vi+1). Each
/// mass is Lambert's sum of the three edge terms theta_e n_e.z / 2, evaluated in the apex's tangent
/// frame: every angle an atan2 of dots of rounded unit vectors, every z-factor a component of a
/// rounded unit normal or tangent, the same operation counts as eq. (11)'s edge term. So each
/// triangle's error is bounded like the closed form's (support/rounding_bound.hpp): the vertex
/// errors sweep <= (delta_a + delta_b) theta kappa / 2 per edge, the terms <= 22 theta kappa each,
/// their sum (m + 1) sum|terms|, all over 2 pi for the form factor, times pi for E (so / 2); the
/// triangles' masses add with <= (count) u E more. kappa = theta / sin(theta) grows for nearly
/// antipodal fan vertices (near-hemisphere polygons: the great circle through them is
/// ill-conditioned), which is where the sampler's error is largest.
/// `delta`: the input vertices' direction errors in units of u (empty: exact input).
inline double projected_bound_in_u(const poly& p, const std::vector<double>& delta = {}) {
    using namespace ltc_test::polygon_integration;
    const clipped above = clip(delta.empty() ? exact(p) : clipped{p, delta}, dvec3(0, 0, 1));
    if (above.v.size() < 3) return 0;
    double sum = 0, e = 0;
    for (std::size_t i = 1; i + 1 < above.v.size(); ++i) {
        const poly tri = {above.v[0], above.v[i], above.v[i + 1]};
        const std::vector<double> d = {above.delta[0], above.delta[i], above.delta[i + 1]};
        const bound_parts b = rounding_parts(form::cosine, tri, d, 2);
        sum += (b.region + b.terms + b.summation) / 2;
        e += std::abs(ltc::form_factor_signed(tri.data(), 3)) * kPi;
    }
    return sum + double(above.v.size() - 2) * e;
}

struct wedge_grid {
    dvec3 t, b, c;
    double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
    int k = 1;

    /// The grid over P clipped to z >= 0 (P: planar, convex, not through the origin).
    wedge_grid(const poly& p, int cells_per_side) : k(cells_per_side) {
        c = facing_normal(p);
        t = glm::normalize(std::abs(c.x) < 0.9 ? glm::cross(c, dvec3(1, 0, 0)) : glm::cross(c, dvec3(0, 1, 0)));
        b = glm::cross(c, t);
        const poly above = clip(exact(p), dvec3(0, 0, 1)).v;
        x0 = y0 = kPi, x1 = y1 = -kPi;
        for (const dvec3& v : above) {
            const double x = std::atan2(glm::dot(v, t), glm::dot(v, c)), y = std::atan2(glm::dot(v, b), glm::dot(v, c));
            x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
        }
    }
    int cells() const { return k * k; }
    double x_at(int i) const { return x0 + (x1 - x0) * i / k; }
    double y_at(int j) const { return y0 + (y1 - y0) * j / k; }
    /// The cell of direction w (w.c > 0); directions beyond the range go to the border cells.
    int cell_of(const dvec3& w) const {
        const auto index = [&](double a, double lo, double hi) {
            const int i = static_cast<int>(std::floor((a - lo) / (hi - lo) * k));
            return std::min(std::max(i, 0), k - 1);
        };
        return index(std::atan2(glm::dot(w, t), glm::dot(w, c)), x0, x1) * k +
               index(std::atan2(glm::dot(w, b), glm::dot(w, c)), y0, y1);
    }
    /// The four inward plane normals of cell (i, j).
    std::vector<dvec3> planes(int cell) const {
        const int i = cell / k, j = cell % k;
        const auto side = [&](const dvec3& axis, double a) { return std::cos(a) * axis - std::sin(a) * c; };
        return {side(t, x_at(i)), -side(t, x_at(i + 1)), side(b, y_at(j)), -side(b, y_at(j + 1))};
    }
    /// P intersected with cell (i, j), in P's coordinates (any linear image of the cells too:
    /// pass the planes already mapped).
    clipped cut(const poly& p, const std::vector<dvec3>& cell_planes) const {
        clipped q = exact(p);
        for (const dvec3& n : cell_planes) q = clip(q, n);
        return q;
    }
};


using ltc_test::chi_square;
using ltc_test::chi_square_test;

/// A test polygon in the shading frame (z = normal), given in one winding; `reversed` gives the
/// other.
struct named_polygon {
    std::string name;
    poly v;
};

inline poly reversed(poly p) {
    std::reverse(p.begin(), p.end());
    return p;
}

/// Regular n-gon of circumradius r around `centre` in the plane spanned by unit e1, e2.
inline poly ngon(const dvec3& centre, const dvec3& e1, const dvec3& e2, double r, int n, double phase = 0.3) {
    poly p;
    for (int i = 0; i < n; ++i) {
        const double a = phase + 2 * kPi * i / n;
        p.push_back(centre + r * (std::cos(a) * e1 + std::sin(a) * e2));
    }
    return p;
}

/// The rectangle centre +- a e1 +- b e2.
inline poly rect(const dvec3& centre, const dvec3& e1, const dvec3& e2, double a, double b) {
    return {centre - a * e1 - b * e2, centre + a * e1 - b * e2, centre + a * e1 + b * e2, centre - a * e1 + b * e2};
}

/// Vertices rounded to T (the exact input of the sampler in T, and of the references in double).
template <typename T>
poly rounded(const poly& p) {
    poly r;
    for (const dvec3& v : p) r.push_back(dvec3(glm::vec<3, T>(v)));
    return r;
}

template <typename T>
std::vector<glm::vec<3, T>> as(const poly& p) {
    std::vector<glm::vec<3, T>> r;
    for (const dvec3& v : p) r.push_back(glm::vec<3, T>(v));
    return r;
}

/// The polygons of the projected-sampler tests: above, straddling, near-hemisphere, grazing,
/// tiny (angular size `tiny` radians, at distance 1) and slivers; in either winding by reversed().
inline std::vector<named_polygon> test_polygons(double tiny) {
    const dvec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    const dvec3 tilted_a = glm::normalize(dvec3(1, 0.2, 0.4));
    const dvec3 tilted_b = glm::normalize(glm::cross(dvec3(0.3, -0.5, 1), tilted_a));
    const dvec3 diagonal = glm::normalize(dvec3(1, 1, 0)), anti_diagonal = glm::normalize(dvec3(-1, 1, 0));
    const dvec3 tiny_dir = glm::normalize(dvec3(0.5, -0.3, 0.6));
    const dvec3 tiny_e1 = glm::normalize(glm::cross(tiny_dir, z)), tiny_e2 = glm::cross(tiny_dir, tiny_e1);
    return {
        {"quad above", rect(dvec3(0.3, -0.2, 1), x, y, 0.4, 0.3)},
        {"tilted pentagon above", ngon(dvec3(-0.4, 0.5, 1.2), tilted_a, tilted_b, 0.5, 5)},
        {"straddling quad", rect(dvec3(1, 0.1, 0.2), y, z, 0.6, 0.7)},
        {"straddling pentagon", ngon(dvec3(0.6, 0.6, 0.1), tilted_a, tilted_b, 0.8, 5)},
        {"near-hemisphere quad", rect(dvec3(0, 0, 1), x, y, 300, 200)},
        {"grazing quad", rect(dvec3(0.2, 1, 0.004), x, z, 0.5, 0.003)},
        {"grazing straddling quad", rect(dvec3(1, 0, -0.3), y, z, 0.5, 0.301)},
        {"tiny quad", rect(tiny_dir, tiny_e1, tiny_e2, tiny / 2, tiny / 2)},
        {"sliver quad", rect(dvec3(0.2, 0.1, 1), diagonal, anti_diagonal, 0.6, 1e-3)},
        {"sliver triangle", {dvec3(-0.5, 0.2, 1), dvec3(0.7, 0.25, 0.8), dvec3(0.7, 0.2502, 0.8)}},
    };
}

/// A test polygon of test_polygons in one winding, rounded to T, with its sampler, the closed
/// form E = pi F (F the two-sided form factor of the clipped polygon, in double on the rounded
/// vertices) and the allowed |E_sampler - E|: the sampler's bound in T plus the closed form's in
/// double (tests/test_projected_sampling.cpp explains it).
template <typename T>
struct projected_fixture {
    std::string name;
    poly p;
    std::vector<glm::vec<3, T>> v;
    ltc::projected_polygon_sampler<T> s;
    double E, bound;
};

template <typename T>
std::vector<projected_fixture<T>> projected_fixtures() {
    using ltc_test::polygon_integration::form;
    const double tiny = sizeof(T) == sizeof(float) ? 1e-3 : 1e-5;
    std::vector<projected_fixture<T>> r;
    for (const named_polygon& np : test_polygons(tiny))
        for (int winding = 0; winding < 2; ++winding) {
            projected_fixture<T> f;
            f.name = np.name + (winding ? " (reversed)" : "");
            f.p = rounded<T>(winding ? reversed(np.v) : np.v);
            f.v = as<T>(f.p);
            f.s = ltc::projected_polygon_sampler<T>(f.v.data(), f.v.size());
            const double F = ltc::form_factor(f.p.data(), f.p.size(), ltc::sidedness::two_sided);
            f.E = kPi * F;
            f.bound = std::numeric_limits<T>::epsilon() / 2 * projected_bound_in_u(f.p) +
                      kPi * ltc_test::polygon_integration::rounding_bound(form::cosine, f.p, {}, 0x1p-53, F);
            r.push_back(f);
        }
    return r;
}

}  // namespace ltc_test::polygon_sampling
