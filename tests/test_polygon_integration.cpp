// Closed-form polygon integrals against an independent brute-force integration (supplement
// section 2.3), for the four original distributions. The transformed ones are in
// test_transformed_integration.cpp, the conventions of ltc/core/polygon.hpp in
// test_polygon_conventions.cpp, the cube in test_polygon_cube.cpp.
//
// Tolerances are derived, not tuned: |closed - brute| <= e + B, where e is the brute force's own
// error estimate (support/brute_force.hpp) and B a first-order bound on the rounding error of the
// closed form in the scalar type T, computed in double for each polygon by rounding_bound() of
// support/rounding_bound.hpp (the derivation is written next to it). Test inputs are exactly
// representable in float (vertices and matrices are rounded to float first), so B only accounts
// for the library's own arithmetic.
#include <ltc/ltc.hpp>

#include "support/brute_force.hpp"
#include "support/polygon_error_stats.hpp"
#include "support/polygon_references.hpp"
#include "support/rng.hpp"
#include "support/rounding_bound.hpp"
#include "support/star_polygons.hpp"

#include <catch2/catch.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <string>

namespace ltc_test_polygon_integration {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::polygon_integration;  // support/polygon_references.hpp and the bound

namespace {

// Closed form vs brute force for one distribution, one type, plus the sign of the signed form.
template <typename T>
void check_original(int id, const poly_t& p, const ltc_test::brute_force_result<4>& bf, error_stats& stats) {
    const double u = unit_roundoff<T>();
    const double closed = closed_form<T>(id, p);
    const double brute = bf.value[id];
    // tolerance = quadrature estimate + first-order rounding bound of the closed form
    const double bound = rounding_bound(form_of(id), p, {}, u, brute, default_factor_error<T>(id));
    const double tol = bf.error[id] + bound;
    const std::string polygon = str(p);
    const char* distribution = dist_names[id];
    const char* type = sizeof(T) == 4 ? "float" : "double";
    CAPTURE(distribution, type, polygon, closed, brute, bf.error[id], tol);
    CHECK(std::abs(closed - brute) <= tol);
    stats.add(id, sizeof(T) == 4 ? 0 : 1, closed, brute, tol, bound);

    // The signed integral has the polygon's orientation sign (polygon.hpp's convention: positive
    // when dot(p, N) > 0 for N the oriented area vector, p on the plane) wherever it is not 0.
    const double s = closed_form_signed<T>(id, p);
    CAPTURE(s, bound);
    CHECK(std::abs(std::abs(s) - closed) == 0);
    if (brute > bound) CHECK((s > 0 ? 1 : -1) == ltc_test::orientation_sign(p, p[0]));
}

}  // namespace

// =============================================================================================

TEST_CASE("original distributions: closed-form polygon integrals equal a brute-force integration",
          "[integration][original]") {
    ltc_test::rng r(0x5eed0001);
    error_stats stats;
    int crossing = 0, positive = 0, nonconvex = 0;
    for (int i = 0; i < 200; ++i) {
        ltc_test::polygon_options o;
        o.cross_horizon = i % 2 == 1;          // half of them cross the horizon
        o.orientation = (i / 2) % 2 ? -1 : 1;  // both windings, for both kinds
        const ltc_test::test_polygon tp = ltc_test::random_polygon(r, o);
        crossing += o.cross_horizon;
        positive += o.orientation > 0;
        // count non-convex polygons (a reflex vertex: the turn differs from the orientation)
        const dvec3 n = ltc_test::area_vector(tp.v);
        bool reflex = false;
        for (std::size_t k = 0; k < tp.v.size(); ++k) {
            const dvec3 a = tp.v[k], b = tp.v[(k + 1) % tp.v.size()], c = tp.v[(k + 2) % tp.v.size()];
            reflex = reflex || glm::dot(glm::cross(b - a, c - b), n) < 0;
        }
        nonconvex += reflex;

        const auto bf = ltc_test::integrate_polygon<4>(tp.v, tp.kernel, dvec3(0, 0, 1), reference_densities);
        REQUIRE(bf.converged);
        for (int id = 0; id < 4; ++id) {
            check_original<float>(id, tp.v, bf, stats);
            check_original<double>(id, tp.v, bf, stats);
        }
    }
    CHECK(crossing == 100);
    CHECK(positive == 100);
    CHECK(nonconvex > 20);   // the generator does produce non-convex polygons
    CHECK(nonconvex < 180);  // ... and convex ones
    static bool printed = false;
    if (!printed) stats.print("original distributions (200 random polygons)"), printed = true;
}

}  // namespace ltc_test_polygon_integration
