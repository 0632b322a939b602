// The opt-in GGX tables' tests against the Monte Carlo ground truth (test_two_lobe.cpp,
// test_cosine_lobe.cpp): the relative errors of the one-lobe shading and of another shading for
// one light.
#pragma once

#include "support/shading_scenes.hpp"

#include <ltc/fitting/brdf/ggx.hpp>
#include <ltc/fitting/brdf/schlick.hpp>
#include <ltc/reference/ground_truth.hpp>
#include <ltc/shading/polygon_light.hpp>

#include <catch2/catch.hpp>
#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace ltc_test::shading_checks {

struct lobe_errors {
    double one = 0, other = 0;
};

/// |LTC - GT| / GT of the one-lobe shading and of `other`, a shading with the arguments of
/// ltc::shade_polygon_light (P, N, V, roughness, F0, albedo, radiance, vertices, n, side; called
/// at the origin, N = z, no diffuse, one-sided), for the light L (vertices facing the origin) at
/// view angle theta (deg) and roughness r, with the specular colour f0 (1: no Fresnel term;
/// otherwise Schlick's factor in the ground truth, ltc/fitting/brdf/schlick.hpp); ground truth by
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
    const auto one = shade([](auto&&... a) { return ltc::shade_polygon_light(a...); });
    const auto o = shade(other);
    const lobe_errors e{std::abs(one.specular.x - gt.mean) / gt.mean, std::abs(o.specular.x - gt.mean) / gt.mean};
    CAPTURE(theta, r, seed, gt.mean, gt.standard_error, one.specular.x, o.specular.x, e.one, e.other);
    CHECK(gt.standard_error <= 0.005 * gt.mean);
    return e;
}

}  // namespace ltc_test::shading_checks
