// Closed-form polygon integrals against an independent brute-force integration (supplement
// section 2.3), for the four original distributions and for linearly transformed ones; plus the
// sign, sidedness and horizon-clipping conventions of ltc/core/polygon.hpp.
//
// Tolerances are derived, not tuned: |closed - brute| <= e + B, where e is the brute force's own
// error estimate (support/brute_force.hpp) and B a first-order bound on the rounding error of the
// closed form in the scalar type T, computed in double for each polygon by rounding_bound()
// below (the derivation is written next to it). Test inputs are exactly representable in float
// (vertices and matrices are rounded to float first), so B only accounts for the library's
// own arithmetic.
#include <ltc/ltc.hpp>

#include "support/brute_force.hpp"
#include "support/rng.hpp"

#include <catch2/catch.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace {

using glm::dmat3;
using glm::dvec3;
using poly_t = std::vector<dvec3>;

constexpr double kPi = 3.141592653589793238462643383279502884;

// ---------------------------------------------------------------------------------------------
// Reference densities in double, written from their definitions (supplement section 1); the
// library is never called to build a reference.

enum dist_id { sphere = 0, hemisphere = 1, cosine = 2, squared = 3 };
const char* const dist_names[4] = {"uniform_sphere", "uniform_hemisphere", "clamped_cosine", "squared_clamped_cosine"};

/// The four D_o at a direction of height z (they depend on z only).
std::array<double, 4> reference_densities_z(double z_signed) {
    const double z = std::max(0.0, z_signed);
    return {1 / (4 * kPi), z_signed >= 0 ? 1 / (2 * kPi) : 0.0, z / kPi, 3 * z * z / (2 * kPi)};
}

/// Integrand for the brute force with h = (0, 0, 1): s = w.z, given accurately.
std::array<double, 4> reference_densities(const dvec3&, double s) { return reference_densities_z(s); }

/// D(w) = D_o(M^-1 w / |M^-1 w|) |det M^-1| / |M^-1 w|^3 (supplement section 2.1), for the
/// brute force with h = transformed_horizon(m_inv): s = <w, h> = (M^-1 w).z, given accurately.
std::array<double, 4> reference_transformed(const dmat3& m_inv, double abs_det_inv, const dvec3& w, double s) {
    const double l = glm::length(m_inv * w);
    std::array<double, 4> d = reference_densities_z(s / l);
    const double jac = abs_det_inv / (l * l * l);
    for (double& x : d) x *= jac;
    return d;
}

/// Brute-force options for D over P: D = D_o(s / l) |det| / l^3 with l = |M^-1 w| depends on w
/// through l with a power up to 5, and l's relative sensitivity to w is at most the condition
/// number kappa = |M^-1|_F |M|_F; computing l (3-term dots and a norm) errs by <= (3 kappa + 2) u.
ltc_test::brute_force_options transformed_options(const dmat3& m, const dmat3& m_inv) {
    const auto frob = [](const dmat3& a) {
        return std::sqrt(glm::dot(a[0], a[0]) + glm::dot(a[1], a[1]) + glm::dot(a[2], a[2]));
    };
    const double kappa = frob(m) * frob(m_inv);
    ltc_test::brute_force_options o;
    o.direction_condition = 5 * kappa;
    o.evaluation_error = 4 + 5 * (3 * kappa + 2);
    return o;
}

/// The normal h of the plane <w, h> = 0 across which D over P has its kink or jump:
/// (M^-1 w).z = <row 2 of M^-1, w>. GLM is column-major (m[col][row]), so row 2 is
/// transpose(m_inv)[2] = (m_inv[0][2], m_inv[1][2], m_inv[2][2]).
dvec3 transformed_horizon(const dmat3& m_inv) { return glm::transpose(m_inv)[2]; }

std::string str(const poly_t& p) {
    std::ostringstream s;
    s << std::setprecision(17) << "{";
    for (const dvec3& v : p) s << " (" << v.x << ", " << v.y << ", " << v.z << ")";
    s << " }";
    return s.str();
}

std::string str(const dmat3& m) {  // row-major, as the paper prints matrices
    std::ostringstream s;
    s << std::setprecision(17) << "[";
    for (int r = 0; r < 3; ++r) s << (r ? "; " : "") << m[0][r] << " " << m[1][r] << " " << m[2][r];
    s << "]";
    return s.str();
}

template <typename T>
std::vector<glm::vec<3, T>> to(const poly_t& p) {
    std::vector<glm::vec<3, T>> v;
    for (const dvec3& x : p) v.push_back(glm::vec<3, T>(x));
    return v;
}

poly_t reversed(poly_t p) {
    std::reverse(p.begin(), p.end());
    return p;
}

poly_t transform(const dmat3& m, const poly_t& p) {
    poly_t q;
    for (const dvec3& x : p) q.push_back(m * x);
    return q;
}

/// M^-1 P for the brute force of D_o over M^-1 P: components accurate to 1u of themselves, so
/// that vertices close to the horizon keep their small heights accurately.
poly_t accurate_transform(const dmat3& m, const poly_t& p) {
    poly_t q;
    for (const dvec3& x : p) q.push_back(ltc_test::accurate_transform(m, x));
    return q;
}

/// The paper's row-major 3x3 matrix as a GLM (column-major) matrix, rounded to float so that the
/// float and double tests see the same, exactly representable, M.
dmat3 row_major(double a, double b, double c, double d, double e, double f, double g, double h, double i) {
    return dmat3(glm::mat3(glm::transpose(dmat3(a, b, c, d, e, f, g, h, i))));
}

// ---------------------------------------------------------------------------------------------
// Closed forms under test, by distribution id.

template <typename T>
T closed_form(int id, const poly_t& p) {
    const auto v = to<T>(p);
    switch (id) {
        case sphere: return ltc::uniform_sphere<T>::integrate(v.data(), v.size());
        case hemisphere: return ltc::uniform_hemisphere<T>::integrate(v.data(), v.size());
        case cosine: return ltc::clamped_cosine<T>::integrate(v.data(), v.size());
        default: return ltc::squared_clamped_cosine<T>::integrate(v.data(), v.size());
    }
}

template <typename T>
T closed_form_signed(int id, const poly_t& p) {
    const auto v = to<T>(p);
    const glm::vec<3, T>* d = v.data();
    switch (id) {
        case sphere: return ltc::uniform_sphere<T>::signed_integral(d, v.size());
        case hemisphere: return ltc::uniform_hemisphere<T>::signed_integral(d, v.size());
        case cosine: return ltc::clamped_cosine<T>::signed_integral(d, v.size());
        default: return ltc::squared_clamped_cosine<T>::signed_integral(d, v.size());
    }
}

