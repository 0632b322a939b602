// Shading with the shipped GGX tables (ltc/shading/polygon_light.hpp's world-space functions: the
// default, an LTC and the cosine, and shade_polygon_light_one_lobe): V parallel to N, float
// against double, and the LTC shading against the Monte Carlo ground truth of the real GGX
// integral over a small documented grid.
#include <catch2/catch.hpp>

#include <ltc/brdf/ggx.hpp>
#include <ltc/reference/ground_truth.hpp>
#include <ltc/ltc.hpp>
#include <ltc/shading/polygon_light.hpp>

#include "support/shading_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <cstdint>
#include <vector>

namespace ltc_test_shading_ggx {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::shading_checks;  // lobes, random scenes, rel_diff

namespace {

// The two world-space shadings, as callables of the same arguments.
const auto default_shading = [](auto&&... a) { return ltc::shade_polygon_light(a...); };
const auto one_lobe_shading = [](auto&&... a) { return ltc::shade_polygon_light_one_lobe(a...); };

template <typename Shading>
void check_v_parallel_to_n(Shading&& shade) {
    const dvec3 quad[4] = {{-1, -1, 2}, {1, -1, 2}, {1, 1, 2.5}, {-1, 1, 2.5}};
    const dvec3 F0(0.04), albedo(0.5), radiance(1.0);
    for (const auto mode : all_modes) {
        CAPTURE(int(mode));
        // V = N exactly (Duff's tangent) and V within 1e-7 of N in two different directions:
        // at normal incidence the lobe is isotropic, so they all agree.
        const dvec3 N(0, 0, 1);
        const auto exact = shade(dvec3(0), N, N, 0.3, F0, albedo, radiance, quad, 4, ltc::sidedness::one_sided, mode);
        REQUIRE(exact.specular.x > 0);
        for (const dvec3 tilt : {dvec3(1e-7, 0, 0), dvec3(0, -1e-7, 0), dvec3(-7e-8, 7e-8, 0)}) {
            const auto near = shade(dvec3(0), N, glm::normalize(N + tilt), 0.3, F0, albedo, radiance, quad, 4,
                                    ltc::sidedness::one_sided, mode);
            CHECK(rel_diff(near.specular.x, exact.specular.x) <= 1e-6);
            CHECK(rel_diff(near.diffuse.x, exact.diffuse.x) <= 1e-12);
        }
        // float agrees with double.
        glm::vec3 qf[4];
        for (int i = 0; i < 4; ++i) qf[i] = glm::vec3(quad[i]);
        const dvec3 V = glm::normalize(dvec3(0.6, 0.2, 0.5));
        const auto d = shade(dvec3(0), N, V, 0.4, F0, albedo, radiance, quad, 4, ltc::sidedness::one_sided, mode);
        const auto f = shade(glm::vec3(0), glm::vec3(N), glm::vec3(V), 0.4f, glm::vec3(F0), glm::vec3(albedo),
                             glm::vec3(radiance), qf, 4, ltc::sidedness::one_sided, mode);
        CHECK(f.specular.x == Approx(d.specular.x).epsilon(2e-5));
        CHECK(f.diffuse.x == Approx(d.diffuse.x).epsilon(2e-6));
    }
}

}  // namespace

TEST_CASE("shading with the GGX tables: V parallel to N, and float against double", "[shading]") {
    SECTION("default: an LTC and the cosine") { check_v_parallel_to_n(default_shading); }
    SECTION("one lobe") { check_v_parallel_to_n(one_lobe_shading); }
}

TEST_CASE("LTC shading against the Monte Carlo GGX ground truth on a small grid", "[shading][ground_truth]") {
    // Grid (local frame, shading point at the origin, N = +z, V = (sin theta_v, 0, cos theta_v)):
    //   theta_v in {0, 45, 75} deg, roughness in {0.25, 0.5, 1} (alpha = roughness^2), and two
    //   lights facing the origin at distance 1: "mirror", a square of half-size 0.5 centred on
    //   the mirror direction, and "low", a 2:1 rectangle of half-size 1 x 0.5 centred at
    //   azimuth 180 deg, elevation 10 deg (partly below the horizon).
    // Ground truth: ltc::ground_truth::integrate with ltc::brdf::ggx<double>, MIS, 2^17
    // iterations, fixed seeds (standard errors 0.2-0.5%). Specular with F0 = 1 (magnitude *
    // I_ltc), like the ground truth (no Fresnel). The bounds are the measured errors of the
    // shipped tables (tools/ggx_error_report/ has the full grid), rounded up.
    struct light_case {
        const char* name;
        std::vector<dvec3> v;
    };
    const auto make = facing_rectangle;
    // Measured with the shipped tables and these seeds (max over all 18 configurations, max over
    // the 9 "mirror" ones, mean over all), rounded up in the fourth digit. One lobe
    // (shade_polygon_light_one_lobe):
    //   exact (ltc_space)  24.62%, 2.181%, 3.695%
    //   shading_first      24.62%, 2.181%, 3.384%
    //   sphere_analytic    46.23%, 2.689%, 5.841%
    // (the 24% and 46% are the "low" light at normal incidence and roughness 0.25, in the tail
    // of the lobe; on the mirror lights the fit is within 2.2%). The default, an LTC and the
    // cosine (shade_polygon_light):
    //   exact (ltc_space)  14.54%, 10.65%, 2.945%
    //   shading_first       7.996%, 5.239%, 2.256%
    //   sphere_analytic    64.17%, 10.64%, 8.109%
    // (it halves the "low" light's error at normal incidence, 24.6% to 8.0%, but both lights at
    // theta_v = 75, roughness 0.5 are over by 10.6% and 14.5%, where one lobe is within 1.6%; with
    // the sphere approximation the cosine's integral is the clipless form factor's, whose error on
    // the "low" light adds to the LTC's.)
    // The ground truth's standard errors are 0.1-0.3%, so another seed moves these figures in
    // their third digit: a new table or new seeds need new figures, from this test's output.
    struct bound {
        double max_all, max_mirror, mean_all;
    };
    const bound bounds[2][3] = {{{0.2463, 0.02181, 0.03696}, {0.2463, 0.02181, 0.03385}, {0.4624, 0.02689, 0.05842}},
                                {{0.1454, 0.1065, 0.02945}, {0.07996, 0.05239, 0.02256}, {0.6417, 0.1064, 0.08109}}};
    double worst[2][3] = {}, worst_mirror[2][3] = {}, sum[2][3] = {};
    int count = 0;
    int seed = 0;
    for (const double theta : {0.0, 45.0, 75.0})
        for (const double r : {0.25, 0.5, 1.0}) {
            const light_case lights[] = {{"mirror", make(180, 90 - theta, 0.5, 0.5)},
                                         {"low", make(180, 10, 1.0, 0.5)}};
            for (const auto& L : lights) {
                const dvec3 V = ltc::brdf::view_from_cos(std::cos(theta * pi / 180));
                ltc::ground_truth::options opt;
                opt.samples = 1u << 17;
                opt.seed = 1000 + std::uint64_t(seed++);
                const auto gt = ltc::ground_truth::integrate(ltc::brdf::ggx<double>{}, V, r * r, L.v.data(), L.v.size(), opt);
                CHECK(gt.standard_error <= 0.006 * gt.mean);
                const clip_mode modes[3] = {clip_mode::ltc_space, clip_mode::shading_first, clip_mode::sphere_analytic};
                for (int t = 0; t < 2; ++t)
                    for (int m = 0; m < 3; ++m) {
                        const auto args = std::make_tuple(dvec3(0), dvec3(0, 0, 1), V, r, dvec3(1), dvec3(0), dvec3(1),
                                                          L.v.data(), L.v.size(), ltc::sidedness::one_sided, modes[m]);
                        const auto s = t == 0 ? std::apply(one_lobe_shading, args) : std::apply(default_shading, args);
                        const double e = std::abs(s.specular.x - gt.mean) / gt.mean;
                        CAPTURE(theta, r, L.name, t, m, gt.mean, gt.standard_error, s.specular.x, e);
                        CHECK(std::isfinite(e));  // with -s, prints each configuration's figures
                        worst[t][m] = std::max(worst[t][m], e);
                        if (&L == &lights[0]) worst_mirror[t][m] = std::max(worst_mirror[t][m], e);
                        sum[t][m] += e;
                    }
                ++count;
            }
        }
    for (int t = 0; t < 2; ++t)
        for (int m = 0; m < 3; ++m) {
            CAPTURE(t, m, worst[t][m], worst_mirror[t][m], sum[t][m] / count);
            CHECK(worst[t][m] <= bounds[t][m].max_all);
            CHECK(worst_mirror[t][m] <= bounds[t][m].max_mirror);
            CHECK(sum[t][m] / count <= bounds[t][m].mean_all);
        }
}

}  // namespace ltc_test_shading_ggx
