// The default GGX table of one LTC plus the clamped cosine (ltc/shading/ggx_cosine_lobe_fetch.hpp)
// and its shading (ltc/shading/cosine_lobe_polygon_light.hpp): the table's entries, the shading's
// identities with the generic two-lobe shading (the cosine's integral is the form factor), bad
// input, the fit's independence of the thread count, and the table against the Monte Carlo GGX
// ground truth where the one-lobe table is weakest.
#include <catch2/catch.hpp>

#include <ltc/brdf/ggx.hpp>
#include <ltc/fitting/fit_two_lobes.hpp>
#include <ltc/reference/ground_truth.hpp>
#include <ltc/shading/cosine_lobe_polygon_light.hpp>
#include <ltc/shading/polygon_light.hpp>
#include <ltc/shading/two_lobe_polygon_light.hpp>

#include "support/bad_input.hpp"
#include "support/lobe_errors.hpp"
#include "support/shading_scenes.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace ltc_test_cosine_lobe {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::shading_checks;  // dvec3, pi, facing_rectangle, node_m_inv

namespace {

/// The errors of the one-lobe and of the LTC-and-cosine shading (support/lobe_errors.hpp).
lobe_errors errors_against_ground_truth(double theta_v, double r, const std::vector<dvec3>& L, std::uint64_t seed,
                                        double f0 = 1.0) {
    return errors_against_truth(
        theta_v, r, L, seed, [](auto&&... a) { return ltc::shade_polygon_light_cosine_lobe(a...); }, f0);
}

}  // namespace

TEST_CASE("cosine-lobe table: the cosine's identity matrix, finite entries, invertible LTCs", "[cosine_lobe]") {
    const int n = ltc::ggx_cosine_lobe::size;
    REQUIRE(n == ltc::fit::two_lobe_default_size);
    const ltc::ltc_table cosine = ltc::ggx_cosine_lobe::lobe_table(0), lobe = ltc::ggx_cosine_lobe::lobe_table(1);
    int all_ltc = 0;
    for (int a = 0; a < n; ++a)
        for (int u = 0; u < n; ++u) {
            CAPTURE(a, u);
            CHECK(node_m_inv(cosine, u, a) == glm::dmat3(1.0));
            // The LTC's M^-1 is stored premultiplied by its magnitude channel.
            ltc::ltc_coefficients<double> c;
            c.m_inv = node_m_inv(lobe, u, a);
            c.magnitude = lobe.node(u, a, ltc::channel::magnitude);
            const double det = glm::determinant(ltc::ggx_cosine_lobe::unpremultiplied(c).m_inv);
            CHECK(std::isfinite(det));
            CHECK(det != 0);
            for (const ltc::ltc_table* t : {&cosine, &lobe}) {
                CHECK(t->node(u, a, ltc::channel::magnitude) >= 0);
                CHECK(t->node(u, a, ltc::channel::fresnel) >= 0);
                CHECK(std::isfinite(t->node(u, a, ltc::channel::magnitude)));
                CHECK(std::isfinite(t->node(u, a, ltc::channel::fresnel)));
            }
            all_ltc += cosine.node(u, a, ltc::channel::magnitude) == 0 ? 1 : 0;
        }
    // The cosine takes a share somewhere, else the table would be the one-lobe fit.
    CHECK(all_ltc < n * n);
}