// ---------------------------------------------------------------------------------------------
// First-order rounding bound of the closed forms.
//
// Every closed form is  I = Sigma / norm,  Sigma a sum of m terms over the edges of the unit
// polygon (clipped to z >= 0 except for the sphere), norm = 4 pi (sphere) or 2 pi. Let u = eps/2
// of T. To first order the computed value differs from I by at most u B / norm + 3u |I|, with
//   B = R + C + (m + 1) Sum|terms|:
//
// * R, the vertices: each unit vertex the library computes points off the exact direction by
//   delta_i u (radians), delta_i = d_i + 2: d_i from the input (0 for the exact, float
//   representable, inputs of the original distributions; for transformed ones the rounding of
//   M^-1 p in T, see transformed_input_error), plus 2 for safe_normalize (v / max and s / |s|
//   round each component once; the rounding of |s| only changes the length, by <= 2u, which the
//   terms below account for where they assume unit vectors).
//   A horizon crossing x ~ in (-out.z) + out in.z (2 roundings per component, relative to
//   |in.z| + |out.z| <= |x| / cos(theta/2)), z := 0, then normalized (2), points off the exact
//   great circle by <= (max(delta_in, delta_out) + 2) / cos(theta/2) + 2 <= (max + 4) kappa,
//   kappa = theta / sin(theta) >= 1 / cos(theta/2), theta the angle of the edge in -> out. Its
//   displacement along the horizon is harmless: it sweeps a triangle of height in.z, i.e. acts as
//   a vertex perturbation of size |d in.z| again. The exact integral of the perturbed polygon
//   differs from the exact one by at most the density times the swept area; moving one end of an
//   arc of length theta by delta sweeps delta tan(theta/2) <= delta theta kappa / 2. So
//     R = rho Sum_edges (delta_a + delta_b) theta kappa / 2,
//   rho the largest "density" of Sigma: 1 for the solid angles (Sigma = Omega), 2 for the cosine
//   (Sigma = 2 int z), 3 for the squared cosine (Sigma = 3 int z^2).
// * C, the terms computed from the rounded unit vertices (absolute errors, in units of u):
//   - eq. (11) edge term t = theta (a x b) / |a x b|, |t| = theta: c = a.b errs by 3;
//     stable_cross a x (b -+ a) by 6 |a x b| (b -+ a 1, products and difference 2, relative to
//     |a| |b -+ a| <= sqrt 2 |a x b|); s = |a x b| by 8 s (6 + dot and sqrt 2); theta = atan2(s, c)
//     by theta (8 c s / theta + 3 s / theta + 1) <= 12 theta; the unit vector (a x b) / s keeps
//     6 (its perpendicular part) + 2 (length rounding); division and product 2: <= 22 theta,
//     times kappa for safety on long edges;
//   - Arvo's second-moment edge term (a x b).z / s |b - a| (a + b).z / |a + b| (<= |b - a|
//     <= theta): the first factor errs by 6 + 8 + 1 = 15, |b - a| by 3 |b - a| relative, plus 4
//     absolute from the length errors of a and b, the third factor by 1 + 3 + 1 = 5, two
//     products 2: <= 25 theta + 4;
//   - Van Oosterom triangle (q, a, b) = 2 atan2(y, x), fanned from the first vertex q for the
//     unclipped solid angle: y = (q - a).(a x (b -+ a)), x = 1 + q.a + q.b + a.b,
//     |dy| <= 9 |q - a| |b -+ a| (q - a 1, cross 4.3, dot 3), |dx| <= 27 (three dots of
//     near-unit vectors 3 + 2 each, three additions on |x| <= 4: 12); fanned from the pole z for
//     the clipped ones (pole_triangle_solid_angle): y = (a x (b -+ a)).z, x = 1 + a.z + b.z + a.b,
//     |dy| <= 6 |b -+ a|, |dx| <= 21 (one dot 3, lengths 6, three additions 12);
//     then |d Omega_t| <= 2 (|x| |dy| + |y| |dx|) / (x^2 + y^2) + 2 |Omega_t| (atan2 and x2).
// * (m + 1) Sum|terms|: recursive summation of the m per-edge terms (for the squared cosine each
//   edge adds a triangle and an edge term: one more addition per edge, hence m + 1);
// * 3u |I|: the final division by the rounded 2 pi or 4 pi.
// These are worst-case first-order counts (every rounding error aligned), so the bound is
// pessimistic: the measured errors (printed at the end of the test cases) are 10 to 50 times
// below it. The float checks are therefore sensitive to gross errors only (a relative bias of
// 1e-6 passes them); the double checks catch relative errors down to ~3e-14.

enum class form { sphere, hemisphere, cosine, squared, cosine_unclipped };

form form_of(int id) {
    switch (id) {
        case sphere: return form::sphere;
        case hemisphere: return form::hemisphere;
        case cosine: return form::cosine;
        default: return form::squared;
    }
}

double angle(const dvec3& a, const dvec3& b) { return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)); }
double kappa(double theta) { return theta > 1e-8 ? theta / std::sin(theta) : 1.0; }

struct unit_vertex {
    dvec3 w;
    double delta;  // direction error in units of u
};

struct bound_parts {
    double region = 0, terms = 0, summation = 0, norm = 1;
};

/// q: the polygon in D_o space, in double; d: input direction errors per vertex in units of u
/// (empty: exact input), to which `normalize` is added for the normalization of the vertices.
bound_parts rounding_parts(form f, const poly_t& q, const std::vector<double>& d, double normalize) {
    std::vector<unit_vertex> in;
    for (std::size_t i = 0; i < q.size(); ++i)
        in.push_back({glm::normalize(q[i]), (d.empty() ? 0.0 : d[i]) + normalize});
    std::vector<unit_vertex> w;  // the polygon the library sums over
    const bool clip = f != form::sphere && f != form::cosine_unclipped;
    if (!clip) {
        w = in;
    } else {
        for (std::size_t i = 0; i < in.size(); ++i) {
            const unit_vertex& p = in[i];
            const unit_vertex& n = in[(i + 1) % in.size()];
            const bool p_in = p.w.z >= 0, n_in = n.w.z >= 0;
            if (p_in != n_in) {
                const unit_vertex& a = p_in ? p : n;
                const unit_vertex& b = p_in ? n : p;
                dvec3 x = a.w * (-b.w.z) + b.w * a.w.z;
                x.z = 0;
                w.push_back({glm::normalize(x), (std::max(a.delta, b.delta) + 4) * kappa(angle(a.w, b.w))});
            }
            if (n_in) w.push_back(n);
        }
    }
    const std::size_t m = w.size();
    bound_parts parts;
    parts.norm = f == form::sphere ? 4 * kPi : 2 * kPi;
    if (m < 3) return parts;  // nothing above the horizon: the library returns exactly 0
    const double rho = f == form::cosine || f == form::cosine_unclipped ? 2 : (f == form::squared ? 3 : 1);
    double region = 0, terms = 0, sum_abs = 0;
    const dvec3 q0 = w[0].w;
    for (std::size_t i = 0; i < m; ++i) {
        const dvec3 a = w[i].w, b = w[(i + 1) % m].w;
        const double th = angle(a, b), k = kappa(th);
        region += rho * (w[i].delta + w[(i + 1) % m].delta) * th * k / 2;
        if (f == form::cosine || f == form::cosine_unclipped) {
            terms += 22 * th * k;
            sum_abs += th;
        }
        if (f == form::squared) {
            terms += 25 * th + 4;
            sum_abs += glm::length(b - a);
        }
        if (f != form::cosine && f != form::cosine_unclipped) {
            // apex: the first vertex (unclipped solid angle) or the pole (clipped ones)
            const dvec3 apex = clip ? dvec3(0, 0, 1) : q0;
            const double ab = glm::dot(a, b);
            const double y = glm::dot(apex - a, glm::cross(a, ab >= 0 ? b - a : b + a));
            const double x = 1 + glm::dot(apex, a) + glm::dot(apex, b) + ab;
            const double r2 = x * x + y * y;
            const double omega = 2 * std::atan2(y, x);
            const double dy = clip ? 6 * glm::length(ab >= 0 ? b - a : b + a)
                                   : 9 * glm::length(q0 - a) * glm::length(ab >= 0 ? b - a : b + a);
            const double dx = clip ? 21 : 27;
            if (r2 > 0) terms += 2 * (std::abs(x) * dy + std::abs(y) * dx) / r2;
            terms += 2 * std::abs(omega);
            sum_abs += std::abs(omega);
        }
    }
    parts.region = region;
    parts.terms = terms;
    parts.summation = double(m + 1) * sum_abs;
    return parts;
}

