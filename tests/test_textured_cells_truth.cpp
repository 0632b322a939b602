// ltc/shading/textured_cells.hpp against independent references: at full refinement it is sum_t
// L_t I_D(t) (that sum; brute-force quadrature of D over each texel; Monte Carlo of the texel-
// constant texture, ltc/reference/textured_ground_truth.hpp); below it, its bound is rigorous.
#include <ltc/reference/textured_ground_truth.hpp>
#include <ltc/shading/textured_light.hpp>

#include "support/brute_force.hpp"
#include "support/images.hpp"
#include "support/rng.hpp"
#include "support/textured_cases.hpp"
#include "support/textured_quads.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace ltc_test_textured_cells_truth {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::textured_cells;

constexpr double u_d = std::numeric_limits<double>::epsilon() / 2, kPi = 3.141592653589793;
namespace tgt = ltc::textured_ground_truth;

TEMPLATE_TEST_CASE("full refinement is the sum over the texels of L_t I_D(t)", "[textured][cells]", float, double) {
    using T = TestType;
    for (const auto& [w, h] : {std::pair{7, 5}, std::pair{16, 16}, std::pair{33, 9}}) {
        const auto img = ltc_test::random_image(w, h, 0xce20 + w, 2);
        const ltc::cell_pyramid<T> cells(w, h, to<T>(img).data());
        for (const light& l : lights)
            for (int lo = 0; lo < 2; ++lo)
                for (auto side : {ltc::sidedness::one_sided, ltc::sidedness::two_sided}) {
                    dvec3 qd[4];
                    glm::vec<3, T> q[4];
                    l.corners(qd, q);
                    const auto d = lobe<T>(lo);
                    const auto r = ltc::integrate_textured_cells(d, q, cells, side, {std::size_t(w * h), 0});
                    // sum_t L_t I_D(t), I_D(t) by d.integrate over the texel's corners (cell_corners):
                    // the library's numbers in double; in float (its batch kernel) both are within
                    // integral_bound of the exact I_D over these corners.
                    glm::dvec3 sum(0.0), kernel(0.0);
                    for (int y = 0; y < h; ++y)
                        for (int x = 0; x < w; ++x) {
                            glm::vec<3, T> c[4];
                            cell_corners(q, w, h, x, y, x + 1, y + 1, c);
                            const dvec3 cd[4] = {dvec3(c[0]), dvec3(c[1]), dvec3(c[2]), dvec3(c[3])};
                            const glm::dvec3 L(img[std::size_t(y) * w + x]);
                            sum += double(d.integrate(c, 4, side)) * L;
                            kernel += 2 * integral_bound<T>(lobe_m_inv(lo), cd, 0) * L;
                        }
                    CAPTURE(w, h, l.name, lobe_names[lo], int(side));
                    // Random texels, no two equal: every leaf is a texel (range > 0 above level 0),
                    // except cells unseen (I_D = 0: bound 0) across the horizon.
                    CHECK((r.cells == std::size_t(w * h) || (&l == &lights[2] && r.cells < std::size_t(w * h))));
                    CHECK(r.error_bound == T(0));
                    // The same n products L_t I_D(t) summed in double in another order: <= 2 n u_d
                    // sum_t L_t I_D(t) apart (two recursive sums of n >= 0 terms); then rounded to T.
                    for (int k = 0; k < 3; ++k)
                        CHECK(std::abs(double(r.value[k]) - sum[k]) <=
                              kernel[k] + unit_roundoff<T>() * sum[k] + 2 * double(w * h) * u_d * sum[k]);
                }
    }
}

