// Importance sampling of Linearly Transformed Spherical Distributions (supplement section 2.4,
// Algorithm 1: w_o ~ D_o, w = M w_o / |M w_o| has pdf D), for the four original distributions, in
// float and double, for the original distributions themselves (Dist::sample) and for the test
// matrices of support/sphere_quadrature.hpp:
//   (a) the moments E[w] and E[w_i^2] of N samples match the moments computed by quadrature
//       within 4 Monte Carlo standard errors (sigma from the quadrature moments, not the samples);
//   (b) every sample is a unit vector with pdf(w) > 0, and pdf == eval;
//   (c) a chi-square goodness-of-fit test of the sampler against the exact cell probabilities of
//       a cube map (closed-form integrals of D over each cell);
//   (d) the ends of the domain of u: u = (0, 0) and u next to 1 give finite unit directions
//       with non-zero pdf. (The library's inversions: cos(theta) = 1 - 2 u.x (sphere), 1 - u.x
//       (hemisphere), sqrt(1 - u.x) (cosine), cbrt(1 - u.x) (squared cosine); phi = 2 pi u.y.)
// Every random sequence has a fixed seed (ltc_test::rng), so the tests are deterministic.
#include "support/original_distributions.hpp"
#include "support/chi_square.hpp"
#include "support/rng.hpp"
#include "support/sphere_quadrature.hpp"

#include <ltc/ltc.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace ltc_test_sampling {  // the file's own names, apart from the other files of a unity batch

namespace {

using ltc_test::named_matrix;

template <typename T>
double eps() {
    return static_cast<double>(std::numeric_limits<T>::epsilon());
}

/// One sampler under test: the original distribution (Dist::sample / Dist::pdf, M = I) or
/// transformed<Dist>(M). `M` holds exactly the entries of the matrix in precision T (the float
/// distribution's reference is the distribution of its rounded matrix).
template <typename Dist>
struct sampler_case {
    using T = typename Dist::scalar;
    std::string name;
    bool original;
    glm::dmat3 M;
    ltc::transformed<Dist> d;

    glm::vec<3, T> sample(const glm::vec<2, T>& u) const { return original ? Dist::sample(u) : d.sample(u); }
    T pdf(const glm::vec<3, T>& w) const { return original ? Dist::pdf(w) : d.pdf(w); }
    T eval(const glm::vec<3, T>& w) const { return original ? Dist::eval(w) : d.eval(w); }
    /// Exact probability of the spherical polygon, in double (closed form).
    double probability(const std::vector<glm::dvec3>& polygon) const {
        using D = ltc_test::as_double_t<Dist>;
        if (original) return D::integrate(polygon.data(), polygon.size());
        return ltc::transformed<D>(M).integrate(polygon.data(), polygon.size());
    }
};

template <typename Dist>
std::vector<sampler_case<Dist>> sampler_cases() {
    using T = typename Dist::scalar;
    std::vector<sampler_case<Dist>> cases;
    cases.push_back({"original", true, glm::dmat3(1.0), ltc::transformed<Dist>(glm::mat<3, 3, T>(1))});
    for (const named_matrix& nm : ltc_test::test_matrices()) {
        const glm::mat<3, 3, T> m(nm.m);
        cases.push_back({nm.name, false, glm::dmat3(m), ltc::transformed<Dist>(m)});
    }
    return cases;
}

/// First, second and fourth moments of the components of w (E[w_i], E[w_i^2], E[w_i^4]).
struct moments4 {
    glm::dvec3 m1{0}, m2{0}, m4{0};
};
moments4 operator+(const moments4& a, const moments4& b) { return {a.m1 + b.m1, a.m2 + b.m2, a.m4 + b.m4}; }
moments4 operator*(double s, const moments4& a) { return {s * a.m1, s * a.m2, s * a.m4}; }
// Found by argument-dependent lookup from ltc_test::integrate.
double max_abs(const moments4& a) {
    return std::max({ltc_test::max_abs(a.m1), ltc_test::max_abs(a.m2), ltc_test::max_abs(a.m4)});
}

/// The largest float / double below 1 (rng::uniform2 never exceeds it).
template <typename T>
T below_one() {
    return T(1) - std::numeric_limits<T>::epsilon() / 2;
}

using ltc_test::chi_square_critical_1e4;

}  // namespace