/// The first-order bound on |computed - exact| for the closed form of magnitude `value`.
double rounding_bound(form f, const poly_t& q, const std::vector<double>& d, double u, double value) {
    const bound_parts b = rounding_parts(f, q, d, 2);
    if (b.region == 0 && b.terms == 0) return 0;
    return u * (b.region + b.terms + b.summation) / b.norm + 3 * u * std::abs(value);
}

/// The change of the exact integral when every vertex direction of q moves by up to delta u
/// (the region term alone): the error of a reference whose input polygon is rounded.
double region_bound(form f, const poly_t& q, double delta, double u) {
    const bound_parts b = rounding_parts(f, q, {}, delta);
    return u * b.region / b.norm;
}

/// d_i of rounding_bound for the vertices M^-1 p_i that transformed<> computes in T, in units of
/// u: m_inv * (p / s) is 1 division and a 3-term dot product per component, so each component is
/// off by <= 4u (|M^-1| |p|)_i / s, a direction error <= 4u kappa_p with the condition ratio
/// kappa_p = | |M^-1| |p| | / |M^-1 p|; plus the difference between the M^-1 the library stores
/// (inverse_matrix(), rounded in T) and the exact one, projected orthogonally to M^-1 p (a
/// common scale factor does not change directions).
std::vector<double> transformed_input_error(const dmat3& m_inv_exact, const dmat3& m_inv_used, const poly_t& p,
                                            double u) {
    std::vector<double> d;
    const dmat3 abs_m(glm::abs(m_inv_exact[0]), glm::abs(m_inv_exact[1]), glm::abs(m_inv_exact[2]));
    const dmat3 delta = m_inv_used - m_inv_exact;
    for (const dvec3& x : p) {
        const dvec3 q = m_inv_exact * x;
        const double lq = glm::length(q);
        const double kappa_p = glm::length(abs_m * glm::abs(x)) / lq;
        const dvec3 dq = delta * x;
        const dvec3 qh = q / lq;
        const double perp = glm::length(dq - glm::dot(dq, qh) * qh) / lq;
        d.push_back(4 * kappa_p + perp / u);
    }
    return d;
}

template <typename T>
constexpr double unit_roundoff() {
    return std::numeric_limits<T>::epsilon() / 2;
}

// ---------------------------------------------------------------------------------------------
// Measured errors, printed once per test case.

struct error_stats {
    // [distribution][0: float, 1: double]
    double max_rel[4][2] = {};      // max |closed - brute| / |brute|, all polygons
    double max_rel_big[4][2] = {};  // the same over the polygons with brute >= 1e-3
    double max_abs[4][2] = {};      // max |closed - brute|
    double max_ratio[4][2] = {};    // max |closed - brute| / tolerance (asserted <= 1)
    double max_bound[4][2] = {};    // max |closed - brute| / rounding bound (informative)

    void add(int id, int t, double closed, double brute, double tol, double bound) {
        const double err = std::abs(closed - brute);
        if (brute > 0) max_rel[id][t] = std::max(max_rel[id][t], err / brute);
        if (brute >= 1e-3) max_rel_big[id][t] = std::max(max_rel_big[id][t], err / brute);
        max_abs[id][t] = std::max(max_abs[id][t], err);
        max_ratio[id][t] = std::max(max_ratio[id][t], err / tol);
        if (bound > 0) max_bound[id][t] = std::max(max_bound[id][t], err / bound);
    }

    void print(const char* title) const {
        std::ostringstream s;
        s << "\n"
          << title << "\n"
          << "  rel = max |closed - brute| / brute; rel(I>=1e-3) over integrals >= 1e-3; abs = max |closed - brute|;\n"
          << "  err/tol <= 1 is asserted (tol = brute-force estimate + rounding bound); err/bound: bound alone\n";
        s << "  " << std::left << std::setw(24) << "distribution" << std::setw(7) << "type" << std::right
          << std::setw(10) << "rel" << std::setw(15) << "rel(I>=1e-3)" << std::setw(10) << "abs" << std::setw(9)
          << "err/tol" << std::setw(11) << "err/bound"
          << "\n";
        for (int id = 0; id < 4; ++id)
            for (int t = 0; t < 2; ++t) {
                s << "  " << std::left << std::setw(24) << dist_names[id] << std::setw(7) << (t ? "double" : "float")
                  << std::right << std::scientific << std::setprecision(2) << std::setw(10) << max_rel[id][t]
                  << std::setw(15) << max_rel_big[id][t] << std::setw(10) << max_abs[id][t] << std::fixed
                  << std::setprecision(3) << std::setw(9) << max_ratio[id][t] << std::setw(11) << max_bound[id][t]
                  << "\n";
            }
        std::cout << s.str() << std::flush;
    }
};

