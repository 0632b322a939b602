// Tests of the microfacet BRDF models of ltc/brdf (ggx, beckmann) that the LTC fit is made
// against: normalization of D and of the visible normals, the sampler against its pdf
// (normalization and a chi-square test), unbiasedness of eval / pdf, reciprocity, energy, the
// robust closed forms against the textbook ones, and degenerate input.
//
// Configurations: both models, float and double, alpha in {0.05, 0.2, 0.5, 1}, theta_v in
// {0, 30, 60, 85} degrees, V = view_from_cos(cos theta_v) (in the xz-plane).
//
// Tolerances.
//   - Quadrature (support/brdf_quadrature.hpp: product Gauss-Legendre rules of n and 2n points
//     on quadtree cells, refined until the summed |Q_n - Q_2n| of the double model is <= 1e-10
//     or 1e-11): the error of the 2n-point value is bounded by that sum (geometric convergence
//     on cells where the integrand is analytic; every jump or kink is on a cell boundary). The
//     tests require convergence, so an unresolved integrand cannot pass with a wide error bar.
//   - Rounding of the model in precision T (the quadrature itself runs in double): rho_T(alpha)
//     = (256 + 16 / alpha) eps_T relative, a worst-case bound per node, hence for the integral:
//       * the node direction is rounded to T, which moves it by ~eps_T; D's logarithmic
//         derivative along theta is <= 2 / alpha for GGX and ~2 k / alpha for Beckmann at
//         tan theta = k alpha, and the tail beyond k = 8 carries < e^-64 of the mass: <= 16 / alpha;
//       * ~10 roundings in the rational parts, and Beckmann's exp(-e) with e <= 64 (beyond,
//         the mass is negligible) computed from an e with ~4 eps_T relative error: 256 eps_T.
//   - Monte Carlo: 4 standard errors, the variance estimated from the same samples. Acceptable
//     here: N = 10^5 samples of a bounded weight (GGX: eval / pdf = G2 / G1(V) <= 1; Beckmann:
//     G2 V.h / (V.z h.z) <= 4 / V.z^2, as L.z > 0 needs h.z > V.z / (2 V.h)), so the variance
//     estimate's own relative error is ~ sqrt(2 / N) ~ 0.5%. (A run with 2e7 samples agrees
//     with the quadrature albedos within 1.3 standard errors.)
//   - Chi-square: below the p = 1e-4 critical value (Wilson-Hilferty approximation).
#include <ltc/fitting/brdf/beckmann.hpp>
#include <ltc/fitting/brdf/ggx.hpp>

#include <catch2/catch.hpp>

#include "support/brdf_quadrature.hpp"
#include "support/rng.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace {

constexpr double pi = 3.141592653589793238462643383279502884;
constexpr std::size_t n_alpha = 4, n_theta = 4;
constexpr double alphas[n_alpha] = {0.05, 0.2, 0.5, 1.0};
constexpr double theta_v_deg[n_theta] = {0, 30, 60, 85};

double theta_v(std::size_t it) { return theta_v_deg[it] * pi / 180; }

template <typename T>
glm::vec<3, T> view(std::size_t it) {
    return ltc::brdf::view_from_cos<T>(static_cast<T>(std::cos(theta_v(it))));
}

template <typename T>
double eps() {
    return static_cast<double>(std::numeric_limits<T>::epsilon());
}

/// Relative rounding bound of the model in precision T (file comment).
template <typename T>
double rho(double alpha) {
    return (256 + 16 / alpha) * eps<T>();
}

