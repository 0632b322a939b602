// Tests of ltc/shading/ggx_anisotropic_fetch.hpp and ltc/tables/anisotropic_table.hpp: the lookup
// at the nodes returns the table's nodes (the inverse of the stored M, the stored magnitude and
// Fresnel term), the nodes with alpha_x < alpha_y are the swap of the stored ones, the nodes on
// the mirror planes have the mirror's zeros, the lookup's symmetries (phi -> -phi mirrors y,
// phi -> pi - phi mirrors x, alpha_x <-> alpha_y with phi -> pi/2 - phi swaps x and y), its
// continuity across cells and quadrants (no jump beyond the slope on either side), the isotropic
// diagonal against ltc::ggx::fetch rotated by phi_v (within the sum of both fits' L1 errors), and
// degenerate input.
#include <ltc/brdf/ggx_anisotropic.hpp>
#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/fitting/fit_anisotropic.hpp>  // the node coordinates, the L1 estimator
#include <ltc/shading/ggx_anisotropic_fetch.hpp>
#include <ltc/shading/ggx_fetch.hpp>

#include <catch2/catch.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <limits>
#include <vector>

namespace ltc_test_ggx_anisotropic_fetch {  // the file's own names, apart from the other files of a unity batch

namespace {

using glm::dmat3;
using glm::dvec3;
constexpr double pi = 3.141592653589793;
const auto& table = ltc::ggx_anisotropic::table;
constexpr int n = ltc::tables::ggx_anisotropic_size;

double max_abs(const dmat3& m) {
    double r = 0;
    for (int c = 0; c < 3; ++c)
        for (int w = 0; w < 3; ++w) r = std::max(r, std::abs(m[c][w]));
    return r;
}

/// m_inv scaled to unit largest element (the LTC does not depend on the scale).
dmat3 unit_scale(const dmat3& m) { return m / max_abs(m); }

double distance(const dmat3& a, const dmat3& b) { return max_abs(unit_scale(a) - unit_scale(b)); }

}  // namespace

TEST_CASE("ggx_anisotropic::fetch at the nodes returns the nodes", "[ggx_anisotropic]") {
    REQUIRE(n == 8);
    int checked = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k)
                for (int l = 0; l < n; ++l) {
                    // Node i sits at the lookup coordinate alpha = i / (n - 1) (node 0 holds the fit at alpha_min).
                    const double ax = double(i) / (n - 1), ay = double(j) / (n - 1);
                    const double c = std::cos(ltc::fit::anisotropic_node_theta(k, n));
                    const double phi = ltc::fit::anisotropic_node_phi(l, n);
                    const auto f = ltc::ggx_anisotropic::fetch(c, phi, ax, ay);
                    const auto e = table.node<double>(i, j, k, l);
                    bool same = f.magnitude == e.magnitude && f.fresnel == e.fresnel;
                    for (int a = 0; a < 3; ++a)
                        for (int b = 0; b < 3; ++b) same = same && f.m_inv[a][b] == e.m_inv[a][b];
                    if (!same) {
                        CAPTURE(i, j, k, l);
                        CHECK(same);
                    }
                    ++checked;
                }
    CHECK(checked == n * n * n * n);
}

TEST_CASE("anisotropic_table: swapped nodes, mirror planes and normal incidence", "[ggx_anisotropic]") {
    const auto S = [](const glm::mat3& m) { return ltc::detail::swap_xy(m); };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                for (int l = 0; l < n; ++l) {
                    const glm::mat3 M = table.matrix<float>(i, j, k, l);
                    // alpha_x <-> alpha_y with l -> n - 1 - l: S M S, the same floats.
                    CHECK(M == S(table.matrix<float>(j, i, k, n - 1 - l)));
                    CHECK(glm::determinant(glm::dmat3(M)) > 0);
                    CHECK(std::abs(glm::length(glm::dvec3(M[2])) - 1) < 1e-6);
                }
                // phi = 0: symmetric under y -> -y; phi = pi/2: under x -> -x (exact zeros).
                const glm::mat3 m0 = table.matrix<float>(i, j, k, 0), m1 = table.matrix<float>(i, j, k, n - 1);
                CHECK((m0[0][1] == 0 && m0[1][0] == 0 && m0[1][2] == 0 && m0[2][1] == 0));
                CHECK((m1[0][1] == 0 && m1[1][0] == 0 && m1[0][2] == 0 && m1[2][0] == 0));
                // Normal incidence: one node for every phi.
                for (int l = 1; l < n; ++l) CHECK(table.matrix<float>(i, j, 0, l) == table.matrix<float>(i, j, 0, 0));
            }
}

