// Shared pieces of the exact textured-cell tests (test_textured_cells.cpp,
// test_textured_cells_truth.cpp): the three textures of the README's textured table (smooth,
// checker, small bright detail), parallelogram lights, the two lobes, the cell parallelograms as
// ltc/shading/textured_cells.hpp maps them, and first-order rounding bounds of one polygon
// integral (the derivation of tests/support/rounding_bound.hpp).
#pragma once

#include <ltc/shading/textured_light.hpp>

#include "support/rounding_bound.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace ltc_test::textured_cells {

using glm::dmat3;
using glm::dvec3;
using polygon_integration::unit_roundoff;  // u = epsilon / 2 of T

enum class pattern { smooth, checker, detail };

/// w x h texels, row-major (v = 0 on the first row), in float so that the float and double
/// tests (and the double references) see the same, exactly representable, radiance.
inline std::vector<glm::vec3> make_image(pattern p, int w, int h) {
    std::vector<glm::vec3> img(std::size_t(w) * std::size_t(h));
    const auto blob = [](double u, double v, double cu, double cv, double s) {
        return std::exp(-((u - cu) * (u - cu) + (v - cv) * (v - cv)) / (2 * s * s));
    };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double u = (x + 0.5) / w, v = (y + 0.5) / h;
            dvec3 c;
            if (p == pattern::smooth)  // colour gradient plus two Gaussian blobs
                c = dvec3(0.2 + 0.8 * u, 0.3 + 0.5 * v, 0.5 + 0.3 * (1 - u)) +
                    blob(u, v, 0.3, 0.6, 0.12) * dvec3(1.5, 0.5, 0.2) +
                    blob(u, v, 0.7, 0.3, 0.08) * dvec3(0.3, 1.2, 0.8);
            else if (p == pattern::checker)  // 4-texel squares
                c = ((x / 4 + y / 4) % 2) ? dvec3(1.0, 0.8, 0.2) : dvec3(0.1, 0.2, 0.6);
            else  // 3 x 3 texels of 100 on 0.02
                c = (x >= 5 * w / 8 && x < 5 * w / 8 + 3 && y >= 3 * h / 8 && y < 3 * h / 8 + 3) ? dvec3(100.0)
                                                                                                 : dvec3(0.02);
            img[std::size_t(y) * w + x] = glm::vec3(c);
        }
    return img;
}

template <typename T>
std::vector<glm::vec<3, T>> to(const std::vector<glm::vec3>& v) {
    return std::vector<glm::vec<3, T>>(v.begin(), v.end());
}

/// Parallelogram lights q_0, q_0 + e_1, q_0 + e_1 + e_3, q_0 + e_3, all coordinates dyadic with
/// few bits (every sum of corners and edges is exact in float). Clockwise as seen from the
/// shading point (positive one-sided integrals) except where the name says otherwise.
struct light {
    const char* name;
    dvec3 q0, e1, e3;
    void corners(dvec3 q[4]) const { q[0] = q0, q[1] = q0 + e1, q[2] = q0 + e1 + e3, q[3] = q0 + e3; }
    /// The same in double and in T (exactly: dyadic coordinates).
    template <typename T>
    void corners(dvec3 qd[4], glm::vec<3, T> q[4]) const {
        corners(qd);
        for (int i = 0; i < 4; ++i) q[i] = glm::vec<3, T>(qd[i]);
    }
};
inline const light lights[] = {
    {"facing, above the shading point", {-0.5, -0.5, 1}, {1, 0, 0}, {0, 1, 0}},
    {"tilted, towards the mirror direction of theta_v = 60 deg", {-2, -0.75, 0.5}, {1.5, 0, 0}, {0, 1.5, 0.75}},
    {"vertical, crossing the horizon", {0.75, -0.5, -0.5}, {0, 1, 0}, {0.25, 0, 1.5}},
};
inline const light facing_away{"facing away (counter-clockwise)", {-0.5, 0.5, 1}, {1, 0, 0}, {0, -1, 0}};
inline const light below_horizon{"below the horizon", {-0.5, -0.5, -1}, {1, 0, 0}, {0, 1, 0}};