template <typename T>
bool finite(const glm::vec<3, T>& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// ---------------------------------------------------------------------------------------------
// Model families: TestType is M<T>; the references are computed once per family.

/// Quadrature reference of one (model, alpha, theta_v): the integrals over the sphere of L of
/// pdf(V, L) and eval(V, L), in double and float, by the adaptive rule of
/// support/brdf_quadrature.hpp in (theta, phi). Coarse grid: theta breaks at pi / 2 (eval's
/// horizon) and at pi - theta_v, the circle (V + L).z = 0 where the half vector crosses the
/// horizon (GGX's pdf jumps there; Beckmann's flips h); that circle goes through L = -V, a mesh
/// corner (theta = pi - theta_v, phi = pi) where GGX's pdf has a bounded direction-dependent
/// limit and Beckmann's an integrable 1 / |V + L| singularity; theta_v too (the lobe's peak, the
/// mirror direction, is the corner (theta_v, pi)). Every integrand is even in L.y (isotropic
/// model, V in the xz-plane; checked by the reciprocity test), so only phi in [0, pi] is
/// integrated, and each leaf stands for itself and its mirror image in phi in [pi, 2 pi].
/// The double pdf and eval steer the refinement, to a summed |Q_n - Q_2n| <= 1e-10 each.
struct reference {
    ltc_test::quadtree_integral<4> q;  // components: pdf, eval (double); pdf, eval (float)
    double pdf_total[2], pdf_error[2], albedo[2], albedo_error[2];  // [0]: double, [1]: float
};

constexpr double reference_tol = 1e-10;

template <typename T>
constexpr int precision_index() {
    return std::is_same<T, float>::value ? 1 : 0;
}

template <template <typename> class M>
reference make_reference(double alpha, double tv) {
    using Bd = M<double>;
    using Bf = M<float>;
    const glm::dvec3 Vd = ltc::brdf::view_from_cos<double>(std::cos(tv));
    const glm::vec3 Vf = ltc::brdf::view_from_cos<float>(static_cast<float>(std::cos(tv)));
    const float af = static_cast<float>(alpha);
    const auto f = [&](const glm::dvec3& L) -> std::array<double, 4> {
        const glm::vec3 Lf(L);
        return {Bd::pdf(Vd, L, alpha), Bd::eval(Vd, L, alpha), static_cast<double>(Bf::pdf(Vf, Lf, af)),
                static_cast<double>(Bf::eval(Vf, Lf, af))};
    };
    reference r;
    r.q = ltc_test::integrate_adaptive<4>(f, ltc_test::z_frame(),
                                          ltc_test::breakpoints(0, pi, {tv, pi / 2, pi - tv}, pi / 8),
                                          ltc_test::breakpoints(0, pi, {}, pi / 8), 5, 2, reference_tol);
    for (int p = 0; p < 2; ++p) {
        r.pdf_total[p] = 2 * r.q.value[2 * p];
        r.pdf_error[p] = 2 * r.q.error[2 * p];
        r.albedo[p] = 2 * r.q.value[2 * p + 1];
        r.albedo_error[p] = 2 * r.q.error[2 * p + 1];
    }
    return r;
}

template <template <typename> class M>
const reference& reference_for(std::size_t ia, std::size_t it) {
    static std::unique_ptr<reference> cache[n_alpha][n_theta];
    std::unique_ptr<reference>& p = cache[ia][it];
    if (!p) p.reset(new reference(make_reference<M>(alphas[ia], theta_v(it))));
    return *p;
}

template <typename B>
struct family;
template <template <typename> class M, typename T>
struct family<M<T>> {
    using as_double = M<double>;
    static const reference& ref(std::size_t ia, std::size_t it) { return reference_for<M>(ia, it); }
};
template <typename B>
using rebind_double = typename family<B>::as_double;

// ---------------------------------------------------------------------------------------------
// Hemisphere integrals in the lune frame (support/brdf_quadrature.hpp): h = cos(b) y +
// sin(b) (cos(p) x + sin(p) z); h.z > 0 is p in (0, pi), and V.h > 0 is p in (-theta_v,
// pi - theta_v). D peaks at h = z, the grid corner b = p = pi / 2. The integrand returns the
// double model (which steers the refinement, to 1e-11) and the model in T.

constexpr double lune_tol = 1e-11;

template <typename F>
ltc_test::quadtree_integral<2> lune_integral(const F& f, double psi_max) {
    return ltc_test::integrate_adaptive<2>(f, ltc_test::lune_frame(), ltc_test::breakpoints(0, pi, {pi / 2}, pi / 8),
                                           ltc_test::breakpoints(0, psi_max, {pi / 2}, pi / 8), 6, 1, lune_tol);
}

/// Chi-square critical value at upper-tail probability 1e-4, Wilson-Hilferty (1931): for
/// X ~ chi^2_k, (X / k)^(1/3) is nearly normal with mean 1 - 2 / (9k) and variance 2 / (9k), so
/// x_p = k (1 - 2 / (9k) + z_p sqrt(2 / (9k)))^3 with z_p = Phi^-1(1 - 1e-4) = 3.7190165.
/// (Relative error < 1e-3 for k >= 10, far below what matters here.)
double chi2_critical_1e4(double k) {
    const double z = 3.7190164854556804, c = 2 / (9 * k);
    const double b = 1 - c + z * std::sqrt(c);
    return k * b * b * b;
}

#define LTC_BRDF_TYPES \
    ltc::brdf::ggx<float>, ltc::brdf::ggx<double>, ltc::brdf::beckmann<float>, ltc::brdf::beckmann<double>

}  // namespace