// Closed form vs brute force for one distribution, one type, plus the sign of the signed form.
template <typename T>
void check_original(int id, const poly_t& p, const ltc_test::brute_force_result<4>& bf, error_stats& stats) {
    const double u = unit_roundoff<T>();
    const double closed = closed_form<T>(id, p);
    const double brute = bf.value[id];
    // tolerance = quadrature estimate + first-order rounding bound of the closed form
    const double bound = rounding_bound(form_of(id), p, {}, u, brute);
    const double tol = bf.error[id] + bound;
    const std::string polygon = str(p);
    const char* distribution = dist_names[id];
    const char* type = sizeof(T) == 4 ? "float" : "double";
    CAPTURE(distribution, type, polygon, closed, brute, bf.error[id], tol);
    CHECK(std::abs(closed - brute) <= tol);
    stats.add(id, sizeof(T) == 4 ? 0 : 1, closed, brute, tol, bound);

    // The signed integral has the polygon's orientation sign (polygon.hpp's convention: positive
    // when dot(p, N) > 0 for N the oriented area vector, p on the plane) wherever it is not 0.
    const double s = closed_form_signed<T>(id, p);
    CAPTURE(s, bound);
    CHECK(std::abs(std::abs(s) - closed) == 0);
    if (brute > bound) CHECK((s > 0 ? 1 : -1) == ltc_test::orientation_sign(p, p[0]));
}

}  // namespace

// =============================================================================================

TEST_CASE("original distributions: closed-form polygon integrals equal a brute-force integration",
          "[integration][original]") {
    ltc_test::rng r(0x5eed0001);
    error_stats stats;
    int crossing = 0, positive = 0, nonconvex = 0;
    for (int i = 0; i < 200; ++i) {
        ltc_test::polygon_options o;
        o.cross_horizon = i % 2 == 1;          // half of them cross the horizon
        o.orientation = (i / 2) % 2 ? -1 : 1;  // both windings, for both kinds
        const ltc_test::test_polygon tp = ltc_test::random_polygon(r, o);
        crossing += o.cross_horizon;
        positive += o.orientation > 0;
        // count non-convex polygons (a reflex vertex: the turn differs from the orientation)
        const dvec3 n = ltc_test::area_vector(tp.v);
        bool reflex = false;
        for (std::size_t k = 0; k < tp.v.size(); ++k) {
            const dvec3 a = tp.v[k], b = tp.v[(k + 1) % tp.v.size()], c = tp.v[(k + 2) % tp.v.size()];
            reflex = reflex || glm::dot(glm::cross(b - a, c - b), n) < 0;
        }
        nonconvex += reflex;

        const auto bf = ltc_test::integrate_polygon<4>(tp.v, tp.kernel, dvec3(0, 0, 1), reference_densities);
        REQUIRE(bf.converged);
        for (int id = 0; id < 4; ++id) {
            check_original<float>(id, tp.v, bf, stats);
            check_original<double>(id, tp.v, bf, stats);
        }
    }
    CHECK(crossing == 100);
    CHECK(positive == 100);
    CHECK(nonconvex > 20);   // the generator does produce non-convex polygons
    CHECK(nonconvex < 180);  // ... and convex ones
    static bool printed = false;
    if (!printed) stats.print("original distributions (200 random polygons)"), printed = true;
}

namespace {

struct named_matrix {
    const char* name;
    dmat3 m;  // GLM column-major, entries exactly representable in float
};

std::vector<named_matrix> test_matrices() {
    // rotation by 1 rad about (1, 2, 3) / |(1, 2, 3)| (Rodrigues), written column-major
    const dvec3 k = glm::normalize(dvec3(1, 2, 3));
    const double c = std::cos(1.0), s = std::sin(1.0);
    const dmat3 kx(0, k.z, -k.y, -k.z, 0, k.x, k.y, -k.x, 0);  // columns of [k]_x
    const dmat3 rot = dmat3(1) * c + kx * s + glm::outerProduct(k, k) * (1 - c);
    return {
        // The supplement's example, printed row-major: M = [0.1 0.5 1; 0.2 1 1; 0 2 0.5].
        {"supplement", row_major(0.1, 0.5, 1, 0.2, 1, 1, 0, 2, 0.5)},
        {"rotation", dmat3(glm::mat3(rot))},
        {"near-identity", row_major(1.001, 0.0005, -0.0007, -0.0003, 0.9992, 0.0004, 0.0006, -0.0002, 1.0009)},
        // GGX-like fit matrix [a 0 b; 0 c 0; d 0 1] of a rough-to-sharp lobe
        {"ggx-like", row_major(0.05, 0, -0.02, 0, 0.05, 0, 0.3, 0, 1)},
        {"anisotropic", row_major(0.2, 0, 0.1, 0, 0.6, 0, -0.4, 0, 1)},
        // det < 0 (about -0.991): M flips orientations
        {"negative-det", row_major(1, 0.2, 0.1, 0.3, -0.7, 0.2, -0.1, 0.4, 1.2)},
    };
}

template <typename Dist>
struct transformed_check {
    using T = typename Dist::scalar;
    // Checks transformed<Dist> built both ways against the two brute-force references.
    static void run(int id, const named_matrix& nm, const dmat3& m_inv, const ltc_test::test_polygon& tp,
                    const ltc_test::brute_force_result<4>& over_p, const ltc_test::brute_force_result<4>& over_mp,
                    double region_mp, error_stats& stats) {
        using mat = glm::mat<3, 3, T>;
        const double u = unit_roundoff<T>();
        const auto v = to<T>(tp.v);
        const auto vr = to<T>(reversed(tp.v));
        const poly_t q = transform(m_inv, tp.v);  // M^-1 P, in double
        const poly_t qr = transform(m_inv, reversed(tp.v));
        const ltc::transformed<Dist> constructions[2] = {
            ltc::transformed<Dist>(mat(nm.m)),
            ltc::transformed<Dist>::from_inverse(mat(glm::inverse(nm.m))),
        };
        const char* const construction_names[2] = {"transformed(M)", "from_inverse(inverse(M))"};
        double closed_by[2] = {0, 0}, bound_by[2] = {0, 0};
        for (int c = 0; c < 2; ++c) {
            const auto& d = constructions[c];
            const dmat3 used(d.inverse_matrix());
            const double bound =
                rounding_bound(form_of(id), q, transformed_input_error(m_inv, used, tp.v, u), u, over_p.value[id]);
            const double bound_r = rounding_bound(
                form_of(id), qr, transformed_input_error(m_inv, used, reversed(tp.v), u), u, over_p.value[id]);
            const double closed = d.integrate(v.data(), v.size());
            const double signed_value = d.integrate_signed(v.data(), v.size());
            const double signed_reversed = d.integrate_signed(vr.data(), vr.size());
            // tolerance = quadrature estimate of the reference + rounding bound (see rounding_bound)
            const double tol_p = over_p.error[id] + bound;
            const double tol_mp = over_mp.error[id] + region_mp + bound;
            const std::string polygon = str(tp.v), matrix = str(nm.m);
            const char* distribution = dist_names[id];
            const char* type = sizeof(T) == 4 ? "float" : "double";
            const char* construction = construction_names[c];
            CAPTURE(distribution, type, construction, matrix, polygon, closed, over_p.value[id], over_mp.value[id],
                    tol_p, tol_mp, signed_value, signed_reversed, bound, bound_r);
            // (i) brute force of D over P and (ii) of D_o over M^-1 P
            CHECK(std::abs(closed - over_p.value[id]) <= tol_p);
            CHECK(std::abs(closed - over_mp.value[id]) <= tol_mp);
            stats.add(id, sizeof(T) == 4 ? 0 : 1, closed, over_p.value[id], tol_p, bound);
            // the sign refers to P's own orientation, whatever the sign of det M
            CHECK(std::abs(signed_value) == closed);
            if (over_p.value[id] > bound)
                CHECK((signed_value > 0 ? 1 : -1) == ltc_test::orientation_sign(tp.v, tp.kernel));
            // reversing the winding flips the sign (the two are computed from different fans)
            CHECK(std::abs(signed_value + signed_reversed) <= bound + bound_r);
            // sidedness
            CHECK(d.integrate(v.data(), v.size(), ltc::sidedness::two_sided) == closed);
            CHECK(d.integrate(v.data(), v.size(), ltc::sidedness::one_sided) == std::max<T>(T(signed_value), T(0)));
            closed_by[c] = closed;
            bound_by[c] = bound;
        }
        // both constructions give the same distribution (each within its own rounding bound)
        CAPTURE(closed_by[0], closed_by[1], bound_by[0], bound_by[1]);
        CHECK(std::abs(closed_by[0] - closed_by[1]) <= bound_by[0] + bound_by[1]);
    }
};

template <typename T>
void run_transformed(int id, const named_matrix& nm, const dmat3& m_inv, const ltc_test::test_polygon& tp,
                     const ltc_test::brute_force_result<4>& over_p, const ltc_test::brute_force_result<4>& over_mp,
                     double region_mp, error_stats& stats) {
    switch (id) {
        case sphere:
            transformed_check<ltc::uniform_sphere<T>>::run(id, nm, m_inv, tp, over_p, over_mp, region_mp, stats);
            break;
        case hemisphere:
            transformed_check<ltc::uniform_hemisphere<T>>::run(id, nm, m_inv, tp, over_p, over_mp, region_mp, stats);
            break;
        case cosine:
            transformed_check<ltc::clamped_cosine<T>>::run(id, nm, m_inv, tp, over_p, over_mp, region_mp, stats);
            break;
        default:
            transformed_check<ltc::squared_clamped_cosine<T>>::run(id, nm, m_inv, tp, over_p, over_mp, region_mp,
                                                                   stats);
    }
}

}  // namespace

