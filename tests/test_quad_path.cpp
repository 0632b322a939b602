// The scalar path's quad fast path (polygon.hpp, detail::quad_form_factor: clipping before
// normalization by a switch on the vertices above the horizon, five edge terms) against the
// general path (streaming clipper on unit vertices), which every other vertex count takes: a quad
// p0 p1 p2 p3 and the pentagon p0 p1 p2 p3 p3 have the same integral (the repeated vertex adds a
// zero-length edge, worth exactly 0), and the pentagon goes the general way.
//
// Tolerance: the two paths normalize the same M^-1 p identically; they differ in the horizon
// crossings (from the raw vertices here, from the unit vertices there: the same cancellation
// kappa_X amplifies the rounding of either) and in the order of summation (5 terms against m).
// Both are bounded by ltc_test::clip_tolerance with same_normalization. In float with the
// symmetric fits the quad path runs on four lanes (ltc/core/detail/quad_lanes.hpp), in every
// build, with crossings from the raw vertices normalized by 1 / sqrt of their squared lengths:
// bounded by clip_tolerance without same_normalization (tests/test_batch.cpp derives it). Where
// the quad path hands over to the general path (non-convex quads with two runs above the horizon,
// vertices at the origin, tiny or huge), the results are bitwise equal.
#include "support/clip_comparison.hpp"
#include "support/rng.hpp"

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/polygon.hpp>
#include <ltc/core/transformed.hpp>

#include <catch2/catch.hpp>

#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace ltc_test_quad_path {  // the file's own names, apart from the other files of a unity batch

namespace {

template <typename Policy>
float quad_value(const glm::mat3& mi, const std::vector<glm::vec3>& quad, ltc::sidedness s) {
    return ltc::transformed<ltc::clamped_cosine<float, Policy>>::from_inverse(mi).integrate(quad.data(), 4, s);
}

template <typename Policy>
float general_value(const glm::mat3& mi, const std::vector<glm::vec3>& quad, ltc::sidedness s) {
    const glm::vec3 pentagon[5] = {quad[0], quad[1], quad[2], quad[3], quad[3]};
    return ltc::transformed<ltc::clamped_cosine<float, Policy>>::from_inverse(mi).integrate(pentagon, 5, s);
}

unsigned above_mask(const glm::mat3& mi, const std::vector<glm::vec3>& quad) {
    unsigned m = 0;
    for (unsigned k = 0; k < 4; ++k) m |= ((mi * quad[k]).z >= 0.0f ? 1u : 0u) << k;
    return m;
}

}  // namespace

TEMPLATE_TEST_CASE("quad fast path matches the general path, for every set of vertices above the horizon",
                   "[polygon][quad]", ltc::edge_policy::exact, ltc::edge_policy::minimax_rational,
                   ltc::edge_policy::polynomial, ltc::edge_policy::rational) {
    using Policy = TestType;
    ltc_test::rng g(2024);
    std::array<int, 16> seen{};
    int violations = 0, handed_over_unequal = 0;
    double worst_ratio = 0;
    for (int i = 0; i < 6000; ++i) {
        glm::mat3 mi = ltc_test::random_matrix(g, i % 2 == 1);
        auto quad = ltc_test::random_polygon(g, 4, i % 3 != 0, i % 5 == 0);
        if (i % 10 == 9) {
            // An arrowhead whose reflex vertex is above the horizon with its tip: two runs above
            // (mask 5 or 10), turned about z, scaled and started at any vertex.
            const double phi = g.uniform(0, 2 * ltc_test::kPi), scale = g.uniform(0.1, 10);
            const glm::dmat3 turn(std::cos(phi), std::sin(phi), 0, -std::sin(phi), std::cos(phi), 0, 0, 0, 1);
            const glm::dvec3 dart[4] = {{1, 0, 1.5}, {1, 1, -1.5}, {1, 0, 0.5}, {1, -1, -1.5}};
            for (std::size_t k = 0; k < 4; ++k) quad[k] = glm::vec3(scale * (turn * dart[(k + static_cast<std::size_t>(i / 10)) % 4]));
            mi = glm::mat3(1.0f);
        }
        const unsigned mask = above_mask(mi, quad);
        ++seen[mask];
        for (const auto s : {ltc::sidedness::two_sided, ltc::sidedness::one_sided}) {
            const float a = quad_value<Policy>(mi, quad, s), b = general_value<Policy>(mi, quad, s);
            if (mask == 5u || mask == 10u) {
                handed_over_unequal += a != b;
                continue;
            }
            // The lanes path (float, symmetric fits) normalizes otherwise than the general path.
            const bool same_normalization = !ltc::detail::quad_on_lanes<float, Policy>;
            const double err = std::abs(static_cast<double>(a) - b);
            const double tol = ltc_test::clip_tolerance<Policy>(mi, quad, same_normalization);
            violations += !(err <= tol);
            if (err > 0) worst_ratio = std::max(worst_ratio, err / tol);
        }
    }
    CAPTURE(worst_ratio);
    CHECK(violations == 0);
    CHECK(handed_over_unequal == 0);
    for (unsigned m = 0; m < 16; ++m) {
        CAPTURE(m);
        CHECK(seen[m] > 0);  // every case of the switch, and both hand-overs, were exercised
    }
}

