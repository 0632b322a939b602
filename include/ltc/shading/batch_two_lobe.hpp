// ltc/shading/batch_two_lobe.hpp -- the opt-in two-lobe GGX shading (ltc/shading/
// two_lobe_polygon_light.hpp) in batches: one polygonal light over many shading points.
//
//   ltc::batch::shade_polygon_light_two_lobe(pts, radiance, vertices, n, ltc::sidedness::one_sided, res, count);
//   ltc::batch::shade_quad_lights_two_lobe(P, N, V, roughness, F0, albedo, lights, ltc::sidedness::one_sided, res, count);
//
// Item i gets what ltc::shade_polygon_light_two_lobe gives for it with horizon_clipping::ltc_space,
// up to rounding: the SIMD kernel of ltc/shading/batch_lobes.hpp with both lobe tables
// (ltc::ggx_two_lobe::lobe_table) in one pass: one frame and one form factor per point, an LTC
// integral per lobe (benchmarks/bench_shading.cpp: the cost against the one-lobe batch). Points
// the kernel hands back, and the tail, get ltc::shade_polygon_light_two_lobe itself. The tolerance
// against the scalar shading with the kernel's coefficients is the sum of the one-lobe batch's for
// each lobe (tests/test_batch_shading.cpp). shade_quad_lights_two_lobe: one point and many quad
// lights, as batch::shade_quad_lights_one_lobe, with one more LTC integral per light for lobe 2.
#pragma once

#include <ltc/config.hpp>

#include <ltc/shading/batch_lobes.hpp>
#include <ltc/shading/ggx_two_lobe_fetch.hpp>
#include <ltc/shading/two_lobe_polygon_light.hpp>

#include <glm/glm.hpp>

#include <cstddef>

LTC_NAMESPACE_BEGIN
namespace batch {

/// Shades count points with one polygonal light of n >= 3 world-space vertices (n < 3: zeros)
/// and the given radiance, like ltc::shade_polygon_light_two_lobe item by item.
template <typename Policy = edge_policy::automatic, typename T>
void shade_polygon_light_two_lobe(const shading_points<T>& points, const glm::vec<3, T>& radiance,
                                  const glm::vec<3, T>* vertices, std::size_t n, sidedness side,
                                  const shading_results<T>& out, std::size_t count, isa which = isa::automatic) {
    const ltc_table lobe_1 = ggx_two_lobe::lobe_table(0), lobe_2 = ggx_two_lobe::lobe_table(1);
    const ltc_table* const tables[2] = {&lobe_1, &lobe_2};
    const auto scalar = [&](const shading_frame<T>& frame, std::size_t i) {
        const glm::vec<3, T> P(points.px[i], points.py[i], points.pz[i]);
        return ltc::shade_polygon_light_two_lobe<Policy>(
            frame, ggx_two_lobe::fetch<T>(frame.cos_theta_v, points.roughness[i]), P, detail::item(points.f0, i),
            detail::item(points.albedo, i), radiance, vertices, n, side);
    };
    detail::shade_polygon_light_lobes<Policy, 2>(tables, points, radiance, vertices, n, side, out, count, which, scalar);
}

/// shade_quad_lights with the two-lobe GGX table: one point, count quad lights, light i's
/// specular (both lobes) and diffuse at item i, like ltc::shade_polygon_light_two_lobe light by
/// light. The frame, the fetch and the lights' local coordinates once; one more quad-kernel
/// integral per light than the one-lobe call.
template <typename Policy = edge_policy::automatic, typename T>
void shade_quad_lights_two_lobe(const glm::vec<3, T>& P, const glm::vec<3, T>& N, const glm::vec<3, T>& V, T roughness,
                                const glm::vec<3, T>& F0, const glm::vec<3, T>& albedo, const quad_lights<T>& lights,
                                sidedness side, const shading_results<T>& out, std::size_t count,
                                isa which = isa::automatic) {
    const shading_frame<T> frame = make_shading_frame(N, V);
    const auto lobes = ggx_two_lobe::fetch<T>(frame.cos_theta_v, roughness);
    detail::shade_quad_lights_lobes<Policy>(P, frame, lobes.data(), 2, F0, albedo, lights, side, out, count, which);
}

}  // namespace batch
LTC_NAMESPACE_END