TEMPLATE_TEST_CASE("constant texture on random rectangles: c I_D within the rounding bound", "[textured][cells]", float,
                   double) {
    using T = TestType;
    using vec3 = glm::vec<3, T>;
    const vec3 c(0.75, 2.5, 0.125);
    const std::vector<vec3> img(15, c);
    const ltc::cell_pyramid<T> cells(5, 3, img.data());
    ltc_test::rng r(0xce11);
    for (int i = 0; i < 100; ++i) {
        dvec3 qd[4];
        ltc_test::textured_checks::random_quad(r, qd);
        vec3 q[4];
        to_t(qd, q);
        for (int k = 0; k < 4; ++k) qd[k] = dvec3(q[k]);
        const auto d = ltc_test::textured_checks::ggx_lobe(T(r.uniform(0, 1)), T(r.uniform(0.05, 1)));
        const dmat3 m(d.inverse_matrix());
        const auto res = ltc::integrate_textured_cells(d, q, cells, ltc::sidedness::two_sided, {64, 0});
        const T i_d = d.integrate(q, 4);
        // c I_D(root) (range 0: an exact leaf), I_D(root) within root_bound of the exact I_D of
        // the parallelogram on q_0, q_1, q_3; d.integrate(q) within integral_bound of it (corner
        // 2 off by parallelogram_defect); then two products rounded (2u of the value).
        const double b = integral_bound<T>(m, qd, parallelogram_defect(qd)) + root_bound<T>(m, qd, 5, 3);
        for (int k = 0; k < 3; ++k)
            CHECK(std::abs(double(res.value[k]) - double(c[k] * i_d)) <=
                  c[k] * b + 2 * unit_roundoff<T>() * c[k] * i_d);
        CHECK(res.error_bound == T(0));
    }
}

TEMPLATE_TEST_CASE("full refinement against brute-force quadrature of D over each texel", "[textured][cells]", float,
                   double) {
    using T = TestType;
    const int w = 6, h = 5;
    const auto img = ltc_test::random_image(w, h, 0xce21, 2);
    const ltc::cell_pyramid<T> cells(w, h, to<T>(img).data());
    for (const light& l : lights)
        for (int lo = 0; lo < 2; ++lo) {
            dvec3 qd[4];
            glm::vec<3, T> q[4];
            l.corners(qd, q);
            const dmat3 m = lobe_m_inv(lo);
            // D(w) = max(0, s) |M^-1| / (pi |M^-1 w|^4), s = (M^-1 w).z (eq. 1 with D_o the
            // clamped cosine), written here from its definition; h = the third row of M^-1.
            const dvec3 hz(m[0][2], m[1][2], m[2][2]);
            const auto D = [&](const dvec3& dir, double s) {
                const double l2 = glm::dot(m * dir, m * dir);
                return std::array<double, 1>{std::max(0.0, s) * std::abs(glm::determinant(m)) / (kPi * l2 * l2)};
            };
            // Order 8, relative tolerance 1e-11, defaults; direction condition |grad_w |M^-1 w|^-4|
            // |w| / |M^-1 w|^-4 <= 4 cond(M^-1) <= 4 |M^-1|_F |M|_F; evaluation error: M^-1 w (3),
            // |.|^2 (3), ^2 (1), products and division (4): 11 + 4 u.
            const ltc_test::brute_force_options bo{8, 1e-11, 1e-18, 6000, 4 * frobenius(m) * frobenius(glm::inverse(m)),
                                                   15};
            glm::dvec3 ref(0.0), tol(0.0);
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    dvec3 c[4];
                    exact_cell(qd, w, h, x, y, x + 1, y + 1, c);
                    const dvec3 kernel = 0.25 * (c[0] + c[1] + c[2] + c[3]);
                    const auto bf = ltc_test::integrate_polygon<1>({c[0], c[1], c[2], c[3]}, kernel, hz, D, bo);
                    REQUIRE(bf.converged);
                    const glm::dvec3 L(img[std::size_t(y) * w + x]);
                    ref += L * bf.value[0];
                    // The brute force's error estimate plus the library's (cell_bound: its corners
                    // off by corner_error, the closed form's rounding, the float kernel's).
                    tol += L * (bf.error[0] + cell_bound<T>(m, qd, w, h, x, y, x + 1, y + 1));
                }
            const auto r = ltc::integrate_textured_cells(lobe<T>(lo), q, cells, ltc::sidedness::two_sided, {100, 0});
            CAPTURE(l.name, lobe_names[lo], ref.x, ref.y, ref.z, tol.x, tol.y, tol.z);
            for (int k = 0; k < 3; ++k)  // plus the library's double sum of 30 terms, rounded to T
                CHECK(std::abs(double(r.value[k]) - ref[k]) <= tol[k] + (unit_roundoff<T>() + 60 * u_d) * ref[k]);
        }
}

