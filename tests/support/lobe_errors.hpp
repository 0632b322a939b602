// The opt-in GGX tables' tests against the Monte Carlo ground truth (test_two_lobe.cpp,
// test_cosine_lobe.cpp): the relative errors of the one-lobe shading and of another shading for
// one light.
#pragma once

#include "support/shading_scenes.hpp"

#include <ltc/brdf/ggx.hpp>
#include <ltc/brdf/schlick.hpp>
#include <ltc/reference/ground_truth.hpp>
#include <ltc/shading/polygon_light.hpp>

#include <catch2/catch.hpp>
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace ltc_test::shading_checks {

struct lobe_errors {
    double one = 0, other = 0;
};

/// |LTC - GT| / GT of the one-lobe shading and of `other`, a shading with the arguments of
/// ltc::shade_polygon_light_one_lobe (P, N, V, roughness, F0, albedo, radiance, vertices, n, side; called
/// at the origin, N = z, no diffuse, one-sided), for the light L (vertices facing the origin) at
/// view angle theta (deg) and roughness r, with the specular colour f0 (1: no Fresnel term;
/// otherwise Schlick's factor in the ground truth, ltc/brdf/schlick.hpp); ground truth by
/// ltc::ground_truth::integrate (MIS, 2^16 iterations, the given seed; relative standard error
/// below 0.5%, checked).
template <typename Other>
lobe_errors errors_against_truth(double theta, double r, const std::vector<dvec3>& L, std::uint64_t seed, Other&& other,
                                 double f0 = 1.0) {
    const dvec3 V = ltc::brdf::view_from_cos(std::cos(theta * pi / 180));
    ltc::ground_truth::options opt;
    opt.samples = 1u << 16;
    opt.seed = seed;
    const auto gt = ltc::ground_truth::integrate(ltc::brdf::with_schlick<ltc::brdf::ggx>{f0}, V, r * r, L.data(), L.size(), opt);
    const auto shade = [&](auto&& shading) -> ltc::polygon_light_result<double> {
        return shading(dvec3(0), dvec3(0, 0, 1), V, r, dvec3(f0), dvec3(0), dvec3(1), L.data(), L.size(),
                       ltc::sidedness::one_sided);
    };
    const auto one = shade([](auto&&... a) { return ltc::shade_polygon_light_one_lobe(a...); });
    const auto o = shade(other);
    const lobe_errors e{std::abs(one.specular.x - gt.mean) / gt.mean, std::abs(o.specular.x - gt.mean) / gt.mean};
    CAPTURE(theta, r, seed, gt.mean, gt.standard_error, one.specular.x, o.specular.x, e.one, e.other);
    CHECK(gt.standard_error <= 0.005 * gt.mean);
    return e;
}

/// Mean and worst |LTC - GT| / GT, of the one-lobe shading and of another, over some lights.
struct lobe_error_summary {
    double mean_one = 0, mean_other = 0, worst_one = 0, worst_other = 0;
};

/// The grazing test's 12 lights (tests/test_two_lobe.cpp): theta_v in {70, 80} deg, roughness in
/// {0.3, 0.5}, and three 0.5 x 0.25 rectangles facing the origin at distance 1: "mirror"
/// (azimuth 180 deg, elevation 90 - theta_v), "zenith" (elevation 80 deg, azimuth 0) and "side"
/// (azimuth 90, elevation 30); seeds 7000, 7001, ... in that order. `errors(theta, r, L, seed,
/// f0)` returns a lobe_errors (errors_against_truth with the other shading), f0 the specular colour.
template <typename Errors>
lobe_error_summary grazing_light_errors(Errors&& errors, double f0) {
    lobe_error_summary s;
    int count = 0;
    for (const double theta : {70.0, 80.0})
        for (const double r : {0.3, 0.5}) {
            const std::vector<dvec3> lights[] = {facing_rectangle(180, 90 - theta, 0.5, 0.25), facing_rectangle(0, 80, 0.5, 0.25),
                                                 facing_rectangle(90, 30, 0.5, 0.25)};
            for (const auto& L : lights) {
                const lobe_errors e = errors(theta, r, L, 7000 + std::uint64_t(count), f0);
                s.mean_one += e.one, s.mean_other += e.other;
                s.worst_one = std::max(s.worst_one, e.one), s.worst_other = std::max(s.worst_other, e.other);
                ++count;
            }
        }
    s.mean_one /= count, s.mean_other /= count;
    return s;
}

/// Prints the summary (`label` names the other shading) and checks the other shading against the
/// grazing tests' bounds: its mean and worst error, and at most half the one-lobe mean.
inline void check_grazing_summary(const lobe_error_summary& e, const char* label, double mean_bound,
                                  double worst_bound) {
    CAPTURE(label, e.mean_one, e.worst_one, e.mean_other, e.worst_other);
    WARN("one lobe: mean " << 100 * e.mean_one << "%, worst " << 100 * e.worst_one << "%; " << label << ": mean "
                           << 100 * e.mean_other << "%, worst " << 100 * e.worst_other << "%");
    CHECK(e.mean_other <= mean_bound);
    CHECK(e.worst_other <= worst_bound);
    CHECK(e.mean_other < 0.5 * e.mean_one);
}

}  // namespace ltc_test::shading_checks
