// The opt-in two-lobe GGX table (ltc/shading/ggx_two_lobe_fetch.hpp) and its shading
// (ltc/shading/two_lobe_polygon_light.hpp): the table's entries, its shares adding up to the
// magnitude, the shading's identities with the one-lobe shading, float against double, bad input,
// and the two lobes against the Monte Carlo GGX ground truth where one lobe is weakest.
#include <catch2/catch.hpp>

#include <ltc/brdf/ggx.hpp>
#include <ltc/fitting/fit_two_lobes.hpp>
#include <ltc/reference/ground_truth.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/shading/polygon_light.hpp>
#include <ltc/shading/two_lobe_polygon_light.hpp>

#include "support/bad_input.hpp"
#include "support/lobe_errors.hpp"
#include "support/shading_scenes.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <thread>
#include <vector>

namespace ltc_test_two_lobe {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::shading_checks;  // dvec3, pi, facing_rectangle, node_m_inv

TEST_CASE("two-lobe table: finite entries, invertible lobes, shares adding up to the magnitude", "[two_lobe]") {
    const int n = ltc::ggx_two_lobe::size;
    REQUIRE(n == ltc::fit::two_lobe_default_size);
    for (int l = 0; l < 2; ++l) {
        const ltc::ltc_table t = ltc::ggx_two_lobe::lobe_table(l);
        for (int a = 0; a < n; ++a)
            for (int u = 0; u < n; ++u) {
                CAPTURE(l, a, u);
                const double det = glm::determinant(node_m_inv(t, u, a));
                CHECK(std::isfinite(det));
                CHECK(det != 0);
                CHECK(t.node(u, a, ltc::channel::magnitude) >= 0);
                CHECK(t.node(u, a, ltc::channel::fresnel) >= 0);
            }
    }
    // A dropped lobe (share 0: fit_two_lobes) is a copy of the other, not a spike that the
    // table's interpolation would carry into the neighbouring cells.
    const ltc::ltc_table t0 = ltc::ggx_two_lobe::lobe_table(0), t1 = ltc::ggx_two_lobe::lobe_table(1);
    int dropped = 0;
    for (int a = 0; a < n; ++a)
        for (int u = 0; u < n; ++u)
            for (int l = 0; l < 2; ++l) {
                const ltc::ltc_table& dead = l == 0 ? t0 : t1;
                const ltc::ltc_table& other = l == 0 ? t1 : t0;
                if (dead.node(u, a, ltc::channel::magnitude) != 0) continue;
                ++dropped;
                CAPTURE(a, u, l);
                for (const int ch : {ltc::channel::m_inv_00, ltc::channel::m_inv_02, ltc::channel::m_inv_20, ltc::channel::m_inv_22})
                    CHECK(dead.node(u, a, ch) == other.node(u, a, ch));
            }
    CHECK(dropped > 0);  // the low roughnesses, where one lobe follows GGX
    // At the corners of the parameter square the 32 x 32 and the 64 x 64 grids share their nodes
    // and both fits take the magnitude and Fresnel term from the same moments: the lobes'
    // float(m (1 - s)) + float(m s) is float(m) up to three float roundings, at most
    // 2^-24 (m (1 - s) + m s) + 2^-24 m = 2^-23 m.
    for (const double c : {0.0, 1.0})
        for (const double r : {0.0, 1.0}) {
            const auto two = ltc::ggx_two_lobe::fetch(c, r);
            const auto one = ltc::ggx::fetch(c, r);
            CAPTURE(c, r, two[0].magnitude, two[1].magnitude, one.magnitude);
            CHECK(std::abs(two[0].magnitude + two[1].magnitude - one.magnitude) <= std::ldexp(one.magnitude, -23));
            CHECK(std::abs(two[0].fresnel + two[1].fresnel - one.fresnel) <= std::ldexp(one.fresnel, -23));
        }
}

TEST_CASE("two-lobe shading: the one-lobe diffuse term, lobes that add, float against double", "[two_lobe]") {
    const std::vector<dvec3> quad = facing_rectangle(200, 25, 0.6, 0.3);
    const dvec3 P(0), N(0, 0, 1), F0(0.04, 0.5, 1.0), albedo(0.5), radiance(2.0);
    const ltc::horizon_clipping modes[] = {ltc::horizon_clipping::ltc_space, ltc::horizon_clipping::shading_first,
                                           ltc::horizon_clipping::sphere_analytic};
    for (const double theta : {0.0, 40.0, 70.0, 85.0})
        for (const double r : {0.1, 0.35, 0.8})
            for (const auto mode : modes) {
                CAPTURE(theta, r, int(mode));
                const dvec3 V = ltc::brdf::view_from_cos(std::cos(theta * pi / 180));
                const auto two = ltc::shade_polygon_light_two_lobe(P, N, V, r, F0, albedo, radiance, quad.data(), 4,
                                                                   ltc::sidedness::one_sided, mode);
                const auto one = ltc::shade_polygon_light_one_lobe(P, N, V, r, F0, albedo, radiance, quad.data(), 4,
                                                                   ltc::sidedness::one_sided, mode);
                // The diffuse term is the one-lobe shading's, bit for bit.
                CHECK(two.diffuse == one.diffuse);
                // The specular term is the sum of each lobe shaded alone (the other's share 0).
                const auto frame = ltc::make_shading_frame(N, V);
                auto lobes = ltc::ggx_two_lobe::fetch(frame.cos_theta_v, r);
                dvec3 sum(0);
                for (int l = 0; l < 2; ++l)
                    sum += ltc::shade_polygon_light(frame, lobes[std::size_t(l)], P, F0, albedo, radiance, quad.data(), 4,
                                                    ltc::sidedness::one_sided, mode)
                               .specular;
                CHECK(two.specular == sum);
                CHECK(two.specular.x >= 0);
                // float against double: the one-lobe shading's relative bound (test_shading_ggx.cpp) per
                // lobe, and an absolute one for values that the edge sum's cancellation leaves small: a
                // lobe's float integral is off by at most 20 u (at most 5 clipped edges, each term of
                // size <= pi within 8 u, over 2 pi), times the Fresnel-weighted magnitude (<= 1) and
                // the radiance; for E likewise, times the albedo.
                glm::vec3 qf[4];
                for (int i = 0; i < 4; ++i) qf[i] = glm::vec3(quad[std::size_t(i)]);
                const auto f = ltc::shade_polygon_light_two_lobe(glm::vec3(P), glm::vec3(N), glm::vec3(V), float(r),
                                                                 glm::vec3(F0), glm::vec3(albedo), glm::vec3(radiance), qf, 4,
                                                                 ltc::sidedness::one_sided, mode);
                const double u = 0x1p-24;
                CAPTURE(double(f.specular.y) - two.specular.y);
                CHECK(f.specular.y == Approx(two.specular.y).epsilon(4e-5).margin(2 * 20 * u * radiance.y));
                CHECK(f.diffuse.x == Approx(two.diffuse.x).epsilon(2e-6).margin(20 * u * albedo.x * radiance.x));
            }
}

TEST_CASE("two-lobe shading: bad input gives finite results", "[two_lobe][bad_input]") {
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    const std::vector<dvec3> quad = facing_rectangle(180, 40, 0.5, 0.5);
    const dvec3 N(0, 0, 1), V = glm::normalize(dvec3(0.5, 0, 0.5));
    const auto finite = [](const ltc::polygon_light_result<double>& r) {
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(r.specular[k]) || !std::isfinite(r.diffuse[k])) return false;
        return true;
    };
    for (const double r : {nan, inf, -inf, -1.0, 2.0, 0.0})
        CHECK(finite(ltc::shade_polygon_light_two_lobe(dvec3(0), N, V, r, dvec3(1), dvec3(1), dvec3(1), quad.data(), 4,
                                                       ltc::sidedness::one_sided)));
    for (const dvec3 v : {dvec3(nan, 0, 1), dvec3(0), dvec3(1, 0, -1), dvec3(inf, 0, 0)})
        CHECK(finite(ltc::shade_polygon_light_two_lobe(dvec3(0), N, v, 0.5, dvec3(1), dvec3(1), dvec3(1), quad.data(), 4,
                                                       ltc::sidedness::one_sided)));
    // n < 3, N = 0 and a vertex at the shading point: 0, as for one lobe.
    ltc_test::check_degenerate_lights_give_zero(quad.data(), N, [&](const dvec3& n, const dvec3* v, std::size_t count) {
        return ltc::shade_polygon_light_two_lobe(dvec3(0), n, V, 0.5, dvec3(1), dvec3(1), dvec3(1), v, count,
                                                 ltc::sidedness::one_sided);
    });
}

