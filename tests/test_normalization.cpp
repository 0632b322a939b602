// Normalization of Linearly Transformed Spherical Distributions (supplement section 2.2), for the
// four original distributions, in float and double, and the test matrices of
// support/sphere_quadrature.hpp (identity, the supplement's M, a rotation, a narrow GGX-like
// lobe, a negative determinant):
//   (a) the integral of D = transformed<D_o>(M) over the sphere, by quadrature in the
//       transformed space as the supplement does, is 1;
//   (b) the closed form: the 6 faces of the cube [-1, 1]^3 tile the sphere, and their integrals
//       (transformed<>::integrate, D_o::integrate) add up to 1 to rounding;
//   (c) the Jacobian: test_jacobian.cpp.
//
// Rounding bounds use u = eps / 2 (unit roundoff of T), kappa_F = |M|_F |M^-1|_F (an upper bound
// of the 2-norm condition number; see frobenius_condition) and the standard model
// fl(a op b) = (a op b)(1 + d), |d| <= u, gamma_n = n u / (1 - n u) ~ n u (Higham, "Accuracy and
// Stability of Numerical Algorithms", 2nd ed., ch. 2-3).
#include "support/matrix_precision.hpp"
#include "support/original_distributions.hpp"
#include "support/sphere_quadrature.hpp"

#include <ltc/ltc.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