TEMPLATE_TEST_CASE("the error bound is rigorous, non-increasing in the budget, and stops at a tolerance",
                   "[textured][cells]", float, double) {
    using T = TestType;
    const int w = 32, h = 32;
    const auto side = ltc::sidedness::two_sided;
    for (const pattern p : {pattern::smooth, pattern::detail}) {
        const auto img = make_image(p, w, h);
        const ltc::cell_pyramid<T> cells(w, h, to<T>(img).data());
        for (const light& l : lights)
            for (int lo = 0; lo < 2; ++lo) {
                dvec3 qd[4];
                glm::vec<3, T> q[4];
                l.corners(qd, q);
                const auto d = lobe<T>(lo);
                const auto full = ltc::integrate_textured_cells(d, q, cells, side, {std::size_t(w * h), 0});
                // textured_cells.hpp: with the exact integrals I_c of the exact cells,
                // |sum_leaves mean_c I_c - sum_t L_t I_t| <= sum_leaves range_c I_c. The library's
                // I_c are within cell_bound e_c of them (or sums of level top - 2's), so its value,
                // the full value and its bound each move by <= pyramid_bound: 3 of it, plus the sums
                // (<= 2 n u_d of the value, n < 2 w h terms) and the roundings to T (u_T each).
                const double slack = 3 * pyramid_bound<T>(lobe_m_inv(lo), qd, img, w, h);
                double prev = INFINITY;
                for (const std::size_t b : {1, 4, 7, 16, 64, 256}) {
                    const auto r = ltc::integrate_textured_cells(d, q, cells, side, {b, 0});
                    CAPTURE(int(p), l.name, lobe_names[lo], b, r.cells, r.integrals, r.error_bound, slack);
                    CHECK(r.cells <= b);
                    // 32 x 32: every refined cell has four children, so cells = 1 + 3 R after R
                    // refinements, and integrals <= 16 + 4 R (one for the root, or the 4 x 4 cells
                    // of level top - 2 at once, their sums giving the levels above; four per step).
                    CHECK((r.cells - 1) % 3 == 0);
                    CHECK(r.integrals <= 16 + 4 * ((r.cells - 1) / 3));
                    for (int k = 0; k < 3; ++k) {
                        const double v = double(r.value[k]), f = double(full.value[k]);
                        CHECK(std::abs(v - f) <=
                              double(r.error_bound) + slack +
                                  (unit_roundoff<T>() + 4 * w * h * u_d) * (v + f + double(r.error_bound)));
                    }
                    // Refining replaces range_c I_c by sum range_child I_child <= range_c I_c
                    // (children's ranges <= the parent's, I additive), up to the same rounding.
                    CHECK(double(r.error_bound) <= prev + slack);
                    prev = double(r.error_bound);
                }
                // Tolerance 1%: stopped by it (bound <= 0.01 x the largest channel, on running double
                // sums drifting by <= u_d per addition, 2 per integral, of at most the root's bound
                // and L_max I_D(quad); then rounded to T: 3 u_T), by the budget (the next refinement
                // adds 3 leaves), or with nothing left to refine (bound 0).
                const auto root = ltc::integrate_textured_cells(d, q, cells, side, {1, 0});
                const double drift = 2 * u_d * (double(root.error_bound) + 0.01 * max_texel(img) * d.integrate(q, 4));
                for (const std::size_t b : {16, 1024}) {
                    const auto r = ltc::integrate_textured_cells(d, q, cells, side, {b, 0.01});
                    const auto all = ltc::integrate_textured_cells(d, q, cells, side, {b, 0});
                    CAPTURE(int(p), l.name, lobe_names[lo], b, r.cells, all.cells, r.error_bound);
                    CHECK(r.cells <= all.cells);
                    const double vmax = max_component(glm::dvec3(r.value)), tol = 0.01 * vmax + drift * r.integrals;
                    CHECK((r.cells + 3 > b || double(r.error_bound) <= tol * (1 + 3 * unit_roundoff<T>())));
                    // The smooth texture needs far fewer than 32 x 32 cells for 1%.
                    if (p == pattern::smooth && b == 1024) CHECK(r.cells < all.cells);
                }
            }
    }
}