template <typename T>
void to_t(const dvec3 q[4], glm::vec<3, T> out[4]) {
    for (int i = 0; i < 4; ++i) out[i] = glm::vec<3, T>(q[i]);
}

/// The inverse LTC matrices under test: the clamped cosine itself (diffuse) and GGX at
/// roughness 0.25, theta_v = 60 deg from the shipped table (rounded to float, so that float and
/// double see the same matrix).
inline dmat3 lobe_m_inv(int i) { return i == 0 ? dmat3(1.0) : dmat3(ltc::ggx::fetch<float>(0.5f, 0.25f).m_inv); }
inline const char* const lobe_names[2] = {"clamped cosine (M = I)", "GGX roughness 0.25, theta_v 60 deg"};

template <typename T>
ltc::transformed<ltc::clamped_cosine<T>> lobe(int i) {
    return ltc::transformed<ltc::clamped_cosine<T>>::from_inverse(glm::mat<3, 3, T>(lobe_m_inv(i)));
}

/// The corners of the texel rectangle [x0, x1) x [y0, y1) of a w x h texture on the quad, in T,
/// by the mapping of textured_cells.hpp (q_0 + u e_1 + v e_3, u = x (1 / w)), so that the
/// integrals are the same numbers as the library's.
template <typename T>
void cell_corners(const glm::vec<3, T> quad[4], int w, int h, int x0, int y0, int x1, int y1, glm::vec<3, T> c[4]) {
    const glm::vec<3, T> q0 = quad[0], e1 = quad[1] - quad[0], e3 = quad[3] - quad[0];
    const T du = T(1) / T(w), dv = T(1) / T(h);
    const T u0 = T(x0) * du, u1 = T(x1) * du, v0 = T(y0) * dv, v1 = T(y1) * dv;
    c[0] = q0 + u0 * e1 + v0 * e3, c[1] = q0 + u1 * e1 + v0 * e3;
    c[2] = q0 + u1 * e1 + v1 * e3, c[3] = q0 + u0 * e1 + v1 * e3;
}

/// The exact texel rectangle's corners in double (no reference to T's rounding).
inline void exact_cell(const dvec3 quad[4], int w, int h, int x0, int y0, int x1, int y1, dvec3 c[4]) {
    const dvec3 e1 = quad[1] - quad[0], e3 = quad[3] - quad[0];
    const double u0 = double(x0) / w, u1 = double(x1) / w, v0 = double(y0) / h, v1 = double(y1) / h;
    c[0] = quad[0] + u0 * e1 + v0 * e3, c[1] = quad[0] + u1 * e1 + v0 * e3;
    c[2] = quad[0] + u1 * e1 + v1 * e3, c[3] = quad[0] + u0 * e1 + v1 * e3;
}

/// I_D, in double, of the exact cell [x0, x1) x [y0, y1) (exact_cell) for the inverse matrix m_inv.
inline double exact_cell_integral(const dmat3& m_inv, const dvec3 quad[4], int w, int h, int x0, int y0, int x1,
                                  int y1) {
    dvec3 c[4];
    exact_cell(quad, w, h, x0, y0, x1, y1, c);
    return ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(m_inv).integrate(c, 4);
}

/// How far (absolute, per component) a corner computed in T by cell_corners (or the library)
/// is from the exact one: e_1, e_3 (1 rounding each), du (1), u = x du (1), u e_1 and v e_3
/// (1 each), two additions (1 each): 8 roundings, each relative to a magnitude of at most
/// |q_0| + |q_1| + |q_3| (infinity norms), to first order.
template <typename T>
double corner_error(const dvec3 quad[4]) {
    const auto inf = [](const dvec3& a) { return std::max({std::abs(a.x), std::abs(a.y), std::abs(a.z)}); };
    return 8 * polygon_integration::unit_roundoff<T>() * (inf(quad[0]) + inf(quad[1]) + inf(quad[3]));
}

