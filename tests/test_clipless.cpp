// Tests of the clipless approximation of ltc/shading/clipless.hpp: exact above and below the
// horizon, the orientation, the error against exact clipping over a documented set of polygons,
// and the edge policies. The sphere form factor and its table are tested in
// test_sphere_form_factor.cpp.
#include <catch2/catch.hpp>

#include <ltc/shading/clipless.hpp>
#include <ltc/ltc.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ltc_test_clipless {  // the file's own names, apart from the other files of a unity batch

namespace {

using glm::dvec3;
namespace cl = ltc::clipless;
constexpr double pi = 3.141592653589793;

/// The documented polygon set for the clipless error: a rectangle of aspect 1, 4 or 16 (long
/// side 2 tan(half)) or an isosceles-ish triangle squashed by the aspect, facing the origin,
/// centred at elevation `elevation` (azimuth 0), rolled by `roll` about its axis (roll 0: the
/// long side parallel to the horizon).
std::vector<dvec3> documented_light(int shape, double aspect, double half_deg, double elevation_deg, double roll_deg) {
    const double e = elevation_deg * pi / 180, r = roll_deg * pi / 180, s = std::tan(half_deg * pi / 180);
    const dvec3 c(std::cos(e), 0, std::sin(e)), e1(0, 1, 0), e2 = glm::cross(c, e1);
    const dvec3 u = std::cos(r) * e1 + std::sin(r) * e2, w = -std::sin(r) * e1 + std::cos(r) * e2;
    std::vector<glm::dvec2> p;
    if (shape == 0)
        p = {{-s, -s / aspect}, {s, -s / aspect}, {s, s / aspect}, {-s, s / aspect}};
    else
        for (int i = 0; i < 3; ++i) {
            const double phi = 2 * pi * i / 3 + 0.2;
            p.push_back({s * std::cos(phi), s * std::sin(phi) / aspect});
        }
    std::vector<dvec3> v;
    for (const auto& q : p) v.push_back(c + q.x * u + q.y * w);
    if (glm::dot(v[0], glm::cross(v[1] - v[0], v[2] - v[0])) < 0) std::reverse(v.begin(), v.end());
    return v;
}

}  // namespace

TEST_CASE("clipless is exact above and below the horizon, and follows the orientation", "[clipless]") {
    const dvec3 above[4] = {{-1, 0, 0.5}, {1, 0, 0.5}, {1, 2, 1.5}, {-1, 2, 1.5}};
    const dvec3 below[3] = {{0, 0, -1}, {1, 0, -1.5}, {0, 1, -1}};
    dvec3 reversed[4];
    std::reverse_copy(above, above + 4, reversed);
    for (const auto how : {cl::method::analytic, cl::method::table}) {
        const double exact = ltc::form_factor_signed(above, 4);
        REQUIRE(exact > 0);
        CHECK_THAT(cl::form_factor_signed(above, 4, how), Catch::Matchers::WithinRel(exact, 1e-12));
        CHECK_THAT(cl::form_factor_signed(reversed, 4, how), Catch::Matchers::WithinRel(-exact, 1e-12));
        CHECK(cl::form_factor(reversed, 4, ltc::sidedness::one_sided, how) == 0.0);
        CHECK_THAT(cl::form_factor(reversed, 4, ltc::sidedness::two_sided, how), Catch::Matchers::WithinRel(exact, 1e-12));
        CHECK(cl::form_factor(below, 3, ltc::sidedness::two_sided, how) == 0.0);
        // Degenerate input: nothing, a vertex at the origin.
        CHECK(cl::form_factor(above, 2, ltc::sidedness::two_sided, how) == 0.0);
        const dvec3 at_origin[3] = {{0, 0, 0}, {1, 0, 1}, {0, 1, 1}};
        CHECK(cl::form_factor(at_origin, 3, ltc::sidedness::two_sided, how) == 0.0);
    }
    // Through an LTC: exact when M^-1 P is above the LTC's horizon; a matrix with negative
    // determinant flips the orientation of M^-1 P but not the sign of the result.
    const glm::dmat3 m_inv = glm::transpose(glm::dmat3(1.2, 0, 0.3, 0, 0.8, 0, -0.2, 0, 1));
    for (const double flip : {1.0, -1.0}) {
        glm::dmat3 mi = m_inv;
        mi[1] *= flip;  // negate the y column
        const auto d = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(mi);
        const double exact = d.integrate_signed(above, 4);
        CAPTURE(flip);
        CHECK_THAT(cl::integrate_signed(d, above, 4), Catch::Matchers::WithinRel(exact, 1e-12));
        CHECK_THAT(cl::integrate(d, reversed, 4, ltc::sidedness::two_sided), Catch::Matchers::WithinRel(exact, 1e-12));
        CHECK(cl::integrate(d, reversed, 4, ltc::sidedness::one_sided) == 0.0);
    }
    // float
    const glm::vec3 above_f[4] = {{-1, 0, 0.5f}, {1, 0, 0.5f}, {1, 2, 1.5f}, {-1, 2, 1.5f}};
    CHECK_THAT(cl::form_factor(above_f, 4, ltc::sidedness::one_sided), Catch::Matchers::WithinRel(float(ltc::form_factor_signed(above, 4)), 1e-5f));
}