TEST_CASE("cosine-lobe shading: the form factor as the cosine's integral, the one-lobe diffuse term", "[cosine_lobe]") {
    const std::vector<dvec3> quad = facing_rectangle(200, 25, 0.6, 0.3);
    const dvec3 P(0), N(0, 0, 1), F0(0.04, 0.5, 1.0), albedo(0.5), radiance(2.0);
    for (const double theta : {0.0, 40.0, 70.0, 85.0})
        for (const double r : {0.1, 0.35, 0.8})
            for (const auto mode : {ltc::horizon_clipping::ltc_space, ltc::horizon_clipping::shading_first}) {
                CAPTURE(theta, r, int(mode));
                const dvec3 V = ltc::brdf::view_from_cos(std::cos(theta * pi / 180));
                const auto frame = ltc::make_shading_frame(N, V);
                auto lobes = ltc::ggx_cosine_lobe::fetch(frame.cos_theta_v, r);
                // The cosine lobe shaded as an LTC of M = I: its M^-1 p is p, so that in LTC space
                // the integral is the form factor's, bit for bit.
                lobes[0].m_inv = glm::dmat3(1.0);
                const auto fast = ltc::shade_polygon_light_cosine_lobe(frame, lobes, P, F0, albedo, radiance, quad.data(), 4,
                                                                       ltc::sidedness::one_sided, mode);
                const auto generic = ltc::shade_polygon_light_two_lobe(frame, {lobes[1], lobes[0]}, P, F0, albedo, radiance,
                                                                       quad.data(), 4, ltc::sidedness::one_sided, mode);
                if (mode == ltc::horizon_clipping::ltc_space) CHECK(fast.specular == generic.specular);
                // shading_first: the generic path clips the cosine's (already clipped) polygon again
                // in its own space, which can move a clipped vertex by a rounding. Each side's E is
                // within 20 u of the exact integral (at most 5 clipped edges, each term of size <= pi
                // within 8 u, over 2 pi), times the cosine's Fresnel-weighted magnitude and the
                // radiance; plus 2 u of the sum, which each side rounds once (measured: up to 2.4 u
                // of the sum). The exact integral of the re-clipped polygon differs from the first
                // clip's by a vertex on the horizon moved by a few u: first order in that move, a few
                // u of E (the edge terms' derivatives are bounded by pi at this size), inside these
                // bounds.
                const double eps = std::numeric_limits<double>::epsilon();
                const dvec3 brdf_cosine = F0 * lobes[0].magnitude + (dvec3(1) - F0) * lobes[0].fresnel;
                for (int c = 0; c < 3; ++c)
                    CHECK(std::abs(fast.specular[c] - generic.specular[c]) <=
                          2 * 20 * eps * brdf_cosine[c] * radiance[c] + 2 * eps * std::abs(generic.specular[c]));
                CHECK(fast.diffuse == generic.diffuse);
                // The cosine's lookup: the identity, and its two channels as the full lookup gives them.
                const auto fetched = ltc::ggx_cosine_lobe::fetch(frame.cos_theta_v, r);
                const ltc::ltc_table cosine_table = ltc::ggx_cosine_lobe::lobe_table(0);
                const auto full = cosine_table.fetch_at(cosine_table.locate(frame.cos_theta_v, r));
                CHECK(fetched[0].m_inv == glm::dmat3(1.0));
                CHECK(full.m_inv == glm::dmat3(1.0));  // the stored matrix, interpolated
                CHECK(fetched[0].magnitude == full.magnitude);
                CHECK(fetched[0].fresnel == full.fresnel);
                // The diffuse term is the one-lobe shading's.
                const auto one = ltc::shade_polygon_light_one_lobe(P, N, V, r, F0, albedo, radiance, quad.data(), 4,
                                                                   ltc::sidedness::one_sided, mode);
                CHECK(fast.diffuse == one.diffuse);
                CHECK(fast.specular.x >= 0);
            }
}

TEST_CASE("cosine-lobe shading: bad input gives finite results", "[cosine_lobe][bad_input]") {
    const std::vector<dvec3> quad = facing_rectangle(180, 30, 0.5, 0.25);
    const dvec3 N(0, 0, 1), V = ltc::brdf::view_from_cos(0.5);
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    for (const double r : {-1.0, 0.0, 2.0, nan, inf}) {
        const auto s = ltc::shade_polygon_light_cosine_lobe(dvec3(0), N, V, r, dvec3(1), dvec3(1), dvec3(1), quad.data(), 4,
                                                            ltc::sidedness::one_sided);
        CAPTURE(r);
        for (int c = 0; c < 3; ++c) CHECK((std::isfinite(s.specular[c]) && std::isfinite(s.diffuse[c])));
    }
    ltc_test::check_degenerate_lights_give_zero(quad.data(), N, [&](const dvec3& n, const dvec3* v, std::size_t count) {
        return ltc::shade_polygon_light_cosine_lobe(dvec3(0), n, V, 0.5, dvec3(1), dvec3(1), dvec3(1), v, count,
                                                    ltc::sidedness::one_sided);
    });
}

TEST_CASE("cosine-lobe table against the Monte Carlo GGX ground truth at grazing views", "[cosine_lobe][ground_truth]") {
    // The lights of tests/test_two_lobe.cpp's grazing test (theta_v 70 and 80 deg, roughness 0.3
    // and 0.5; 0.5 x 0.25 rectangles at distance 1 at the mirror direction, near the zenith and at
    // the side; off the report's grid), and its ground truth (2^16 MIS iterations, the same seeds,
    // relative standard errors below 0.5%, checked). Measured with the shipped tables and these
    // seeds, signed errors one lobe / LTC and cosine:
    //                   mirror          zenith           side
    //   70 deg, 0.3   -2.5 / +1.3    +123.1 / +38.9   -83.7 / -19.6
    //   70 deg, 0.5   +2.0 / +6.0     +62.9 / +15.0   -70.0 / -14.3
    //   80 deg, 0.3   -4.8 / +15.7   +224.8 / +9.7    -95.9 / -39.7
    //   80 deg, 0.5  +13.9 / +21.7    +66.3 / +23.6   -87.8 / -7.5
    // Mean |error| 69.8% / 17.7%, worst 224.8% / 39.7% (two lobes: 22.7%, 87.9%): the tails'
    // error falls to a quarter, the mirror lights get worse. (The table shipped before, fitted to
    // the rings' family with a 1% floor: 33.0%, worst 79.6%.) Bounds: the figures rounded up in
    // their second digit (new tables or seeds need new figures, from this test's output).
    check_grazing_summary(grazing_light_errors(errors_against_ground_truth, 1.0), "LTC and cosine", 0.18, 0.40);
}