TEST_CASE("the bound is nearly attained: a sharp lobe on the one bright texel of a strip", "[textured][cells]") {
    // The facing light as 15 x 1 texels, texel 7 (|x| <= a = 1/30) of radiance 1, the others 0;
    // M = diag(alpha, alpha, 1), alpha = 0.01: D's hit points on z = 1 are alpha times those of
    // the cosine, whose radius exceeds R with probability 1 / (1 + R^2). So I_D(quad) <= 1,
    // I_7 >= 1 - 1 / (1 + (a / alpha)^2) - 2 / (1 + (0.5 / alpha)^2) > 0.916, and the root's
    // error I_7 - I_D(quad) / 15 > 0.85 >= 0.85 of its bound range I_D(quad) = I_D(quad).
    std::vector<glm::dvec3> img(15, glm::dvec3(0.0));
    img[7] = glm::dvec3(1.0);
    const ltc::cell_pyramid<double> cells(15, 1, img.data());
    dvec3 q[4];
    lights[0].corners(q);
    const auto d = ltc::transformed<ltc::clamped_cosine<double>>(glm::dmat3(0.01, 0, 0, 0, 0.01, 0, 0, 0, 1));
    const auto root = ltc::integrate_textured_cells(d, q, cells, ltc::sidedness::two_sided, {1, 0});
    const auto full = ltc::integrate_textured_cells(d, q, cells, ltc::sidedness::two_sided, {15, 0});
    const double err = std::abs(root.value.x - full.value.x);
    CHECK(root.error_bound == Approx(d.integrate(q, 4)).epsilon(1e-12));
    CHECK(err <= root.error_bound * (1 + 1e-12));
    CHECK(err >= 0.85 * root.error_bound);
}

TEMPLATE_TEST_CASE("a cell with one child: the child covers its texels with its integral", "[textured][cells]", float,
                   double) {
    // 6 x 1 texels 1 1 1 1 a b: levels of 6, 3, 2 and 1 cells. The root refines into the exact
    // cell of texels 0-3 and the cell of texels 4-5, whose only child (level 1, the same texels)
    // then replaces it; a budget of 2 stops there: value = I_D(0-3) + (a + b) / 2 I_D(4-5), bound
    // range I_D(4-5) (range 1.75 = max |a - b|), each I_D within cell_bound, then rounded (2u).
    using T = TestType;
    const std::vector<glm::vec3> img = {glm::vec3(1), glm::vec3(1), glm::vec3(1),
                                        glm::vec3(1), {0.5f, 2, 3}, {1.5f, 0.25f, 3}};
    const ltc::cell_pyramid<T> cells(6, 1, to<T>(img).data());
    dvec3 qd[4];
    glm::vec<3, T> q[4];
    lights[1].corners(qd, q);
    const auto r = ltc::integrate_textured_cells(lobe<T>(1), q, cells, ltc::sidedness::two_sided, {2, 0});
    const dmat3 m = lobe_m_inv(1);
    const double i03 = exact_cell_integral(m, qd, 6, 1, 0, 0, 4, 1);  // integrated, or summed from level 1:
    const double e03 = cell_bound<T>(m, qd, 6, 1, 0, 0, 4, 1) + cell_bound<T>(m, qd, 6, 1, 0, 0, 2, 1) +
                       cell_bound<T>(m, qd, 6, 1, 2, 0, 4, 1) + unit_roundoff<T>() * i03;
    const double i45 = exact_cell_integral(m, qd, 6, 1, 4, 0, 6, 1), e45 = cell_bound<T>(m, qd, 6, 1, 4, 0, 6, 1);
    const glm::dvec3 mean = 0.5 * (glm::dvec3(img[4]) + glm::dvec3(img[5]));
    CHECK(r.cells == 2);
    for (int k = 0; k < 3; ++k)
        CHECK(std::abs(r.value[k] - (i03 + mean[k] * i45)) <=
              e03 + mean[k] * e45 + 2 * unit_roundoff<T>() * r.value[k]);
    CHECK(std::abs(r.error_bound - 1.75 * i45) <= 1.75 * e45 + 2 * unit_roundoff<T>() * r.error_bound);
}