TEST_CASE("clipless vs exact clipping over the documented set of straddling polygons", "[clipless]") {
    // Documented set: rectangles (aspect 1, 4, 16) and triangles (squashed by the same aspect)
    // of half-size 5, 20, 45 and 75 degrees, centred at elevations -30 to 30 degrees in steps of
    // 2.5, rolled by 0, 30, 60 and 90 degrees (roll 0: long side along the horizon). The error
    // is measured relative to f = |F| (the unclipped magnitude, which scales what a pixel
    // shows), and relative to the exact value where that is >= 1e-3 f.
    struct group {
        double aspect;
        double max_abs_measured;   // max |clipless - exact| / f over the group (measured, rounded up)
        double mean_rel_measured;  // mean |clipless - exact| / exact over the group (same)
    };
    // Measured: aspect 1: 0.01190, 4.72%; aspect 4: 0.09614, 32.4%; aspect 16: 0.19304, 48.4%.
    const group groups[] = {{1, 0.0120, 0.0473}, {4, 0.0962, 0.325}, {16, 0.1931, 0.484}};
    for (const group& g : groups) {
        double worst = 0, sum_rel = 0, worst_table_gap = 0, worst_exact_case = 0;
        int n_rel = 0, n_exact_cases = 0;
        for (int shape = 0; shape < 2; ++shape)
            for (const double half : {5.0, 20.0, 45.0, 75.0})
                for (int k = -12; k <= 12; ++k)
                    for (const double roll : {0.0, 30.0, 60.0, 90.0}) {
                        const auto v = documented_light(shape, g.aspect, half, 2.5 * k, roll);
                        const double exact = ltc::form_factor(v.data(), v.size(), ltc::sidedness::one_sided);
                        const double approx = cl::form_factor(v.data(), v.size(), ltc::sidedness::one_sided);
                        const double tab = cl::form_factor(v.data(), v.size(), ltc::sidedness::one_sided, cl::method::table);
                        const double f = cl::sphere_of_polygon(v.data(), v.size()).f;
                        worst = std::max(worst, std::abs(approx - exact) / f);
                        worst_table_gap = std::max(worst_table_gap, std::abs(tab - approx) / f);
                        if (exact >= 1e-3 * f) sum_rel += std::abs(approx - exact) / exact, ++n_rel;
                        // The polygon and its sphere (cos omega >= sin sigma) entirely above the
                        // horizon: exact.
                        const auto sph = cl::sphere_of_polygon(v.data(), v.size());
                        bool above = sph.cos_omega >= std::sqrt(sph.f);
                        for (const auto& p : v) above = above && p.z >= 0;
                        if (above) {
                            ++n_exact_cases;
                            worst_exact_case = std::max(worst_exact_case, std::abs(approx - exact) / exact);
                        }
                    }
        CAPTURE(g.aspect, worst, sum_rel / n_rel, worst_table_gap, n_exact_cases);
        CHECK(n_exact_cases > 0);
        CHECK(worst_exact_case <= 1e-12);
        CHECK(worst <= g.max_abs_measured);
        CHECK(sum_rel / n_rel <= g.mean_rel_measured);
        CHECK(worst_table_gap <= 2.3e-3);
    }
}

TEST_CASE("clipless through an LTC with any edge policy: invariant to the scale of M^-1", "[clipless]") {
    // Every edge policy but exact assumes unit vertices (c = a.b is a cosine only for them). The
    // LTC, hence the clipless result, does not depend on the scale of M^-1: scaling it by a power
    // of two scales M^-1 p exactly, and the normalized vertices, the edge terms and the result
    // are bitwise those of the unscaled matrix. Without the normalization the polynomial policy
    // was off by up to 0.4 on bench_polygon's configurations.
    const glm::vec3 straddling[4] = {{-1, -0.5f, -0.1f}, {1, -0.5f, -0.1f}, {1, 1.5f, 1.5f}, {-1, 1.5f, 1.5f}};
    const glm::vec3 above[4] = {{-1, 0, 0.5f}, {1, 0, 0.5f}, {1, 2, 1.5f}, {-1, 2, 1.5f}};
    const glm::mat3 m_inv = glm::transpose(glm::mat3(0.4f, 0, 0.3f, 0, 0.6f, 0, -0.2f, 0, 1));
    using poly = ltc::transformed<ltc::clamped_cosine<float, ltc::edge_policy::polynomial>>;
    for (const glm::vec3* quad : {straddling, above})
        for (const auto how : {cl::method::analytic, cl::method::table})
            for (const float scale : {1024.0f, 1.0f / 1024.0f}) {
                CAPTURE(scale, static_cast<int>(how), quad == above);
                const float unit = cl::integrate(poly::from_inverse(m_inv), quad, 4, ltc::sidedness::two_sided, how);
                REQUIRE(unit > 0.0f);
                CHECK(cl::integrate(poly::from_inverse(m_inv * scale), quad, 4, ltc::sidedness::two_sided, how) == unit);
            }
    // And the polynomial result is the exact policy's up to float rounding: the two edge terms
    // differ by 2.6e-7 relative at most (tests/test_edge_policies.cpp) and each path rounds its
    // vertices and sums: 1e-5 relative leaves a wide margin over both.
    using exact = ltc::transformed<ltc::clamped_cosine<float>>;
    for (const glm::vec3* quad : {straddling, above})
        CHECK_THAT(cl::integrate(poly::from_inverse(m_inv), quad, 4, ltc::sidedness::two_sided),
                   Catch::Matchers::WithinRel(cl::integrate(exact::from_inverse(m_inv), quad, 4, ltc::sidedness::two_sided), 1e-5f));
}

}  // namespace ltc_test_clipless
