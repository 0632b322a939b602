// Tests of ltc/brdf/ggx_anisotropic.hpp: normalization of D, of the visible normals and of the
// pdf (quadrature, the tolerances of support/brdf_references.hpp), sample() against pdf()
// (chi-square, and the Monte Carlo albedo eval / pdf against the quadrature), reciprocity,
// bit-for-bit equality with ggx<T> at alpha_x == alpha_y, swapping alpha_x and alpha_y as a
// rotation by 90 degrees about z, degenerate input; and ltc::ground_truth::integrate with the
// anisotropic parameter, against the isotropic ground truth and a brute-force quadrature.
//
// The two exact-equality tests (isotropic diagonal, rotation) hold in IEEE arithmetic: the
// expressions compared differ only by products with 1, commuted sums and negations. A compiler
// that contracts a * b + c into FMAs may contract the two sides differently; ltc::ltc's
// -ffp-contract=off (LTC_FP_CONTRACT_OFF, the default) rules that out, as for the determinism test.
#include <ltc/brdf/ggx.hpp>
#include <ltc/brdf/ggx_anisotropic.hpp>
#include <ltc/reference/ground_truth.hpp>

#include <catch2/catch.hpp>

#include "support/brdf_quadrature.hpp"
#include "support/brdf_references.hpp"
#include "support/brute_force.hpp"
#include "support/rng.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <type_traits>
#include <vector>

