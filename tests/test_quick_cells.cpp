// Tests of ltc/shading/quick_cells.hpp: with every leaf its texels' mean, the error bound is
// rigorous against the texel-constant integral (integrate_textured_cells at full refinement);
// the counts of leaves and integrals; the fetch inside wide leaves; robustness; the policy.
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
#include <type_traits>
#include <utility>
#include <vector>

namespace ltc_test_quick_cells {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::textured_cells;
using ltc_test::textured_checks::finite;

namespace {

constexpr double u_d = std::numeric_limits<double>::epsilon() / 2;
const auto two = ltc::sidedness::two_sided;

/// quick_cells' leaves are cells of levels base - 2 to base (base = top - 2, at least 0), each
/// I_D integrated directly, within e_c = cell_bound<T> (textured_cases.hpp: corners in T, then the
/// float batch kernel or the exact double policy) of the exact cell's. Over all the cells of those
/// levels (a superset of the leaves): {sum e_c (how far the leaves' summed I_D is from the exact
/// I_D of the parallelogram), sum (max_channel(mean_c) + range_c) e_c (how far the value and the
/// bound move by the rounding of the leaves' I_D: texels >= 0, so mean, range <= that weight)}.
template <typename T>
std::pair<double, double> quick_slack(const dmat3& m, const dvec3 q[4], const ltc::cell_pyramid<double>& cells) {
    const int base = std::max(cells.level_count() - 3, 0);
    double sum_e = 0, weighted = 0;
    for (int k = std::max(base - 2, 0); k <= base; ++k)
        for (int j = 0; j < cells.cells_y(k); ++j)
            for (int i = 0; i < cells.cells_x(k); ++i) {
                int x0, y0, x1, y1;
                cells.texels(k, i, j, x0, y0, x1, y1);
                const double b = cell_bound<T>(m, q, cells.width(), cells.height(), x0, y0, x1, y1);
                sum_e += b, weighted += (max_component(cells.mean(k, i, j)) + cells.range(k, i, j)) * b;
            }
    return {sum_e, weighted};
}

/// Item 1 (use_fetch = false) and the counts on one light, lobe and texture. r.value =
/// T(sum_leaves i_c mean_c) (<= 22 products in double); the exact texel-constant integral X is
/// within sum range_c I_c + u_T sum mean_c I_c (means rounded to T) of sum mean_c I_c; and
/// r.error_bound = T(sum range_c i_c) (ranges rounded to T). So |value - full| <= error_bound +
/// quick_slack (the leaves' I_D off by e_c, in value and bound) + full_refinement_bound (the full
/// value's leaves, textured_cases.hpp) +
/// 2 u_T (value + full + bound) (roundings to T, the means' and ranges') + 4 w h u_d of the same
/// (double sums and products, fewer than 2 w h terms each).
template <typename T>
void check_bound(const ltc::light_texture<T>& tex, const ltc::cell_pyramid<double>& cells_d,
                 const ltc::transformed<ltc::clamped_cosine<T>>& d, const dvec3 qd[4], const glm::vec<3, T> q[4]) {
    const int w = tex.width(), h = tex.height();
    const dmat3 m(d.inverse_matrix());
    const auto r = ltc::integrate_quick_cells(d, q, tex, two, false);
    const auto full = ltc::integrate_textured_cells(d, q, tex.cells(), two, {std::size_t(w) * std::size_t(h), 0});
    const double slack = quick_slack<T>(m, qd, cells_d).second + full_refinement_bound<T>(m, qd, cells_d);
    CAPTURE(w, h, r.cells, r.integrals, r.error_bound, slack);
    CHECK((r.cells <= 22 && r.integrals <= 24 && full.error_bound == T(0)));
    for (int k = 0; k < 3; ++k) {
        const double v = double(r.value[k]), f = double(full.value[k]), b = double(r.error_bound);
        CHECK(std::abs(v - f) <= b + slack + (2 * unit_roundoff<T>() + 4 * w * h * u_d) * (v + f + b));
    }
}

/// Light l (0 to 2: textured_cases.hpp's lights, one crossing the horizon; else a random one) in
/// T, and in double exactly as the library sees it.
template <typename T>
void make_light(int l, ltc_test::rng& r, dvec3 qd[4], glm::vec<3, T> q[4]) {
    if (l < 3) lights[l].corners(qd, q);
    else ltc_test::textured_checks::random_quad(r, qd), to_t(qd, q);
    for (int c = 0; c < 4; ++c) qd[c] = dvec3(q[c]);
}

/// The diffuse lobe, GGX at roughness 0.25 and theta_v 60 deg, or a random GGX lobe.
template <typename T>
ltc::transformed<ltc::clamped_cosine<T>> make_lobe(int i, ltc_test::rng& r) {
    return i < 2 ? lobe<T>(i) : ltc_test::textured_checks::ggx_lobe(T(r.uniform(0, 1)), T(r.uniform(0.05, 1)));
}

}  // namespace

TEMPLATE_TEST_CASE("quick_cells with the means: the bound holds against the texel-constant integral",
                   "[textured][quick_cells]", float, double) {
    using T = TestType;
    ltc_test::rng r(0x9c01);
    for (const auto& [w, h] : {std::pair{64, 64}, std::pair{32, 32}, std::pair{37, 23}}) {
        std::vector<ltc::light_texture<T>> tex;
        std::vector<ltc::cell_pyramid<double>> cells_d;
        for (const pattern p : {pattern::smooth, pattern::checker, pattern::detail}) {
            const auto img = make_image(p, w, h);
            tex.emplace_back(w, h, to<T>(img).data());
            cells_d.emplace_back(w, h, to<double>(img).data());
        }
        for (int l = 0; l < 5; ++l)
            for (int lo = 0; lo < 3; ++lo) {
                dvec3 qd[4];
                glm::vec<3, T> q[4];
                make_light(l, r, qd, q);
                const auto d = make_lobe<T>(lo, r);
                CAPTURE(l, lo);
                for (std::size_t p = 0; p < 3; ++p) check_bound(tex[p], cells_d[p], d, qd, q);
            }
    }
}

TEMPLATE_TEST_CASE("quick_cells on 1 x 1, 4 x 4, 1024 x 1 and 1 x 300 textures", "[textured][quick_cells]", float,
                   double) {
    using T = TestType;
    using vec3 = glm::vec<3, T>;
    const double u = unit_roundoff<T>();
    for (const light& l : lights)
        for (int lo = 0; lo < 2; ++lo) {
            dvec3 qd[4];
            vec3 q[4];
            l.corners(qd, q);
            const auto d = lobe<T>(lo);
            CAPTURE(l.name, lo);
            // 1 x 1: the texel times I_D of the quad (one cell, one integral, bound 0): the cell's
            // I_D within root_bound of the exact I_D of the quad (a parallelogram, dyadic corners),
            // d.integrate within integral_bound of it; then two products rounded (2u).
            const vec3 c(0.75, 2.5, 0.125);
            const ltc::light_texture<T> one(1, 1, &c);
            const T i_d = d.integrate(q, 4, two);
            const double tol = integral_bound<T>(lobe_m_inv(lo), qd, 0) + root_bound<T>(lobe_m_inv(lo), qd, 1, 1);
            for (const bool fetch : {false, true}) {
                const auto r = ltc::integrate_quick_cells(d, q, one, two, fetch);
                CHECK((r.cells == 1 && r.integrals == 1 && r.error_bound == T(0)));
                for (int k = 0; k < 3; ++k)
                    CHECK(std::abs(double(r.value[k]) - double(c[k] * i_d)) <= c[k] * (tol + 2 * u * i_d));
            }
            // 4 x 4: the base level is level 0 (every leaf a texel): bound 0, and the same 16 I_D
            // as full refinement (the same kernel call on the same cells) times the same texels,
            // summed in double in another order (2 x 16 u_d), each rounded to T.
            const auto img = ltc_test::random_image(4, 4, 0x9c02, 2);
            const ltc::light_texture<T> tex(4, 4, to<T>(img).data());
            for (const auto side : {ltc::sidedness::one_sided, two}) {
                const auto r = ltc::integrate_quick_cells(d, q, tex, side);
                const auto full = ltc::integrate_textured_cells(d, q, tex.cells(), side, {16, 0});
                CHECK((r.cells == 16 && r.integrals == 16 && r.error_bound == T(0)));
                for (int k = 0; k < 3; ++k) {
                    const double v = double(r.value[k]), f = double(full.value[k]);
                    CHECK(std::abs(v - f) <= (u + 32 * u_d) * (v + f));
                }
            }
            // 1024 x 1 and 1 x 300 (base cells of 256 and 128 texels): the bound holds.
            for (const auto& [w, h] : {std::pair{1024, 1}, std::pair{1, 300}})
                for (const pattern p : {pattern::smooth, pattern::detail}) {
                    const auto image = make_image(p, w, h);
                    const ltc::light_texture<T> strip(w, h, to<T>(image).data());
                    CAPTURE(w, h, int(p));
                    check_bound(strip, ltc::cell_pyramid<double>(w, h, to<double>(image).data()), d, qd, q);
                    CHECK(finite(glm::dvec3(ltc::integrate_quick_cells(d, q, strip).value)));
                }
        }
}

TEMPLATE_TEST_CASE("quick_cells with the fetch: the means where no leaf is wider than the lobe, texel bounds otherwise",
                   "[textured][quick_cells]", float, double) {
    using T = TestType;
    using vec3 = glm::vec<3, T>;
    const double u = unit_roundoff<T>(), u_f = unit_roundoff<float>();
    ltc_test::rng r(0x9c03);
    int differ = 0;
    for (const auto& [w, h] : {std::pair{64, 64}, std::pair{37, 23}})
        for (const pattern p : {pattern::smooth, pattern::checker, pattern::detail}) {
            const auto img = make_image(p, w, h);
            const ltc::light_texture<T> tex(w, h, to<T>(img).data());
            const ltc::cell_pyramid<double> cells_d(w, h, to<double>(img).data());
            glm::dvec3 lo(INFINITY), hi(0.0);
            for (const glm::vec3& c : img) lo = glm::min(lo, glm::dvec3(c)), hi = glm::max(hi, glm::dvec3(c));
            // Far away under the clamped cosine: sigma = 8 / sqrt(2) uv units, lod the last level,
            // so no leaf is wider than the lobe's footprint: every leaf its mean, bit for bit.
            const vec3 far[4] = {{-0.5, -0.5, 8}, {0.5, -0.5, 8}, {0.5, 0.5, 8}, {-0.5, 0.5, 8}};
            CHECK(ltc::integrate_quick_cells(lobe<T>(0), far, tex).value ==
                  ltc::integrate_quick_cells(lobe<T>(0), far, tex, two, false).value);
            for (int l = 0; l < 6; ++l)
                for (int lobe_i = 0; lobe_i < 3; ++lobe_i) {
                    dvec3 qd[4];
                    vec3 q[4];
                    make_light(l, r, qd, q);
                    const auto d = make_lobe<T>(lobe_i, r);
                    const dmat3 m(d.inverse_matrix());
                    const auto a = ltc::integrate_quick_cells(d, q, tex, two, true);
                    const auto b = ltc::integrate_quick_cells(d, q, tex, two, false);
                    CAPTURE(w, h, int(p), l, lobe_i);
                    // The same leaves and integrals (chosen before any fetch): only radiance differs.
                    CHECK((a.cells == b.cells && a.integrals == b.integrals && a.error_bound == b.error_bound));
                    differ += a.value != b.value;
                    // Every leaf's radiance is a convex combination of texels: its mean, or a trilinear
                    // lookup of levels whose samples are Gaussian sums with weights >= 0, normalized
                    // (light_texture.hpp, (*)), stored in float within [lo, hi]; then up to 4 float
                    // lerps a + t (b - a), t in [0, 1] (3 u_f of hi each). The leaves' I_D sum to S,
                    // within sum e_c of the exact I_D of the parallelogram (itself computed within
                    // cell_bound<double> in double); then <= 22 double products and sums, and the
                    // rounding to T.
                    const double i_d = exact_cell_integral(m, qd, 1, 1, 0, 0, 1, 1), round = u + 24 * u_d;
                    const double err =
                        cell_bound<double>(m, qd, 1, 1, 0, 0, 1, 1) + quick_slack<T>(m, qd, cells_d).first;
                    const double s_hi = i_d + err, s_lo = std::max(i_d - err, 0.0);
                    for (int k = 0; k < 3; ++k) {
                        CHECK(double(a.value[k]) <= hi[k] * s_hi * (1 + 12 * u_f + round));
                        CHECK(double(a.value[k]) >= lo[k] * s_lo * (1 - round) - 12 * u_f * hi[k] * s_hi);
                    }
                }
        }
    CHECK(differ > 0);  // the fetch was taken somewhere
}

TEMPLATE_TEST_CASE("quick_cells: below the horizon, non-finite, rescaled and huge quads; the policy",
                   "[textured][quick_cells]", float, double) {
    using T = TestType;
    using vec3 = glm::vec<3, T>;
    const auto img = make_image(pattern::detail, 37, 23);
    const ltc::light_texture<T> tex(37, 23, to<T>(img).data());
    const ltc::cell_pyramid<double> cells_d(37, 23, to<double>(img).data());
    const auto same = [](const ltc::cells_result<T>& a, const ltc::cells_result<T>& b) {
        return a.value == b.value && a.error_bound == b.error_bound && a.cells == b.cells && a.integrals == b.integrals;
    };
    const T inf = std::numeric_limits<T>::infinity();
    const auto quick = ltc::textured_method::quick_cells;
    const int top = tex.cells().level_count() - 1;
    ltc_test::rng r(0x9c04);
    for (int lo = 0; lo < 2; ++lo)
        for (const auto side : {ltc::sidedness::one_sided, two})
            for (const bool fetch : {false, true}) {
                CAPTURE(lo, int(side), fetch);
                const auto d = lobe<T>(lo);
                dvec3 qd[4];
                vec3 q[4];
                below_horizon.corners(qd, q);
                const auto below = ltc::integrate_quick_cells(d, q, tex, side, fetch);
                CHECK((below.value == vec3(0) && below.error_bound == T(0)));
                // A non-finite corner (+-inf, or NaN, in any corner, corner 2 included though the
                // cells do not use it): I_D of the quad (0 if NaN) times the texture's mean, as
                // integrate_textured_cells gives (the same expression: bit for bit).
                const T nan = std::numeric_limits<T>::quiet_NaN();
                for (int c = 0; c < 12; ++c) {
                    lights[1].corners(qd, q);
                    q[c % 4][c / 4 == 2 ? 1 : c / 4 * 2] = c >= 8 ? nan : c % 2 ? -inf : inf;
                    const auto a = ltc::integrate_quick_cells(d, q, tex, side, fetch);
                    const T i_d = d.integrate(q, 4, side);
                    CAPTURE(c);
                    CHECK(same(a, ltc::integrate_textured_cells(d, q, tex.cells(), side)));
                    CHECK(a.value == vec3(double(i_d > 0 ? i_d : T(0)) * glm::dvec3(tex.cells().mean(top, 0, 0))));
                    CHECK((finite(glm::dvec3(a.value)) && a.cells == 1 && a.integrals == 1));
                }
                for (int i = 0; i < 8; ++i) {
                    make_light(3, r, qd, q);
                    CAPTURE(i);
                    // Corners scaled by 2^10 or 2^-10: the same result, bit for bit.
                    const auto a = ltc::integrate_quick_cells(d, q, tex, side, fetch);
                    for (const int e : {10, -10}) {
                        vec3 s[4];
                        for (int c = 0; c < 4; ++c) s[c] = q[c] * std::ldexp(T(1), e);
                        CHECK(same(a, ltc::integrate_quick_cells(d, s, tex, side, fetch)));
                    }
                    // Huge corners (beyond an eighth of the largest finite value some are scaled
                    // by 2^-4; the kernel takes none of them: the scalar path): finite, the bound holds.
                    const int big = std::numeric_limits<T>::max_exponent - 4;
                    for (const T scale : {T(std::is_same_v<T, float> ? 1e37 : 1e307), std::ldexp(T(1), big)}) {
                        vec3 s[4];
                        dvec3 sd[4];  // for the bound, scaled back by a power of two (it overflows in double)
                        const double back = std::ldexp(1.0, -std::ilogb(scale));
                        for (int c = 0; c < 4; ++c) s[c] = q[c] * scale, sd[c] = dvec3(s[c]) * back;
                        const auto b = ltc::integrate_quick_cells(d, s, tex, side, fetch);
                        CHECK((finite(glm::dvec3(b.value)) && std::isfinite(b.error_bound)));
                        CHECK((b.value.x >= 0 && b.value.y >= 0 && b.value.z >= 0));
                        if (side == two && !fetch) check_bound(tex, cells_d, d, sd, s);
                    }
                    // textured_method::quick_cells is integrate_quick_cells, whatever the budget says.
                    for (const ltc::cell_budget budget : {ltc::cell_budget{0, 0}, {1, 0}, {16, 0.5}, {5000, 0}})
                        CHECK(ltc::integrate_textured_quad(d, q, tex, side, {quick, budget}) ==
                              ltc::integrate_quick_cells(d, q, tex, side).value);
                }
            }
}

}  // namespace ltc_test_quick_cells
