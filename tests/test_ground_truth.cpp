// Tests of ltc/reference/ground_truth.hpp: the Monte Carlo estimator against closed forms (a
// Lambertian "BRDF" against ltc::form_factor, the LTC distribution itself against
// transformed::integrate), for each technique and heuristic; GGX, and degenerate input. The
// samplers are tested in test_ground_truth_sampling.cpp.
//
// Every random test uses a fixed seed, so it is deterministic; the tolerances are 4 to 5
// standard errors, which a correct estimator fails with probability < 1e-4 per check for the
// seed chosen (and, being deterministic, either always or never).
#include <catch2/catch.hpp>

#include <ltc/brdf/ggx.hpp>
#include <ltc/reference/ground_truth.hpp>
#include <ltc/ltc.hpp>

#include "support/ground_truth_models.hpp"

#include <cmath>
#include <vector>

namespace ltc_test_ground_truth {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::ground_truth_checks;  // the "BRDFs" and the test polygons

TEST_CASE("ground truth of a Lambertian BRDF matches the exact form factor within 4 sigma", "[ground_truth]") {
    const dvec3 V = glm::normalize(dvec3(0.5, 0, 0.8));
    for (const auto& poly : polygons()) {
        CAPTURE(poly.name);
        const std::size_t n = poly.v.size();
        const double exact = ltc::form_factor(poly.v.data(), n, ltc::sidedness::two_sided);
        for (const auto use : {gt::techniques::mis, gt::techniques::brdf_only, gt::techniques::polygon_only})
            for (const auto h : {gt::heuristic::balance, gt::heuristic::power}) {
                if (use != gt::techniques::mis && h == gt::heuristic::power) continue;
                // BRDF sampling alone rarely hits a 1e-4 sr triangle: nothing to test there.
                if (use == gt::techniques::brdf_only && ltc::solid_angle(poly.v.data(), n) < 0.01) continue;
                gt::options opt;
                opt.samples = 100000;
                opt.use = use;
                opt.weighting = h;
                opt.seed = 1234;
                const gt::estimate e = gt::integrate(lambert{}, V, 0.0, poly.v.data(), n, opt);
                CAPTURE(int(use), int(h), e.mean, e.standard_error, exact);
                CHECK(e.samples == opt.samples);
                // For the tiny triangle, BRDF samples hit about once per 1e5 iterations: the
                // standard error cannot see that technique's share (ground_truth.hpp, caveat),
                // at most Omega max(p_brdf) = Omega / pi of the integral.
                const double omega = std::abs(ltc::solid_angle(poly.v.data(), n));
                const double rare = use == gt::techniques::polygon_only || omega > 0.01 ? 0.0 : omega / pi * exact;
                CHECK(std::abs(e.mean - exact) <= 4 * e.standard_error + rare + 1e-12);
                CHECK(e.standard_error <= 0.02 * exact + 1e-9);  // the estimator is useful
            }
    }
}

TEST_CASE("ground truth of an LTC as the BRDF matches transformed::integrate within 4 sigma", "[ground_truth]") {
    // Two matrices of the paper's form and a general one; the LTC leaks below the horizon,
    // and the ground truth integrates over the whole polygon, as integrate() does.
    const glm::dmat3 Ms[] = {
        glm::transpose(glm::dmat3(0.3, 0, 0.2, 0, 0.4, 0, -0.1, 0, 1)),
        glm::transpose(glm::dmat3(1, 0, 0.6, 0, 1, 0, 0.5, 0, 1)),
        glm::transpose(glm::dmat3(0.1, 0.5, 1, 0.2, 1, 1, 0, 2, 0.5)),  // the supplement's
    };
    for (const glm::dmat3& M : Ms) {
        const ltc_model model{ltc::transformed<ltc::clamped_cosine<double>>(M)};
        for (const auto& poly : polygons()) {
            CAPTURE(poly.name);
            const double exact = model.d.integrate(poly.v.data(), poly.v.size());
            gt::options opt;
            opt.samples = 100000;
            opt.seed = 99;
            const gt::estimate e = gt::integrate(model, dvec3(0, 0, 1), 0.0, poly.v.data(), poly.v.size(), opt);
            CAPTURE(e.mean, e.standard_error, exact);
            // The rare BRDF hits of the tiny triangle (see the Lambertian case): their share is
            // about Omega D (D nearly constant over the triangle).
            const double omega = std::abs(ltc::solid_angle(poly.v.data(), poly.v.size()));
            const double rare = omega > 0.01 ? 0.0 : 1.5 * omega * model.d.eval(glm::normalize(poly.v[0])) * exact;
            CHECK(std::abs(e.mean - exact) <= 4 * e.standard_error + rare + 1e-12);
        }
    }
}

TEST_CASE("ground truth of GGX: the techniques agree, and adaptive mode reaches its target", "[ground_truth]") {
    const auto polys = polygons();
    for (const double theta : {0.0, 60.0, 85.0})
        for (const double alpha : {0.01, 0.2, 1.0}) {
            const dvec3 V = ltc::brdf::view_from_cos(std::cos(theta * ltc::pi<double>() / 180));
            for (const auto& poly : {polys[0], polys[1], polys[4]}) {
                CAPTURE(theta, alpha, poly.name);
                gt::options opt;
                opt.samples = 50000;
                opt.seed = 5;
                const gt::estimate mis = gt::integrate(ltc::brdf::ggx<double>{}, V, alpha, poly.v.data(), poly.v.size(), opt);
                opt.use = gt::techniques::polygon_only;
                opt.seed = 6;
                const gt::estimate pol = gt::integrate(ltc::brdf::ggx<double>{}, V, alpha, poly.v.data(), poly.v.size(), opt);
                opt.use = gt::techniques::mis;
                opt.weighting = gt::heuristic::power;
                opt.seed = 7;
                const gt::estimate pow = gt::integrate(ltc::brdf::ggx<double>{}, V, alpha, poly.v.data(), poly.v.size(), opt);
                CAPTURE(mis.mean, mis.standard_error, pol.mean, pol.standard_error, pow.mean, pow.standard_error);
                CHECK(std::abs(mis.mean - pol.mean) <= 4.5 * std::hypot(mis.standard_error, pol.standard_error) + 1e-15);
                CHECK(std::abs(mis.mean - pow.mean) <= 4.5 * std::hypot(mis.standard_error, pow.standard_error) + 1e-15);
            }
        }
    gt::options opt;
    opt.samples = 4096;
    opt.target_relative_error = 0.01;
    const auto& quad = polys[0];
    const gt::estimate e = gt::integrate(ltc::brdf::ggx<double>{}, ltc::brdf::view_from_cos(0.7), 0.3, quad.v.data(), 4, opt);
    CHECK(e.standard_error <= 0.01 * e.mean);
    CHECK(e.samples % 4096 == 0);
    CHECK(e.samples <= opt.max_samples);
}

TEST_CASE("ground truth is deterministic and handles degenerate polygons", "[ground_truth]") {
    const auto polys = polygons();
    const dvec3 V = ltc::brdf::view_from_cos(0.6);
    gt::options opt;
    opt.samples = 1000;
    const gt::estimate a = gt::integrate(ltc::brdf::ggx<double>{}, V, 0.1, polys[1].v.data(), 4, opt);
    const gt::estimate b = gt::integrate(ltc::brdf::ggx<double>{}, V, 0.1, polys[1].v.data(), 4, opt);
    CHECK(a.mean == b.mean);
    CHECK(a.standard_error == b.standard_error);
    opt.seed = 2;
    const gt::estimate c = gt::integrate(ltc::brdf::ggx<double>{}, V, 0.1, polys[1].v.data(), 4, opt);
    CHECK(a.mean != c.mean);

    const dvec3 below[3] = {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}};
    const gt::estimate e = gt::integrate(lambert{}, V, 0.0, below, 3, opt);
    CHECK(e.mean == 0.0);
    CHECK(e.standard_error == 0.0);
    const dvec3 at_origin[3] = {{0, 0, 0}, {1, 0, 1}, {0, 1, 1}};
    CHECK(gt::integrate(lambert{}, V, 0.0, at_origin, 3, opt).mean == 0.0);
    CHECK(gt::integrate(lambert{}, V, 0.0, at_origin, 2, opt).mean == 0.0);
    const dvec3 collinear[3] = {{0, 0, 1}, {1, 0, 1}, {2, 0, 1}};
    CHECK(gt::integrate(lambert{}, V, 0.0, collinear, 3, opt).mean == 0.0);
}

}  // namespace ltc_test_ground_truth
