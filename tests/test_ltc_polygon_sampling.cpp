// ltc/core/ltc_polygon_sampling.hpp: the LTC D = transformed<clamped_cosine> restricted to a
// polygon, for nine GGX lobes x three polygons (support/ltc_sampling_cases.hpp): integral() against
// the closed form, chi-square of the samples against exact cell probabilities, the moments E[w]
// against quadrature, and pdf() against the samples and d.eval. The variance of estimates of the
// GGX integral with this sampler against BRDF and light-area sampling:
// test_ltc_polygon_sampling_variance.cpp.
#include "support/brute_force.hpp"
#include "support/ltc_sampling_cases.hpp"
#include "support/polygon_sampling.hpp"
#include "support/rng.hpp"
#include "support/sphere_quadrature.hpp"

#include <ltc/core/ltc_polygon_sampling.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace ltc_test_ltc_polygon_sampling {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::polygon_sampling;

// integral() == I_D = ref.integrate(P) in double (closed form, eq. 3) on the same M^-1 and vertices.
// Tolerance (ltc_case::bound): the projected sampler's first-order bound (support/polygon_sampling.hpp)
// on M^-1 P with its vertices off by 4 kappa_p + 3 units of u (M^-1 p and the normalization in T,
// support/rounding_bound.hpp), over pi; plus the closed form's own bound in double. Measured:
// <= 0.02 of it.
TEMPLATE_TEST_CASE("ltc sampler: integral() is the closed-form integral of D over the polygon",
                   "[ltc-sampling]", float, double) {
    using T = TestType;
    for (const ltc_case<T>& c : ltc_cases<T>()) {
        const double i = static_cast<double>(c.s.integral());
        INFO(c.name << ": integral() " << i << ", closed form " << c.I << ", bound " << c.bound);
        REQUIRE_FALSE(c.s.empty());
        CHECK(std::abs(i - c.I) <= c.bound);
    }
}

// Bins: the 8 x 8 wedge grid of support/polygon_sampling.hpp built over M^-1 P in the cosine's
// space, where the density (w_o.z) is spread evenly; a cell bounded there by planes with normals n
// is bounded in the space of w by the planes M^-T n (w . M^-T n = M^-1 w . n), so the cell's
// probability is ref.integrate(P clipped by those planes) / I_D, and a sample w is binned by
// M^-1 w. Test, critical value, pooling and applicability (rounding shift <= dof / 4, with
// bound / I as the relative bound): as for the projected sampler (test_projected_sampling.cpp);
// N = 2^16, fixed seeds. The cell probabilities' sum is checked against 1 within the closed
// forms' bounds (vertex errors: 4 kappa_p from M^-1 p plus the crossing points' errors times
// kappa_F(M^-1), which maps w-space directions to cosine-space ones).
TEMPLATE_TEST_CASE("ltc sampler: chi-square of the samples against exact cell probabilities",
                   "[ltc-sampling][chi-square]", float, double) {
    using T = TestType;
    using ltc_test::polygon_integration::form;
    constexpr long N = 1 << 16;
    std::uint64_t seed = 0x17c500000001ull + (sizeof(T) == sizeof(float) ? 0x100 : 0x200);
    int tested = 0;
    for (const ltc_case<T>& c : ltc_cases<T>()) {
        const wedge_grid grid(c.q, 8);
        const glm::dmat3 to_w = glm::transpose(c.m_inv);
        const double kappa = ltc_test::frobenius_condition(c.m_inv);
        std::vector<double> p;
        double sum = 0, sum_bound = 0, shift = 0;
        int dof = -1;
        for (int i = 0; i < grid.cells(); ++i) {
            std::vector<dvec3> planes = grid.planes(i);
            for (dvec3& n : planes) n = to_w * n;
            const clipped cell = grid.cut(c.p, planes);
            const double integral = cell.v.size() < 3 ? 0 : c.ref.integrate(cell.v.data(), cell.v.size());
            p.push_back(integral / c.I);
            sum += p.back();
            dof += N * p.back() >= 5 ? 1 : 0;
            if (p.back() > 0) shift += 4 * (c.bound / c.I) * (c.bound / c.I) / p.back() * N;
            if (cell.v.size() < 3) continue;
            poly q;
            std::vector<double> d =
                ltc_test::polygon_integration::transformed_input_error(c.m_inv, c.m_inv, cell.v, 0x1p-53);
            for (std::size_t k = 0; k < cell.v.size(); ++k)
                q.push_back(c.m_inv * cell.v[k]), d[k] += kappa * cell.delta[k];
            sum_bound += ltc_test::polygon_integration::rounding_bound(form::cosine, q, d, 0x1p-53, integral);
        }
        sum_bound = (sum_bound + c.bound) / c.I;
        INFO(c.name << ": sum of the cell probabilities - 1 = " << sum - 1 << " (bound " << sum_bound
                    << "); rounding shift of X^2 " << shift << " (dof ~ " << dof << ")");
        CHECK(std::abs(sum - 1) <= sum_bound);
        if (sizeof(T) == sizeof(double)) CHECK(shift <= dof / 4.0);
        if (!(shift <= dof / 4.0)) continue;
        ++tested;
        std::vector<long> observed(grid.cells(), 0);
        ltc_test::rng rng(seed++);
        for (long i = 0; i < N; ++i) ++observed[grid.cell_of(c.m_inv * dvec3(c.s.sample(rng.uniform2<T>()).direction))];
        const chi_square x = chi_square_test(p, observed, N);
        INFO("X^2 = " << x.x2 << " with " << x.dof << " dof, critical value (p = 1e-4) " << x.critical);
        CHECK(x.dof >= 8);
        CHECK(x.x2 < x.critical);
    }
    CHECK(tested >= (sizeof(T) == sizeof(float) ? 9 : 27));
}

