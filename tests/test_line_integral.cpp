// Line lights (ltc/core/line_integral.hpp): the closed forms (L2) and (L3) against brute-force
// quadrature of the thin-line integral (L1) (support/line_quadrature.hpp), over random segments
// including horizon crossings, nearly collinear, short, near-origin and far-off segments; the
// thin-cylinder limit behind (L3) against the library's exact polygon integrals over thin strips;
// and the degenerate input the header documents.
//
// Tolerances: the quadrature's error estimate plus C u kappa (I + S), u the unit roundoff of the
// type under test, I the reference, S the same integral with the cosine factor D_o replaced by its
// bound 1/pi (and, for an LTC, times the Jacobian |M^-1| / |M^-1 w|^3): the closed forms get every
// direction along the segment to u kappa, which moves the integrand by at most u kappa times that
// bound, and every length to u kappa, which moves I by u kappa I. kappa = 1 + |p|max / d is the
// condition number of the segment's line (d, the distance from the origin to it, is known to
// u |p|max only); for an LTC, kappa adds cond(M^-1) times the image segment's own kappa.
#include <ltc/core/line_integral.hpp>
#include <ltc/core/polygon.hpp>
#include <ltc/shading/ggx_fetch.hpp>

#include "support/line_quadrature.hpp"
#include "support/rng.hpp"

#include <catch2/catch.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