// -----------------------------------------------------------------------------------------------
// (a) Moments, and (b) unit length, pdf > 0 and pdf == eval of every sample.
//
// Reference moments: quadrature in the original space (ltc_test::expectation, order 128 and
// 256), E[g(w)] = integral of D_o(w_o) g(M w_o / |M w_o|) over D_o's support, with g = w_i,
// w_i^2, w_i^4; its error estimate is checked to be below 1e-9 (far below sigma ~ 1e-3).
// For the sample mean of X = w_i (or w_i^2) over N independent samples, sigma = sqrt(Var X / N)
// with Var w_i = E[w_i^2] - E[w_i]^2 and Var w_i^2 = E[w_i^4] - E[w_i^2]^2 from the quadrature.
// Allowed: 4 sigma (two-sided p = 6.3e-5 per check for a correct sampler, ~1% for all 288
// checks, and the seeds are fixed) + the quadrature's error estimate + the bias of rounding the
// samples in T: each sample's components are off by <= (7 kappa_F + 10) u_T (the product M w_o
// with gamma_3 relative to |M||w_o|, amplified by |M| / |M w_o| <= kappa_F, the normalization
// and the sampler of D_o <= 10 u), twice that for w_i^2.
//
// Unit length. transformed::sample normalizes with safe_normalize (dot gamma_3, sqrt u,
// reciprocal u, product u; its rare rescaled path is exact): | |w| - 1 | <= 4u; the original samplers build
// (cos phi sin theta, sin phi sin theta, cos theta) from cos theta and sin theta computed
// separately (each with <= 3u: 1 - u.x or cbrt, sqrt, products) and cos, sin of phi (u each):
// | |w| - 1 | <= 3u + 3u + u + u = 8u. Checked: <= 4 eps = 8u (|w| computed in double).
TEMPLATE_TEST_CASE("sampling: moments of the samples match the quadrature moments; samples are unit with pdf > 0",
                   "[sampling][moments]", LTC_ORIGINAL_DISTRIBUTIONS) {
    using Dist = TestType;
    using T = typename Dist::scalar;
    constexpr int N = 1 << 18;
    // Different streams for float and double, and for each case.
    std::uint64_t seed = 0x5a3d1e000001ull + (sizeof(T) == sizeof(float) ? 0x100 : 0x200);
    for (const sampler_case<Dist>& c : sampler_cases<Dist>()) {
        const auto g = [](const glm::dvec3& w) {
            const glm::dvec3 w2 = w * w;
            return moments4{w, w2, w2 * w2};
        };
        const ltc_test::estimate<moments4> ref = ltc_test::expectation<Dist, moments4>(c.M, g, 128);

        ltc_test::rng rng(seed++);
        glm::dvec3 s1(0), s2(0);
        double worst_norm = 0;  // | |w| - 1 | / eps
        long zero_pdf = 0, pdf_ne_eval = 0, not_finite = 0;
        for (int i = 0; i < N; ++i) {
            const glm::vec<3, T> w = c.sample(rng.uniform2<T>());
            const glm::dvec3 wd(w);
            if (!std::isfinite(wd.x) || !std::isfinite(wd.y) || !std::isfinite(wd.z)) {
                ++not_finite;
                continue;
            }
            worst_norm = std::max(worst_norm, std::abs(glm::length(wd) - 1) / eps<T>());
            const T p = c.pdf(w);
            if (!(p > T(0))) ++zero_pdf;
            if (!(p == c.eval(w))) ++pdf_ne_eval;
            s1 += wd;
            s2 += wd * wd;
        }
        const glm::dvec3 mean1 = s1 / double(N), mean2 = s2 / double(N);
        const double kappa = ltc_test::frobenius_condition(c.M);
        const double bias = (7 * kappa + 10) * eps<T>() / 2;
        double worst_sigma = 0;
        for (int k = 0; k < 3; ++k) {
            const double var1 = ref.value.m2[k] - ref.value.m1[k] * ref.value.m1[k];
            const double var2 = ref.value.m4[k] - ref.value.m2[k] * ref.value.m2[k];
            const double sigma1 = std::sqrt(std::max(var1, 0.0) / N), sigma2 = std::sqrt(std::max(var2, 0.0) / N);
            const double dev1 = std::abs(mean1[k] - ref.value.m1[k]), dev2 = std::abs(mean2[k] - ref.value.m2[k]);
            worst_sigma = std::max({worst_sigma, dev1 / sigma1, dev2 / sigma2});
            INFO(c.name << ", component " << k << ": E[w] sample " << mean1[k] << " vs quadrature " << ref.value.m1[k]
                        << " (" << dev1 / sigma1 << " sigma); E[w^2] sample " << mean2[k] << " vs "
                        << ref.value.m2[k] << " (" << dev2 / sigma2 << " sigma)");
            CHECK(dev1 <= 4 * sigma1 + ref.error + bias);
            CHECK(dev2 <= 4 * sigma2 + ref.error + 2 * bias);
        }
        INFO(c.name << ": largest deviation " << worst_sigma << " sigma; quadrature error estimate " << ref.error
                    << "; largest | |w| - 1 | = " << worst_norm << " eps");
        CHECK(ref.error <= 1e-9);
        CHECK(not_finite == 0);
        CHECK(worst_norm <= 4);
        CHECK(zero_pdf == 0);
        CHECK(pdf_ne_eval == 0);
    }
}

