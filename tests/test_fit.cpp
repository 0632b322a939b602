// Tests of ltc/fitting/fit.hpp: the shipped GGX table's consistency with a re-fit, the
// determinism of the fit across thread counts, the moments, and Nelder-Mead. The lookup of the
// table is tested in test_ggx_fetch.cpp, the fitted distributions in test_fitted_table.cpp.
// No 64 x 64 fit happens here: the re-fits are a few rows, the thread test an 8 x 8 table.
#include <catch2/catch.hpp>

#include <ltc/brdf/ggx.hpp>
#include <ltc/fitting/fit.hpp>
#include <ltc/tables/ltc_table.hpp>

#include "support/ggx_table.hpp"

#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace ltc_test_fit {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::table_checks;  // n, shipped, table_options

TEST_CASE("the shipped table is what the fit computes (re-fit of three rows)", "[fit][table]") {
    const ltc::fit::options opt = table_options();
    // The table is deterministic: re-running the fit's sequence for a row (the normal-incidence
    // chain from roughness 1 down, then the row from normal incidence to grazing) gives its
    // nodes again. Same compiler semantics give the same floats; across platforms (another
    // libm, FMA contraction) Nelder-Mead may stop elsewhere within its tolerance, so the
    // requirement is derived from the fit instead: each stored matrix is a minimizer of the
    // node's L3 objective to the fit's tolerance (estimator of the re-fit, same samples).
    const std::vector<ltc::fit::node_result> normal = ltc::fit::fit_normal_incidence<ltc::brdf::ggx>(opt);
    int exact = 0, total = 0;
    for (const int a : {n - 1, 40, 12}) {
        const std::vector<ltc::fit::node_result> row = ltc::fit::fit_row<ltc::brdf::ggx>(a, normal[std::size_t(a)], opt);
        const double alpha = ltc::fit::node_alpha(a, n, opt.alpha_min);
        for (int t = 0; t < n; ++t) {
            CAPTURE(a, t);
            const ltc::fit::node_result& r = row[std::size_t(t)];
            const float refit[6] = {float(r.m_inv[0][0]), float(r.m_inv[0][2]), float(r.m_inv[2][0]),
                                    float(r.m_inv[2][2]), float(r.magnitude), float(r.fresnel)};
            bool all = true;
            for (int k = 0; k < 6; ++k) all = all && refit[k] == shipped.node(t, a, k);
            exact += all ? 1 : 0;
            ++total;
            // Magnitude and Fresnel term: deterministic quadratures, no minimization.
            CHECK(shipped.node(t, a, ltc::channel::magnitude) == Approx(r.magnitude).epsilon(1e-6));
            CHECK(shipped.node(t, a, ltc::channel::fresnel) == Approx(r.fresnel).epsilon(1e-6).margin(1e-12));
            // The stored matrix is as good a fit as the re-fit's.
            const double cos_theta = ltc::fit::node_cos_theta(t, n, opt.cos_theta_min);
            const glm::dvec3 V = ltc::brdf::view_from_cos(cos_theta);
            ltc::fit::sample_set s;
            ltc::fit::make_sample_set<ltc::brdf::ggx>(V, alpha, ltc::fit::invert_structured(r.m_inv).inverse,
                                                      opt.error_samples, s);
            glm::dmat3 stored(0.0);
            stored[0][0] = shipped.node(t, a, 0);
            stored[0][2] = shipped.node(t, a, 1);
            stored[2][0] = shipped.node(t, a, 2);
            stored[2][2] = shipped.node(t, a, 3);
            stored[1][1] = 1;
            const double e_refit = s.l3(r.m_inv, r.magnitude);
            const double e_stored = s.l3(stored, r.magnitude);
            CHECK(e_stored <= e_refit * (1 + 1e-3));
        }
    }
    // On the platform that generated the table every node is identical; elsewhere, say so.
    if (exact != total) WARN("re-fit: " << exact << " of " << total << " nodes identical to the last bit");
}

