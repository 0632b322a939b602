// The samplers of the microfacet BRDF models of ltc/brdf (ggx, beckmann) against their pdf:
// chi-square goodness of fit, and the Monte Carlo albedo eval / pdf against the quadrature
// references of support/brdf_references.hpp (which explains the tolerances).
#include <ltc/brdf/beckmann.hpp>
#include <ltc/brdf/ggx.hpp>

#include <catch2/catch.hpp>

#include "support/brdf_references.hpp"
#include "support/rng.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace ltc_test_brdf_sampling {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::brdf_checks;  // configurations, references, LTC_BRDF_TYPES

namespace {

/// Chi-square critical value at upper-tail probability 1e-4, Wilson-Hilferty (1931): for
/// X ~ chi^2_k, (X / k)^(1/3) is nearly normal with mean 1 - 2 / (9k) and variance 2 / (9k), so
/// x_p = k (1 - 2 / (9k) + z_p sqrt(2 / (9k)))^3 with z_p = Phi^-1(1 - 1e-4) = 3.7190165.
/// (Relative error < 1e-3 for k >= 10, far below what matters here.)
double chi2_critical_1e4(double k) {
    const double z = 3.7190164854556804, c = 2 / (9 * k);
    const double b = 1 - c + z * std::sqrt(c);
    return k * b * b * b;
}

}  // namespace

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

}  // namespace ltc_test_brdf_sampling