TEST_CASE("cosine-lobe table: a dielectric's specular term (F0 = 0.04) at grazing views", "[cosine_lobe][ground_truth]") {
    // The grazing test's 12 lights above, with Schlick's factor at F0 = 0.04 in the ground truth
    // (ltc::brdf::with_schlick) and in the shading: at these views a large part of the specular
    // term (31-90% at theta_v 75-80 deg: the test of every node below prints it) is the Fresnel
    // part, the integral of f (1 - V.H)^5, which weighs the lobe's directions farthest from V
    // more than f does. The table splits it between its lobes by its own least-squares fit
    // (fit_two_lobes.hpp, fresnel_share_of). Measured with the shipped tables and these seeds:
    // mean |error| 355% with one lobe, 101% with the LTC and the cosine (worst 477%; 222% and
    // 736% with the table before the split, which took the magnitude's split). A dielectric's
    // specular term is far harder for these lobes than F0 = 1's (17.7% above): its shape is not
    // f's. Bounds: the figures rounded up in their second digit.
    check_grazing_summary(grazing_light_errors(errors_against_ground_truth, 0.04), "F0 = 0.04, LTC and cosine", 1.1, 4.8);
}

TEST_CASE("both opt-in tables: each node's lobes add up to its magnitude and Fresnel term", "[cosine_lobe][two_lobe]") {
    // Whatever the split of each (s for the magnitude, s_F for the Fresnel term: fit_two_lobes.hpp,
    // fresnel_share_of), the lobes' channels of a node add up to the node's moments
    // (ltc::fit::compute_moments at the node's view and roughness, as the fit takes them):
    // float(X (1 - s)) + float(X s) is float(X) up to three float roundings, at most 2^-23 X, plus,
    // in the LTC-and-cosine table, two subnormals flushed to 0 (2 FLT_MIN). And a dead LTC there
    // (its magnitude channel 0, its matrix stored as 0, read as the cosine) carries no Fresnel term.
    const ltc::fit::options opt;
    struct table {
        ltc::ltc_table lobe1, lobe2;
        bool premultiplied;
    };
    const table tables[] = {{ltc::ggx_cosine_lobe::lobe_table(0), ltc::ggx_cosine_lobe::lobe_table(1), true},
                            {ltc::ggx_two_lobe::lobe_table(0), ltc::ggx_two_lobe::lobe_table(1), false}};
    const int n = ltc::fit::two_lobe_default_size;
    int split_fresnel = 0;
    // Also printed (README, "The Fresnel term's split"): the nodes whose split s_F clamps to 0 or 1
    // among those that keep both lobes, the two-LTC nodes that give most of the Fresnel term
    // (s_F > 0.5) to a lobe of under 10% of the magnitude (s < 0.1), and the Fresnel part's share
    // of a dielectric's (F0 = 0.04) specular term, 0.96 F / (0.04 m + 0.96 F), at the views of
    // the rows between 75 and 80 deg and below 30 deg.
    double share_grazing_lo = 1, share_grazing_hi = 0, share_low_hi = 0;
    for (const table& tab : tables) {
        int both = 0, clamped = 0, minor_lobe = 0;
        for (int a = 0; a < n; ++a)
            for (int t = 0; t < n; ++t) {
                const double c = ltc::fit::node_cos_theta(t, n, opt.cos_theta_min);
                const double alpha = ltc::fit::node_alpha(a, n, opt.alpha_min);
                const auto mom = ltc::fit::compute_moments<ltc::brdf::ggx>(ltc::brdf::view_from_cos(c), alpha, opt.moment_samples);
                const double f1 = tab.lobe1.node(t, a, ltc::channel::fresnel), f2 = tab.lobe2.node(t, a, ltc::channel::fresnel);
                const double m1 = tab.lobe1.node(t, a, ltc::channel::magnitude), m2 = tab.lobe2.node(t, a, ltc::channel::magnitude);
                const double flush = tab.premultiplied ? 2.0 * std::numeric_limits<float>::min() : 0.0;
                CAPTURE(tab.premultiplied, t, a, m1, m2, mom.magnitude, f1, f2, mom.fresnel);
                CHECK(std::abs(m1 + m2 - double(float(mom.magnitude))) <= std::ldexp(mom.magnitude, -23) + flush);
                CHECK(std::abs(f1 + f2 - double(float(mom.fresnel))) <= std::ldexp(mom.fresnel, -23) + flush);
                if (tab.premultiplied && m2 == 0) CHECK(f2 == 0);
                split_fresnel += f1 > 0 && f2 > 0 && std::min(f1, f2) > 1e-3 * (f1 + f2);
                if (m2 > 0 && (tab.premultiplied || m1 > 0) && f1 + f2 > 0) {
                    ++both;
                    clamped += f1 == 0 || f2 == 0;
                    minor_lobe += m2 < 0.1 * (m1 + m2) && f2 > 0.5 * (f1 + f2);
                }
                const double theta = std::acos(c) * 180 / pi;
                const double share = 0.96 * mom.fresnel / (0.04 * mom.magnitude + 0.96 * mom.fresnel);
                if (theta >= 75 && theta <= 80)
                    share_grazing_lo = std::min(share_grazing_lo, share), share_grazing_hi = std::max(share_grazing_hi, share);
                if (theta < 30) share_low_hi = std::max(share_low_hi, share);
            }
        WARN((tab.premultiplied ? "LTC and cosine" : "two LTCs")
             << ": the Fresnel split clamps to 0 or 1 at " << clamped << " of the " << both
             << " nodes that keep both lobes; " << minor_lobe << " give most of it to a lobe of under 10% of the magnitude");
    }
    WARN("the Fresnel part's share of a dielectric's specular term: " << 100 * share_grazing_lo << "-" << 100 * share_grazing_hi
                                                                       << "% at theta_v 75-80 deg, at most " << 100 * share_low_hi
                                                                       << "% below 30 deg");
    WARN(split_fresnel << " of the " << 2 * n * n << " nodes split their Fresnel term between both lobes (more than 0.1% each)");
    CHECK(split_fresnel > 0);  // the sums above are not all trivial
}

