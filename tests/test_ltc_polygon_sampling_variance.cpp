// The variance that the restricted-LTC sampler (ltc/core/ltc_polygon_sampling.hpp) buys: one-sample
// estimates of int_P f, f = rho cos of GGX (ltc/brdf/ggx.hpp, alpha = roughness^2, V =
// (sin theta_v, 0, cos theta_v)), for the nine lobes x three polygons of
// support/ltc_sampling_cases.hpp, with
//   (a) the LTC of ltc::ggx::fetch restricted to P: f(w) / pdf, w ~ D / I_D;
//   (b) GGX sampling of visible normals (ggx::sample / ggx::pdf): f / pdf if w is in P, else 0;
//   (c) uniform light-area sampling (polygon_area_sampler): f / solid_angle_pdf.
#include "support/ltc_sampling_cases.hpp"
#include "support/polygon_sampling.hpp"
#include "support/rng.hpp"

#include <ltc/core/ltc_polygon_sampling.hpp>
#include <ltc/core/polygon_area_sampling.hpp>
#include <ltc/brdf/ggx.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace ltc_test_ltc_polygon_sampling_variance {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::polygon_sampling;

namespace {

struct moments {
    double sum = 0, sum2 = 0;
    long n = 0;
    void add(double x) { sum += x, sum2 += x * x, ++n; }
    double mean() const { return sum / double(n); }
    double std() const { return std::sqrt(std::max(sum2 / double(n) - mean() * mean(), 0.0)); }
    double relative() const { return std() / mean(); }  // std / mean of one sample
    double standard_error() const { return std() / std::sqrt(double(n)); }
};

}  // namespace