TEST_CASE("transformed distributions: closed form equals brute force of D over P and of D_o over M^-1 P",
          "[integration][transformed]") {
    ltc_test::rng r(0x5eed0002);
    error_stats stats;
    for (const named_matrix& nm : test_matrices()) {
        const dmat3 m_inv = glm::inverse(nm.m);
        const double abs_det_inv = std::abs(glm::determinant(m_inv));
        const dvec3 h = transformed_horizon(m_inv);
        // h is the third row of M^-1: <h, w> = (M^-1 w).z, so D's kink or jump is on <w, h> = 0
        const dvec3 w(0.3, -0.5, 0.8);
        REQUIRE(std::abs(glm::dot(h, w) - (m_inv * w).z) <= 1e-14 * glm::length(m_inv * w));
        const auto density = [&](const dvec3& w, double s) { return reference_transformed(m_inv, abs_det_inv, w, s); };
        const ltc_test::brute_force_options options_p = transformed_options(nm.m, m_inv);
        for (int i = 0; i < 40; ++i) {
            ltc_test::polygon_options o;
            o.cross_plane = i % 2 == 1;  // half of them cross the transformed horizon
            o.plane_normal = h;
            o.orientation = (i / 2) % 2 ? -1 : 1;
            const ltc_test::test_polygon tp = ltc_test::random_polygon(r, o);
            const auto over_p = ltc_test::integrate_polygon<4>(tp.v, tp.kernel, h, density, options_p);
            const poly_t q = accurate_transform(m_inv, tp.v);
            const auto over_mp =
                ltc_test::integrate_polygon<4>(q, m_inv * tp.kernel, dvec3(0, 0, 1), reference_densities);
            REQUIRE(over_p.converged);
            REQUIRE(over_mp.converged);
            for (int id = 0; id < 4; ++id) {
                // the supplement's identity: int_P D = int_{M^-1 P} D_o
                const char* distribution = dist_names[id];
                const std::string polygon = str(tp.v), matrix = str(nm.m);
                // tolerance: both estimates, plus the effect of rounding M^-1 P to 1u per component
                // (a direction error <= 1u per vertex: region_bound)
                const double region_mp = region_bound(form_of(id), q, 1, unit_roundoff<double>());
                CAPTURE(distribution, matrix, polygon, over_p.value[id], over_mp.value[id], over_p.error[id],
                        over_mp.error[id], region_mp);
                CHECK(std::abs(over_p.value[id] - over_mp.value[id]) <=
                      over_p.error[id] + over_mp.error[id] + region_mp);
                run_transformed<float>(id, nm, m_inv, tp, over_p, over_mp, region_mp, stats);
                run_transformed<double>(id, nm, m_inv, tp, over_p, over_mp, region_mp, stats);
            }
        }
    }
    static bool printed = false;
    if (!printed)
        stats.print("transformed distributions (6 matrices x 40 random polygons, 2 constructions)"), printed = true;
}