TEST_CASE("full refinement against Monte Carlo of the texel-constant texture", "[textured][cells][ground_truth]") {
    const int w = 64, h = 64;
    const std::size_t n = w * h;
    int seed = 0;
    for (const pattern p : {pattern::smooth, pattern::checker, pattern::detail}) {
        const auto img = make_image(p, w, h);
        const auto imgd = to<double>(img);
        const ltc::cell_pyramid<float> cells_f(w, h, img.data());
        const ltc::cell_pyramid<double> cells_d(w, h, imgd.data());
        // Area sampling proportional to luminance puts samples on the small bright detail.
        std::vector<double> lum(imgd.size());
        for (std::size_t t = 0; t < lum.size(); ++t) lum[t] = glm::dot(imgd[t], glm::dvec3(0.2126, 0.7152, 0.0722));
        const tgt::texel_distribution by_luminance(w, h, lum.data());
        const auto radiance = [&](double u, double v) { return ltc::nearest_image_lookup(w, h, imgd.data(), u, v); };
        for (int li = 0; li < 2; ++li)
            for (int lo = 0; lo < 2; ++lo) {
                dvec3 qd[4];
                glm::vec3 qf[4];
                lights[li].corners(qd, qf);
                const tgt::options opt{std::size_t(1) << 16, 0xce30 + std::uint64_t(seed++)};  // samples, seed
                const auto e = tgt::integrate(tgt::ltc_lobe{lobe<double>(lo)}, qd, radiance, opt,
                                              p == pattern::detail ? &by_luminance : nullptr);
                const auto side = ltc::sidedness::two_sided;
                const auto rd = ltc::integrate_textured_cells(lobe<double>(lo), qd, cells_d, side, {n, 0});
                const auto rf = ltc::integrate_textured_cells(lobe<float>(lo), qf, cells_f, side, {n, 0});
                // Each result's rounding: full_refinement_bound (its leaves' I_D against the exact
                // cells'), the double sum of n terms (2 n u_d) and the rounding to T. These first-
                // order worst cases come to 1e-3 to 7e-2 of the value in float (the sharp lobe's
                // M^-1 amplifies vertex errors) and 1e-10 in double; the measured float - double
                // difference is <= 2e-6 of it, far below 4 standard errors (1e-2).
                const double bf = full_refinement_bound<float>(lobe_m_inv(lo), qd, cells_d);
                const glm::dvec3 slack_f = bf + (unit_roundoff<float>() + 2 * n * u_d) * rd.value;
                const glm::dvec3 slack_d =
                    full_refinement_bound<double>(lobe_m_inv(lo), qd, cells_d) + 2 * n * u_d * rd.value;
                CAPTURE(int(p), lights[li].name, lobe_names[lo], e.mean.y, e.standard_error.y, rd.value.y, rf.value.y);
                for (int k = 0; k < 3; ++k) {
                    // Unbiased MC, fixed seeds: 4 standard errors (a false failure ~6e-5 per check
                    // for a normal mean), plus the result's rounding.
                    CHECK(std::abs(rd.value[k] - e.mean[k]) <= 4 * e.standard_error[k] + slack_d[k]);
                    CHECK(std::abs(double(rf.value[k]) - rd.value[k]) <= slack_f[k] + slack_d[k]);
                    CHECK(std::abs(double(rf.value[k]) - e.mean[k]) <= 4 * e.standard_error[k] + slack_f[k]);
                }
            }
    }
}

}  // namespace ltc_test_textured_cells_truth