// -----------------------------------------------------------------------------------------------
// (c) Chi-square goodness of fit on the cube map.
//
// Bins: the 6 x 8 x 8 cells of the cube map (ltc_test::cube_map): a direction falls in the cell
// whose planar quad on the cube surface it pierces; the cell's exact probability is the closed
// form transformed<Dist>::integrate(cell quad, 4) (Dist::integrate for the original
// distributions), in double, for the distribution of the matrix rounded to T. Cells with expected
// count < 5 are pooled into one bin (Cochran's rule); if the pooled bin's expected count is still
// below 5 it is merged into the smallest regular bin. X^2 = sum (O - E)^2 / E over the bins, with
// bins - 1 degrees of freedom (no fitted parameters), must stay below the p = 1e-4 critical value
// (Wilson-Hilferty, above): a correct sampler fails one of the 48 checks with probability ~0.5%,
// and with fixed seeds the outcome is deterministic.
//
// The cell probabilities must add up to 1: as for the six faces in test_normalization.cpp, the
// computed cells tile the sphere exactly (shared corners are computed identically), so only the
// arithmetic of each edge term counts, <= 22 u per edge of a cell; 384 cells x 6 edges x 22 u
// < 51000 u = 25500 eps (5.7e-12 in double).
TEMPLATE_TEST_CASE("sampling: chi-square test of the samples against exact cube-map cell probabilities",
                   "[sampling][chi-square]", LTC_ORIGINAL_DISTRIBUTIONS) {
    using Dist = TestType;
    using T = typename Dist::scalar;
    constexpr int N = 1 << 18;
    const ltc_test::cube_map cube{8};
    std::uint64_t seed = 0xc41500000001ull + (sizeof(T) == sizeof(float) ? 0x100 : 0x200);
    for (const sampler_case<Dist>& c : sampler_cases<Dist>()) {
        std::vector<double> p(cube.cells());
        double total = 0;
        for (int i = 0; i < cube.cells(); ++i) total += p[i] = c.probability(cube.cell_quad(i));

        std::vector<long> observed(cube.cells(), 0);
        ltc_test::rng rng(seed++);
        for (int i = 0; i < N; ++i) ++observed[cube.cell_of(glm::dvec3(c.sample(rng.uniform2<T>())))];

        // Pooling.
        double pooled_e = 0, x2 = 0;
        long pooled_o = 0, in_zero_cells = 0;
        std::vector<double> e_bins;
        std::vector<long> o_bins;
        for (int i = 0; i < cube.cells(); ++i) {
            if (p[i] == 0) in_zero_cells += observed[i];
            const double e = N * p[i];
            if (e < 5) {
                pooled_e += e;
                pooled_o += observed[i];
            } else {
                e_bins.push_back(e);
                o_bins.push_back(observed[i]);
            }
        }
        REQUIRE(!e_bins.empty());
        if (pooled_e >= 5) {
            e_bins.push_back(pooled_e);
            o_bins.push_back(pooled_o);
        } else {
            const auto smallest = std::min_element(e_bins.begin(), e_bins.end()) - e_bins.begin();
            e_bins[smallest] += pooled_e;
            o_bins[smallest] += pooled_o;
        }
        for (std::size_t b = 0; b < e_bins.size(); ++b) {
            const double diff = static_cast<double>(o_bins[b]) - e_bins[b];
            x2 += diff * diff / e_bins[b];
        }
        const int dof = static_cast<int>(e_bins.size()) - 1;
        const double critical = chi_square_critical_1e4(dof);
        INFO(c.name << ": X^2 = " << x2 << " with " << dof << " dof, critical value (p = 1e-4) " << critical
                    << "; sum of cell probabilities - 1 = " << total - 1);
        REQUIRE(dof >= 1);
        CHECK(std::abs(total - 1) <= 25500 * eps<double>());
        CHECK(in_zero_cells == 0);  // no sample where the density integrates to exactly 0
        CHECK(x2 < critical);
    }
}