namespace {

/// The errors of the one-lobe and of the two-lobe shading (support/lobe_errors.hpp).
lobe_errors errors_against_two_lobes(double theta, double r, const std::vector<dvec3>& L, std::uint64_t seed,
                                     double f0 = 1.0) {
    return errors_against_truth(
        theta, r, L, seed, [](auto&&... a) { return ltc::shade_polygon_light_two_lobe(a...); }, f0);
}

}  // namespace

TEST_CASE("two lobes against the Monte Carlo GGX ground truth at grazing views", "[two_lobe][ground_truth]") {
    // Where one lobe is weakest (tools/ggx_error_report: theta_v = 80 deg, roughness 0.25-0.5,
    // lights off the lobe's peak): theta_v in {70, 80} deg, roughness in {0.3, 0.5}, and three
    // 0.5 x 0.25 rectangles facing the origin at distance 1: "mirror" (azimuth 180 deg, elevation
    // 90 - theta_v), "zenith" (elevation 80 deg, azimuth 0) and "side" (azimuth 90, elevation 30).
    // Ground truth: ltc::ground_truth::integrate, MIS, 2^16 iterations, fixed seeds (relative
    // standard errors below 0.5%, checked). These are off the report's grid (other roughnesses,
    // view angles and lights). Measured with the shipped tables and these seeds, signed errors
    // one lobe / two lobes:
    //                   mirror          zenith           side
    //   70 deg, 0.3   -2.5 / +0.3    +123.1 / +33.2   -83.7 / -62.8
    //   70 deg, 0.5   +2.0 / -3.5     +62.9 /  -7.0   -70.0 / -20.9
    //   80 deg, 0.3   -4.8 / +8.8    +224.8 /  +8.3   -95.9 / -87.9
    //   80 deg, 0.5  +13.9 / +3.5     +66.3 /  -9.8   -87.8 / -25.8
    // Mean |error| 69.8% / 22.7%, worst 224.8% / 87.9%: the second lobe cuts the tails' error by
    // 3x on average, but a small light at the side of a sharp grazing lobe stays far off, and a
    // mirror light can get worse (80 deg, 0.3). Bounds: the two-lobe figures rounded up in
    // their second digit (new tables or seeds need new figures, from this test's output).
    check_grazing_summary(grazing_light_errors(errors_against_two_lobes, 1.0), "two lobes", 0.23, 0.88);
}