// (a) int D(h) cos(theta_h) dh = 1 over the upper hemisphere.
TEMPLATE_TEST_CASE("brdf: the NDF is normalized", "[brdf]", LTC_BRDF_TYPES) {
    using B = TestType;
    using Bd = rebind_double<B>;
    using T = typename B::scalar;
    for (const double alpha : alphas) {
        const auto f = [&](const glm::dvec3& h) -> std::array<double, 2> {
            const double dt = static_cast<double>(B::ndf(glm::vec<3, T>(h), static_cast<T>(alpha)));
            return {Bd::ndf(h, alpha) * h.z, dt * h.z};
        };
        const auto q = lune_integral(f, pi);
        INFO(B::name << " alpha " << alpha << ": " << q.value[1] << " +- " << q.error[1] << " (" << q.leaves.size()
                     << " cells)");
        CHECK(q.converged);
        CHECK(std::abs(q.value[1] - 1) <= q.error[1] + rho<T>(alpha));
    }
}

// (b) Smith's visible-normal normalization: int G1(V) max(0, V.h) D(h) dh = V.z, the projected
// area of the visible microsurface equals that of the macrosurface (Heitz 2014, JCGT 3(2); it
// is why D_V of Heitz 2018 is a density). Integrated over the lune {h.z > 0, V.h > 0}.
TEMPLATE_TEST_CASE("brdf: the visible normals are normalized", "[brdf]", LTC_BRDF_TYPES) {
    using B = TestType;
    using Bd = rebind_double<B>;
    using T = typename B::scalar;
    for (const double alpha : alphas)
        for (std::size_t it = 0; it < n_theta; ++it) {
            const glm::vec<3, T> V = view<T>(it);
            const glm::dvec3 Vd(V);
            const T a = static_cast<T>(alpha);
            const double g1 = static_cast<double>(B::g1(V, a)), g1d = Bd::g1(Vd, alpha);
            const auto f = [&](const glm::dvec3& h) -> std::array<double, 2> {
                const glm::vec<3, T> ht(h);
                const double vh = std::max(0.0, static_cast<double>(glm::dot(V, ht)));
                const double dt = static_cast<double>(B::ndf(ht, a));
                return {g1d * std::max(0.0, glm::dot(Vd, h)) * Bd::ndf(h, alpha), g1 * vh * dt};
            };
            const auto q = lune_integral(f, pi - std::atan2(Vd.x, Vd.z));
            INFO(B::name << " alpha " << alpha << " theta_v " << theta_v_deg[it] << ": " << q.value[1] << " +- "
                         << q.error[1] << ", V.z " << Vd.z);
            CHECK(q.converged);
            CHECK(std::abs(q.value[1] - Vd.z) <= q.error[1] + rho<T>(alpha) * Vd.z);
        }
}