namespace ltc_test_line_integral {  // the file's own names, apart from the other files of a unity batch

namespace {

using glm::dmat3;
using glm::dvec3;
using ltc_test::lmat3;
using ltc_test::lvec3;
using ltc_test::frobenius;
using ltc_test::line_kappa;
using ltc_test::pi_l;
using ltc_test::random_segment;
using ltc_test::vec_str;
using ltc_test::error_record;
template <typename T>
using vec3 = glm::vec<3, T>;

template <typename T>
double unit_roundoff() { return std::numeric_limits<T>::epsilon() / 2; }

// C of the tolerance: (L2) and (L3) chain ~30 roundings from the inputs to the result, so
// u kappa (I + S) times 32 bounds them with a margin (the worst observed ratio, printed below, is
// ~1.5); a wrong term or an unguarded cancellation exceeds it by orders of magnitude.
constexpr double c_tol = 32;

struct reference {
    long double value, error, bound;  // I, its quadrature error, S
};

/// I and S of the clamped cosine by brute force, for the segment as given (in long double).
reference cosine_reference(const lvec3& p1, const lvec3& p2) {
    const std::vector<long double> kink = {ltc_test::linear_root(p1.z, p2.z)};
    const auto q = ltc_test::integrate_line_density(p1, p2, ltc_test::cosine_density, kink);
    REQUIRE(q.converged);
    return {q.value, q.error, q.bound};
}

/// Checks a closed form `got` (and its value for the swapped ends) against a reference.
void check_against(double got, double swapped, const reference& ref, long double kappa, double u,
                   error_record& rec) {
    CHECK(std::isfinite(got));
    CHECK(got >= 0);
    if (!std::isfinite(double(kappa))) {  // the rounded segment's line passes through the origin
        CHECK(got == 0);
        return;
    }
    const double scale = u * double(kappa * (ref.value + ref.bound));
    const double err = std::abs(got - double(ref.value)), tol = double(ref.error) + c_tol * scale;
    CAPTURE(got, swapped, double(ref.value), double(ref.error), double(kappa), tol);
    CHECK(err <= tol);
    CHECK(std::abs(swapped - got) <= 2 * c_tol * scale);  // no orientation: symmetric in p1, p2
    rec.add(err, double(ref.value), double(kappa), scale);
}

template <typename T>
void check_cosine(const dvec3& p1d, const dvec3& p2d, error_record& rec) {
    const vec3<T> p1(p1d), p2(p2d);  // the reference integrates the rounded segment itself
    const lvec3 l1(p1), l2(p2);
    CAPTURE(sizeof(T), vec_str(p1d), vec_str(p2d));
    check_against(ltc::integrate_line_cosine(p1, p2), ltc::integrate_line_cosine(p2, p1), cosine_reference(l1, l2),
                  line_kappa(l1, l2), unit_roundoff<T>(), rec);
}

/// I and S of D (eq. 1) by brute force in world space, (L1) with D in place of D_o: for the
/// thin limit of the cylinder in world space, independent of the width factor of (L3).
reference ltc_reference(const lmat3& m_inv, const lvec3& p1, const lvec3& p2) {
    const long double det = std::abs(glm::determinant(m_inv));
    const long double cond = frobenius(m_inv) * frobenius(glm::inverse(m_inv));
    const auto density = [&](const lvec3& w) {
        const lvec3 q = m_inv * w;
        const long double l = glm::length(q), jacobian = det / (l * l * l) / pi_l;
        return std::array<long double, 2>{std::max(0.0L, q.z / l) * jacobian, q.z > 0 ? jacobian : 0};
    };
    const std::vector<long double> kink = {ltc_test::linear_root((m_inv * p1).z, (m_inv * p2).z)};
    const auto q = ltc_test::integrate_line_density(p1, p2, density, kink, cond);
    REQUIRE(q.converged);
    return {q.value, q.error, q.bound};
}

template <typename T>
void check_ltc(const dmat3& m_inv_d, const dvec3& p1d, const dvec3& p2d, error_record& rec) {
    const glm::mat<3, 3, T> m_inv(m_inv_d);
    const vec3<T> p1(p1d), p2(p2d);
    const lmat3 lm(m_inv);
    const lvec3 l1(p1), l2(p2);
    const auto d = ltc::transformed<ltc::clamped_cosine<T>>::from_inverse(m_inv);
    const long double cond = frobenius(lm) * frobenius(glm::inverse(lm));
    const long double kappa = line_kappa(l1, l2) + cond * line_kappa(lm * l1, lm * l2);
    CAPTURE(sizeof(T), vec_str(m_inv_d[0]), vec_str(m_inv_d[1]), vec_str(m_inv_d[2]), vec_str(p1d), vec_str(p2d));
    check_against(ltc::integrate_line(d, p1, p2), ltc::integrate_line(d, p2, p1), ltc_reference(lm, l1, l2), kappa,
                  unit_roundoff<T>(), rec);
}

/// LTC matrices: the GGX table's at a few view angles and roughnesses, and random ones of
/// condition number (Frobenius) <= 30.
std::vector<dmat3> test_matrices() {
    std::vector<dmat3> m;
    for (const auto& [c, r] : {std::pair{0.9, 0.3}, {0.6, 0.5}, {0.3, 0.7}, {0.95, 0.9}})
        m.push_back(dmat3(ltc::ggx::fetch(c, r).m_inv));
    ltc_test::rng r(0x11e6);
    while (m.size() < 8) {
        dmat3 a(1.5);
        for (int i = 0; i < 9; ++i) a[i / 3][i % 3] += r.uniform(-1, 1);
        if (frobenius(lmat3(a)) * frobenius(glm::inverse(lmat3(a))) <= 30) m.push_back(a);
    }
    return m;
}

}  // namespace

TEST_CASE("integrate_line_cosine equals brute-force quadrature of the thin-line integral", "[line]") {
    ltc_test::rng r(0x11e5);
    error_record rec[2];
    int zeros = 0, crossings = 0;
    for (int i = 0; i < 400; ++i) {
        const auto [p1, p2] = random_segment(r, i);
        zeros += p1.z <= 0 && p2.z <= 0;
        crossings += (p1.z < 0) != (p2.z < 0);
        check_cosine<float>(p1, p2, rec[0]);
        check_cosine<double>(p1, p2, rec[1]);
    }
    CHECK(crossings > 80);  // the horizon is exercised, as is the all-below case
    CHECK(zeros > 20);
    std::cout << "\nline integrals vs quadrature (400 segments; 8 matrices x 100 segments for the LTC)\n";
    rec[0].print("integrate_line_cosine", "float ");
    rec[1].print("integrate_line_cosine", "double");
}

TEST_CASE("integrate_line equals quadrature of D over the segment in world space (the width factor)", "[line]") {
    ltc_test::rng r(0x11e7);
    error_record rec[2];
    for (const dmat3& m_inv : test_matrices())
        for (int i = 0; i < 100; ++i) {
            const auto [p1, p2] = random_segment(r, i);
            check_ltc<float>(m_inv, p1, p2, rec[0]);
            check_ltc<double>(m_inv, p1, p2, rec[1]);
        }
    rec[0].print("integrate_line       ", "float ");
    rec[1].print("integrate_line       ", "double");
}

TEST_CASE("integrate_line is the thin-cylinder limit: exact polygon integrals of D over thin strips", "[line]") {
    // The rays through the strip {x + v m: x on the segment, |v| <= h} (m the unit normal of the
    // plane of the origin and the segment) are exactly those passing within h d / sqrt(d^2 + h^2) of
    // the axis, between the ends: a cylinder's band. Its integral of D (eq. 3, exact) over 2h
    // is v(h) = I_line,D + c h^2 + O(h^4) (the band is symmetric in v), so v(h) - I is
    // (v(2h) - v(h)) / 3 (Richardson): asserted to 5%, i.e. the bands' limit is (L3) to within 5% of
    // the h^2 term, wherever v(2h) - v(h) stands above the polygon integral's rounding: u cond(M^-1)
    // kappa in its vertices' directions, relative to its edge terms (~ its angular perimeter
    // (h + L)/|x|), so 64 u cond kappa |p|max (1/h + 1/L) relative to its value (~ its angular area
    // h L/|x|^2). Generic segments (kind 0) and h = d/100: the h^2 term stands far above it.
    ltc_test::rng r(0x11e8);
    double worst = 0;
    int richardson = 0;
    for (const dmat3& m_inv : test_matrices()) {
        const auto d = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(m_inv);
        const long double cond = frobenius(lmat3(m_inv)) * frobenius(glm::inverse(lmat3(m_inv)));
        for (int i = 0; i < 25; ++i) {
            const auto segment = random_segment(r, 0);
            const dvec3 p1 = segment.first, p2 = segment.second;  // (not a structured binding: captured below)
            const dvec3 m = glm::normalize(glm::cross(p1, p2 - p1));
            const double dist = glm::length(glm::cross(p1, p2 - p1)) / glm::length(p2 - p1);
            const double h = 1e-2 * dist, line = ltc::integrate_line(d, p1, p2);
            const auto strip = [&](double w) {
                const dvec3 q[4] = {p1 + w * m, p2 + w * m, p2 - w * m, p1 - w * m};
                return d.integrate(q, 4) / (2 * w);
            };
            const double v1 = strip(h), v2 = strip(2 * h);
            const double pmax = std::max(glm::length(p1), glm::length(p2)), len = glm::length(p2 - p1);
            const double kappa = double(cond * line_kappa(lvec3(p1), lvec3(p2)));
            const double floor = 64 * unit_roundoff<double>() * kappa * pmax * (1 / h + 1 / len) * v1;
            CAPTURE(i, vec_str(p1), vec_str(p2), line, (v1 - line) / line, (v2 - v1) / line, floor / line);
            CHECK(std::abs(v1 - line) <= std::abs(v2 - v1) / 3 * 1.05 + floor);
            if (line > 0 && std::abs(v2 - v1) > 100 * floor) {  // (0: below D's horizon, v(h) = O(h^2))
                CHECK((v1 - line) / (v2 - v1) == Approx(1.0 / 3).epsilon(0.05));
                ++richardson;
            }
            if (line > 0) worst = std::max(worst, std::abs((4 * v1 - v2) / 3 - line) / line);
        }
    }
    CHECK(richardson > 100);  // of 200 segments, some below the horizon
    std::cout << "  thin strips (h = d/100, d/50) extrapolated to h = 0 vs integrate_line, double: max rel "
              << "difference " << worst << " (" << richardson << " segments)\n";
}

TEMPLATE_TEST_CASE("exact segments pointing at the origin keep full relative accuracy", "[line]", float, double) {
    // Foot point d (-4, 0, 3), direction (3, 0, 4): dyadic d and ends give exact coordinates, so the
    // result is well determined (no input rounding) even for d << |p|, where the endpoint terms of
    // (L2) cancel (cos S -> -1) and D - sin D cancels: K's two-term form and the series must keep
    // ~u relative, not u kappa (kappa up to 2^45 here).
    using T = TestType;
    const int digits = std::numeric_limits<T>::digits;
    for (const int k : {4, 10, digits / 2, digits - 8})
        for (const auto& [s1, s2] : {std::pair{1.0L, 2.0L}, {1.0L, 1.0L + 0x1p-8L}, {0.5L, 8.0L}}) {
            const long double dk = std::ldexp(1.0L, -k);
            const lvec3 foot = dk * lvec3(-4, 0, 3), v(3, 0, 4);
            const vec3<T> p1(foot + s1 * v), p2(foot + s2 * v);
            REQUIRE(lvec3(p1) == foot + s1 * v);  // exactly representable
            REQUIRE(lvec3(p2) == foot + s2 * v);
            const auto ref = ltc_test::integrate_line_through(foot, v, s1, s2, ltc_test::cosine_density);
            const double got = ltc::integrate_line_cosine(p1, p2);
            const double err = std::abs(got - double(ref.value));
            CAPTURE(k, double(s1), double(s2), got, double(ref.value), err / double(ref.value));
            CHECK(err <= double(ref.error) + c_tol * unit_roundoff<T>() * double(ref.value));
        }
}

TEMPLATE_TEST_CASE("line integrals of degenerate segments are finite and as documented", "[line][bad-input]", float,
                   double) {
    using T = TestType;
    using v3 = vec3<T>;
    using dist = ltc::transformed<ltc::clamped_cosine<T>>;
    const auto d = dist::from_inverse(glm::mat<3, 3, T>(ltc::ggx::fetch(0.7, 0.4).m_inv));
    const auto both = [&](const v3& a, const v3& b) {
        const T c = ltc::integrate_line_cosine(a, b), l = ltc::integrate_line(d, a, b);
        CHECK(std::isfinite(c));
        CHECK(std::isfinite(l));
        return std::pair<T, T>{c, l};
    };
    const std::pair<T, T> zero{0, 0};
    // zero length; edge-on (through, ending at, pointing at the origin); below or in the horizon
    CHECK(both(v3(0.3f, 0.2f, 1), v3(0.3f, 0.2f, 1)) == zero);
    CHECK(both(v3(0), v3(1, 0, 1)) == zero);
    CHECK(both(v3(-1, -2, -1), v3(1, 2, 1)) == zero);
    CHECK(both(v3(0.5f, 0.5f, 1), v3(1, 1, 2)) == zero);
    CHECK(both(v3(1, 0, -1), v3(0, 1, -2)) == zero);
    CHECK(both(v3(1, 0, 0), v3(0, 1, -2)) == zero);
    CHECK(both(v3(1, 0, 0), v3(0, 1, 0)) == zero);
    // an end on the horizon changes nothing: the other end's segment is wholly above
    CHECK(both(v3(1, 0, 0), v3(0, 1, 1)).first > 0);
    // pointing at the origin is the limit d -> 0 of segments next to it: the integral vanishes like d
    const T e1 = ltc::integrate_line_cosine(v3(0.5f, 0.5f, 1), v3(1, 1 + T(1e-2), 2));
    const T e2 = ltc::integrate_line_cosine(v3(0.5f, 0.5f, 1), v3(1, 1 + T(1e-3), 2));
    CHECK(e2 == Approx(e1 / 10).epsilon(0.02));
    // passing next to the origin at height delta: I = (atan(1/delta) + delta/(1 + delta^2)) /
    // (pi delta), ~1/(2 delta), diverging; beyond the largest finite value it saturates
    for (const T delta : {T(1e-3), T(1e-10), T(1e-30)}) {
        const long double dl = delta, exact = (std::atan(1 / dl) + dl / (1 + dl * dl)) / (pi_l * dl);
        const T got = both(v3(-1, 0, delta), v3(1, 0, delta)).first;
        CHECK(got == Approx(double(exact)).epsilon(64 * unit_roundoff<T>()));
    }
    const T sub = std::numeric_limits<T>::denorm_min() * 4;
    CHECK(both(v3(-1, 0, sub), v3(1, 0, sub)).first == std::numeric_limits<T>::max());
    // power-of-two scales are exact (I has units of 1/length; bitwise but for FMA contraction, which
    // may differ between the fast and the rescaled path), down to saturation at subnormal scales
    const v3 a(0.7f, -0.4f, 1.2f), b(-1.1f, 0.3f, 0.5f);
    const T ref = ltc::integrate_line_cosine(a, b), ref_l = ltc::integrate_line(d, a, b);
    for (const int k : {std::numeric_limits<T>::max_exponent - 3, 40, -40, std::numeric_limits<T>::min_exponent + 4}) {
        CAPTURE(k);
        const auto [c, l] = both(a * std::ldexp(T(1), k), b * std::ldexp(T(1), k));
        CHECK(c == Approx(std::ldexp(ref, -k)).epsilon(8 * unit_roundoff<T>()));
        CHECK(l == Approx(std::ldexp(ref_l, -k)).epsilon(8 * unit_roundoff<T>()));
    }
    CHECK(both(a * sub, b * sub) == std::pair<T, T>{std::numeric_limits<T>::max(), std::numeric_limits<T>::max()});
    // M^-1 = identity gives the cosine itself; M^-1 times a power of two (up to the largest one,
    // whose products overflow) the same distribution and the same integral
    const glm::mat<3, 3, T> m_inv = d.inverse_matrix();
    CHECK(ltc::integrate_line(dist::from_inverse(glm::mat<3, 3, T>(1)), a, b) == ref);
    const T big = std::ldexp(T(1), std::numeric_limits<T>::max_exponent - 2);
    CHECK(ltc::integrate_line(dist::from_inverse(m_inv * big), a, b) == Approx(ref_l).epsilon(16 * unit_roundoff<T>()));
    // the angle by atan2 (edge_policy::exact) instead of float's fit: the same to a few ulps
    CHECK(ltc::integrate_line_cosine<T, ltc::edge_policy::exact>(a, b) == Approx(ref).epsilon(16 * unit_roundoff<T>()));
}

}  // namespace ltc_test_line_integral