TEST_CASE("two lobes: a dielectric's specular term (F0 = 0.04) at grazing views", "[two_lobe][ground_truth]") {
    // The lights above with Schlick's factor at F0 = 0.04 (tests/test_cosine_lobe.cpp has the
    // same test for the LTC-and-cosine table): a large part of the specular term is then the
    // Fresnel part, which the table splits between its lobes by its own least-squares fit
    // (fit_two_lobes.hpp, fresnel_share_of). Measured with the shipped tables and these seeds:
    // mean |error| 355% with one lobe, 121% with two (worst 640%; 160% and 723% with the table
    // before the split). Bounds: the figures rounded up in their second digit.
    check_grazing_summary(grazing_light_errors(errors_against_two_lobes, 0.04), "F0 = 0.04, two lobes", 1.3, 6.5);
}

namespace {

struct mirror_errors {
    double mean1 = 0, mean2 = 0, worst2 = 0;  // |LTC - GT| / GT: one lobe, two lobes
};

/// Small and medium rectangles (0.05 x 0.025 and 0.2 x 0.1 at distance 1) centred on the mirror
/// direction, at each view angle and roughness (errors_against_two_lobes, seeds from seed0).
mirror_errors mirror_light_errors(std::initializer_list<double> thetas, std::initializer_list<double> roughnesses,
                                  std::uint64_t seed0) {
    mirror_errors m;
    int count = 0;
    for (const double theta : thetas)
        for (const double r : roughnesses)
            for (const double size : {0.05, 0.2}) {
                const lobe_errors e =
                    errors_against_two_lobes(theta, r, facing_rectangle(180, 90 - theta, size, size / 2), seed0 + std::uint64_t(count));
                m.mean1 += e.one, m.mean2 += e.other;
                m.worst2 = std::max(m.worst2, e.other);
                ++count;
            }
    m.mean1 /= count, m.mean2 /= count;
    WARN("one lobe: mean " << 100 * m.mean1 << "%; two lobes: mean " << 100 * m.mean2 << "%, worst " << 100 * m.worst2 << "%");
    return m;
}

}  // namespace

