// Tests of the exact textured integral: ltc/shading/cell_pyramid.hpp (means and ranges of
// 2^k x 2^k texel blocks), ltc/shading/textured_cells.hpp (the adaptive quadtree of cells, its
// error bound and its budget) and the textured_policy of ltc/shading/textured_light.hpp. The
// comparisons with independent references (texel sums, brute-force quadrature, Monte Carlo) are
// in test_textured_cells_truth.cpp.
#include <ltc/shading/textured_light.hpp>

#include "support/images.hpp"
#include "support/rng.hpp"
#include "support/textured_cases.hpp"
#include "support/textured_quads.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

namespace ltc_test_textured_cells {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::textured_cells;
using ltc_test::textured_checks::finite;

namespace {

/// Levels until one cell: 1 + the smallest k with 2^k >= max(w, h) (cell_pyramid.hpp).
int levels_of(int w, int h) {
    int k = 0;
    while ((1 << k) < std::max(w, h)) ++k;
    return k + 1;
}

}  // namespace

TEMPLATE_TEST_CASE("cell_pyramid: levels, cell rectangles, means and ranges", "[textured][cells]", float, double) {
    using vec3 = glm::vec<3, TestType>;
    // All texel values are multiples of 1/8 below 2^12: every sum below is exact in double, so
    // each mean is the correctly rounded quotient both here and in the library (whatever the
    // order of summation) and the ranges are exact differences: means and ranges compare exactly.
    const auto check_cells = [](const ltc::cell_pyramid<TestType>& cp, int w, int h, const std::vector<vec3>& img) {
        REQUIRE(cp.level_count() == levels_of(w, h));
        for (int k = 0; k < cp.level_count(); ++k) {
            const int s = 1 << k;
            REQUIRE(cp.cells_x(k) == (w + s - 1) / s);
            REQUIRE(cp.cells_y(k) == (h + s - 1) / s);
            for (int j = 0; j < cp.cells_y(k); ++j)
                for (int i = 0; i < cp.cells_x(k); ++i) {
                    int x0, y0, x1, y1;
                    cp.texels(k, i, j, x0, y0, x1, y1);
                    CHECK((x0 == i * s && y0 == j * s && x1 == std::min((i + 1) * s, w) &&
                           y1 == std::min((j + 1) * s, h)));
                    glm::dvec3 sum(0.0), lo(INFINITY), hi(-INFINITY);
                    for (int y = y0; y < y1; ++y)
                        for (int x = x0; x < x1; ++x) {
                            const glm::dvec3 c(img[std::size_t(y) * w + x]);
                            sum += c, lo = glm::min(lo, c), hi = glm::max(hi, c);
                        }
                    CAPTURE(k, i, j);
                    CHECK(cp.mean(k, i, j) == vec3(sum / double((x1 - x0) * (y1 - y0))));
                    CHECK(cp.range(k, i, j) == TestType(max_component(hi - lo)));
                }
        }
        // Level 0 is the image itself, exactly.
        for (int t = 0; t < w * h; ++t) CHECK(cp.mean(0, t % w, t / w) == img[std::size_t(t)]);
    };
    SECTION("5 x 3: levels 5 x 3, 3 x 2, 2 x 1, 1 x 1; light_texture builds the same pyramid") {
        std::vector<vec3> img(15);
        for (int t = 0; t < 15; ++t) img[std::size_t(t)] = vec3(t, ((7 * t) % 15) * 1.5, 100 - 0.25 * t);
        const ltc::cell_pyramid<TestType> cp(5, 3, img.data());
        CHECK(cp.level_count() == 4);
        check_cells(cp, 5, 3, img);
        check_cells(ltc::light_texture<TestType>(5, 3, img.data()).cells(), 5, 3, img);
    }
    SECTION("1 x 1 (one level), 1024 x 1 (11 levels) and 1 x 300 (10 levels: 2^9 >= 300)") {
        for (const auto& [w, h, levels] : {std::tuple{1, 1, 1}, std::tuple{1024, 1, 11}, std::tuple{1, 300, 10}}) {
            std::vector<vec3> img(std::size_t(w) * h);
            for (int t = 0; t < w * h; ++t) img[std::size_t(t)] = vec3((t % 17) * 0.5, t * 0.25, (t % 5) * 0.125);
            const ltc::cell_pyramid<TestType> cp(w, h, img.data());
            CHECK(cp.level_count() == levels);
            check_cells(cp, w, h, img);  // the top cell's mean is the image mean
        }
    }
}

TEMPLATE_TEST_CASE("cell_pyramid and light_texture reject empty, null and non-finite images", "[textured][cells]",
                   float, double) {
    using vec3 = glm::vec<3, TestType>;
    const std::vector<vec3> img(12, vec3(1));
    const auto both_throw = [](int w, int h, const vec3* p) {
        CAPTURE(w, h);
        CHECK_THROWS_AS(ltc::cell_pyramid<TestType>(w, h, p), std::invalid_argument);
        CHECK_THROWS_AS(ltc::light_texture<TestType>(w, h, p), std::invalid_argument);
        CHECK_THROWS_WITH(ltc::light_texture<TestType>(w, h, p), Catch::Contains("light_texture"));
    };
    for (const auto& [w, h] : {std::pair{0, 3}, std::pair{4, 0}, std::pair{-1, 3}, std::pair{4, -2}, std::pair{0, 0}})
        both_throw(w, h, img.data());
    both_throw(4, 3, nullptr);
    const TestType inf = std::numeric_limits<TestType>::infinity();
    for (const TestType bad : {std::numeric_limits<TestType>::quiet_NaN(), inf, -inf})
        for (int c = 0; c < 3; ++c) {
            std::vector<vec3> b = img;
            b[7][c] = bad;
            both_throw(4, 3, b.data());
        }
    CHECK_NOTHROW(ltc::cell_pyramid<TestType>(4, 3, img.data()));
}

TEMPLATE_TEST_CASE("constant texture: the cells give c I_D, with a zero bound", "[textured][cells]", float, double) {
    using T = TestType;
    using vec3 = glm::vec<3, T>;
    const vec3 c(0.75, 2.5, 0.125);
    const std::vector<vec3> img(15, c);
    const ltc::cell_pyramid<T> cells(5, 3, img.data());
    const light all[] = {lights[0], lights[1], lights[2], facing_away, below_horizon};
    for (const light& l : all)
        for (int lo = 0; lo < 2; ++lo)
            for (const auto side : {ltc::sidedness::one_sided, ltc::sidedness::two_sided})
                for (const std::size_t budget : {1, 64, 1000}) {
                    dvec3 qd[4];
                    vec3 q[4];
                    l.corners(qd, q);
                    const auto d = lobe<T>(lo);
                    const auto r = ltc::integrate_textured_cells(d, q, cells, side, ltc::cell_budget{budget, 0});
                    CAPTURE(l.name, lobe_names[lo], int(side), budget);
                    // The root has range 0 (textured_cells.hpp: an exact leaf, never refined, bound
                    // 0), so the value is c I_D(root): I_D(root) within root_bound of the exact
                    // integral, d.integrate(q) within integral_bound (dyadic corners: exact input);
                    // then two products rounded (2u). 0 where the light is not seen.
                    const T i_d = d.integrate(q, 4, side);
                    const double tol =
                        integral_bound<T>(lobe_m_inv(lo), qd, 0) + root_bound<T>(lobe_m_inv(lo), qd, 5, 3);
                    for (int k = 0; k < 3; ++k)
                        CHECK(std::abs(double(r.value[k]) - double(c[k] * i_d)) <=
                              c[k] * (tol + 2 * unit_roundoff<T>() * i_d));
                    CHECK((r.error_bound == T(0) && r.cells == 1));
                    if (&l == &all[4] || (&l == &all[3] && side == ltc::sidedness::one_sided))
                        CHECK(r.value == vec3(0));
                    else
                        CHECK(r.value.y > T(0));
                }
}

TEST_CASE("textured policies: fetch, quick_cells and exact_cells (textured_light.hpp)", "[textured][cells]") {
    using ltc::textured_method;
    const float u = std::numeric_limits<float>::epsilon() / 2;
    const glm::vec3 F0(0.04f, 0.5f, 1.0f), albedo(0.8f, 0.3f, 0.1f);
    ltc_test::rng r(0xce12);
    SECTION("a constant texture: the three methods agree to float rounding") {
        const glm::vec3 c(0.75f, 2.5f, 0.125f);
        const std::vector<glm::vec3> img(64, c);
        const ltc::light_texture<float> tex(8, 8, img.data());
        for (int i = 0; i < 100; ++i) {
            dvec3 qd[4];
            ltc_test::textured_checks::random_quad(r, qd);
            glm::vec3 q[4];
            const glm::vec3 P(float(r.uniform(-1, 1)), float(r.uniform(-1, 1)), float(r.uniform(-0.2, 0.2)));
            for (int k = 0; k < 4; ++k) q[k] = glm::vec3(qd[k]) + P;
            const glm::vec3 N = glm::normalize(glm::vec3(r.direction()) + glm::vec3(0, 0, 1.5f));
            const glm::vec3 V = glm::normalize(glm::vec3(r.direction()) + glm::vec3(0, 0, 1.2f));
            const float rough = float(r.uniform(0.05, 1));
            // The local quad and lobes that shade_textured_quad_light integrates (its comment:
            // make_shading_frame, the GGX fetch at cos theta_v, and M = I for the diffuse term).
            const ltc::shading_frame<float> frame = ltc::make_shading_frame(N, V);
            dvec3 local[4];
            for (int k = 0; k < 4; ++k) local[k] = dvec3(frame.to_local(q[k] - P));
            const ltc::ltc_coefficients<float> co = ltc::ggx::fetch<float>(frame.cos_theta_v, rough);
            const glm::vec3 brdf = F0 * co.magnitude + (glm::vec3(1) - F0) * co.fresnel;
            // fetch: I_D c exactly (test_textured.cpp); the cells: c I_D(root) (constant texture),
            // the root on q_0, q_1, q_3 (corner 2 off the parallelogram by parallelogram_defect);
            // so they differ by integral_bound + root_bound (as in the constant-texture tests)
            // times c and the BRDF factor, plus 4u of the value (two rounded products each side).
            const auto bound = [&](const dmat3& m) {
                return integral_bound<float>(m, local, parallelogram_defect(local)) + root_bound<float>(m, local, 8, 8);
            };
            const double b_spec = bound(dmat3(co.m_inv)), b_diff = bound(dmat3(1.0));
            for (auto side : {ltc::sidedness::one_sided, ltc::sidedness::two_sided}) {
                const auto a = ltc::shade_textured_quad_light(P, N, V, rough, F0, albedo, q, tex, side);
                for (const auto m : {textured_method::quick_cells, textured_method::exact_cells}) {
                    const auto b = ltc::shade_textured_quad_light(P, N, V, rough, F0, albedo, q, tex, side,
                                                                  ltc::textured_policy{m, {64, 0}});
                    for (int k = 0; k < 3; ++k) {
                        CHECK(std::abs(a.specular[k] - b.specular[k]) <=
                              brdf[k] * c[k] * b_spec + 4 * u * a.specular[k]);
                        CHECK(std::abs(a.diffuse[k] - b.diffuse[k]) <=
                              albedo[k] * c[k] * b_diff + 4 * u * a.diffuse[k]);
                    }
                }
            }
        }
    }
    SECTION("a texture: exact_cells is integrate_textured_cells with its budget, quick_cells integrate_quick_cells") {
        // Left half one colour, right half another: the root's four 16 x 16 children are
        // constant, so 16 cells or more give the exact integral with every leaf exact (bound 0).
        std::vector<glm::vec3> halves(32 * 32);
        for (std::size_t t = 0; t < halves.size(); ++t)
            halves[t] = t % 32 < 16 ? glm::vec3(0.25f, 1.5f, 0.5f) : glm::vec3(2, 0.125f, 1);
        const auto img = make_image(pattern::smooth, 32, 32);
        const ltc::light_texture<float> tex(32, 32, img.data()), tex_h(32, 32, halves.data());
        const auto quad = [&](const auto& d, const glm::vec3* q, const auto& t, auto side, textured_method m,
                              std::size_t b) {
            return ltc::integrate_textured_quad(d, q, t, side, {m, {b, 0}});
        };
        for (int i = 0; i < 50; ++i) {
            dvec3 qd[4];
            ltc_test::textured_checks::random_quad(r, qd);
            glm::vec3 q[4];
            to_t(qd, q);
            const auto d = ltc_test::textured_checks::ggx_lobe(float(r.uniform(0, 1)), float(r.uniform(0.05, 1)));
            for (auto side : {ltc::sidedness::one_sided, ltc::sidedness::two_sided}) {
                // The same function with the same arguments: the same numbers.
                CHECK(quad(d, q, tex, side, textured_method::exact_cells, 2000) ==
                      ltc::integrate_textured_cells(d, q, tex.cells(), side, {2000, 0}).value);
                const auto h16 = ltc::integrate_textured_cells(d, q, tex_h.cells(), side, {16, 0});
                CHECK(h16.error_bound == 0.0f);
                CHECK(quad(d, q, tex_h, side, textured_method::exact_cells, 2000) == h16.value);
                // quick_cells: integrate_quick_cells whatever the policy's budget says; on the
                // halves every base cell is constant (bound 0, nothing split), so it is h16 up to
                // the order of the sums: h16 adds the base cells' float I_D four at a time (three
                // roundings of positive terms: gamma_3 < 3.01u relative) before its double
                // products, quick_cells none; the double products and sums add < 0.01u.
                const auto quick = ltc::integrate_quick_cells(d, q, tex_h, side);
                CHECK(quick.error_bound == 0.0f);
                for (int k = 0; k < 3; ++k) CHECK(std::abs(quick.value[k] - h16.value[k]) <= 4 * u * h16.value[k]);
                CHECK(quad(d, q, tex_h, side, textured_method::quick_cells, 1) == quick.value);
                CHECK(quad(d, q, tex, side, textured_method::quick_cells, 1) ==
                      quad(d, q, tex, side, textured_method::quick_cells, 2000));
            }
        }
        // A light far away under the clamped cosine: no cell is wider than the lobe's footprint
        // (the fetch's sigma = r / sqrt(2 A) = 8 / sqrt(2) uv units, the whole texture), so
        // quick_cells takes every leaf's mean.
        const auto two = ltc::sidedness::two_sided;
        const glm::vec3 far[4] = {{-0.5f, -0.5f, 8}, {0.5f, -0.5f, 8}, {0.5f, 0.5f, 8}, {-0.5f, 0.5f, 8}};
        CHECK(quad(lobe<float>(0), far, tex, two, textured_method::quick_cells, 1) ==
              ltc::integrate_quick_cells(lobe<float>(0), far, tex, two, false).value);
        // shade_textured_quad_light with exact_cells: (F0 magnitude + (1 - F0) fresnel) and the
        // albedo times the cell integrals of the local quad (two rounded products: 2u).
        const glm::vec3 P(0.1f, -0.2f, 0), N = glm::normalize(glm::vec3(0.1f, 0, 1));
        const glm::vec3 V = glm::normalize(glm::vec3(0.8f, 0.1f, 1));
        const ltc::shading_frame<float> frame = ltc::make_shading_frame(N, V);
        const ltc::ltc_coefficients<float> co = ltc::ggx::fetch<float>(frame.cos_theta_v, 0.3f);
        const auto spec_lobe = ltc::transformed<ltc::clamped_cosine<float>>::from_inverse(co.m_inv);
        const ltc::cell_budget budget{100, 0};
        for (const light& l : lights) {
            dvec3 qd[4];
            glm::vec3 q[4], local[4];
            l.corners(qd, q);
            for (int k = 0; k < 4; ++k) local[k] = frame.to_local(q[k] - P);
            const auto s = ltc::shade_textured_quad_light(P, N, V, 0.3f, F0, albedo, q, tex, two,
                                                          {textured_method::exact_cells, budget});
            const glm::vec3 spec = (F0 * co.magnitude + (glm::vec3(1) - F0) * co.fresnel) *
                                   ltc::integrate_textured_cells(spec_lobe, local, tex.cells(), two, budget).value;
            const glm::vec3 diff =
                albedo * ltc::integrate_textured_cells(lobe<float>(0), local, tex.cells(), two, budget).value;
            for (int k = 0; k < 3; ++k) {
                CHECK(std::abs(s.specular[k] - spec[k]) <= 2 * u * spec[k]);
                CHECK(std::abs(s.diffuse[k] - diff[k]) <= 2 * u * diff[k]);
            }
        }
    }
}

TEMPLATE_TEST_CASE("the cells are finite for degenerate and extreme lights", "[textured][cells]", float, double) {
    using T = TestType;
    using vec3 = glm::vec<3, T>;
    const auto img = ltc_test::random_image(16, 8, 0xce13, 2);
    const ltc::light_texture<T> tex(16, 8, to<T>(img).data());
    const T big = T(1e30), tiny = T(1e-30);
    const vec3 cases[][4] = {
        {{0, 0, 1}, {1, 0, 1}, {2, 0, 1}, {3, 0, 1}},                                          // zero area (collinear)
        {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}},                                          // coincident corners
        {{1, 1, 1}, {1, 1, 1}, {1, 2, 1}, {1, 2, 1}},                                          // q_1 = q_0: zero area
        {{-big, -big, big}, {big, -big, big}, {big, big, big}, {-big, big, big}},              // huge
        {{-tiny, -tiny, tiny}, {tiny, -tiny, tiny}, {tiny, tiny, tiny}, {-tiny, tiny, tiny}},  // tiny
        {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}},                                      // in the shading plane
        {{0, -1, -1}, {0, 1, -1}, {0, 1, 1}, {0, -1, 1}},                  // a plane through the point
        {{0, 0, 0}, {1, 0, 1}, {1, 1, 1}, {0, 1, 0}},                      // a corner at the point
        {{-1, -1, 1e-7f}, {1, -1, 1e-7f}, {1, 1, 1e-7f}, {-1, 1, 1e-7f}},  // grazing
    };
    const auto d = ltc_test::textured_checks::ggx_lobe(T(0.3), T(0.2));
    for (std::size_t c = 0; c < std::size(cases); ++c)
        for (auto side : {ltc::sidedness::one_sided, ltc::sidedness::two_sided})
            for (const std::size_t budget : {1, 16, 1000}) {
                CAPTURE(c, int(side), budget);
                const auto r = ltc::integrate_textured_cells(d, cases[c], tex.cells(), side, {budget, 0});
                CHECK((finite(glm::dvec3(r.value)) && std::isfinite(double(r.error_bound))));
                CHECK((r.value.x >= 0 && r.value.y >= 0 && r.value.z >= 0 && r.error_bound >= 0));
                CHECK(r.cells <= budget);
                if (c < 3) CHECK(r.value == vec3(0));  // textured_cells.hpp: a zero-area quad gives 0
                for (const auto m : {ltc::textured_method::fetch, ltc::textured_method::quick_cells,
                                     ltc::textured_method::exact_cells}) {
                    const auto s = ltc::shade_textured_quad_light(vec3(0), vec3(0, 0, 1), vec3(0.3, 0, 1), T(0.3),
                                                                  vec3(0.04), vec3(0.5), cases[c], tex, side,
                                                                  ltc::textured_policy{m, {budget, 0}});
                    CHECK(finite(glm::dvec3(s.specular + s.diffuse)));
                }
            }
}

}  // namespace ltc_test_textured_cells
