// Accuracy of ltc/shading/polygon_light.hpp: an edge policy other than exact changes the
// integrals by no more than the policy's bound, and the shading does not depend on the scale of
// M^-1, down to 1e-20 in float.
#include <catch2/catch.hpp>

#include <ltc/ltc.hpp>
#include <ltc/shading/clipless.hpp>
#include <ltc/shading/polygon_light.hpp>

#include "support/shading_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace ltc_test_shading_accuracy {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::shading_checks;  // lobes, random scenes, rel_diff

namespace {

// Lipschitz constant of the clipless integral with respect to the vector form factor F, per unit
// of a per-component change of F: I = sphere_form_factor(f, c) with f = min(|F|, 1) and
// c = F.z / |F|, so |dI| <= |dI/df| |dF| + |dI/dc| 2 |dF| / f and |dF| <= sqrt(3) per-component.
// The partial derivatives are taken by central differences on a 200 x 400 grid of (f, c).
double clipless_slope() {
    double worst = 0;
    const double h = 1e-5;
    for (int i = 1; i <= 200; ++i)
        for (int j = 0; j <= 400; ++j) {
            const double f = std::min(i / 200.0, 1 - h), c = std::clamp(-1 + j / 200.0, -1 + h, 1 - h);
            const double df = (ltc::clipless::sphere_form_factor(f + h, c) - ltc::clipless::sphere_form_factor(f - h, c)) / (2 * h);
            const double dc = (ltc::clipless::sphere_form_factor(f, c + h) - ltc::clipless::sphere_form_factor(f, c - h)) / (2 * h);
            worst = std::max(worst, std::sqrt(3.0) * (std::abs(df) + 2 * std::abs(dc) / f));
        }
    return worst;
}

}  // namespace

TEST_CASE("shading with an edge policy other than exact: same integrals within the policy's bound", "[shading]") {
    // The clipped polygons are the same; only theta / sin(theta) changes, by at most 4.1e-8 + 41 u
    // relative for minimax_rational and 8 u for exact (tests/test_edge_policies.cpp), and each
    // integral is a sum of m <= clipped_capacity(n) terms of size <= pi / (2 pi):
    // |difference| <= bound * m / 2. For the clipless modes the policy enters through the vector
    // form factor F, whose components change by as much, times the sphere's slope in F.
    using fast = ltc::edge_policy::minimax_rational;
    const double factor_bound = 4.1e-8 + (41 + 8) * (std::numeric_limits<double>::epsilon() / 2);
    const double slope = clipless_slope();
    const auto k = lobe(0.4, -0.2, 0.7, 0.1);
    for (const clip_mode mode : all_modes) {
        const bool clipless = mode == clip_mode::sphere_analytic || mode == clip_mode::sphere_table;
        double worst = 0;
        for (const scene& sc : random_scenes(300, 31)) {
            const auto frame = ltc::make_shading_frame(sc.N, sc.V);
            const std::size_t n = sc.light.size();
            const double bound = factor_bound * static_cast<double>(ltc::clipped_capacity(n)) / 2 * (clipless ? slope : 1);
            const auto a = ltc::integrate_polygon_light(frame, k.m_inv, sc.P, sc.light.data(), n, mode);
            const auto b = ltc::integrate_polygon_light<fast>(frame, k.m_inv, sc.P, sc.light.data(), n, mode);
            const double err = std::max(std::abs(a.ltc - b.ltc), std::abs(a.form_factor - b.form_factor));
            worst = std::max(worst, err / bound);
            CHECK(err <= bound);
        }
        CAPTURE(static_cast<int>(mode), worst, slope);
        CHECK(worst > 0);  // the policies do differ: the comparison is not vacuous
    }
}

TEST_CASE("shading is invariant to the scale of M^-1, down to 1e-20 in float", "[shading]") {
    // The LTC does not depend on the scale of M^-1; the edge terms get unit vertices whatever
    // it is (|M^-1 p| ~ 1e-20 would put |a x b| of unnormalized vertices below FLT_MIN). Both
    // sides normalize directions that differ by the rounding of the scaled product: a few float
    // ulps per vertex, amplified by at most the number of edges: 1e-4 relative leaves a margin.
    const auto k = lobe(0.4, -0.2, 0.7, 0.1);
    const glm::mat3 mi(k.m_inv);
    for (const clip_mode mode : {clip_mode::ltc_space, clip_mode::shading_first}) {
        for (const scene& sc : random_scenes(100, 37)) {
            const auto frame = ltc::make_shading_frame(glm::vec3(sc.N), glm::vec3(sc.V));
            std::vector<glm::vec3> light;
            for (const dvec3& v : sc.light) light.push_back(glm::vec3(v));
            const glm::vec3 P(sc.P);
            const float a = ltc::integrate_polygon_light(frame, mi, P, light.data(), light.size(), mode).ltc;
            const float b = ltc::integrate_polygon_light(frame, mi * 1e-20f, P, light.data(), light.size(), mode).ltc;
            CAPTURE(static_cast<int>(mode), a, b);
            CHECK(std::abs(a - b) <= 1e-4f * std::max(std::abs(a), 1e-3f));
        }
    }
}

}  // namespace ltc_test_shading_accuracy