TEST_CASE("the supplement's example triangle: exact value 0.00589055 by brute force and closed form",
          "[integration][transformed]") {
    // M = [0.1 0.5 1; 0.2 1 1; 0 2 0.5] is printed row-major; GLM is column-major, hence the
    // transpose. The supplement prints 0.0059141 for this triangle: that is its 401 x 401 Riemann
    // sum, 0.4% high (reproduced and explained in test_supplement.cpp); the exact value is
    // 0.0058905479..., which both brute-force integrations and the closed form give here.
    const dmat3 m = glm::transpose(dmat3(0.1, 0.5, 1, 0.2, 1, 1, 0, 2, 0.5));
    const poly_t p = {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}};
    const dmat3 m_inv = glm::inverse(m);
    const double abs_det_inv = std::abs(glm::determinant(m_inv));
    const dvec3 kernel = (p[0] + p[1] + p[2]) / 3.0;
    const auto over_p = ltc_test::integrate_polygon<4>(
        p, kernel, transformed_horizon(m_inv),
        [&](const dvec3& w, double s) { return reference_transformed(m_inv, abs_det_inv, w, s); },
        transformed_options(m, m_inv));
    const poly_t q = accurate_transform(m_inv, p);
    const auto over_mp = ltc_test::integrate_polygon<4>(q, m_inv * kernel, dvec3(0, 0, 1), reference_densities);
    const auto vd = to<double>(p);
    const auto vf = to<float>(p);
    const ltc::transformed<ltc::clamped_cosine<double>> dd(m);
    const ltc::transformed<ltc::clamped_cosine<float>> df{glm::mat3(m)};
    const double closed_d = dd.integrate(vd.data(), 3);
    const double closed_f = df.integrate(vf.data(), 3);
    // tolerances: brute-force estimates + region_bound of the rounded M^-1 P + rounding bounds
    // (the float M is glm::mat3(m), whose entries are not those of m: compare the float closed
    // form with the exact value for glm::mat3(m) instead, by its own brute force)
    const double ud = unit_roundoff<double>();
    const double region = region_bound(form::cosine, q, 1, ud);
    const double bound_d = rounding_bound(
        form::cosine, q, transformed_input_error(m_inv, dmat3(dd.inverse_matrix()), p, ud), ud, over_p.value[cosine]);
    CAPTURE(over_p.value[cosine], over_mp.value[cosine], over_p.error[cosine], over_mp.error[cosine], closed_d,
            closed_f, bound_d);
    CHECK(std::abs(over_p.value[cosine] - over_mp.value[cosine]) <=
          over_p.error[cosine] + over_mp.error[cosine] + region);
    CHECK(std::abs(closed_d - over_p.value[cosine]) <= over_p.error[cosine] + bound_d);
    CHECK(std::abs(closed_d - over_mp.value[cosine]) <= over_mp.error[cosine] + region + bound_d);
    {
        const dmat3 mf = dmat3(glm::mat3(m));
        const dmat3 mf_inv = glm::inverse(mf);
        const double adf = std::abs(glm::determinant(mf_inv));
        const auto ref_f = ltc_test::integrate_polygon<4>(
            p, kernel, transformed_horizon(mf_inv),
            [&](const dvec3& w, double s) { return reference_transformed(mf_inv, adf, w, s); },
            transformed_options(mf, mf_inv));
        const double uf = unit_roundoff<float>();
        const double bound_f =
            rounding_bound(form::cosine, transform(mf_inv, p),
                           transformed_input_error(mf_inv, dmat3(df.inverse_matrix()), p, uf), uf, ref_f.value[cosine]);
        CAPTURE(ref_f.value[cosine], bound_f);
        CHECK(std::abs(closed_f - ref_f.value[cosine]) <= ref_f.error[cosine] + bound_f);
    }
    // five significant digits of the exact value, and the printed Riemann sum is 0.4% above it
    CHECK(std::abs(closed_d - 0.0058905) <= 0.5e-7);
    CHECK((0.0059141 - closed_d) / closed_d == Approx(0.004).margin(0.0005));
    // the untransposed matrix is another distribution: the convention matters
    const double wrong =
        ltc::transformed<ltc::clamped_cosine<double>>(dmat3(0.1, 0.5, 1, 0.2, 1, 1, 0, 2, 0.5)).integrate(vd.data(), 3);
    CAPTURE(wrong);
    CHECK(std::abs(wrong - closed_d) > 1e-4);
}

// =============================================================================================
// Conventions of polygon.hpp.

TEST_CASE("sign convention: signed integrals are positive when dot(p0, (p1 - p0) x (p2 - p0)) > 0", "[polygon][sign]") {
    ltc_test::rng r(0x5eed0003);
    for (int i = 0; i < 50; ++i) {
        // convex polygons (all radii equal), where the header's literal formula applies
        ltc_test::polygon_options o;
        o.above_horizon = true;
        ltc_test::test_polygon tp = ltc_test::random_polygon(r, o);
        // make it convex: project every vertex onto the circle of radius 1 around the kernel
        const dvec3 c = tp.kernel;
        for (dvec3& v : tp.v) {
            const dvec3 d = v - c - glm::dot(v - c, tp.normal) * tp.normal;
            v = dvec3(glm::vec3(c + glm::normalize(d)));
        }
        if (!std::all_of(tp.v.begin(), tp.v.end(), [](const dvec3& v) { return v.z > 0; })) continue;
        const poly_t& p = tp.v;
        const double literal = glm::dot(p[0], glm::cross(p[1] - p[0], p[2] - p[0]));
        const int sign = literal > 0 ? 1 : -1;
        const auto vd = to<double>(p);
        const auto vf = to<float>(p);
        const std::string polygon = str(p);
        CAPTURE(polygon, literal);
        CHECK(sign == ltc_test::orientation_sign(p, c));
        CHECK(ltc::solid_angle(vd.data(), vd.size()) * sign > 0);
        CHECK(ltc::solid_angle(vf.data(), vf.size()) * sign > 0);
        CHECK(ltc::clipped_solid_angle(vd.data(), vd.size()) * sign > 0);
        CHECK(ltc::form_factor_signed(vd.data(), vd.size()) * sign > 0);
        CHECK(ltc::form_factor_signed(vf.data(), vf.size()) * sign > 0);
        CHECK(ltc::vector_form_factor(vd.data(), vd.size()).z * sign > 0);
        for (int id = 0; id < 4; ++id) {
            CHECK(closed_form_signed<double>(id, p) * sign > 0);
            CHECK(closed_form_signed<float>(id, p) * sign > 0);
            CHECK(closed_form_signed<double>(id, reversed(p)) * sign < 0);
        }
    }
}

TEST_CASE("form_factor: one-sided is max(0, signed), two-sided is |signed|", "[polygon][sidedness]") {
    ltc_test::rng r(0x5eed0004);
    for (int i = 0; i < 40; ++i) {
        ltc_test::polygon_options o;
        o.cross_horizon = i % 2 == 1;
        o.orientation = 1;
        const ltc_test::test_polygon tp = ltc_test::random_polygon(r, o);
        for (const poly_t& p : {tp.v, reversed(tp.v)}) {
            const auto v = to<float>(p);
            const float s = ltc::form_factor_signed(v.data(), v.size());
            CAPTURE(s);
            CHECK(ltc::form_factor(v.data(), v.size(), ltc::sidedness::one_sided) == std::max(s, 0.0f));
            CHECK(ltc::form_factor(v.data(), v.size(), ltc::sidedness::two_sided) == std::abs(s));
            CHECK(ltc::apply_sidedness(-s, ltc::sidedness::one_sided) == std::max(-s, 0.0f));
        }
        const auto v = to<double>(tp.v);
        const auto vr = to<double>(reversed(tp.v));
        const double s = ltc::form_factor_signed(v.data(), v.size());
        if (s != 0) {
            // the polygon faces the shading point: the one-sided emitter shows, reversed it does not
            CHECK(s > 0);
            CHECK(ltc::form_factor(v.data(), v.size(), ltc::sidedness::one_sided) == s);
            CHECK(ltc::form_factor(vr.data(), vr.size(), ltc::sidedness::one_sided) == 0);
            CHECK(ltc::form_factor(vr.data(), vr.size(), ltc::sidedness::two_sided) > 0);
        }
    }
}