// (c) int pdf(V, L) dL = 1 over the whole sphere (sample() may go below the horizon).
TEMPLATE_TEST_CASE("brdf: the pdf integrates to one over the sphere", "[brdf]", LTC_BRDF_TYPES) {
    using B = TestType;
    using T = typename B::scalar;
    const int p = precision_index<T>();
    for (std::size_t ia = 0; ia < n_alpha; ++ia)
        for (std::size_t it = 0; it < n_theta; ++it) {
            const reference& r = family<B>::ref(ia, it);
            INFO(B::name << " alpha " << alphas[ia] << " theta_v " << theta_v_deg[it] << ": "
                         << r.pdf_total[p] << " +- " << r.pdf_error[p]);
            // The mesh resolves the double pdf. In float, Beckmann's pdf ~ 1 / |V + L| next to
            // L = -V has a relative condition number ~ eps / |V + L| in L, so rounding the nodes
            // to float shows as noise in |Q_n - Q_2n|, which its tolerance includes.
            CHECK(r.q.converged);
            CHECK(std::abs(r.pdf_total[p] - 1) <= r.pdf_error[p] + rho<T>(alphas[ia]));
        }
}

// (d) sample() is distributed as pdf(): chi-square goodness of fit, and (e) eval / pdf is an
// unbiased estimator of the directional albedo: the Monte Carlo mean agrees with the quadrature
// albedo within 4 standard errors. One set of samples serves both.
//
// Bins: the leaves of the reference quadrature (theta, phi on either side of phi = pi), merged
// greedily in their depth-first order (a partition fixed by the expected probabilities alone,
// never by the data) until each bin expects >= 16 samples; the remainder joins the last bin.
// The statistic has (bins - 1) degrees of freedom. The expected probabilities come from the
// double-precision pdf, also for the float sampler (its directions differ from the exact ones by
// ~eps_float, far below the cell sizes that carry mass).
TEMPLATE_TEST_CASE("brdf: sample() follows pdf(), and eval / pdf is unbiased", "[brdf]", LTC_BRDF_TYPES) {
    using B = TestType;
    using T = typename B::scalar;
    using vec3 = glm::vec<3, T>;
    const int p = precision_index<T>();
    const std::size_t N = 100000;
    for (std::size_t ia = 0; ia < n_alpha; ++ia)
        for (std::size_t it = 0; it < n_theta; ++it) {
            const reference& r = family<B>::ref(ia, it);
            const std::size_t half = r.q.leaves.size();
            const vec3 V = view<T>(it);
            const T alpha = static_cast<T>(alphas[ia]);
            ltc_test::rng rng(0x5eed0000u + 16 * ia + it);
            std::vector<double> count(2 * half, 0.0);
            std::size_t bad_direction = 0, bad_pdf = 0;
            double sum = 0, sum2 = 0;
            for (std::size_t k = 0; k < N; ++k) {
                const vec3 L = B::sample(V, rng.uniform2<T>(), alpha);
                if (!finite(L) || std::abs(static_cast<double>(glm::length(L)) - 1) > 8 * eps<T>()) {
                    ++bad_direction;
                    continue;
                }
                const T pdf = B::pdf(V, L, alpha);
                if (!(pdf > T(0)) || !std::isfinite(pdf)) {
                    ++bad_pdf;
                    continue;
                }
                const double w = static_cast<double>(B::eval(V, L, alpha) / pdf);
                sum += w;
                sum2 += w * w;
                const glm::dvec3 Ld(L);
                const double th = std::atan2(std::sqrt(Ld.x * Ld.x + Ld.y * Ld.y), Ld.z);
                const double ph = std::atan2(Ld.y, Ld.x);  // (-pi, pi]: phi in (pi, 2 pi) is ph < 0
                count[(ph < 0 ? half : 0) + r.q.locate(th, std::abs(ph))] += 1;
            }
            INFO(B::name << " alpha " << alphas[ia] << " theta_v " << theta_v_deg[it]);
            CHECK(bad_direction == 0);
            CHECK(bad_pdf == 0);

            // (d) chi-square
            std::vector<double> bin_expected, bin_observed;
            double expected = 0, observed = 0;
            for (std::size_t c = 0; c < 2 * half; ++c) {
                expected += N * r.q.nodes[r.q.leaves[c % half]].value[0];
                observed += count[c];
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
            const std::size_t bins = bin_expected.size();
            const double df = static_cast<double>(bins - 1), crit = chi2_critical_1e4(df);
            INFO("chi2 " << chi2 << " with " << df << " dof, critical value (p = 1e-4) " << crit);
            CHECK(bins > 20);
            CHECK(chi2 < crit);

            // (e) Monte Carlo albedo vs quadrature
            const double mean = sum / N, var = std::max(0.0, sum2 / N - mean * mean) * N / (N - 1);
            const double se = std::sqrt(var / N);
            INFO("albedo: MC " << mean << " +- " << se << ", quadrature " << r.albedo[p] << " +- "
                               << r.albedo_error[p]);
            CHECK(std::abs(mean - r.albedo[p]) <= 4 * se + r.albedo_error[p] + rho<T>(alphas[ia]) * r.albedo[p]);
        }
}

// (f) reciprocity: rho(V, L) = rho(L, V), i.e. eval(V, L) / L.z == eval(L, V) / V.z. Both sides
// evaluate the same D (V + L == L + V exactly) and a G2 symmetric up to the order of two
// additions; with the divisions that is <= ~8 roundings per side: 16 eps_T relative. The pdf
// and eval are also even in L.y for V in the xz-plane (used by the quadrature references):
// the same bound.
TEMPLATE_TEST_CASE("brdf: reciprocity and mirror symmetry", "[brdf]", LTC_BRDF_TYPES) {
    using B = TestType;
    using T = typename B::scalar;
    using vec3 = glm::vec<3, T>;
    ltc_test::rng rng(20160724);
    const double tol = 16 * eps<T>();
    for (const double alpha : {0.0001, 0.05, 0.2, 0.5, 1.0, 3.0}) {
        const T a = static_cast<T>(alpha);
        for (int k = 0; k < 2000; ++k) {
            glm::dvec3 v = rng.direction(), l = rng.direction();
            v.z = std::abs(v.z), l.z = std::abs(l.z);
            const vec3 V(v), L(l);
            const double f = static_cast<double>(B::eval(V, L, a) / L.z);
            const double g = static_cast<double>(B::eval(L, V, a) / V.z);
            INFO(B::name << " alpha " << alpha << " V " << v.x << " " << v.y << " " << v.z << " L " << l.x
                         << " " << l.y << " " << l.z << ": " << f << " vs " << g);
            REQUIRE(std::isfinite(f));
            // (+ the smallest normal T: subnormal results have no relative precision)
            const double floor = static_cast<double>(std::numeric_limits<T>::min());
            REQUIRE(std::abs(f - g) <= tol * std::max(std::abs(f), std::abs(g)) + floor);
            const vec3 Vxz(V.x, T(0), V.z), Lm(L.x, -L.y, L.z);  // V in the xz-plane (not unit: scaled below)
            const vec3 Vn = Vxz / glm::length(Vxz);
            const double p1 = static_cast<double>(B::pdf(Vn, L, a)), p2 = static_cast<double>(B::pdf(Vn, Lm, a));
            const double e1 = static_cast<double>(B::eval(Vn, L, a)), e2 = static_cast<double>(B::eval(Vn, Lm, a));
            REQUIRE(std::abs(p1 - p2) <= tol * std::max(p1, p2) + floor);
            REQUIRE(std::abs(e1 - e2) <= tol * std::max(e1, e2) + floor);
        }
    }
}

// (g) energy: the directional albedo int eval dL <= 1 (no Fresnel, G2 <= G1: the white furnace
// loses energy to single-scattering), and for GGX at normal incidence it decreases with alpha.
TEMPLATE_TEST_CASE("brdf: energy conservation", "[brdf]", LTC_BRDF_TYPES) {
    using B = TestType;
    using T = typename B::scalar;
    const int p = precision_index<T>();
    for (std::size_t ia = 0; ia < n_alpha; ++ia)
        for (std::size_t it = 0; it < n_theta; ++it) {
            const reference& r = family<B>::ref(ia, it);
            INFO(B::name << " alpha " << alphas[ia] << " theta_v " << theta_v_deg[it] << ": albedo "
                         << r.albedo[p] << " +- " << r.albedo_error[p]);
            CHECK(r.albedo[p] > 0);
            CHECK(r.albedo[p] <= 1 + r.albedo_error[p] + rho<T>(alphas[ia]));
        }
    if (std::string(B::name) == "ggx")
        for (std::size_t ia = 0; ia + 1 < n_alpha; ++ia) {
            const reference &r0 = family<B>::ref(ia, 0), &r1 = family<B>::ref(ia + 1, 0);
            INFO("alpha " << alphas[ia] << " -> " << alphas[ia + 1] << ": " << r0.albedo[p] << " -> "
                          << r1.albedo[p]);
            CHECK(r0.albedo[p] - r1.albedo[p] >
                  r0.albedo_error[p] + r1.albedo_error[p] + rho<T>(alphas[ia]) + rho<T>(alphas[ia + 1]));
        }
}

// The robust closed forms of the headers against the textbook ones, in double, away from the
// cancellations that the textbook forms suffer (theta in [3, 87] degrees): relative 1e-10
// (the textbook -1 + sqrt(1 + x) loses up to eps / x ~ 1e-12 for x = alpha^2 tan^2 >= 5e-6).
TEST_CASE("brdf: the robust forms agree with the textbook formulas", "[brdf]") {
    using G = ltc::brdf::ggx<double>;
    using K = ltc::brdf::beckmann<double>;
    ltc_test::rng rng(42);
    const auto rel = [](double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); };
    for (const double a : {0.05, 0.2, 0.5, 1.0}) {
        for (int k = 0; k < 500; ++k) {
            glm::dvec3 V = rng.direction(), L = rng.direction();
            V.z = std::abs(V.z), L.z = std::abs(L.z);
            if (V.z < 0.05 || V.z > 0.9986 || L.z < 0.05 || L.z > 0.9986) continue;
            const glm::dvec3 h = glm::normalize(V + L);
            const double ch = h.z, t2h = (1 - ch * ch) / (ch * ch);
            const auto tan2 = [](const glm::dvec3& w) { return (1 - w.z * w.z) / (w.z * w.z); };
            // GGX
            const double Dg = a * a / (pi * std::pow(ch * ch * (a * a - 1) + 1, 2));
            const auto lam_g = [&](const glm::dvec3& w) { return (-1 + std::sqrt(1 + a * a * tan2(w))) / 2; };
            const double G2g = 1 / (1 + lam_g(V) + lam_g(L)), G1g = 1 / (1 + lam_g(V));
            CHECK(rel(G::ndf(h, a), Dg) < 1e-10);
            CHECK(rel(G::lambda(V, a), lam_g(V)) < 1e-10);
            CHECK(rel(G::g1(V, a), G1g) < 1e-10);
            CHECK(rel(G::g2(V, L, a), G2g) < 1e-10);
            CHECK(rel(G::eval(V, L, a), Dg * G2g / (4 * V.z)) < 1e-10);
            CHECK(rel(G::pdf(V, L, a), G1g * glm::dot(V, h) * Dg / V.z / (4 * glm::dot(V, h))) < 1e-10);
            // Beckmann
            const double Db = std::exp(-t2h / (a * a)) / (pi * a * a * std::pow(ch, 4));
            const auto lam_b = [&](const glm::dvec3& w) {
                const double x = 1 / (a * std::sqrt(tan2(w)));
                return (std::erf(x) - 1) / 2 + std::exp(-x * x) / (2 * x * std::sqrt(pi));
            };
            const double G2b = 1 / (1 + lam_b(V) + lam_b(L));
            CHECK(rel(K::ndf(h, a), Db) < 1e-10);
            CHECK(std::abs(K::lambda(V, a) - lam_b(V)) < 1e-12);  // tiny for large 1 / (alpha tan)
            CHECK(rel(K::g2(V, L, a), G2b) < 1e-10);
            CHECK(rel(K::eval(V, L, a), Db * G2b / (4 * V.z)) < 1e-10);
            CHECK(rel(K::pdf(V, L, a), Db * ch / (4 * std::abs(glm::dot(V, h)))) < 1e-10);
        }
    }
    // Closed-form spot values: GGX Lambda at tan theta = sqrt(3), alpha = 1 is (-1 + 2) / 2.
    CHECK(G::lambda(ltc::brdf::view_from_cos(0.5), 1.0) == Approx(0.5).epsilon(1e-14));
    CHECK(G::ndf(glm::dvec3(0, 0, 1), 0.5) == Approx(1 / (pi * 0.25)).epsilon(1e-14));
    CHECK(K::ndf(glm::dvec3(0, 0, 1), 0.5) == Approx(1 / (pi * 0.25)).epsilon(1e-14));
    CHECK(K::lambda(glm::dvec3(0, 0, 1), 0.5) == 0);
}