inline double frobenius(const dmat3& m) {
    return std::sqrt(glm::dot(m[0], m[0]) + glm::dot(m[1], m[1]) + glm::dot(m[2], m[2]));
}

/// First-order bound on |I_D(p') computed in T - I_D(p)| (d with the inverse matrix m_inv, p the
/// exact polygon in double, p' its corners as computed in T, each within corner_err per
/// component), by either of the library's evaluations. d.integrate: rounding_bound of the clamped
/// cosine over M^-1 p (tests/support/rounding_bound.hpp) with the direction errors of
/// transformed<> (transformed_input_error), plus those of the corners, |M^-1 dp| / |M^-1 p| <=
/// |M^-1|_F sqrt(3) corner_err / |M^-1 p|, plus 2u for the normalization. In float the cells also
/// go through the batch kernel (textured_cells.hpp), which normalizes by rsqrt and one Newton
/// step (<= 4.5u more) and whose edge terms on its own unit vertices are within 32u |e_j| of the
/// scalar path's (tests/test_batch.cpp): its vertices' error goes into the region term (a change
/// of O(delta theta) per polygon, not O(delta) per edge), its terms' into the term error.
template <typename T>
double integral_bound(const dmat3& m_inv, const dvec3 p[4], double corner_err) {
    namespace pr = polygon_integration;
    const double u = unit_roundoff<T>(), kernel = std::is_same_v<T, float> ? 1 : 0;
    const pr::poly_t poly(p, p + 4);
    const pr::poly_t q = pr::transform(m_inv, poly);
    std::vector<double> d = pr::transformed_input_error(m_inv, m_inv, poly, u);
    for (std::size_t i = 0; i < 4; ++i) d[i] += std::sqrt(3.0) * frobenius(m_inv) * corner_err / glm::length(q[i]) / u;
    const pr::bound_parts b = pr::rounding_parts(pr::form::cosine, q, d, 2 + 4.5 * kernel,
                                                 pr::default_factor_error<T>(pr::cosine) + 32 * kernel);
    if (b.region == 0 && b.terms == 0) return 0;  // nothing above the horizon: exactly 0
    const double value = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(m_inv).integrate(p, 4);
    return u * (b.region + b.terms + b.summation) / b.norm + 3 * u * value;
}

/// integral_bound of the library's I_D of cell [x0, x1) x [y0, y1) of a w x h texture on the quad.
template <typename T>
double cell_bound(const dmat3& m_inv, const dvec3 quad[4], int w, int h, int x0, int y0, int x1, int y1) {
    dvec3 c[4];
    exact_cell(quad, w, h, x0, y0, x1, y1, c);
    return integral_bound<T>(m_inv, c, corner_error<T>(quad));
}

/// |q_2 - (q_1 + q_3 - q_0)| (infinity norm): how far corner 2, which the cells do not use, is
/// from the parallelogram's (0 for the lights above; the rounding of a rectangle otherwise).
inline double parallelogram_defect(const dvec3 q[4]) {
    const dvec3 d = glm::abs(q[2] - (q[1] + q[3] - q[0]));
    return std::max({d.x, d.y, d.z});
}

inline double max_component(const glm::dvec3& v) { return std::max({v.x, v.y, v.z}); }

/// The largest channel of any texel.
inline double max_texel(const std::vector<glm::vec3>& img) {
    double m = 0;
    for (const glm::vec3& c : img) m = std::max(m, max_component(glm::dvec3(c)));
    return m;
}

/// How far the library's I_D of the root cell (the parallelogram on q_0, q_1, q_3) may be from
/// the exact one, however it gets it: integrated over the root cell, or summed in T from the
/// integrals of the cells of a level at most two below the last (<= 16 cells): the cell_bound of
/// the cells of those three levels plus the summation, 15 u_T I_D.
template <typename T>
double root_bound(const dmat3& m_inv, const dvec3 quad[4], int w, int h) {
    int top = 0;
    while ((1 << top) < std::max(w, h)) ++top;
    double sum =
        15 * unit_roundoff<T>() * ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(m_inv).integrate(quad, 4);
    for (int k = std::max(top - 2, 0); k <= top; ++k) {
        const int s = 1 << k;
        for (int j = 0; j * s < h; ++j)
            for (int i = 0; i * s < w; ++i)
                sum +=
                    cell_bound<T>(m_inv, quad, w, h, i * s, j * s, std::min((i + 1) * s, w), std::min((j + 1) * s, h));
    }
    return sum;
}

