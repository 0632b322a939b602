// The chi-square goodness-of-fit test shared by the sampler tests (test_sampling.cpp,
// test_solid_angle_sampling.cpp and, through support/polygon_sampling.hpp, the polygon samplers'):
// the critical value and the statistic with Cochran's pooling.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace ltc_test {

/// Upper 1e-4 quantile of chi-square with nu degrees of freedom, by the Wilson-Hilferty
/// approximation: (X^2 / nu)^(1/3) is nearly normal with mean 1 - 2 / (9 nu) and variance
/// 2 / (9 nu), so chi2_p(nu) ~= nu (1 - 2 / (9 nu) + z_p sqrt(2 / (9 nu)))^3 with z_p the upper-p
/// normal quantile, z = Phi^-1(1 - 1e-4) = 3.7190164854557. Source: E. B. Wilson and
/// M. M. Hilferty, "The distribution of chi-square", PNAS 17(12):684-688, 1931; Abramowitz &
/// Stegun, Handbook of Mathematical Functions, 26.4.17. At this tail it errs on the high side:
/// 16.2 vs 15.14 exact for nu = 1, 26.3 vs 25.7 for nu = 5, 36.0 vs 35.6 for nu = 10, within 0.5%
/// for nu >= 50.
inline double chi_square_critical_1e4(int nu) {
    const double z = 3.7190164854557084;
    const double a = 2.0 / (9.0 * nu);
    const double c = 1.0 - a + z * std::sqrt(a);
    return nu * c * c * c;
}

struct chi_square {
    double x2 = 0;
    int dof = 0;
    double critical = 0;
};

/// X^2 of the observed counts against the expected probabilities p (sum 1) of N samples, cells
/// with expected count < 5 pooled into one bin (Cochran), which joins the smallest regular bin
/// when its own expectation stays below 5; bins - 1 degrees of freedom (nothing is fitted).
inline chi_square chi_square_test(const std::vector<double>& p, const std::vector<long>& observed, long n) {
    std::vector<double> e_bins;
    std::vector<long> o_bins;
    double pooled_e = 0;
    long pooled_o = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double e = double(n) * p[i];
        if (e < 5)
            pooled_e += e, pooled_o += observed[i];
        else
            e_bins.push_back(e), o_bins.push_back(observed[i]);
    }
    chi_square r;
    if (e_bins.empty()) return r;
    if (pooled_e >= 5 || pooled_o > 0) {
        if (pooled_e >= 5) {
            e_bins.push_back(pooled_e), o_bins.push_back(pooled_o);
        } else {
            const auto s = std::min_element(e_bins.begin(), e_bins.end()) - e_bins.begin();
            e_bins[s] += pooled_e, o_bins[s] += pooled_o;
        }
    }
    for (std::size_t i = 0; i < e_bins.size(); ++i) {
        const double d = double(o_bins[i]) - e_bins[i];
        r.x2 += d * d / e_bins[i];
    }
    r.dof = int(e_bins.size()) - 1;
    r.critical = r.dof > 0 ? chi_square_critical_1e4(r.dof) : 0;
    return r;
}

}  // namespace ltc_test