// Where one lobe already follows GGX (lights on the mirror direction at low roughness), the
// second lobe must not cost more than a fraction of a percent. These sit off the report's grid and
// between the table's nodes, where the table fitted before fit_two_lobes' guards (dropped lobes,
// refits of stalled nodes: the table of commit a52164d) failed. Bounds: the figures measured with
// the shipped tables and these seeds, rounded up in their second digit, as above.
TEST_CASE("two lobes near mirror roughness: mirror lights within a fraction of a percent", "[two_lobe][ground_truth]") {
    // Roughness 0-0.03 (the table's first row at the clamp alpha = 1e-4, and the cell above it),
    // theta_v 0-75 deg. The earlier table: 30.4% mean, 100% worst (small lights at theta_v >= 60
    // deg missed entirely); one lobe 0.032%, 0.10%. Measured: two lobes 0.0481% mean, 0.145% worst.
    const mirror_errors m = mirror_light_errors({0.0, 30.0, 60.0, 75.0}, {0.0, 0.01, 0.02, 0.03}, 9000);
    CHECK(m.mean2 <= 0.00049);
    CHECK(m.worst2 <= 0.0015);
}

TEST_CASE("two lobes at low roughness near grazing: mirror lights within 2%", "[two_lobe][ground_truth]") {
    // Roughness 0.15 and 0.18, theta_v 60-75 deg. The earlier table: lobe 2 had drifted into a
    // spike of share 1e-6, Nelder-Mead stopped on its first simplex along the rows at roughness
    // 0.16, and the interpolated lobes missed these lights by 14.6% mean, 41.1% worst (one lobe:
    // 0.28%, 1.01%). Measured: two lobes 0.606% mean, 1.974% worst.
    const mirror_errors m = mirror_light_errors({60.0, 65.0, 70.0, 75.0}, {0.15, 0.18}, 8000);
    CHECK(m.mean2 <= 0.0061);
    CHECK(m.worst2 <= 0.020);
}

TEST_CASE("fit_two_lobe_table: the same table on any number of threads", "[two_lobe][fit]") {
    // The chain of normal-incidence nodes runs on one thread while the others take rows as their
    // first node is fitted: the table must not depend on that schedule.
    ltc::fit::options opt;
    opt.size = 4;
    opt.threads = 1;
    const std::vector<float> one = ltc::fit::fit_two_lobe_table<ltc::brdf::ggx>(opt).packed();
    opt.threads = 3;
    const std::vector<float> three = ltc::fit::fit_two_lobe_table<ltc::brdf::ggx>(opt).packed();
    REQUIRE(one.size() == three.size());
    for (std::size_t i = 0; i < one.size(); ++i) {
        CAPTURE(i);
        CHECK(std::isfinite(one[i]));
        CHECK(one[i] == three[i]);
    }
    opt.size = 1;
    CHECK_THROWS_AS(ltc::fit::fit_two_lobe_table<ltc::brdf::ggx>(opt), std::invalid_argument);
}

TEST_CASE("fit_two_lobe_table: the progress callback, on the calling thread, leaves the table as it is",
          "[two_lobe][fit]") {
    // As fit_table's: called on the calling thread, done never decreasing, the last call with
    // done == total, and the same table as without a callback; an exception it throws comes out
    // of fit_two_lobe_table once the workers have stopped. Both models.
    for (const auto model : {ltc::fit::two_lobe_model::two_ltcs, ltc::fit::two_lobe_model::ltc_and_cosine}) {
        CAPTURE(int(model));
        ltc::fit::options opt;
        opt.size = 4;
        opt.threads = 2;
        opt.progress_interval = 0.001;
        const std::thread::id caller = std::this_thread::get_id();
        // Recorded in the callback and checked here: Catch's assertions are not for other threads.
        std::size_t last_done = 0, calls = 0;
        bool on_caller = true, ordered = true, totals = true;
        const auto progress = [&](std::size_t done, std::size_t total) {
            on_caller = on_caller && std::this_thread::get_id() == caller;
            ordered = ordered && done >= last_done && done <= total;
            totals = totals && total == 16;
            last_done = done;
            ++calls;
        };
        const std::vector<float> with = ltc::fit::fit_two_lobe_table<ltc::brdf::ggx>(opt, model, progress).packed();
        CHECK(on_caller);
        CHECK(ordered);
        CHECK(totals);
        CHECK(last_done == 16);
        CHECK(calls >= 1);
        const std::vector<float> without = ltc::fit::fit_two_lobe_table<ltc::brdf::ggx>(opt, model).packed();
        REQUIRE(with.size() == without.size());
        CHECK(std::memcmp(with.data(), without.data(), with.size() * sizeof(float)) == 0);
        const auto throws = [](std::size_t, std::size_t) { throw std::runtime_error("stop"); };
        CHECK_THROWS_AS(ltc::fit::fit_two_lobe_table<ltc::brdf::ggx>(opt, model, throws), std::runtime_error);
    }
}

}  // namespace ltc_test_two_lobe
