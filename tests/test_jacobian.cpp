// The Jacobian of Linearly Transformed Spherical Distributions (supplement section 2.2), for the
// four original distributions, in float and double, and the test matrices of
// support/sphere_quadrature.hpp: D(w) = jacobian(w) D_o(M^-1 w / |M^-1 w|); the Jacobian
// integrates to 4 pi (the area of the sphere: it is the Jacobian of a bijection of the sphere onto
// itself); and it is the area ratio of tiny spherical triangles mapped by w -> M^-1 w / |M^-1 w|.
//
// Rounding bounds as in test_normalization.cpp (u = eps / 2, kappa_F = |M|_F |M^-1|_F, the
// standard model of floating-point arithmetic), whose bound (a) is quoted below.
#include "support/matrix_precision.hpp"
#include "support/original_distributions.hpp"
#include "support/rng.hpp"
#include "support/sphere_quadrature.hpp"

#include <ltc/ltc.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

namespace ltc_test_jacobian {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::precision;  // eps, in_precision, exact_matrix

namespace {

using ltc_test::named_matrix;

constexpr double pi_d = 3.141592653589793238462643383279502884;

/// Largest value of D_o (at +z; constant for the uniform ones). The Lipschitz constant of D_o
/// with respect to the direction is <= 2 D_o,max (z / pi: 1 / pi; 3 z^2 / (2 pi): 3 / pi).
template <typename Dist>
double dist_max() {
    return ltc_test::as_double_t<Dist>::eval(glm::dvec3(0, 0, 1));
}

}  // namespace

// -----------------------------------------------------------------------------------------------
// (c) The Jacobian.

// D(w) = J(w) D_o(M^-1 w / |M^-1 w|), with the direction normalized by glm::normalize instead of
// the library's division by the length: the two unit vectors differ by <= 4u per component
// (each: dot gamma_3 / 2 + sqrt u / 2 + division/product u), which moves D_o by <= Lip * 4u
// <= 2 D_o,max * 4u; the two products J * D_o round by u each: |difference| <= J (8 u D_o,max +
// 2u D_o) <= 6 eps J D_o,max; checked with 8 eps J D_o,max. The jump of the uniform hemisphere
// at (M^-1 w).z = 0 is excluded: directions whose |z_o| < 8 eps (where the two normalizations
// may disagree on the side) are skipped.
TEMPLATE_TEST_CASE("normalization: eval(w) == jacobian(w) * D_o(normalize(M^-1 w))", "[normalization][jacobian]",
                   LTC_ORIGINAL_DISTRIBUTIONS) {
    using Dist = TestType;
    using T = typename Dist::scalar;
    using vec3 = glm::vec<3, T>;
    const double dmax = dist_max<Dist>();
    const double tol_rel = 8 * eps<T>();
    for (const named_matrix& nm : ltc_test::test_matrices()) {
        const ltc::transformed<Dist> d(in_precision<T>(nm.m));
        ltc_test::rng rng(0x5eed0001);
        double worst = 0;  // in units of eps J D_o,max
        int mismatches = 0, skipped = 0;
        for (int i = 0; i < 20000; ++i) {
            const vec3 w(rng.direction());
            const vec3 wo = glm::normalize(d.inverse_matrix() * w);
            if (std::abs(static_cast<double>(wo.z)) < 8 * eps<T>()) {
                ++skipped;
                continue;
            }
            const double lhs = static_cast<double>(d.eval(w));
            const double rhs = static_cast<double>(d.jacobian(w)) * static_cast<double>(Dist::eval(wo));
            const double scale = static_cast<double>(d.jacobian(w)) * dmax;
            const double dev = std::abs(lhs - rhs) / (eps<T>() * scale);
            worst = std::max(worst, dev);
            if (!(std::abs(lhs - rhs) <= tol_rel * scale)) ++mismatches;
        }
        INFO(nm.name << ": largest |eval - J D_o| = " << worst << " eps J D_o,max (bound 8), skipped " << skipped);
        CHECK(mismatches == 0);
        CHECK(skipped < 10);
    }
}

// transformed<Other>(d): the same M over another original distribution (ltc_polygon_sampler holds
// its lobe's Jacobian this way, whatever the lobe's edge policy): M^-1, |M^-1| and so the Jacobian
// are copied, not recomputed, so they agree bit for bit.
TEMPLATE_TEST_CASE("transformed<Other>(d) keeps M^-1, |M^-1| and the Jacobian bit for bit", "[jacobian]", float, double) {
    using T = TestType;
    using vec3 = glm::vec<3, T>;
    for (const named_matrix& nm : ltc_test::test_matrices()) {
        const ltc::transformed<ltc::clamped_cosine<T, ltc::edge_policy::minimax_rational>> d(in_precision<T>(nm.m));
        const ltc::transformed<ltc::uniform_sphere<T>> u(d);
        INFO(nm.name);
        CHECK(u.inverse_matrix() == d.inverse_matrix());
        CHECK(u.inverse_determinant() == d.inverse_determinant());
        ltc_test::rng rng(0x5eed0005);
        int differ = 0;
        for (int i = 0; i < 1000; ++i) {
            const vec3 w(rng.direction());
            differ += u.jacobian(w) != d.jacobian(w);
        }
        CHECK(differ == 0);
    }
}

// The Jacobian of the bijection w -> M^-1 w / |M^-1 w| of the sphere integrates to the area of
// the sphere, 4 pi. Transformed-space quadrature with the uniform-sphere rule of (a) (J / 4 pi
// is D for D_o uniform on the sphere; here through jacobian(), for every D_o). Rounding of J:
// the first two items of the bound in (a), (21 kappa_F + 12.5) u + 10 kappa_F u <= 20 eps
// kappa_F, relative, hence 4 pi * 20 eps kappa_F absolute.
TEMPLATE_TEST_CASE("normalization: the Jacobian integrates to 4 pi", "[normalization][jacobian]",
                   ltc::clamped_cosine<float>, ltc::clamped_cosine<double>) {
    using Dist = TestType;
    using T = typename Dist::scalar;
    for (const named_matrix& nm : ltc_test::test_matrices()) {
        const glm::dmat3 M = exact_matrix<T>(nm.m);
        const ltc::transformed<Dist> d(in_precision<T>(nm.m));
        const ltc_test::transformed_rule rule = ltc_test::transformed_space_rule(M, ltc_test::domain::sphere);
        const auto f = [&](const glm::dvec3& w) { return static_cast<double>(d.jacobian(glm::vec<3, T>(w))); };
        const ltc_test::estimate<double> q = ltc_test::integrate<double>(f, rule.d, 128, rule.fr);
        const double rounding = 4 * pi_d * (20 * eps<T>() * ltc_test::frobenius_condition(M) + 1e-13);
        INFO(nm.name << ": integral / (4 pi) - 1 = " << q.value / (4 * pi_d) - 1 << ", error estimate "
                     << q.error << ", rounding bound " << rounding);
        CHECK(q.error <= 2 * rounding + 1e-9);
        CHECK(std::abs(q.value - 4 * pi_d) <= q.error + rounding);
    }
}

// J(w) is the area ratio d(omega_o) / d(omega) of the map w -> w_o = M^-1 w / |M^-1 w|. The map
// sends great circles to great circles (planes through the origin to planes through the origin),
// so a spherical triangle maps exactly onto the spherical triangle of its mapped vertices, and
//   r(h) = Omega(mapped triangle) / Omega(triangle) = mean of J over the triangle
// for an equilateral triangle of circumradius ~h centred on w: r(h) = J(w) + C h^2 + O(h^3) (the
// linear term of J averages out over the centred triangle). Truncation error of r(h/2):
// ~ (r(h) - r(h/2)) / 3; we allow |r(h) - r(h/2)| (3x margin). Rounding of r (double): each unit
// vertex is off by <= 2u (original) or <= (7 kappa_F + 3) u (mapped), and moving a vertex of a
// triangle of size s by delta changes its area by <= s delta, i.e. relatively by <= 2 delta / s
// (area >= s^2 / 2 for these near-equilateral triangles): 3 vertices x 2 x ((7 kappa_F + 3) u /
// s_o + 2 u / s), with s ~ h and s_o >= h * sigma_min of the map's tangent map
// >= h J |M^-1 w| / |M^-1|_2 (its singular values have product J and are <= |M^-1|_2 / |M^-1 w|);
// plus the few-ulp accuracy of ltc::triangle_solid_angle (8u each). Rounding of jacobian() in T:
// 20 eps_T kappa_F J, as above.
TEMPLATE_TEST_CASE("normalization: jacobian == area ratio of tiny mapped spherical triangles",
                   "[normalization][jacobian]", float, double) {
    using T = TestType;
    using vec3 = glm::vec<3, T>;
    const double u = eps<double>() / 2;
    for (const named_matrix& nm : ltc_test::test_matrices()) {
        const glm::dmat3 M = exact_matrix<T>(nm.m);
        const glm::dmat3 inv = glm::inverse(M);
        const double kappa = ltc_test::frobenius_condition(M);
        double inv_norm2 = 0;  // |M^-1|_2 = sqrt(largest eigenvalue of M^-1 M^-T)
        {
            const glm::dvec3 v = ltc_test::principal_direction(inv);
            inv_norm2 = glm::length(glm::transpose(inv) * v);
        }
        const ltc::transformed<ltc::uniform_sphere<T>> d(in_precision<T>(nm.m));
        ltc_test::rng rng(0x5eed0002);
        double worst = 0;  // |J - r| / tolerance
        for (int i = 0; i < 200; ++i) {
            const glm::dvec3 w = rng.direction();
            const ltc_test::frame fr = ltc_test::frame_from_pole(w);
            const auto ratio = [&](double h) {
                glm::dvec3 v[3], vo[3];
                for (int k = 0; k < 3; ++k) {
                    const double a = 2 * pi_d * k / 3;
                    v[k] = glm::normalize(w + h * (std::cos(a) * fr.t + std::sin(a) * fr.b));
                    vo[k] = glm::normalize(inv * v[k]);
                }
                return std::abs(ltc::triangle_solid_angle(vo[0], vo[1], vo[2])) /
                       std::abs(ltc::triangle_solid_angle(v[0], v[1], v[2]));
            };
            const double h = 1e-3;
            const double r1 = ratio(h), r2 = ratio(h / 2);
            const double J = static_cast<double>(d.jacobian(vec3(w)));
            const double s = h / 2, s_o = s * J * glm::length(inv * w) / inv_norm2;
            const double fd_rounding = r2 * (6 * ((7 * kappa + 3) * u / s_o + 2 * u / s) + 16 * u);
            const double tol = std::abs(r1 - r2) + fd_rounding + 20 * eps<T>() * kappa * J;
            worst = std::max(worst, std::abs(J - r2) / tol);
            INFO(nm.name << ": J = " << J << ", r(h/2) = " << r2 << ", r(h) = " << r1 << ", tol = " << tol);
            REQUIRE(std::abs(J - r2) <= tol);
            // The finite difference resolves J: truncation well below 1e-4 relative.
            REQUIRE(std::abs(r1 - r2) <= 1e-4 * J);
        }
        INFO(nm.name << ": largest |J - r| / tolerance = " << worst);
        CHECK(worst <= 1);
    }
}

}  // namespace ltc_test_jacobian