// E[w] and E[w_i^2] of D restricted to P by brute-force quadrature over P in double
// (support/brute_force.hpp, split at D's kink (M^-1 w).z = 0; D = max(0, s) |M^-1| / (pi |M^-1
// w|^4), s = (M^-1 w).z, from eq. 1), against the mean of N = 2^16 samples (double sampler):
// within 4 sigma, sigma = sqrt((E[w_i^2] - E[w_i]^2) / N) from the quadrature, plus the quadrature's
// error estimate (required <= 1e-9, far below sigma ~ 1e-3) and the samples' rounding bias
// ((7 kappa_F + 10) u per component, as in test_sampling.cpp).
TEST_CASE("ltc sampler: the samples' moments match quadrature of D over the polygon", "[ltc-sampling][moments]") {
    constexpr long N = 1 << 16;
    ltc_test::rng rng(0x17c500000401ull);
    for (const ltc_case<double>& c : ltc_cases<double>()) {
        const glm::dmat3 m = c.m_inv;
        const double det = std::abs(glm::determinant(m));
        const dvec3 h(m[0][2], m[1][2], m[2][2]);  // the third row: s = (M^-1 w).z
        const auto f = [&](const dvec3& w, double s) {
            const dvec3 q = m * w;
            const double r2 = glm::dot(q, q);
            const double dens = std::max(s, 0.0) * det / (kPi * r2 * r2);
            return std::array<double, 7>{dens, dens * w.x, dens * w.y, dens * w.z, dens * w.x * w.x,
                                         dens * w.y * w.y, dens * w.z * w.z};
        };
        dvec3 kernel(0);
        for (const dvec3& v : c.p) kernel += v / double(c.p.size());
        ltc_test::brute_force_options o;
        o.rel_tol = 1e-11;
        const auto q = ltc_test::integrate_polygon<7>(c.p, kernel, h, f, o);
        REQUIRE(q.converged);
        dvec3 s1(0);
        for (long i = 0; i < N; ++i) s1 += c.s.sample(rng.uniform2<double>()).direction;
        const double bias = (7 * ltc_test::frobenius_condition(glm::inverse(m)) + 10) * 0x1p-53;
        for (int k = 0; k < 3; ++k) {
            const double mean = q.value[1 + k] / q.value[0], second = q.value[4 + k] / q.value[0];
            const double err = (q.error[1 + k] + q.error[0] * std::abs(mean)) / q.value[0];
            const double sigma = std::sqrt(std::max(second - mean * mean, 0.0) / N);
            INFO(c.name << ", component " << k << ": sample mean " << s1[k] / N << ", quadrature " << mean << " +- "
                        << err << " (" << std::abs(s1[k] / N - mean) / sigma << " sigma)");
            CHECK(err <= 1e-9);
            CHECK(std::abs(s1[k] / N - mean) <= 4 * sigma + err + bias);
        }
    }
}