TEST_CASE("clip_to_horizon", "[polygon][clip]") {
    SECTION("a triangle with one vertex below: 4 vertices, crossing points exactly on z = 0") {
        const glm::dvec3 in[3] = {{0, 1, 1}, {1, 1, -1}, {-1, 1, 2}};
        glm::dvec3 out[ltc::clipped_capacity(3)];
        REQUIRE(ltc::clip_to_horizon(in, 3, out) == 4);
        // the order is kept: v0, crossing on 0 -> 1, crossing on 1 -> 2, v2
        CHECK(out[0] == in[0]);
        CHECK(out[1].z == 0);
        CHECK(out[2].z == 0);
        CHECK(out[3] == in[2]);
        CHECK(glm::length(glm::cross(out[1] - in[0], in[1] - in[0])) < 1e-15);  // on the edges
        CHECK(glm::length(glm::cross(out[2] - in[1], in[2] - in[1])) < 1e-15);
    }
    SECTION("fully above, fully below, n < 3, a vertex on the horizon") {
        const glm::vec3 above[3] = {{0, 0, 1}, {1, 0, 1}, {0, 1, 2}};
        const glm::vec3 below[3] = {{0, 0, -1}, {1, 0, -1}, {0, 1, -2}};
        const glm::vec3 touching[3] = {{1, 0, 0}, {1, 1, -1}, {0, 1, 2}};
        glm::vec3 out[ltc::clipped_capacity(3)];
        // a polygon above the horizon is copied unchanged
        CHECK(ltc::clip_to_horizon(above, 3, out) == 3);
        CHECK((out[0] == above[0] && out[1] == above[1] && out[2] == above[2]));
        CHECK(ltc::clip_to_horizon(below, 3, out) == 0);
        CHECK(ltc::clip_to_horizon(above, 2, out) == 0);
        CHECK(ltc::form_factor_signed(below, 3) == 0);
        CHECK(ltc::clipped_solid_angle(below, 3) == 0);
        // a vertex on z = 0 counts as inside; the crossing on its outgoing edge is the vertex
        // itself (a zero-length edge, which contributes 0)
        REQUIRE(ltc::clip_to_horizon(touching, 3, out) == 4);
        CHECK(out[0] == touching[0]);
        CHECK(out[1] == touching[0]);
        CHECK(out[2].z == 0);
        CHECK(out[3] == touching[2]);
    }
    SECTION("a non-convex star crossing the horizon three times") {
        // 12-gon star in the plane y = 1 around (0, 1, 0.5): spikes of radius 2 every 60 degrees,
        // inner vertices of radius 0.4 between them. The spikes at 210, 270 and 330 degrees
        // dip below the horizon, the inner vertices between them stay above: three runs below.
        poly_t p;
        const dvec3 c(0, 1, 0.5);
        for (int k = 0; k < 12; ++k) {
            const double a = kPi / 6 * (k + 1) - kPi / 6 * 2;  // k = 0: -30 degrees (a spike)
            const double rad = k % 2 == 0 ? 2 : 0.4;
            p.push_back(dvec3(glm::vec3(c + rad * dvec3(std::cos(a), 0, std::sin(a)))));
        }
        int below = 0;
        for (const dvec3& v : p) below += v.z < 0;
        REQUIRE(below == 3);
        const auto v = to<double>(p);
        std::vector<dvec3> out(ltc::clipped_capacity(p.size()));
        const std::size_t m = ltc::clip_to_horizon(v.data(), v.size(), out.data());
        CHECK(m == 12 - 3 + 2 * 3);
        REQUIRE(m <= ltc::clipped_capacity(12));
        int on_horizon = 0;
        for (std::size_t i = 0; i < m; ++i) {
            CHECK(out[i].z >= 0);
            on_horizon += out[i].z == 0;
        }
        CHECK(on_horizon == 6);
        // Integrals of the clipped polygon without clipping equal the clipped integrals of the
        // original (the back-and-forth edges along z = 0 cancel); and both equal the brute force.
        const double ff = ltc::form_factor_signed(v.data(), v.size());
        const double ff_clipped = ltc::vector_form_factor(out.data(), m).z;
        const double omega = ltc::clipped_solid_angle(v.data(), v.size());
        const double omega_clipped = ltc::solid_angle(out.data(), m);
        const auto bf = ltc_test::integrate_polygon<4>(p, c, dvec3(0, 0, 1), reference_densities);
        const double u = unit_roundoff<double>();
        const poly_t clipped(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(m));
        // tolerances: rounding bounds of both closed forms (+ the quadrature estimate)
        const double b_ff = rounding_bound(form::cosine, p, {}, u, std::abs(ff)) +
                            rounding_bound(form::cosine_unclipped, clipped, {}, u, std::abs(ff));
        const double b_om = 2 * kPi *
                            (rounding_bound(form::hemisphere, p, {}, u, std::abs(omega) / (2 * kPi)) +
                             rounding_bound(form::sphere, clipped, {}, u, std::abs(omega) / (4 * kPi)) * 2);
        CAPTURE(ff, ff_clipped, omega, omega_clipped, bf.value[cosine], bf.value[hemisphere], b_ff, b_om);
        CHECK(std::abs(ff - ff_clipped) <= b_ff);
        CHECK(std::abs(omega - omega_clipped) <= b_om);
        CHECK(std::abs(std::abs(ff) - bf.value[cosine]) <= bf.error[cosine] + b_ff);
        CHECK(std::abs(std::abs(omega) / (2 * kPi) - bf.value[hemisphere]) <= bf.error[hemisphere] + b_om / (2 * kPi));
    }
    SECTION("random polygons: the clipped vertex count follows the runs below the horizon") {
        ltc_test::rng r(0x5eed0005);
        for (int i = 0; i < 100; ++i) {
            ltc_test::polygon_options o;
            o.cross_horizon = true;
            const ltc_test::test_polygon tp = ltc_test::random_polygon(r, o);
            const auto v = to<float>(tp.v);
            std::vector<glm::vec3> out(ltc::clipped_capacity(v.size()));
            const std::size_t m = ltc::clip_to_horizon(v.data(), v.size(), out.data());
            std::size_t above = 0, sign_changes = 0;
            for (std::size_t k = 0; k < v.size(); ++k) {
                above += v[k].z >= 0;
                sign_changes += (v[k].z >= 0) != (v[(k + 1) % v.size()].z >= 0);
            }
            CHECK(m == above + sign_changes);
            for (std::size_t k = 0; k < m; ++k) CHECK(out[k].z >= 0);
        }
    }
}