/// How far the value (or the bound) of any set of leaves of the quadtree moves by the rounding of
/// their I_D: the sum over every cell c of every level of max_c cell_bound<T>(c), max_c the
/// largest channel of c's texels (>= its mean and, for texels >= 0, its range); plus, as the
/// library may sum the I_D of the levels above top - 2 from that level's instead (disjoint
/// leaves: at most once each), L_max (the cell_bound of level top - 2's cells + 15 u_T I_D).
template <typename T>
double pyramid_bound(const dmat3& m_inv, const dvec3 quad[4], const std::vector<glm::vec3>& img, int w, int h) {
    int top = 0;
    while ((1 << top) < std::max(w, h)) ++top;
    double sum = 0, base = 0, l_max = 0;
    for (int k = 0; k <= top; ++k) {
        const int s = 1 << k;
        for (int j = 0; j * s < h; ++j)
            for (int i = 0; i * s < w; ++i) {
                const int x1 = std::min((i + 1) * s, w), y1 = std::min((j + 1) * s, h);
                double m = 0;
                for (int y = j * s; y < y1; ++y)
                    for (int x = i * s; x < x1; ++x)
                        m = std::max(m, max_component(glm::dvec3(img[std::size_t(y) * w + x])));
                const double e = cell_bound<T>(m_inv, quad, w, h, i * s, j * s, x1, y1);
                sum += m * e, l_max = std::max(l_max, m);
                if (k == std::max(top - 2, 0)) base += e;
            }
    }
    const double i_d = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(m_inv).integrate(quad, 4);
    return sum + l_max * (base + 15 * unit_roundoff<T>() * i_d);
}

/// How far the value at full refinement moves by the rounding of its leaves' I_D: the leaves are
/// the cells of range 0 (or of level 0) whose ancestors all have range > 0; each weighs
/// max(mean_c) times its cell_bound, or, above level top - 2 (whose I_D the library may sum
/// from that level's), times the cell_bounds of the level top - 2 cells inside it + 15 u_T I_D.
template <typename T>
double full_refinement_bound(const dmat3& m_inv, const dvec3 quad[4], const ltc::cell_pyramid<double>& cells) {
    const int top = cells.level_count() - 1, base = std::max(top - 2, 0), w = cells.width(), h = cells.height();
    const auto bound = [&](int k, int i, int j) {
        int x0, y0, x1, y1;
        cells.texels(k, i, j, x0, y0, x1, y1);
        double e = cell_bound<T>(m_inv, quad, w, h, x0, y0, x1, y1);
        if (k <= base) return e;
        e += 15 * unit_roundoff<T>() * exact_cell_integral(m_inv, quad, w, h, x0, y0, x1, y1);
        const int s = 1 << base;
        for (int y = y0; y < y1; y += s)
            for (int x = x0; x < x1; x += s)
                e += cell_bound<T>(m_inv, quad, w, h, x, y, std::min(x + s, x1), std::min(y + s, y1));
        return e;
    };
    double sum = 0;
    const auto visit = [&](const auto& self, int k, int i, int j) -> void {
        if (k == 0 || cells.range(k, i, j) == 0) {
            sum += max_component(cells.mean(k, i, j)) * bound(k, i, j);
            return;
        }
        for (int b = 0; b < 2; ++b)
            for (int a = 0; a < 2; ++a)
                if (2 * i + a < cells.cells_x(k - 1) && 2 * j + b < cells.cells_y(k - 1))
                    self(self, k - 1, 2 * i + a, 2 * j + b);
    };
    visit(visit, top, 0, 0);
    return sum;
}

}  // namespace ltc_test::textured_cells