// pdf(x.direction) == x.pdf == d.eval(w) / integral() for the samples x, and > 0. The sample's pdf
// comes from the cosine sample w_o, pdf() and eval from M^-1 w: w_o round-tripped through M and
// M^-1, off by <= (7 kappa_F + 10) u per component (test_sampling.cpp), i.e. relatively
// (7 kappa_F + 10) u / w_o.z in the density w_o.z / E, plus 8u for the divisions and the
// Jacobian. Measured: <= 0.14 of it in both precisions (w_o.z from M^-1 w in double).
TEMPLATE_TEST_CASE("ltc sampler: pdf() and d.eval / integral() agree with the samples' pdf",
                   "[ltc-sampling][pdf]", float, double) {
    using T = TestType;
    const double u = std::numeric_limits<T>::epsilon() / 2;
    ltc_test::rng rng(0x17c500000501ull + sizeof(T));
    for (const ltc_case<T>& c : ltc_cases<T>()) {
        const double kappa = ltc_test::frobenius_condition(c.m_inv);
        long zero = 0;
        double worst_pdf = 0, worst_eval = 0;
        for (int i = 0; i < 4096; ++i) {
            const ltc::polygon_sample<T> x = c.s.sample(rng.uniform2<T>());
            const double p = double(x.pdf);
            if (!(p > 0)) {
                ++zero;
                continue;
            }
            const double wz = glm::normalize(c.m_inv * dvec3(x.direction)).z;
            const double tol = ((7 * kappa + 10) * u / wz + 8 * u) * p;
            worst_pdf = std::max(worst_pdf, std::abs(double(c.s.pdf(x.direction)) - p) / tol);
            worst_eval = std::max(worst_eval, std::abs(double(c.d.eval(x.direction) / c.s.integral()) - p) / tol);
        }
        INFO(c.name << ": " << zero << " samples with pdf 0; largest |pdf() - pdf| / tolerance " << worst_pdf
                    << ", |eval / integral - pdf| / tolerance " << worst_eval);
        CHECK(zero == 0);
        CHECK(worst_pdf <= 1);
        CHECK(worst_eval <= 1);
    }
}

// Regression (found by this test): a sample next to the cosine's horizon in M^-1 P (the projected
// sampler lifts it just above z_o = 0, pdf ~ 1e-23 in float) was carried back below it by the
// round trip M w_o -> M^-1 w, so pdf(sample(u).direction) == 0 (and d.eval == 0) while
// sample(u).pdf > 0. ltc_polygon_sampler now re-lifts such samples, as transformed<>::sample does.
// Found at u on the square's border (u.y = 0 or next to 1), e.g. (float) lobe (0.5, 0.7), the
// wall pentagon, u = (0, 0x1p-149): pdf 1.5e-23, pdf() 0; (double) lobe (0.5, 0.3), the large
// quad, u = (0x1.719d7bf5626p-10, 0x1.fffffffffffffp-1): pdf 3.1e-18, pdf() 0.
TEMPLATE_TEST_CASE("ltc sampler: pdf(sample(u).direction) > 0 for u on the borders of the square",
                   "[ltc-sampling][pdf][degenerate]", float, double) {
    using T = TestType;
    using vec2 = glm::vec<2, T>;
    const std::vector<T> edge = {T(0), std::numeric_limits<T>::denorm_min(), T(0.5),
                                 T(1) - std::numeric_limits<T>::epsilon() / 2, T(1)};
    ltc_test::rng rng(0x17c500000601ull + sizeof(T));
    for (const ltc_case<T>& c : ltc_cases<T>()) {
        std::vector<vec2> us;
        for (const T x : edge)
            for (const T y : edge) us.push_back(vec2(x, y));
        for (int i = 0; i < 256; ++i) {
            const vec2 r = rng.uniform2<T>();
            for (const T e : {edge[0], edge[3]}) us.push_back(vec2(r.x, e)), us.push_back(vec2(e, r.y));
        }
        if (sizeof(T) == sizeof(double)) us.push_back(vec2(T(0x1.719d7bf5626p-10), T(0x1.fffffffffffffp-1)));
        long bad = 0;
        vec2 first(-1);
        for (const vec2& u : us) {
            const ltc::polygon_sample<T> x = c.s.sample(u);
            const glm::dvec3 w(x.direction);
            const bool ok = std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z) && x.pdf > 0 &&
                            c.s.pdf(x.direction) > 0;
            if (!ok && bad++ == 0) first = u;
        }
        INFO(c.name << ": " << bad << " of " << us.size() << " samples with pdf or pdf(direction) 0, the first at u = ("
                    << double(first.x) << ", " << double(first.y) << ")");
        CHECK(bad == 0);
    }
}

}  // namespace ltc_test_ltc_polygon_sampling