namespace ltc_test_brdf_anisotropic {  // the file's own names, apart from the other files of a unity batch

using ltc_test::brdf_checks::eps;
using ltc_test::brdf_checks::finite;
using ltc_test::brdf_checks::pi;
using ltc_test::brdf_checks::rho;

template <typename T>
using aniso = ltc::brdf::ggx_anisotropic<T>;
template <typename T>
using alpha_of = ltc::brdf::anisotropic_alpha<T>;

/// The unit direction at polar angle theta and azimuth phi (degrees).
inline glm::dvec3 direction(double theta_deg, double phi_deg) {
    const double t = theta_deg * pi / 180, p = phi_deg * pi / 180;
    return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

/// The rounding bound of support/brdf_references.hpp at the smaller of the two roughnesses: D is
/// GGX's in coordinates stretched by at most 1 / min(alpha), so the rounding of a node direction
/// costs at most what it costs GGX at min(alpha); the coefficients m, p, q add three roundings to
/// the ~10 of the rational parts that its 256 eps_T covers.
template <typename T>
double rho_aniso(double ax, double ay) {
    return rho<T>(std::min(ax, ay));
}

/// A view direction and a roughness: theta_v and phi_v in degrees.
struct configuration {
    double ax, ay, theta_v, phi_v;
};

/// Narrow and wide lobes along either axis, views at normal incidence, oblique and grazing, at
/// azimuths on and off the axes.
inline constexpr configuration configurations[] = {
    {0.05, 0.3, 0, 0}, {0.05, 0.3, 60, 30}, {0.3, 0.05, 80, 100},
    {0.5, 0.1, 30, 150}, {1.0, 0.25, 60, 45}, {0.2, 1.0, 85, 90},
};
inline constexpr std::size_t n_configurations = sizeof(configurations) / sizeof(configurations[0]);

template <typename T>
glm::vec<3, T> view(const configuration& c) {
    return glm::vec<3, T>(direction(c.theta_v, c.phi_v));
}

// ---------------------------------------------------------------------------------------------
// Quadrature references (support/brdf_quadrature.hpp), in double with the float model riding
// along on the same cells.

/// The z frame turned by phi_v about z: psi = phi - phi_v, so that the mirror direction and -V are
/// at psi = pi. Breakpoints as support/brdf_references.hpp's (theta_v: the peak; pi / 2: eval's
/// horizon; pi - theta_v: the circle (V + L).z = 0 through L = -V, where the pdf jumps), over the
/// whole circle of psi (no mirror symmetry off the axes).
inline ltc_test::polar_frame view_frame(double phi_v_deg) {
    const double p = phi_v_deg * pi / 180;
    ltc_test::polar_frame f;
    f.a = {std::cos(p), std::sin(p), 0};
    f.b = {-std::sin(p), std::cos(p), 0};
    f.p = {0, 0, 1};
    return f;
}

/// The sphere integrals of pdf and eval of one configuration: components pdf, eval (double);
/// pdf, eval (float).
struct sphere_reference {
    ltc_test::quadtree_integral<4> q;
    ltc_test::polar_frame frame;
};

inline sphere_reference make_sphere_reference(const configuration& c) {
    const glm::dvec3 Vd = view<double>(c);
    const glm::vec3 Vf = view<float>(c);
    const alpha_of<double> ad{c.ax, c.ay};
    const alpha_of<float> af{static_cast<float>(c.ax), static_cast<float>(c.ay)};
    const auto f = [&](const glm::dvec3& L) -> std::array<double, 4> {
        const glm::vec3 Lf(L);
        return {aniso<double>::pdf(Vd, L, ad), aniso<double>::eval(Vd, L, ad),
                static_cast<double>(aniso<float>::pdf(Vf, Lf, af)),
                static_cast<double>(aniso<float>::eval(Vf, Lf, af))};
    };
    const double tv = c.theta_v * pi / 180;
    sphere_reference r;
    r.frame = view_frame(c.phi_v);
    r.q = ltc_test::integrate_adaptive<4>(f, r.frame, ltc_test::breakpoints(0, pi, {tv, pi / 2, pi - tv}, pi / 8),
                                          ltc_test::breakpoints(0, 2 * pi, {pi}, pi / 8), 5, 2,
                                          ltc_test::brdf_checks::reference_tol);
    return r;
}

/// Computed once per process (shared by the normalization and the sampling tests).
inline const sphere_reference& sphere_reference_for(std::size_t i) {
    static std::vector<sphere_reference> cache;
    if (cache.empty())
        for (const configuration& c : configurations) cache.push_back(make_sphere_reference(c));
    return cache[i];
}

/// The lune frame of support/brdf_quadrature.hpp turned by phi_v about z: p = z x a, a = (cos
/// phi_v, sin phi_v, 0), b = z. The lune {h.z > 0, V.h > 0} is psi in (0, pi - theta_v); D peaks
/// at h = z, the corner (pi / 2, pi / 2).
inline ltc_test::polar_frame lune_frame(double phi_v_deg) {
    const double p = phi_v_deg * pi / 180;
    ltc_test::polar_frame f;
    f.a = {std::cos(p), std::sin(p), 0};
    f.b = {0, 0, 1};
    f.p = {-std::sin(p), std::cos(p), 0};
    return f;
}

template <typename F>
ltc_test::quadtree_integral<2> lune_integral(const F& f, double phi_v_deg, double psi_max) {
    return ltc_test::integrate_adaptive<2>(f, lune_frame(phi_v_deg), ltc_test::breakpoints(0, pi, {pi / 2}, pi / 8),
                                           ltc_test::breakpoints(0, psi_max, {pi / 2}, pi / 8), 6, 1,
                                           ltc_test::brdf_checks::lune_tol);
}

// (a) int D(h) cos(theta_h) dh = 1 over the upper hemisphere, in double and float.
TEST_CASE("brdf: anisotropic GGX, the NDF is normalized", "[brdf]") {
    const double pairs[][2] = {{0.05, 0.3}, {0.3, 0.05}, {0.5, 0.1}, {1.0, 0.25}, {0.05, 1.0}};
    for (const auto& a : pairs) {
        const alpha_of<double> ad{a[0], a[1]};
        const alpha_of<float> af{static_cast<float>(a[0]), static_cast<float>(a[1])};
        const auto f = [&](const glm::dvec3& h) -> std::array<double, 2> {
            return {aniso<double>::ndf(h, ad) * h.z, static_cast<double>(aniso<float>::ndf(glm::vec3(h), af)) * h.z};
        };
        const auto q = lune_integral(f, 0, pi);
        INFO("alpha (" << a[0] << ", " << a[1] << "): " << q.value[0] << " +- " << q.error[0] << ", float "
                       << q.value[1] << " +- " << q.error[1]);
        CHECK(q.converged);
        CHECK(std::abs(q.value[0] - 1) <= q.error[0] + rho_aniso<double>(a[0], a[1]));
        CHECK(std::abs(q.value[1] - 1) <= q.error[1] + rho_aniso<float>(a[0], a[1]));
    }
}

// (b) Smith's visible-normal normalization int G1(V) max(0, V.h) D(h) dh = V.z (D_V of Heitz
// 2018 is a density), over the lune {h.z > 0, V.h > 0}, for views off the axes.
TEST_CASE("brdf: anisotropic GGX, the visible normals are normalized", "[brdf]") {
    for (const configuration& c : configurations) {
        const glm::dvec3 Vd = view<double>(c);
        const glm::vec3 Vf = view<float>(c);
        const alpha_of<double> ad{c.ax, c.ay};
        const alpha_of<float> af{static_cast<float>(c.ax), static_cast<float>(c.ay)};
        const double g1d = aniso<double>::g1(Vd, ad), g1f = static_cast<double>(aniso<float>::g1(Vf, af));
        const auto f = [&](const glm::dvec3& h) -> std::array<double, 2> {
            const glm::vec3 hf(h);
            const double vhf = std::max(0.0, static_cast<double>(glm::dot(Vf, hf)));
            return {g1d * std::max(0.0, glm::dot(Vd, h)) * aniso<double>::ndf(h, ad),
                    g1f * vhf * static_cast<double>(aniso<float>::ndf(hf, af))};
        };
        const auto q = lune_integral(f, c.phi_v, pi - c.theta_v * pi / 180);
        INFO("alpha (" << c.ax << ", " << c.ay << ") V at (" << c.theta_v << ", " << c.phi_v << ") deg: " << q.value[0]
                       << " +- " << q.error[0] << ", float " << q.value[1] << " +- " << q.error[1] << "; V.z "
                       << Vd.z);
        CHECK(q.converged);
        CHECK(std::abs(q.value[0] - Vd.z) <= q.error[0] + rho_aniso<double>(c.ax, c.ay) * Vd.z);
        CHECK(std::abs(q.value[1] - Vd.z) <= q.error[1] + rho_aniso<float>(c.ax, c.ay) * Vd.z);
    }
}

// (c) int pdf(V, L) dL = 1 over the whole sphere (sample() may go below the horizon), and the
// albedo int eval dL is in (0, 1] (no Fresnel; G2 <= G1 loses energy).
TEST_CASE("brdf: anisotropic GGX, the pdf integrates to one over the sphere", "[brdf]") {
    for (std::size_t i = 0; i < n_configurations; ++i) {
        const configuration& c = configurations[i];
        const auto& q = sphere_reference_for(i).q;
        INFO("alpha (" << c.ax << ", " << c.ay << ") V at (" << c.theta_v << ", " << c.phi_v << ") deg: pdf "
                       << q.value[0] << " +- " << q.error[0] << ", float " << q.value[2] << " +- " << q.error[2]
                       << "; albedo " << q.value[1] << " +- " << q.error[1]);
        CHECK(q.converged);
        CHECK(std::abs(q.value[0] - 1) <= q.error[0] + rho_aniso<double>(c.ax, c.ay));
        CHECK(std::abs(q.value[2] - 1) <= q.error[2] + rho_aniso<float>(c.ax, c.ay));
        CHECK(q.value[1] > 0);
        CHECK(q.value[1] <= 1 + q.error[1] + rho_aniso<double>(c.ax, c.ay));
    }
}

// ---------------------------------------------------------------------------------------------
// (d) sample() follows pdf(): chi-square over the leaves of the sphere reference, merged in
// depth-first order until each bin expects >= 16 samples (a partition fixed by the expected
// probabilities alone), below the p = 1e-4 critical value; and eval / pdf is unbiased: the
// Monte Carlo albedo within 4 standard errors of the quadrature (eval / pdf = G2 / G1(V) <= 1 is
// bounded, so N = 10^5 estimates the variance to ~0.5%). The expected probabilities come from the
// double pdf, also for the float sampler (its directions are off by ~eps_float, far below the
// cells that carry mass).

/// Chi-square critical value at upper-tail probability 1e-4 (Wilson-Hilferty, as
/// test_brdf_sampling.cpp).
inline double chi2_critical_1e4(double k) {
    const double z = 3.7190164854556804, c = 2 / (9 * k);
    const double b = 1 - c + z * std::sqrt(c);
    return k * b * b * b;
}

template <typename T>
void check_sampler(std::size_t i) {
    using vec3 = glm::vec<3, T>;
    const configuration& c = configurations[i];
    const sphere_reference& r = sphere_reference_for(i);
    const int p = std::is_same<T, float>::value ? 1 : 0;
    const vec3 V = view<T>(c);
    const alpha_of<T> alpha{static_cast<T>(c.ax), static_cast<T>(c.ay)};
    const std::size_t N = 100000;
    ltc_test::rng rng(0xa5150000u + 16 * i + static_cast<unsigned>(p));
    std::vector<double> count(r.q.leaves.size(), 0.0);
    std::size_t bad_direction = 0, bad_pdf = 0;
    double sum = 0, sum2 = 0;
    for (std::size_t k = 0; k < N; ++k) {
        const vec3 L = aniso<T>::sample(V, rng.uniform2<T>(), alpha);
        if (!finite(L) || std::abs(static_cast<double>(glm::length(L)) - 1) > 8 * eps<T>()) {
            ++bad_direction;
            continue;
        }
        const T pdf = aniso<T>::pdf(V, L, alpha);
        if (!(pdf > T(0)) || !std::isfinite(pdf)) {
            ++bad_pdf;
            continue;
        }
        const double w = static_cast<double>(aniso<T>::eval(V, L, alpha) / pdf);
        sum += w;
        sum2 += w * w;
        const glm::dvec3 Ld(L);
        const double th = std::atan2(std::sqrt(Ld.x * Ld.x + Ld.y * Ld.y), Ld.z);
        double ps = std::atan2(glm::dot(Ld, r.frame.b), glm::dot(Ld, r.frame.a));
        if (ps < 0) ps += 2 * pi;
        count[r.q.locate(th, ps)] += 1;
    }
    INFO((p ? "float" : "double") << " alpha (" << c.ax << ", " << c.ay << ") V at (" << c.theta_v << ", "
                                  << c.phi_v << ") deg");
    CHECK(bad_direction == 0);
    CHECK(bad_pdf == 0);

    std::vector<double> bin_expected, bin_observed;
    double expected = 0, observed = 0;
    for (std::size_t l = 0; l < r.q.leaves.size(); ++l) {
        expected += N * r.q.nodes[r.q.leaves[l]].value[0];
        observed += count[l];
        if (expected >= 16) {
            bin_expected.push_back(expected), bin_observed.push_back(observed);
            expected = observed = 0;
        }
    }
    REQUIRE(!bin_expected.empty());
    bin_expected.back() += expected, bin_observed.back() += observed;  // the remainder
    double chi2 = 0;
    for (std::size_t b = 0; b < bin_expected.size(); ++b)
        chi2 += (bin_observed[b] - bin_expected[b]) * (bin_observed[b] - bin_expected[b]) / bin_expected[b];
    const double df = static_cast<double>(bin_expected.size() - 1), crit = chi2_critical_1e4(df);
    INFO("chi2 " << chi2 << " with " << df << " dof, critical value (p = 1e-4) " << crit);
    CHECK(bin_expected.size() > 20);
    CHECK(chi2 < crit);

    const double mean = sum / N, var = std::max(0.0, sum2 / N - mean * mean) * N / (N - 1);
    const double se = std::sqrt(var / N), albedo = r.q.value[2 * p + 1], albedo_error = r.q.error[2 * p + 1];
    INFO("albedo: MC " << mean << " +- " << se << ", quadrature " << albedo << " +- " << albedo_error);
    CHECK(std::abs(mean - albedo) <= 4 * se + albedo_error + rho_aniso<T>(c.ax, c.ay) * albedo);
}

TEST_CASE("brdf: anisotropic GGX, sample() follows pdf(), and eval / pdf is unbiased", "[brdf]") {
    for (std::size_t i = 0; i < n_configurations; ++i) {
        check_sampler<double>(i);
        check_sampler<float>(i);
    }
}

// ---------------------------------------------------------------------------------------------
// Pointwise properties, in float and double.

template <typename T>
bool same_bits(T a, T b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}
template <typename T>
bool same_bits(const glm::vec<3, T>& a, const glm::vec<3, T>& b) {
    return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z);
}

/// A roughness log-uniform in [1e-5, 1e4] (beyond the clamp at both ends), or now and then one
/// of the special values (0, negative, NaN, infinite, the clamp's bounds).
template <typename T>
T random_alpha(ltc_test::rng& rng) {
    const T special[] = {T(0), -T(1), std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity(),
                         aniso<T>::alpha_min, aniso<T>::alpha_max, T(1)};
    const double u = rng.uniform();
    if (u < 0.125) return special[static_cast<std::size_t>(rng.uniform() * 7) % 7];
    return static_cast<T>(std::pow(10.0, -5 + 9 * rng.uniform()));
}

// (f) reciprocity: rho(V, L) = rho(L, V), i.e. eval(V, L) / L.z == eval(L, V) / V.z. Both sides
// have the same D (V + L == L + V) and the same denominator (a commuted sum); then three
// roundings per side: 16 eps_T relative leaves a wide margin (+ the smallest normal T, below
// which a result has no relative precision).
template <typename T>
void check_reciprocity() {
    using vec3 = glm::vec<3, T>;
    ltc_test::rng rng(20160724);
    const double floor = static_cast<double>(std::numeric_limits<T>::min());
    for (int k = 0; k < 20000; ++k) {
        glm::dvec3 v = rng.direction(), l = rng.direction();
        v.z = std::abs(v.z), l.z = std::abs(l.z);
        const vec3 V(v), L(l);
        const alpha_of<T> a{random_alpha<T>(rng), random_alpha<T>(rng)};
        const double f = static_cast<double>(aniso<T>::eval(V, L, a) / L.z);
        const double g = static_cast<double>(aniso<T>::eval(L, V, a) / V.z);
        INFO("alpha (" << a.x << ", " << a.y << ") V " << v.x << " " << v.y << " " << v.z << " L " << l.x << " "
                       << l.y << " " << l.z << ": " << f << " vs " << g);
        REQUIRE(std::isfinite(f));
        REQUIRE(std::abs(f - g) <= 16 * eps<T>() * std::max(std::abs(f), std::abs(g)) + floor);
    }
}

TEST_CASE("brdf: anisotropic GGX is reciprocal", "[brdf]") {
    check_reciprocity<float>();
    check_reciprocity<double>();
}

/// Vectors of the degenerate-input tests: the pole, the horizon, below it, grazing, subnormal z.
template <typename T>
std::vector<glm::vec<3, T>> special_directions() {
    using vec3 = glm::vec<3, T>;
    const T tiny = std::numeric_limits<T>::min(), denorm = std::numeric_limits<T>::denorm_min();
    return {vec3(0, 0, 1),
            vec3(1, 0, 0),
            vec3(0, 1, 0),
            vec3(0.6, 0, -0.8),
            vec3(0, 0, -1),
            vec3(direction(89.9, 30)),              // grazing
            ltc::brdf::view_from_cos<T>(tiny),      // V.z = the smallest normal
            vec3(1, 0, denorm),                     // V.z subnormal
            vec3(-1, 0, denorm),
            vec3(0.6, -0.8, 0),
            ltc::brdf::view_from_cos<T>(T(1) - std::numeric_limits<T>::epsilon())};  // nearly normal
}

// Bit-for-bit equality with ggx<T> on the diagonal alpha_x == alpha_y: every function, over random
// directions on the whole sphere (V.z <= 0 included), random and special roughnesses (the clamp
// included) and the special directions.
template <typename T>
void check_isotropic_diagonal() {
    using vec3 = glm::vec<3, T>;
    using G = ltc::brdf::ggx<T>;
    using A = aniso<T>;
    ltc_test::rng rng(0x150);
    std::vector<vec3> dirs = special_directions<T>();
    for (int k = 0; k < 32; ++k) dirs.push_back(vec3(rng.direction()));
    std::size_t checked = 0;
    const auto check = [&](const vec3& V, const vec3& L, const glm::vec<2, T>& u, T a) {
        const alpha_of<T> aa{a, a};
        INFO("alpha " << a << " V " << V.x << " " << V.y << " " << V.z << " L " << L.x << " " << L.y << " " << L.z
                      << " u " << u.x << " " << u.y);
        REQUIRE(same_bits(A::eval(V, L, aa), G::eval(V, L, a)));
        REQUIRE(same_bits(A::pdf(V, L, aa), G::pdf(V, L, a)));
        REQUIRE(same_bits(A::ndf(L, aa), G::ndf(L, a)));
        REQUIRE(same_bits(A::lambda(L, aa), G::lambda(L, a)));
        REQUIRE(same_bits(A::g1(L, aa), G::g1(L, a)));
        REQUIRE(same_bits(A::g2(V, L, aa), G::g2(V, L, a)));
        REQUIRE(same_bits(A::sample_visible_normal(V, u, aa), G::sample_visible_normal(V, u, a)));
        REQUIRE(same_bits(A::sample(V, u, aa), G::sample(V, u, a)));
        ++checked;
    };
    for (int k = 0; k < 20000; ++k) {
        const vec3 V(rng.direction()), L(rng.direction());
        const T a = random_alpha<T>(rng);
        check(V, L, rng.uniform2<T>(), a);
    }
    for (const vec3& V : dirs)
        for (const vec3& L : dirs) check(V, L, rng.uniform2<T>(), random_alpha<T>(rng));
    CHECK(checked == 20000 + dirs.size() * dirs.size());
    CHECK(A::clamp_alpha({T(0), std::numeric_limits<T>::quiet_NaN()}).x == G::alpha_min);
    CHECK(A::clamp_alpha({T(0), std::numeric_limits<T>::quiet_NaN()}).y == G::alpha_min);
    CHECK(A::clamp_alpha({T(1e30), T(0.5)}).x == G::alpha_max);
    CHECK(A::clamp_alpha({T(1e30), T(0.5)}).y == T(0.5));
}

TEST_CASE("brdf: anisotropic GGX at alpha_x == alpha_y is ggx, bit for bit", "[brdf]") {
    check_isotropic_diagonal<float>();
    check_isotropic_diagonal<double>();
}

// Swapping alpha_x and alpha_y is the rotation R (x, y, z) = (-y, x, z) of V and L: every result
// the same, bit for bit (R is exact, and the swap exchanges p and q, which only commutes the sums;
// the sampler's stretch, basis and cross product commute with R exactly). The sampled direction
// rotates too, except where the stretched view is exactly normal and the basis falls back to
// T1 = (1, 0, 0) on both sides (an equally valid sample, not the rotated one): random views never are.
// The visible normal is compared bit for bit; the reflection 2 (V.h) h - V within 4 eps_T per
// component of the unit vector, because GCC 12's vectorizer fuses its multiply-subtract with the
// rotation's negation into an fmsubadd at -march=native even under -ffp-contract=off (one rounding
// less in a term of size <= 3, then the normalization: a few u).
template <typename T>
void check_rotation() {
    using vec3 = glm::vec<3, T>;
    using A = aniso<T>;
    ltc_test::rng rng(90);
    const auto R = [](const vec3& w) { return vec3(-w.y, w.x, w.z); };
    for (int k = 0; k < 20000; ++k) {
        const vec3 V(rng.direction()), L(rng.direction());
        const alpha_of<T> a{random_alpha<T>(rng), random_alpha<T>(rng)}, s{a.y, a.x};
        const glm::vec<2, T> u = rng.uniform2<T>();
        INFO("alpha (" << a.x << ", " << a.y << ") V " << V.x << " " << V.y << " " << V.z << " L " << L.x << " "
                       << L.y << " " << L.z);
        REQUIRE(same_bits(A::eval(V, L, a), A::eval(R(V), R(L), s)));
        REQUIRE(same_bits(A::pdf(V, L, a), A::pdf(R(V), R(L), s)));
        REQUIRE(same_bits(A::ndf(L, a), A::ndf(R(L), s)));
        REQUIRE(same_bits(A::lambda(L, a), A::lambda(R(L), s)));
        REQUIRE(same_bits(A::g1(L, a), A::g1(R(L), s)));
        REQUIRE(same_bits(A::g2(V, L, a), A::g2(R(V), R(L), s)));
        REQUIRE(same_bits(R(A::sample_visible_normal(V, u, a)), A::sample_visible_normal(R(V), u, s)));
        const vec3 l1 = R(A::sample(V, u, a)), l2 = A::sample(R(V), u, s);
        const T tol = 4 * std::numeric_limits<T>::epsilon();
        REQUIRE(std::abs(l1.x - l2.x) <= tol);
        REQUIRE(std::abs(l1.y - l2.y) <= tol);
        REQUIRE(std::abs(l1.z - l2.z) <= tol);
    }
    // And the anisotropy is real: away from the diagonal, the swap changes the values.
    const vec3 V(direction(60, 0)), L(direction(60, 180));
    CHECK(A::eval(V, L, {T(0.1), T(0.5)}) != A::eval(V, L, {T(0.5), T(0.1)}));
    CHECK(A::lambda(V, {T(0.1), T(0.5)}) < A::lambda(V, {T(0.5), T(0.1)}));  // masking along x is alpha_x's
}

TEST_CASE("brdf: anisotropic GGX, swapping alpha_x and alpha_y rotates by 90 degrees", "[brdf]") {
    check_rotation<float>();
    check_rotation<double>();
}

// Degenerate input: finite, non-negative results and the documented zeros, for every pair of bad
// roughnesses and the special directions (and -V, the mirror direction, the samples).
template <typename T>
void check_degenerate() {
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;
    using A = aniso<T>;
    const T big = std::numeric_limits<T>::max(), below_one = T(1) - std::numeric_limits<T>::epsilon() / 2;
    const T tiny = std::numeric_limits<T>::min(), denorm = std::numeric_limits<T>::denorm_min();
    const T bad[] = {T(0), -T(1), denorm, tiny, A::alpha_min, T(0.5), T(1e3), T(1e30), big,
                     std::numeric_limits<T>::quiet_NaN()};
    const vec2 us[] = {vec2(0, 0), vec2(0, below_one), vec2(below_one, 0), vec2(below_one, below_one), vec2(0.5, 0.5),
                       vec2(1, 1)};
    const std::vector<vec3> views = special_directions<T>();
    std::size_t failures = 0;
    for (const T ax : bad)
        for (const T ay : bad) {
            const alpha_of<T> a{ax, ay};
            for (const vec3& V : views) {
                std::vector<vec3> lights = special_directions<T>();
                lights.push_back(-V);
                lights.push_back(V);
                lights.push_back(vec3(-V.x, -V.y, V.z));
                for (const vec2& u : us) {
                    const vec3 L = A::sample(V, u, a);
                    const vec3 h = A::sample_visible_normal(V, u, a);
                    lights.push_back(L);
                    if (!finite(L) || std::abs(glm::length(L) - T(1)) > 8 * std::numeric_limits<T>::epsilon() ||
                        !finite(h) || std::abs(glm::length(h) - T(1)) > 8 * std::numeric_limits<T>::epsilon()) {
                        ++failures;
                        UNSCOPED_INFO("sample: alpha (" << ax << ", " << ay << ") V " << V.x << " " << V.y << " "
                                                        << V.z << " u " << u.x << " " << u.y);
                    }
                }
                for (const vec3& L : lights) {
                    const T values[] = {A::eval(V, L, a), A::pdf(V, L, a), A::ndf(L, a), A::lambda(L, a),
                                        A::g1(L, a),      A::g2(V, L, a)};
                    bool ok = true;
                    for (const T x : values) ok = ok && std::isfinite(x) && x >= T(0);
                    if ((!(V.z > T(0)) || !(L.z > T(0))) && A::eval(V, L, a) != T(0)) ok = false;
                    if (!(V.z > T(0)) && A::pdf(V, L, a) != T(0)) ok = false;
                    if (!ok) {
                        ++failures;
                        UNSCOPED_INFO("alpha (" << ax << ", " << ay << ") V " << V.x << " " << V.y << " " << V.z
                                                << " L " << L.x << " " << L.y << " " << L.z);
                    }
                }
                if (A::eval(V, -V, a) != T(0) || A::pdf(V, -V, a) != T(0)) ++failures;
            }
        }
    CHECK(failures == 0);
    // Below the documented minimum (and NaN) the roughness is the minimum.
    const vec3 V = ltc::brdf::view_from_cos<T>(T(0.7));
    const vec3 L(-V.x, -V.y, V.z);
    const T nan = std::numeric_limits<T>::quiet_NaN();
    CHECK(A::eval(V, L, {T(0), T(0.3)}) == A::eval(V, L, {A::alpha_min, T(0.3)}));
    CHECK(A::pdf(V, L, {nan, T(0.3)}) == A::pdf(V, L, {A::alpha_min, T(0.3)}));
    CHECK(A::eval(V, L, {A::alpha_min, A::alpha_min}) > T(0));
}

TEST_CASE("brdf: anisotropic GGX, degenerate input", "[brdf]") {
    check_degenerate<float>();
    check_degenerate<double>();
}

// ---------------------------------------------------------------------------------------------
// ltc::ground_truth::integrate with the anisotropic parameter (double). Tolerances: 4 standard
// errors, the variance estimated from the same samples, fixed seeds (deterministic); the
// brute-force quadrature (support/brute_force.hpp) adds its own derived error bound.

namespace gt = ltc::ground_truth;

struct test_polygon {
    const char* name;
    std::vector<glm::dvec3> v;  // convex: the vertex mean is a kernel point
};

inline std::vector<test_polygon> test_polygons() {
    return {{"quad above", {{-0.6, -0.3, 1.0}, {0.7, -0.4, 1.1}, {0.8, 0.6, 0.9}, {-0.5, 0.7, 1.0}}},
            {"quad straddling", {{-1.0, 0.2, -0.4}, {1.0, 0.1, -0.4}, {0.9, 1.2, 1.0}, {-0.8, 1.1, 1.0}}},
            {"triangle off-axis", {{0.9, -0.2, 0.3}, {1.0, 0.6, 0.5}, {0.4, 0.3, 1.0}}}};
}

// At alpha_x == alpha_y the anisotropic ground truth is the isotropic one: with the same seed the
// same estimate, bit for bit (the same model values and random numbers through the same code);
// with another seed, within 4 standard errors of the difference.
TEST_CASE("ground truth: anisotropic GGX at alpha_x == alpha_y is the isotropic ground truth", "[brdf][ground_truth]") {
    const glm::dvec3 V = direction(50, 20);
    for (const test_polygon& p : test_polygons())
        for (const double a : {0.15, 0.6}) {
            gt::options opt;
            opt.samples = 1u << 15;
            opt.seed = 7;
            const gt::estimate iso = gt::integrate(ltc::brdf::ggx<double>{}, V, a, p.v.data(), p.v.size(), opt);
            const gt::estimate same =
                gt::integrate(aniso<double>{}, V, alpha_of<double>{a, a}, p.v.data(), p.v.size(), opt);
            opt.seed = 8;
            const gt::estimate other =
                gt::integrate(aniso<double>{}, V, alpha_of<double>{a, a}, p.v.data(), p.v.size(), opt);
            CAPTURE(p.name, a, iso.mean, iso.standard_error, other.mean, other.standard_error);
            CHECK(iso.mean > 0);
            CHECK(same_bits(same.mean, iso.mean));
            CHECK(same_bits(same.standard_error, iso.standard_error));
            CHECK(same.samples == iso.samples);
            const double se = std::sqrt(iso.standard_error * iso.standard_error +
                                        other.standard_error * other.standard_error);
            CHECK(std::abs(other.mean - iso.mean) <= 4 * se);
        }
}

// For alpha_x != alpha_y: the MIS estimate (and each technique alone) against a brute-force
// quadrature of eval over the polygon in solid angle (split at the horizon, where eval has a
// kink), within 4 standard errors plus the quadrature's error bound.
TEST_CASE("ground truth: anisotropic GGX agrees with a brute-force quadrature", "[brdf][ground_truth]") {
    struct view_alpha {
        double theta_v, phi_v, ax, ay;
    };
    const view_alpha cases[] = {{40, 10, 0.1, 0.5}, {70, 120, 0.6, 0.2}};
    for (const test_polygon& p : test_polygons())
        for (const view_alpha& c : cases) {
            const glm::dvec3 V = direction(c.theta_v, c.phi_v);
            const alpha_of<double> a{c.ax, c.ay};
            glm::dvec3 kernel(0);
            for (const glm::dvec3& x : p.v) kernel += x / double(p.v.size());
            ltc_test::brute_force_options bo;
            bo.rel_tol = 1e-9;
            bo.max_leaves = 20000;
            // |grad_w eval| |w| / eval for the rounding term, away from the horizon: D's
            // logarithmic derivative ~2 / alpha per axis, through h = (V + w) / |V + w| with
            // |V + w| >= (V + w).z >= V.z, and G2's. That term is O(u) relative: negligible
            // next to the standard errors, whatever the margin.
            bo.direction_condition = 8 / (std::min(c.ax, c.ay) * V.z);
            // eval on the piece's side of the horizon, as s = w.z (exact at the split) says.
            const auto f = [&](const glm::dvec3& w, double s) {
                return std::array<double, 1>{s > 0 ? aniso<double>::eval(V, w, a) : 0.0};
            };
            const auto bf = ltc_test::integrate_polygon<1>(p.v, kernel, glm::dvec3(0, 0, 1), f, bo);
            REQUIRE(bf.converged);
            for (const auto use : {gt::techniques::mis, gt::techniques::brdf_only, gt::techniques::polygon_only}) {
                gt::options opt;
                opt.samples = 1u << 16;
                opt.seed = 2016;
                opt.use = use;
                const gt::estimate e = gt::integrate(aniso<double>{}, V, a, p.v.data(), p.v.size(), opt);
                CAPTURE(p.name, c.theta_v, c.phi_v, c.ax, c.ay, int(use), e.mean, e.standard_error, bf.value[0],
                        bf.error[0], bf.leaves);
                CHECK(bf.value[0] > 0);
                CHECK(std::abs(e.mean - bf.value[0]) <= 4 * e.standard_error + bf.error[0]);
                if (use == gt::techniques::mis) CHECK(e.standard_error <= 0.02 * bf.value[0]);  // a useful estimate
            }
        }
}

}  // namespace ltc_test_brdf_anisotropic