namespace ltc_test_normalization {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::precision;  // eps, in_precision, exact_matrix

namespace {

using ltc_test::named_matrix;

template <typename T>
std::vector<glm::vec<3, T>> to_precision(const std::vector<glm::dvec3>& v) {
    std::vector<glm::vec<3, T>> r;
    for (const glm::dvec3& p : v) r.emplace_back(p);  // cube corners are exact in float
    return r;
}

}  // namespace

// -----------------------------------------------------------------------------------------------
// (a) Quadrature of D in the transformed space.
//
// The rule (ltc_test::transformed_space_rule) has its pole at M^-T z for the hemispherical D_o
// (D's support is then the upper hemisphere of the frame and D's kink or jump is on the domain
// boundary) and at the least-stretch direction of M for the uniform sphere (D's two peaks on the
// equator, where the nodes cluster). D is analytic on the closed domain and the orders n = 128
// and 2n = 256 (128 x 512 and 256 x 1024 nodes per hemisphere) give the error estimate
// |Q_256 - Q_128|: <= 2e-15 in double (measured; the rule has converged to rounding by n = 128,
// |Q_64 - 1| <= 4e-9), ~1e-8 in float (there it is the rounding noise of the float integrand,
// which the bound below covers).
//
// Rounding bound of the float/double integrand. The sum has positive terms, so the relative
// error of the integral is at most the largest relative error of a term of J = |M^-1| / l^3, and
// the error of D_o enters as sup|dD_o| * (integral of the Jacobian over the support of D_o):
//   - w rounded to T (u), M^-1 (cofactors with <= 2u each, one division u), the product M^-1 w
//     (gamma_3): the vector M^-1 w has relative error <= 7u kappa_F;
//   - |M^-1 w| (2.5u more), cubed (2u), the quotient |M^-1| / l^3 and the product (3u):
//     3 (7 kappa_F + 2.5) u + 5u;
//   - the determinant, det = c0 . (c1 x c2) with relative error <= (gamma_3 + 2u) h, h =
//     |c0||c1 x c2| / |det| <= kappa_F, enters squared (|M^-1| / |M^-1 w|^3 scales as det^2):
//     10 u kappa_F;
//   - the direction M^-1 w / l, off by <= (14 kappa_F + 1) u, moves D_o by at most its Lipschitz
//     constant (<= 3 / pi) times that, weighted by the integral of the Jacobian over the support
//     (2 pi, a hemisphere; the uniform sphere has no such term): <= (84 kappa_F + 6) u; the jump
//     of the uniform hemisphere at most misclassifies a band of that width around its horizon,
//     of probability 1 / (2 pi) * 2 pi * width.
// Sum: (21 + 10 + 84) kappa_F u + 19 u <= 122 kappa_F u <= 64 eps kappa_F (kappa_F >= 3). The
// double summation of the rule adds < 1e-13 (two-level sum of <= 256 + 1024 terms).
TEMPLATE_TEST_CASE("normalization: D integrates to 1 over the sphere (transformed-space quadrature)",
                   "[normalization][quadrature]", LTC_ORIGINAL_DISTRIBUTIONS) {
    using Dist = TestType;
    using T = typename Dist::scalar;
    for (const named_matrix& nm : ltc_test::test_matrices()) {
        const glm::dmat3 M = exact_matrix<T>(nm.m);
        const ltc::transformed<Dist> d(in_precision<T>(nm.m));
        const ltc_test::transformed_rule rule = ltc_test::transformed_space_rule(M, ltc_test::support_of<Dist>());
        const auto f = [&](const glm::dvec3& w) { return static_cast<double>(d.eval(glm::vec<3, T>(w))); };
        const ltc_test::estimate<double> q = ltc_test::integrate<double>(f, rule.d, 128, rule.fr);

        const double rounding = 64 * eps<T>() * ltc_test::frobenius_condition(M) + 1e-13;
        INFO(nm.name << ": integral - 1 = " << q.value - 1 << ", error estimate " << q.error
                     << ", rounding bound " << rounding);
        // The rule resolves D: its error estimate is at the level of the integrand's rounding
        // (both orders are within `rounding` of 1) plus 1e-10 of truncation at most.
        CHECK(q.error <= 2 * rounding + 1e-10);
        CHECK(std::abs(q.value - 1) <= q.error + rounding);

        // The mean direction E[w] = integral of D(w) w dw by the same transformed-space rule
        // (through eval) equals the original-space expectation E_{D_o}[M w_o / |M w_o|] (through
        // D_o only; support/sphere_quadrature.hpp): eval has the right shape, not only the right
        // total. |w| <= 1, so the rounding bound of the integral applies to each component.
        const auto fw = [&](const glm::dvec3& w) { return f(w) * w; };
        const ltc_test::estimate<glm::dvec3> mean_t = ltc_test::integrate<glm::dvec3>(fw, rule.d, 128, rule.fr);
        const ltc_test::estimate<glm::dvec3> mean_o = ltc_test::expectation<Dist, glm::dvec3>(
            M, [](const glm::dvec3& w) { return w; }, 128);
        const double dev = ltc_test::max_abs(mean_t.value - mean_o.value);
        INFO(nm.name << ": E[w] transformed space vs original space: largest difference " << dev
                     << ", error estimates " << mean_t.error << ", " << mean_o.error);
        CHECK(mean_o.error <= 1e-10);
        CHECK(dev <= mean_t.error + mean_o.error + rounding);
    }
}

// -----------------------------------------------------------------------------------------------
// (b) Closed form over the six faces of the cube.
//
// The six faces tile the sphere, and they still do after rounding: a corner shared by several
// faces is transformed (M^-1 p / |M^-1 p|) by the same operations on the same input in each of
// them, and a horizon crossing shared by two faces is computed from the same (inside, outside)
// pair, so the computed image polygons tile the sphere exactly and the condition number of M
// does not enter. What remains is the arithmetic of each edge term: the edge term
// theta (a x b).z / |a x b| (|.| <= pi), the fan triangle's solid angle (|.| < 2 pi) and the
// second-moment term (|.| <= 2), divided by 2 pi or 4 pi: at most (2 pi + 2) / (2 pi) < 1.4 per
// edge of a face. Each is computed to <= 16 u relative (dot gamma_3, cancellation-free cross
// product ~5 u relative to |a x b| for the branch taken, length and division 3 u, atan2 <= 2 u,
// product u, the face's running sum gamma_6), i.e. <= 22 u absolute per edge. A face clipped by
// the horizon has <= 6 edges: 6 faces x 6 edges x 22 u < 800 u = 400 eps (the six face values are
// then added in double).
TEMPLATE_TEST_CASE("normalization: the six cube faces integrate to 1 (closed form)", "[normalization][closed-form]",
                   LTC_ORIGINAL_DISTRIBUTIONS) {
    using Dist = TestType;
    using T = typename Dist::scalar;
    const ltc_test::cube_map faces{1};

    SECTION("original distribution: Dist::integrate and signed_integral") {
        double sum = 0, signed_sum = 0;
        for (int f = 0; f < 6; ++f) {
            const auto quad = to_precision<T>(faces.cell_quad(f));
            sum += static_cast<double>(Dist::integrate(quad.data(), 4));
            signed_sum += static_cast<double>(Dist::signed_integral(quad.data(), 4));
        }
        const double bound = 400 * eps<T>();
        CAPTURE(sum - 1, signed_sum - 1, bound);
        CHECK(std::abs(sum - 1) <= bound);
        CHECK(std::abs(signed_sum - 1) <= bound);  // outward-normal winding: every face positive
    }
    SECTION("transformed: integrate and integrate_signed") {
        for (const named_matrix& nm : ltc_test::test_matrices()) {
            const ltc::transformed<Dist> d(in_precision<T>(nm.m));
            double sum = 0, signed_sum = 0;
            for (int f = 0; f < 6; ++f) {
                const auto quad = to_precision<T>(faces.cell_quad(f));
                sum += static_cast<double>(d.integrate(quad.data(), 4));
                signed_sum += static_cast<double>(d.integrate_signed(quad.data(), 4));
            }
            const double bound = 400 * eps<T>();
            INFO(nm.name << ": sum - 1 = " << sum - 1 << " = " << (sum - 1) / eps<T>() << " eps, signed sum - 1 = "
                         << signed_sum - 1 << ", bound " << bound);
            CHECK(std::abs(sum - 1) <= bound);
            // The sign of integrate_signed refers to P's own orientation whatever sign |M| has.
            CHECK(std::abs(signed_sum - 1) <= bound);

            // The same through from_inverse (any invertible M^-1 defines a normalized D).
            const auto di = ltc::transformed<Dist>::from_inverse(glm::inverse(in_precision<T>(nm.m)));
            double sum_i = 0;
            for (int f = 0; f < 6; ++f) {
                const auto quad = to_precision<T>(faces.cell_quad(f));
                sum_i += static_cast<double>(di.integrate_signed(quad.data(), 4));
            }
            INFO("from_inverse: signed sum - 1 = " << sum_i - 1);
            CHECK(std::abs(sum_i - 1) <= bound);
        }
    }
}

}  // namespace ltc_test_normalization