TEST_CASE("ggx_anisotropic::fetch: the mirror and swap symmetries", "[ggx_anisotropic]") {
    const auto F = [](const dmat3& m, bool fx, bool fy) { return ltc::detail::mirror(m, fx, fy); };
    const double cs[] = {1.0, 0.93, 0.6, 0.31, 0.05};
    const double ps[] = {0.0, 0.13, 0.7, 1.2, 1.5707963267948966};
    const double as[][2] = {{0.2, 0.2}, {0.3, 0.12}, {0.07, 0.55}, {0.8, 0.45}, {1.0, 0.0}};
    for (double c : cs)
        for (double p : ps)
            for (const auto& a : as) {
                CAPTURE(c, p, a[0], a[1]);
                const auto f = ltc::ggx_anisotropic::fetch(c, p, a[0], a[1]);
                // phi -> -phi: the y mirror; phi -> pi - phi: the x mirror; phi + pi: both.
                const auto fy = ltc::ggx_anisotropic::fetch(c, -p, a[0], a[1]);
                const auto fx = ltc::ggx_anisotropic::fetch(c, pi - p, a[0], a[1]);
                const auto fr = ltc::ggx_anisotropic::fetch(c, p + pi, a[0], a[1]);
                CHECK(distance(fy.m_inv, F(f.m_inv, false, true)) < 1e-12);
                CHECK(distance(fx.m_inv, F(f.m_inv, true, false)) < 1e-12);
                CHECK(distance(fr.m_inv, F(f.m_inv, true, true)) < 1e-12);
                CHECK(fy.magnitude == Approx(f.magnitude).epsilon(1e-12));
                CHECK(fx.magnitude == Approx(f.magnitude).epsilon(1e-12));
                // alpha_x <-> alpha_y with phi -> pi/2 - phi: S m_inv S.
                const auto fs = ltc::ggx_anisotropic::fetch(c, 0.5 * pi - p, a[1], a[0]);
                CHECK(distance(fs.m_inv, ltc::detail::swap_xy(f.m_inv)) < 1e-12);
                CHECK(fs.magnitude == Approx(f.magnitude).epsilon(1e-12));
                CHECK(fs.fresnel == Approx(f.fresnel).epsilon(1e-12));
            }
}

TEST_CASE("ggx_anisotropic::fetch is continuous across cells and quadrants", "[ggx_anisotropic]") {
    // At each boundary b (a node plane, a quadrant edge, the alpha diagonal), the step over
    // [b - d, b + d] is at most the larger slope of [b - d - h, b - d] and [b + d, b + d + h]
    // times 2 d, with a factor 2 and an absolute floor for the curvature of M -> M^-1.
    const double d = 1e-7, h = 1e-3;
    int checked = 0;
    const auto check_axis = [&](auto at, double b) {
        const auto lo = at(b - d), hi = at(b + d), lo2 = at(b - d - h), hi2 = at(b + d + h);
        const double slope = std::max(distance(lo.m_inv, lo2.m_inv), distance(hi.m_inv, hi2.m_inv)) / h;
        const double jump = distance(lo.m_inv, hi.m_inv);
        CAPTURE(b, jump, slope);
        CHECK(jump <= 2 * (2 * d) * slope + 1e-9);
        const double mslope = std::max(std::abs(lo.magnitude - lo2.magnitude), std::abs(hi.magnitude - hi2.magnitude)) / h;
        CHECK(std::abs(lo.magnitude - hi.magnitude) <= 2 * (2 * d) * mslope + 1e-12);
        ++checked;
    };
    for (const double c : {0.95, 0.5, 0.2})
        for (const double ax : {0.33, 0.6}) {
            const double ay = 0.21;
            // phi: the nodes and the quadrant edges 0, pi/2, pi, 3 pi/2.
            for (int q = 0; q < 4; ++q)
                for (int l = (q == 0 ? 1 : 0); l < n; ++l)
                    check_axis([&](double p) { return ltc::ggx_anisotropic::fetch(c, p, ax, ay); },
                               0.5 * pi * q + ltc::fit::anisotropic_node_phi(l, n));
            // theta and the alphas: the nodes between the ends.
            for (int k = 1; k < n - 1; ++k)
                check_axis([&](double t) { return ltc::ggx_anisotropic::fetch(std::cos(t), 0.4, ax, ay); },
                           ltc::fit::anisotropic_node_theta(k, n));
            for (int i = 1; i < n - 1; ++i) {
                check_axis([&](double a) { return ltc::ggx_anisotropic::fetch(c, 0.4, a, ay); }, double(i) / (n - 1));
                check_axis([&](double a) { return ltc::ggx_anisotropic::fetch(c, 0.4, ax, a); }, double(i) / (n - 1));
            }
            // The diagonal alpha_x == alpha_y (where the stored half ends).
            check_axis([&](double a) { return ltc::ggx_anisotropic::fetch(c, 0.4, a, 0.4); }, 0.4);
        }
    CHECK(checked > 0);
}