TEST_CASE("cosine-lobe table between nodes where the split between the lobes jumps", "[cosine_lobe][ground_truth]") {
    // At rough, near-normal views the fit's split between the cosine and the LTC jumps between
    // neighbouring nodes (roughness 0.77-0.87: 98% cosine and a flattened LTC next to 9% cosine and
    // an LTC close to the cosine). With the LTC's M^-1 interpolated on its own, the lookup between
    // such nodes gave the flattened matrix half the magnitude: -37% at roughness 0.84, theta_v 1.3
    // deg on the zenith light below, -14.5% and +17.5% at 0.86 (one lobe: within 2%). The table
    // stores M^-1 premultiplied by the LTC's magnitude (two_lobe_table::packed). Lights: 0.6 x 0.6
    // squares at distance 1, elevation 90, 60 and 30 deg towards -x; ground truth as above (2^16
    // MIS iterations, relative standard errors below 0.5%, checked). Measured worst |error|:
    // 3.62% (one lobe 1.87%; 5.95% with the table fitted to the rings' family); bound: that
    // figure rounded up in its second digit.
    double worst = 0, worst1 = 0;
    std::uint64_t seed = 7500;
    for (const double r : {0.8, 0.84, 0.86})
        for (const double theta : {1.3, 8.0})
            for (const double elevation : {90.0, 60.0, 30.0}) {
                CAPTURE(elevation);
                const lobe_errors e = errors_against_ground_truth(theta, r, facing_rectangle(180, elevation, 0.3, 0.3), seed++);
                worst = std::max(worst, e.other), worst1 = std::max(worst1, e.one);
            }
    WARN("one lobe: worst " << 100 * worst1 << "%; LTC and cosine: worst " << 100 * worst << "%");
    CHECK(worst <= 0.037);
}

TEST_CASE("fit_two_lobe_table with the cosine: the same table on any number of threads", "[cosine_lobe][fit]") {
    ltc::fit::options opt;
    opt.size = 4;
    opt.threads = 1;
    const auto model = ltc::fit::two_lobe_model::ltc_and_cosine;
    const std::vector<float> one = ltc::fit::fit_two_lobe_table<ltc::brdf::ggx>(opt, model).packed();
    opt.threads = 3;
    const std::vector<float> three = ltc::fit::fit_two_lobe_table<ltc::brdf::ggx>(opt, model).packed();
    REQUIRE(one.size() == three.size());
    for (std::size_t i = 0; i < one.size(); ++i) {
        CAPTURE(i);
        CHECK(std::isfinite(one[i]));
        CHECK(one[i] == three[i]);
    }
}

}  // namespace ltc_test_cosine_lobe