// (h) degenerate input: finite, non-negative results, and the documented limits.
TEMPLATE_TEST_CASE("brdf: degenerate input", "[brdf]", LTC_BRDF_TYPES) {
    using B = TestType;
    using T = typename B::scalar;
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;
    const T big = std::numeric_limits<T>::max(), below_one = T(1) - std::numeric_limits<T>::epsilon() / 2;
    const T tiny = std::numeric_limits<T>::min(), denorm = std::numeric_limits<T>::denorm_min();
    const std::vector<T> alphas_bad = {T(0), -T(1), denorm, tiny, T(1e-30), B::alpha_min, T(0.5), T(1), T(1e3),
                                       T(1e30), big};
    const std::vector<vec3> views = {
        vec3(0, 0, 1),
        vec3(1, 0, 0),                                   // V.z = 0
        vec3(0.6, 0, -0.8),                              // below the horizon
        ltc::brdf::view_from_cos<T>(T(1e-3)),            // grazing
        ltc::brdf::view_from_cos<T>(tiny),               // V.z = smallest normal
        vec3(1, 0, denorm),                              // V.z subnormal
        ltc::brdf::view_from_cos<T>(T(1) - std::numeric_limits<T>::epsilon()),  // nearly normal
    };
    const std::vector<vec2> us = {vec2(0, 0), vec2(0, below_one), vec2(below_one, 0), vec2(below_one, below_one),
                                  vec2(T(0.5), T(0.5)), vec2(1, 1)};
    for (const T a : alphas_bad)
        for (const vec3& V : views) {
            std::vector<vec3> lights = {-V, V, vec3(1, 0, 0), vec3(0, 0, 1), vec3(0, 0, -1), vec3(-V.x, -V.y, V.z),
                                        vec3(0, 1, 0), vec3(-1, 0, denorm)};
            for (const vec2& u : us) lights.push_back(B::sample(V, u, a));
            for (const vec2& u : us) {
                const vec3 L = B::sample(V, u, a);
                INFO(B::name << " alpha " << a << " V " << V.x << " " << V.y << " " << V.z << " u " << u.x << " "
                             << u.y);
                CHECK(finite(L));
                CHECK(std::abs(glm::length(L) - T(1)) <= 8 * std::numeric_limits<T>::epsilon());
            }
            for (const vec3& L : lights) {
                INFO(B::name << " alpha " << a << " V " << V.x << " " << V.y << " " << V.z << " L " << L.x << " "
                             << L.y << " " << L.z);
                const T values[] = {B::eval(V, L, a), B::pdf(V, L, a), B::ndf(L, a), B::lambda(L, a),
                                    B::g1(L, a), B::g2(V, L, a)};
                for (const T x : values) {
                    CHECK(std::isfinite(x));
                    CHECK(x >= T(0));
                }
                if (!(V.z > T(0)) || !(L.z > T(0))) CHECK(B::eval(V, L, a) == T(0));
                if (!(V.z > T(0))) CHECK(B::pdf(V, L, a) == T(0));
            }
            CHECK(B::eval(V, -V, a) == T(0));
            CHECK(B::pdf(V, -V, a) == T(0));
        }
    // alpha below the documented minimum behaves as the minimum (a Dirac is not a density).
    const vec3 V = ltc::brdf::view_from_cos<T>(T(0.7));
    const vec3 L(-V.x, -V.y, V.z);
    CHECK(B::eval(V, L, T(0)) == B::eval(V, L, B::alpha_min));
    CHECK(B::pdf(V, L, T(0)) == B::pdf(V, L, B::alpha_min));
    CHECK(B::eval(V, L, B::alpha_min) > T(0));
}