TEST_CASE("vector_form_factor: z is the unclipped cosine integral, x and y its other moments",
          "[polygon][vector_form_factor]") {
    ltc_test::rng r(0x5eed0006);
    const double u = unit_roundoff<double>();
    for (int i = 0; i < 60; ++i) {
        ltc_test::polygon_options o;
        o.above_horizon = i % 2 == 0;
        o.cross_horizon = i % 2 == 1;
        const ltc_test::test_polygon tp = ltc_test::random_polygon(r, o);
        const auto v = to<double>(tp.v);
        const dvec3 f = ltc::vector_form_factor(v.data(), v.size());
        const int sign = ltc_test::orientation_sign(tp.v, tp.kernel);
        // F = 1/pi int w dw over the polygon (signed by orientation), with no clamping. The 4th
        // component, 1/pi, bounds the brute force's rounding for the others: a node direction
        // error delta changes w_k / pi by <= delta / pi (direction_condition 1 for it).
        ltc_test::brute_force_options bo;
        bo.direction_condition = 1;
        const auto bf = ltc_test::integrate_polygon<4>(
            tp.v, tp.kernel, dvec3(0),
            [](const dvec3& w, double) {
                return std::array<double, 4>{w.x / kPi, w.y / kPi, w.z / kPi, 1 / kPi};
            },
            bo);
        const double bf_round = bf.error[3] - bf.quadrature_error[3];
        const std::string polygon = str(tp.v);
        for (int k = 0; k < 3; ++k) {
            // the closed form's bound holds for any axis (the edge terms are vectors)
            const double tol =
                bf.error[k] + bf_round + rounding_bound(form::cosine_unclipped, tp.v, {}, u, std::abs(bf.value[k]));
            CAPTURE(polygon, k, f[k], bf.value[k], tol);
            CHECK(std::abs(f[k] * sign - bf.value[k]) <= tol);
        }
        if (o.above_horizon) {
            const double ff = ltc::form_factor_signed(v.data(), v.size());
            const double tol = 2 * rounding_bound(form::cosine, tp.v, {}, u, std::abs(ff));
            CAPTURE(polygon, ff, f.z, tol);
            CHECK(std::abs(f.z - ff) <= tol);
        }
    }
}

TEST_CASE("cube: each face subtends 4 pi / 6, and every distribution integrates to 1 over the six faces",
          "[polygon][integration][cube]") {
    // the faces of [-1, 1]^3, wound with the positive convention (clockwise seen from the centre)
    std::vector<poly_t> faces;
    for (int axis = 0; axis < 3; ++axis)
        for (const double side : {-1.0, 1.0}) {
            poly_t f;
            for (const auto& uv : {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)}) {
                dvec3 p;
                p[axis] = side;
                p[(axis + 1) % 3] = uv.x;
                p[(axis + 2) % 3] = uv.y;
                f.push_back(p);
            }
            if (glm::dot(f[0], glm::cross(f[1] - f[0], f[2] - f[0])) < 0) f = reversed(f);
            faces.push_back(f);
        }
    for (const poly_t& f : faces) {
        const auto vd = to<double>(f);
        const auto vf = to<float>(f);
        // tolerance: rounding bound of the solid angle (Omega = 4 pi I)
        const double bd = 4 * kPi * rounding_bound(form::sphere, f, {}, unit_roundoff<double>(), 1.0 / 6);
        const double bf = 4 * kPi * rounding_bound(form::sphere, f, {}, unit_roundoff<float>(), 1.0 / 6);
        const std::string face = str(f);
        CAPTURE(face, bd, bf);
        CHECK(std::abs(ltc::solid_angle(vd.data(), 4) - 4 * kPi / 6) <= bd);
        CHECK(std::abs(ltc::solid_angle(vf.data(), 4) - 4 * kPi / 6) <= bf);
    }
    // Sum over the faces: 1 for every distribution (they are normalized), original and
    // transformed. Tolerance: the sum of the faces' rounding bounds, plus 5 u_double for the
    // five additions done here in double.
    std::vector<named_matrix> ms = test_matrices();
    ms.insert(ms.begin(), named_matrix{"identity", dmat3(1)});
    for (const named_matrix& nm : ms) {
        const dmat3 m_inv = glm::inverse(nm.m);
        const dmat3 used_d(ltc::transformed<ltc::clamped_cosine<double>>(nm.m).inverse_matrix());
        const dmat3 used_f(ltc::transformed<ltc::clamped_cosine<float>>(glm::mat3(nm.m)).inverse_matrix());
        const double ud = unit_roundoff<double>(), uf = unit_roundoff<float>();
        for (int id = 0; id < 4; ++id) {
            double sum_f = 0, sum_d = 0, sum_of = 0, sum_od = 0, bound_f = 0, bound_d = 0, bound_of = 0, bound_od = 0;
            for (const poly_t& f : faces) {
                const auto vd = to<double>(f);
                const auto vf = to<float>(f);
                const poly_t q = transform(m_inv, f);
                double face_d = 0, face_f = 0;
                switch (id) {
                    case sphere:
                        face_d = ltc::transformed<ltc::uniform_sphere<double>>(nm.m).integrate(vd.data(), 4);
                        face_f = ltc::transformed<ltc::uniform_sphere<float>>(glm::mat3(nm.m)).integrate(vf.data(), 4);
                        break;
                    case hemisphere:
                        face_d = ltc::transformed<ltc::uniform_hemisphere<double>>(nm.m).integrate(vd.data(), 4);
                        face_f =
                            ltc::transformed<ltc::uniform_hemisphere<float>>(glm::mat3(nm.m)).integrate(vf.data(), 4);
                        break;
                    case cosine:
                        face_d = ltc::transformed<ltc::clamped_cosine<double>>(nm.m).integrate(vd.data(), 4);
                        face_f = ltc::transformed<ltc::clamped_cosine<float>>(glm::mat3(nm.m)).integrate(vf.data(), 4);
                        break;
                    default:
                        face_d = ltc::transformed<ltc::squared_clamped_cosine<double>>(nm.m).integrate(vd.data(), 4);
                        face_f = ltc::transformed<ltc::squared_clamped_cosine<float>>(glm::mat3(nm.m))
                                     .integrate(vf.data(), 4);
                }
                sum_d += face_d;
                sum_f += face_f;
                bound_d += rounding_bound(form_of(id), q, transformed_input_error(m_inv, used_d, f, ud), ud, face_d);
                bound_f += rounding_bound(form_of(id), q, transformed_input_error(m_inv, used_f, f, uf), uf, face_f);
                if (nm.name == std::string("identity")) {
                    const double od = closed_form<double>(id, f), of = closed_form<float>(id, f);
                    sum_od += od;
                    sum_of += of;
                    bound_od += rounding_bound(form_of(id), f, {}, ud, od);
                    bound_of += rounding_bound(form_of(id), f, {}, uf, of);
                }
            }
            const char* distribution = dist_names[id];
            const std::string matrix = str(nm.m);
            CAPTURE(distribution, matrix, sum_d, sum_f, bound_d, bound_f);
            CHECK(std::abs(sum_d - 1) <= bound_d + 5 * ud);
            CHECK(std::abs(sum_f - 1) <= bound_f + 5 * ud);
            if (nm.name == std::string("identity")) {
                CAPTURE(sum_od, sum_of, bound_od, bound_of);
                CHECK(std::abs(sum_od - 1) <= bound_od + 5 * ud);
                CHECK(std::abs(sum_of - 1) <= bound_of + 5 * ud);
            }
        }
    }
}