TEST_CASE("fit_table is bitwise identical whatever the thread count", "[fit]") {
    ltc::fit::options opt;
    opt.size = 8;
    opt.threads = 1;
    std::size_t last_done = 0, calls = 0;
    const ltc::fit::table one = ltc::fit::fit_table<ltc::brdf::ggx>(opt, [&](std::size_t done, std::size_t total) {
        CHECK(total == 64);
        CHECK(done >= last_done);
        last_done = done;
        ++calls;
    });
    CHECK(last_done == 64);
    CHECK(calls >= 1);
    opt.threads = 2;
    const ltc::fit::table two = ltc::fit::fit_table<ltc::brdf::ggx>(opt);
    opt.threads = 3;
    const ltc::fit::table three = ltc::fit::fit_table<ltc::brdf::ggx>(opt);
    const std::vector<float> a = one.packed(), b = two.packed(), c = three.packed();
    REQUIRE(a.size() == 8 * 8 * 6);
    REQUIRE(b.size() == a.size());
    REQUIRE(c.size() == a.size());
    CHECK(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
    CHECK(std::memcmp(a.data(), c.data(), a.size() * sizeof(float)) == 0);
    for (std::size_t i = 0; i < a.size(); ++i) REQUIRE(std::isfinite(a[i]));
}

TEST_CASE("moments - magnitude and Fresnel term and average direction", "[fit]") {
    // Schlick: integral of f (F0 + (1 - F0)(1 - V.H)^5) = F0 magnitude + (1 - F0) fresnel, so
    // F0 = 1 is the magnitude and the Fresnel term is at most the magnitude; it grows towards
    // grazing angles, and at normal incidence with a sharp lobe (V.H ~ 1) it vanishes.
    const double alpha = 0.25;
    double previous = 0;
    for (const double c : {1.0, 0.8, 0.5, 0.2, 0.05}) {
        CAPTURE(c);
        const glm::dvec3 V = ltc::brdf::view_from_cos(c);
        const ltc::fit::moments m = ltc::fit::compute_moments<ltc::brdf::ggx>(V, alpha, 64);
        CHECK(m.magnitude > 0);
        CHECK(m.magnitude <= 1);
        CHECK(m.fresnel >= 0);
        CHECK(m.fresnel < m.magnitude);
        CHECK(m.fresnel > previous);
        previous = m.fresnel;
        CHECK(m.average_direction.y == 0);
        CHECK(glm::length(m.average_direction) == Approx(1));
        if (c == 1.0)  // normal incidence: x = 0 by symmetry, up to the rounding of a 64 x 64 sum
            CHECK(std::abs(m.average_direction.x) <= 64 * 64 * std::numeric_limits<double>::epsilon());
        else
            CHECK(m.average_direction.x < 0);  // the lobe is around the mirror direction (-x side)
    }
    const ltc::fit::moments sharp = ltc::fit::compute_moments<ltc::brdf::ggx>(glm::dvec3(0, 0, 1), 1e-3, 64);
    CHECK(sharp.fresnel < 1e-10);
    CHECK(sharp.magnitude == Approx(1).epsilon(1e-4));
}

TEST_CASE("nelder_mead minimizes a quadratic and the Rosenbrock function", "[fit]") {
    const auto quadratic = [](const std::array<double, 2>& x) {
        return (x[0] - 1) * (x[0] - 1) + 10 * (x[1] + 2) * (x[1] + 2) + 3;
    };
    const auto q = ltc::fit::nelder_mead<2>(quadratic, {0.0, 0.0}, {0.5, 0.5}, 1e-14, 2000);
    CHECK(q.x[0] == Approx(1).margin(1e-5));
    CHECK(q.x[1] == Approx(-2).margin(1e-5));
    CHECK(q.value == Approx(3));
    const auto rosenbrock = [](const std::array<double, 2>& x) {
        return 100 * (x[1] - x[0] * x[0]) * (x[1] - x[0] * x[0]) + (1 - x[0]) * (1 - x[0]);
    };
    const auto r = ltc::fit::nelder_mead<2>(rosenbrock, {-1.2, 1.0}, {0.1, 0.1}, 1e-16, 5000);
    CHECK(r.x[0] == Approx(1).margin(1e-4));
    CHECK(r.x[1] == Approx(1).margin(1e-4));
    CHECK(r.evaluations <= 5000);
    // The evaluation budget is respected.
    const auto capped = ltc::fit::nelder_mead<2>(rosenbrock, {-1.2, 1.0}, {0.1, 0.1}, 0.0, 50);
    CHECK(capped.evaluations <= 50 + 3);
}

}  // namespace ltc_test_fit