TEST_CASE("quad fast path hands degenerate quads to the general path", "[polygon][quad]") {
    using Policy = ltc::edge_policy::minimax_rational;
    ltc_test::rng g(7);
    for (int i = 0; i < 200; ++i) {
        const glm::mat3 mi = ltc_test::random_matrix(g, i % 2 == 1);
        const auto quad = ltc_test::random_polygon(g, 4, true, i % 2 == 0);
        auto at_origin = quad, tiny = quad, huge = quad, nan = quad;
        at_origin[static_cast<std::size_t>(i % 4)] = glm::vec3(0.0f);
        for (auto& p : tiny) p *= 1e-20f;
        for (auto& p : huge) p *= 1e20f;
        nan[static_cast<std::size_t>(i % 4)].x = std::nanf("");
        const auto s = ltc::sidedness::two_sided;
        CHECK(quad_value<Policy>(mi, at_origin, s) == 0.0f);
        // Scaled quads: bitwise the general path's result (which rescales by powers of two).
        CHECK(quad_value<Policy>(mi, tiny, s) == general_value<Policy>(mi, tiny, s));
        CHECK(quad_value<Policy>(mi, huge, s) == general_value<Policy>(mi, huge, s));
        // And the same value as the unscaled quad, up to the paths' difference.
        CHECK(std::abs(quad_value<Policy>(mi, huge, s) - quad_value<Policy>(mi, quad, s)) <=
              ltc_test::clip_tolerance<Policy>(mi, quad));  // p * 1e20 rounds: other unit vertices
        // NaN input: the general path's answer, whatever it is, bitwise (both NaN or both equal).
        const float qn = quad_value<Policy>(mi, nan, s), gn = general_value<Policy>(mi, nan, s);
        CHECK(((std::isnan(qn) && std::isnan(gn)) || qn == gn));
    }
}

TEST_CASE("quad fast path: M^-1 p overflowing to NaN does not pass for a quad below the horizon", "[polygon][quad]") {
    // M^-1 p0 = (3e38, 0, 2e38) is above the horizon, but its z, 2 * 3e38 - 2 * 2e38, overflows
    // to inf - inf = NaN in float: NaN counts as below, and the other vertices are below. The
    // general path rescales p0 by a power of two first and sees it above.
    const glm::mat3 mi = glm::transpose(glm::mat3(1, 0, 0, 0, 0, 1, 2, -2, 0));
    const std::vector<glm::vec3> quad = {{3e38f, 2e38f, 0}, {0, 1, 0}, {1, 2, 1}, {0, 1, 1}};
    const auto s = ltc::sidedness::two_sided;
    const float general = general_value<ltc::edge_policy::minimax_rational>(mi, quad, s);
    CHECK(general > 0.0f);
    CHECK(quad_value<ltc::edge_policy::minimax_rational>(mi, quad, s) == general);
    CHECK(quad_value<ltc::edge_policy::exact>(mi, quad, s) == general_value<ltc::edge_policy::exact>(mi, quad, s));
}

}  // namespace ltc_test_quad_path