TEST_CASE("ggx_anisotropic::fetch on the diagonal is the isotropic table rotated by phi_v", "[ggx_anisotropic]") {
    // Bound: |m_a I_a(P) - m_b I_b(P)| <= integral |m_a D_a - f| + integral |f - m_b D_b| (both
    // LTCs against the same rho cos), each estimated by the fit's MIS estimator (48 x 48 samples
    // per distribution, the proposal each LTC itself), with 20% for the estimator's noise.
    const auto l1 = [](const dvec3& V, double alpha, const dmat3& m_inv, double magnitude) {
        ltc::fit::anisotropic_sample_set s;
        const auto a = ltc::fit::anisotropic_alpha{alpha, alpha};
        ltc::fit::make_anisotropic_sample_set<ltc::brdf::ggx_anisotropic>(V, a, glm::inverse(m_inv), 48, s);
        return s.all(m_inv, std::abs(glm::determinant(m_inv)), magnitude).l1;
    };
    const auto integral = [](const dmat3& m_inv, const std::vector<dvec3>& v) {
        return ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(m_inv).integrate(v.data(), v.size());
    };
    const auto square = [](const dvec3& c, double s) {
        const dvec3 e1 = glm::normalize(glm::cross(dvec3(0, 0, 1), c)), e2 = glm::cross(c, e1);
        return std::vector<dvec3>{c - s * e1 - s * e2, c + s * e1 - s * e2, c + s * e1 + s * e2, c - s * e1 + s * e2};
    };
    for (const int i : {2, 4, 7})
        for (const int k : {2, 5})
            for (const int l : {0, 3, 6}) {
                const double alpha = double(i) / (n - 1), theta = ltc::fit::anisotropic_node_theta(k, n);
                const double phi = ltc::fit::anisotropic_node_phi(l, n) + (l == 6 ? pi : 0.0);
                const dvec3 V(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
                const auto a = ltc::ggx_anisotropic::fetch(V.z, phi, alpha, alpha);
                const auto iso = ltc::ggx::fetch(V.z, std::sqrt(alpha));
                const dmat3 R(dvec3(std::cos(phi), -std::sin(phi), 0), dvec3(std::sin(phi), std::cos(phi), 0), dvec3(0, 0, 1));
                const dmat3 b_inv = dmat3(iso.m_inv) * R;  // the isotropic LTC rotated by phi
                const double bound = 1.2 * (l1(V, alpha, a.m_inv, a.magnitude) + l1(V, alpha, b_inv, iso.magnitude));
                const dvec3 mirror(-V.x, -V.y, V.z);
                for (const auto& P : {square(glm::normalize(mirror + dvec3(0, 0, 0.3)), 0.3), square(glm::normalize(dvec3(0.1, 0.05, 1)), 0.5),
                                      square(glm::normalize(dvec3(-V.y, V.x, 0.8)), 0.4)}) {
                    const double ia = a.magnitude * integral(a.m_inv, P), ib = iso.magnitude * integral(b_inv, P);
                    CAPTURE(i, k, l, ia, ib, bound);
                    CHECK(std::abs(ia - ib) <= bound);
                }
                // The magnitudes are the same directional albedo, by two quadratures and two grids.
                CHECK(a.magnitude == Approx(iso.magnitude).epsilon(0.02));
            }
}

TEST_CASE("ggx_anisotropic::fetch: degenerate input gives finite coefficients", "[ggx_anisotropic]") {
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    const double odd[] = {0.0, -0.0, 1.0, -1.0, 2.0, 1e-300, -1e30, 1e30, inf, -inf, nan, 0.5, 7.3};
    const auto finite = [](const auto& c) {
        bool ok = std::isfinite(c.magnitude) && std::isfinite(c.fresnel) && c.magnitude >= 0;
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) ok = ok && std::isfinite(c.m_inv[a][b]);
        return ok && glm::determinant(c.m_inv) > 0;
    };
    for (double c : odd)
        for (double p : odd)
            for (double ax : odd)
                for (double ay : {0.0, 0.3, nan, 5.0}) {
                    CAPTURE(c, p, ax, ay);
                    CHECK(finite(ltc::ggx_anisotropic::fetch(c, p, ax, ay)));
                    CHECK(finite(ltc::ggx_anisotropic::fetch(float(c), float(p), float(ax), float(ay))));
                }
    // Out of range is clamped: alpha above 1 is alpha = 1, cos theta above 1 is normal incidence.
    const auto a = ltc::ggx_anisotropic::fetch(0.7, 0.3, 3.0, 0.4), b = ltc::ggx_anisotropic::fetch(0.7, 0.3, 1.0, 0.4);
    CHECK(a.m_inv == b.m_inv);
    // phi is taken mod 2 pi.
    const auto p0 = ltc::ggx_anisotropic::fetch(0.7, 0.3, 0.5, 0.4), p1 = ltc::ggx_anisotropic::fetch(0.7, 0.3 + 4 * pi, 0.5, 0.4);
    CHECK(distance(p0.m_inv, p1.m_inv) < 1e-12);
}

}  // namespace ltc_test_ggx_anisotropic_fetch
