// ltc/shading/batch_two_lobe.hpp -- the opt-in two-lobe GGX shading (ltc/shading/
// two_lobe_polygon_light.hpp) in batches: one polygonal light over many shading points.
//
//   ltc::batch::shade_polygon_light_two_lobe(pts, radiance, vertices, n, ltc::sidedness::one_sided, res, count);
//   ltc::batch::shade_quad_lights_two_lobe(P, N, V, roughness, F0, albedo, lights, ltc::sidedness::one_sided, res, count);
//
// Item i gets what ltc::shade_polygon_light_two_lobe gives for it with horizon_clipping::ltc_space,
// up to rounding: the SIMD kernel of ltc/shading/batch_shading.hpp runs once per lobe table
// (ltc::ggx_two_lobe::lobe_table; batch::shade_polygon_light_with_table), the first pass writing
// the diffuse term and lobe 1's specular term, the second adding lobe 2's. The second pass also
// computes a form factor that it drops, so this costs about twice the one-lobe batch
// (benchmarks/bench_shading.cpp); its points go through in chunks of 256 with their results on
// the stack. The tolerance of each pass against the scalar shading with the same table is the
// one-lobe batch's (tests/test_batch_shading.cpp). shade_quad_lights_two_lobe: one point and many
// quad lights, as batch::shade_quad_lights, with one more LTC integral per light for lobe 2.
#pragma once

#include <ltc/shading/batch_shading.hpp>
#include <ltc/shading/ggx_two_lobe_fetch.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cstddef>

namespace ltc {
namespace batch {

/// Shades count points with one polygonal light of n >= 3 world-space vertices (n < 3: zeros)
/// and the given radiance, like ltc::shade_polygon_light_two_lobe item by item.
template <typename Policy = edge_policy::automatic, typename T>
void shade_polygon_light_two_lobe(const shading_points<T>& points, const glm::vec<3, T>& radiance,
                                  const glm::vec<3, T>* vertices, std::size_t n, sidedness side,
                                  const shading_results<T>& out, std::size_t count, isa which = isa::automatic) {
    shade_polygon_light_with_table<Policy>(ggx_two_lobe::lobe_table(0), points, radiance, vertices, n, side, out, count,
                                           which);
    constexpr std::size_t chunk = 256;
    T scratch[6][chunk];
    for (std::size_t begin = 0; begin < count; begin += chunk) {
        const std::size_t m = std::min(chunk, count - begin);
        shading_points<T> part = points;
        for (const T** column : {&part.px, &part.py, &part.pz, &part.nx, &part.ny, &part.nz, &part.vx, &part.vy, &part.vz,
                                 &part.roughness, &part.f0[0], &part.f0[1], &part.f0[2], &part.albedo[0],
                                 &part.albedo[1], &part.albedo[2]})
            *column += begin;
        shading_results<T> second;
        for (int c = 0; c < 3; ++c) second.specular[c] = scratch[c], second.diffuse[c] = scratch[3 + c];
        shade_polygon_light_with_table<Policy>(ggx_two_lobe::lobe_table(1), part, radiance, vertices, n, side, second, m,
                                               which);
        for (int c = 0; c < 3; ++c)
            for (std::size_t i = 0; i < m; ++i) out.specular[c][begin + i] += scratch[c][i];
    }
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
}  // namespace ltc