// N = 2^16 samples per estimator and case, independent fixed seeds; the relative standard
// deviation of one sample, std / mean, each estimator with its own mean (the three means must agree
// within 4 standard errors: each estimator is unbiased). Measured (gcc 12 -O2, x86-64; the table
// is printed by the WARN below):
//
//   cos theta_v  roughness  polygon        (a) LTC   (b) GGX   (c) area
//   1.00         0.1        overhead quad  0.00621   0.0718    12
//   1.00         0.1        wall pentagon  0.572     148       0.893
//   1.00         0.1        large quad     0.00661   0.0156    68.3
//   1.00         0.3        overhead quad  0.000878  0.596     1.45
//   1.00         0.3        wall pentagon  0.298     15.7      0.927
//   1.00         0.3        large quad     0.0177    0.133     9.04
//   1.00         0.7        overhead quad  0.0133    2.65      0.27
//   1.00         0.7        wall pentagon  0.0681    4.6       0.914
//   1.00         0.7        large quad     0.0213    0.72      1.88
//   0.50         0.1        overhead quad  0.224     58.7      0.883
//   0.50         0.1        wall pentagon  0.027     0.0788    22.1
//   0.50         0.1        large quad     0.0274    0.0656    39.2
//   0.50         0.3        overhead quad  0.212     6.92      0.817
//   0.50         0.3        wall pentagon  0.136     0.597     3.19
//   0.50         0.3        large quad     0.247     0.422     5.32
//   0.50         0.7        overhead quad  0.0238    2.99      0.244
//   0.50         0.7        wall pentagon  0.196     2.05      1.11
//   0.50         0.7        large quad     0.118     0.769     1.72
//   0.15         0.1        overhead quad  1.68      96.8      0.51
//   0.15         0.1        wall pentagon  0.113     0.0532    51.6
//   0.15         0.1        large quad     1.82      15.6      4.56
//   0.15         0.3        overhead quad  1.22      7.92      0.494
//   0.15         0.3        wall pentagon  0.437     0.431     5.95
//   0.15         0.3        large quad     1.56      1.76      3.62
//   0.15         0.7        overhead quad  0.0655    2.99      0.231
//   0.15         0.7        wall pentagon  0.299     1.81      1.32
//   0.15         0.7        large quad     0.28      0.694     1.63
//
// Where the lobe's mass is in P the LTC sampler's estimate is almost exact (std / mean 1e-3 to
// 2e-2: f / pdf = f I_D / D, nearly constant where the fit is good). It loses where P only holds
// the fitted lobe's tail, whose shape departs from GGX: at grazing view (cos theta_v 0.15)
// light-area sampling beats it on the overhead quad (0.51 vs 1.68, 0.49 vs 1.22) and GGX sampling
// on the wall pentagon (0.053 vs 0.113 at roughness 0.1; a tie at 0.3). (b) and (c) are
// heavy-tailed where they rarely hit the lobe's peak, and so is (a) in a few cases: with three
// other seeds the ratios (b) / (a) and (c) / (a) moved by up to 1.8x (the large quad at 0.5 /
// 0.3: (a) = 0.14 instead of 0.247), all others by < 20%. Asserted: (a) < (b) / 2 and (a) < (c) / 2
// where the measured ratio is >= 4 with every seed tried (the flags below: 18 cases each).
TEST_CASE("ltc sampler: variance of the GGX polygon integral with LTC, BRDF and light-area sampling",
          "[ltc-sampling][variance]") {
    using ggx = ltc::brdf::ggx<double>;
    constexpr long N = 1 << 16;
    // (cos theta_v, roughness, polygon) -> assert (a) < (b) / 2, (a) < (c) / 2: 27 entries, in
    // the order of ltc_cases().
    const bool beats_b[27] = {1, 1, 0, 1, 1, 1, 1, 1, 1, 1, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1, 0, 0, 1, 1, 0};
    const bool beats_c[27] = {1, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1, 0, 1, 1, 1, 1, 1, 0, 1, 0, 0, 1, 0, 0, 1, 1};
    std::ostringstream table;
    table << "cos theta_v  roughness  polygon         (a) LTC   (b) GGX   (c) area   [std / mean of one sample]\n";
    int k = 0;
    for (const ltc_case<double>& c : ltc_cases<double>()) {
        const double alpha = c.roughness * c.roughness;
        const dvec3 V(std::sqrt(1 - c.cos_theta_v * c.cos_theta_v), 0, c.cos_theta_v);
        const ltc::polygon_area_sampler<double> area(c.p.data(), c.p.size());
        ltc_test::rng ra(0x7a2100000001ull + 3 * k), rb(0x7a2100000002ull + 3 * k), rc(0x7a2100000003ull + 3 * k);
        moments a, b, e;
        for (long i = 0; i < N; ++i) {
            const ltc::polygon_sample<double> x = c.s.sample(ra.uniform2<double>());
            a.add(ggx::eval(V, x.direction, alpha) / x.pdf);
            const dvec3 L = ggx::sample(V, rb.uniform2<double>(), alpha);
            const double pb = ggx::pdf(V, L, alpha);
            b.add(inside(c.p, L, 0) && pb > 0 ? ggx::eval(V, L, alpha) / pb : 0);
            const dvec3 X = area.sample(rc.uniform2<double>());
            const double pc = area.solid_angle_pdf(dvec3(0), X);
            e.add(pc > 0 ? ggx::eval(V, glm::normalize(X), alpha) / pc : 0);
        }
        char line[160];
        std::snprintf(line, sizeof line, "%-11.2f  %-9.1f  %-14s  %-8.3g  %-8.3g  %-8.3g\n", c.cos_theta_v, c.roughness,
                      c.name.substr(0, c.name.find(',')).c_str(), a.relative(), b.relative(), e.relative());
        table << line;
        INFO(c.name << ": means (a) " << a.mean() << " +- " << a.standard_error() << ", (b) " << b.mean() << " +- "
                    << b.standard_error() << ", (c) " << e.mean() << " +- " << e.standard_error()
                    << "; std / mean (a) " << a.relative() << ", (b) " << b.relative() << ", (c) " << e.relative());
        CHECK(std::abs(a.mean() - b.mean()) <= 4 * std::hypot(a.standard_error(), b.standard_error()));
        CHECK(std::abs(a.mean() - e.mean()) <= 4 * std::hypot(a.standard_error(), e.standard_error()));
        if (beats_b[k]) CHECK(a.relative() < b.relative() / 2);
        if (beats_c[k]) CHECK(a.relative() < e.relative() / 2);
        ++k;
    }
    WARN(table.str());
}

}  // namespace ltc_test_ltc_polygon_sampling_variance
