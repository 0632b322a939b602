// ltc/shading/batch_shading.hpp -- GGX shading of polygonal lights in batches, shaped as a
// renderer's loops: one light over many shading points (a pass over a G-buffer, a light baker's
// texels), and many quad lights over one point.
//
//   ltc::batch::shading_points<float> pts;     // SoA: P, N, V, roughness, F0, albedo per point
//   ltc::batch::shading_results<float> res;    // SoA: specular and diffuse RGB per point
//   ltc::batch::shade_polygon_light(pts, radiance, vertices, n, ltc::sidedness::one_sided, res, count);
//
// Item i gets what ltc::shade_polygon_light (ltc/shading/polygon_light.hpp) gives for it with
// horizon_clipping::ltc_space, up to rounding (tests/test_batch_shading.cpp derives the
// tolerance): the default GGX table of an LTC and the cosine (ltc/shading/batch_cosine_lobe.hpp),
// the frame, the table fetch, the form factor E and the LTC integral of eq. (3). The _one_lobe
// functions do the same with the one-lobe table (ltc::shade_polygon_light_one_lobe):
// specular = radiance (F0 magnitude + (1 - F0) fresnel) I and diffuse = albedo radiance E. The
// SIMD kernel and its dispatch: ltc/shading/batch_lobes.hpp.
//
// shade_quad_lights: one point, count quad lights (SoA vertices and radiance): the frame and the
// fetch once, the lights moved into the local frame, then their two integrals through the kernel
// of ltc/shading/batch.hpp; out receives each light's own contribution.
#pragma once

#include <ltc/config.hpp>

#include <ltc/core/edge_policy.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/shading/batch.hpp>
#include <ltc/shading/batch_cosine_lobe.hpp>
#include <ltc/shading/batch_lobes.hpp>
#include <ltc/shading/batch_soa.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/shading/polygon_light.hpp>

#include <glm/glm.hpp>

#include <cstddef>

LTC_NAMESPACE_BEGIN
namespace batch {

/// Shades count points with one polygonal light of n >= 3 world-space vertices (n < 3: zeros)
/// and the given radiance, like ltc::shade_polygon_light_one_lobe item by item.
template <typename Policy = edge_policy::automatic, typename T>
void shade_polygon_light_one_lobe(const shading_points<T>& points, const glm::vec<3, T>& radiance,
                                  const glm::vec<3, T>* vertices, std::size_t n, sidedness side,
                                  const shading_results<T>& out, std::size_t count, isa which = isa::automatic) {
    shade_polygon_light_with_table<Policy>(ggx::table, points, radiance, vertices, n, side, out, count, which);
}

/// Shades count points with one polygonal light of n >= 3 world-space vertices (n < 3: zeros)
/// and the given radiance, like ltc::shade_polygon_light item by item: the default table of an
/// LTC and the cosine: it calls shade_polygon_light_cosine_lobe.
template <typename Policy = edge_policy::automatic, typename T>
void shade_polygon_light(const shading_points<T>& points, const glm::vec<3, T>& radiance,
                         const glm::vec<3, T>* vertices, std::size_t n, sidedness side, const shading_results<T>& out,
                         std::size_t count, isa which = isa::automatic) {
    shade_polygon_light_cosine_lobe<Policy>(points, radiance, vertices, n, side, out, count, which);
}

/// Shades one point (as ltc::shade_polygon_light_one_lobe takes it) with each of count quad
/// lights and the one-lobe table: out receives light i's specular and diffuse at item i.
template <typename Policy = edge_policy::automatic, typename T>
void shade_quad_lights_one_lobe(const glm::vec<3, T>& P, const glm::vec<3, T>& N, const glm::vec<3, T>& V,
                                T roughness, const glm::vec<3, T>& F0, const glm::vec<3, T>& albedo,
                                const quad_lights<T>& lights, sidedness side, const shading_results<T>& out,
                                std::size_t count, isa which = isa::automatic) {
    const shading_frame<T> frame = make_shading_frame(N, V);
    const ltc_coefficients<T> lobe = ggx::fetch<T>(frame.cos_theta_v, roughness);
    detail::shade_quad_lights_lobes<Policy>(P, frame, &lobe, 1, F0, albedo, lights, side, out, count, which);
}

/// Shades one point (as ltc::shade_polygon_light takes it) with each of count quad lights: out
/// receives light i's specular and diffuse at item i (sum them for the point's radiance); the
/// default table of an LTC and the cosine: it calls shade_quad_lights_cosine_lobe.
template <typename Policy = edge_policy::automatic, typename T>
void shade_quad_lights(const glm::vec<3, T>& P, const glm::vec<3, T>& N, const glm::vec<3, T>& V, T roughness,
                       const glm::vec<3, T>& F0, const glm::vec<3, T>& albedo, const quad_lights<T>& lights,
                       sidedness side, const shading_results<T>& out, std::size_t count, isa which = isa::automatic) {
    shade_quad_lights_cosine_lobe<Policy>(P, N, V, roughness, F0, albedo, lights, side, out, count, which);
}

}  // namespace batch
LTC_NAMESPACE_END
