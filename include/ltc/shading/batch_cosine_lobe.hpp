// ltc/shading/batch_cosine_lobe.hpp -- the GGX shading of an LTC and the clamped cosine
// (ltc/shading/cosine_lobe_polygon_light.hpp) in batches, the default one (ltc::batch::
// shade_polygon_light and shade_quad_lights call these, ltc/shading/batch_shading.hpp): one
// polygonal light over many shading points, or one point under many quad lights.
//
//   ltc::batch::shade_polygon_light_cosine_lobe(pts, radiance, vertices, n, ltc::sidedness::one_sided, res, count);
//   ltc::batch::shade_quad_lights_cosine_lobe(P, N, V, roughness, F0, albedo, lights, ltc::sidedness::one_sided, res, count);
//
// Item i gets what ltc::shade_polygon_light_cosine_lobe gives for it with
// horizon_clipping::ltc_space, up to rounding: the SIMD kernel of ltc/shading/batch_lobes.hpp with
// the LTC's table and the cosine's magnitude and Fresnel term, the cosine's integral the form
// factor that the diffuse term computes (one frame, one form factor, one LTC integral per point,
// as the one-lobe batch; benchmarks/bench_shading.cpp). Points the kernel hands back, and the
// tail, get ltc::shade_polygon_light_cosine_lobe itself (tests/test_batch_shading.cpp).
#pragma once

#include <ltc/config.hpp>

#include <ltc/shading/batch_lobes.hpp>
#include <ltc/shading/cosine_lobe_polygon_light.hpp>
#include <ltc/shading/ggx_cosine_lobe_fetch.hpp>

#include <glm/glm.hpp>

#include <cstddef>

LTC_NAMESPACE_BEGIN
namespace batch {

/// Shades count points with one polygonal light of n >= 3 world-space vertices (n < 3: zeros)
/// and the given radiance, like ltc::shade_polygon_light_cosine_lobe item by item.
template <typename Policy = edge_policy::automatic, typename T>
void shade_polygon_light_cosine_lobe(const shading_points<T>& points, const glm::vec<3, T>& radiance,
                                     const glm::vec<3, T>* vertices, std::size_t n, sidedness side,
                                     const shading_results<T>& out, std::size_t count, isa which = isa::automatic) {
    const ltc_table cosine = ggx_cosine_lobe::lobe_table(0), lobe = ggx_cosine_lobe::lobe_table(1);
    const ltc_table* const tables[2] = {&cosine, &lobe};
    const auto scalar = [&](const shading_frame<T>& frame, std::size_t i) {
        const glm::vec<3, T> P(points.px[i], points.py[i], points.pz[i]);
        return ltc::shade_polygon_light_cosine_lobe<Policy>(
            frame, ggx_cosine_lobe::fetch<T>(frame.cos_theta_v, points.roughness[i]), P, detail::item(points.f0, i),
            detail::item(points.albedo, i), radiance, vertices, n, side);
    };
    detail::shade_polygon_light_lobes<Policy, 2, true>(tables, points, radiance, vertices, n, side, out, count, which,
                                                       scalar);
}

/// shade_quad_lights with the table of an LTC and the cosine: one point, count quad lights, light
/// i's specular and diffuse at item i, like ltc::shade_polygon_light_cosine_lobe light by light;
/// the same quad-kernel integrals as the one-lobe call.
template <typename Policy = edge_policy::automatic, typename T>
void shade_quad_lights_cosine_lobe(const glm::vec<3, T>& P, const glm::vec<3, T>& N, const glm::vec<3, T>& V,
                                   T roughness, const glm::vec<3, T>& F0, const glm::vec<3, T>& albedo,
                                   const quad_lights<T>& lights, sidedness side, const shading_results<T>& out,
                                   std::size_t count, isa which = isa::automatic) {
    const shading_frame<T> frame = make_shading_frame(N, V);
    const auto lobes = ggx_cosine_lobe::fetch<T>(frame.cos_theta_v, roughness);
    detail::shade_quad_lights_lobes<Policy>(P, frame, &lobes[1], 1, F0, albedo, lights, side, out, count, which, &lobes[0]);
}

}  // namespace batch
LTC_NAMESPACE_END