// -----------------------------------------------------------------------------------------------
// (d) The ends of the domain of u: u.x in {0, the smallest subnormal, 1/2, and the 16 largest
// values below 1}, u.y in {0, k / 256, the largest value below 1}. Unit length within 4 eps as in
// (a). Next to u.x = 1 the original sample is next to D_o's horizon (z_o = 1 - u.x for the
// uniform hemisphere: down to eps / 2), and the round trip w = M w_o / |M w_o| -> M^-1 w must
// still land on the positive side for pdf(w) > 0.
TEMPLATE_TEST_CASE("sampling: u = (0, 0) and u next to 1 give finite unit directions with pdf > 0",
                   "[sampling][edge-cases]", LTC_ORIGINAL_DISTRIBUTIONS) {
    using Dist = TestType;
    using T = typename Dist::scalar;
    using vec2 = glm::vec<2, T>;
    std::vector<T> ux = {T(0), std::numeric_limits<T>::denorm_min(), T(0.5)};
    for (T x = below_one<T>(); ux.size() < 19; x = std::nextafter(x, T(0))) ux.push_back(x);
    std::vector<T> uy = {below_one<T>()};
    for (int k = 0; k < 256; ++k) uy.push_back(T(k) / T(256));
    for (const sampler_case<Dist>& c : sampler_cases<Dist>()) {
        long not_finite = 0, not_unit = 0, zero_pdf = 0;
        vec2 first_zero(-1);
        for (const T x : ux)
            for (const T y : uy) {
                const vec2 u(x, y);
                const glm::vec<3, T> w = c.sample(u);
                const glm::dvec3 wd(w);
                const double p = static_cast<double>(c.pdf(w));
                if (!(std::isfinite(wd.x) && std::isfinite(wd.y) && std::isfinite(wd.z) && std::isfinite(p))) {
                    ++not_finite;
                    continue;
                }
                if (!(std::abs(glm::length(wd) - 1) <= 4 * eps<T>())) ++not_unit;
                if (!(p > 0) && zero_pdf++ == 0) first_zero = u;
            }
        INFO(c.name << ": " << zero_pdf << " of " << ux.size() * uy.size()
                    << " u give pdf(sample(u)) = 0, the first at u = (1 - " << 1 - static_cast<double>(first_zero.x)
                    << ", " << static_cast<double>(first_zero.y) << ")");
        CHECK(not_finite == 0);
        CHECK(not_unit == 0);
        CHECK(zero_pdf == 0);
    }
}

}  // namespace ltc_test_sampling
