// ltc/shading/batch_shading.hpp -- the deprecated GGX batch shading of polygonal lights, one
// light over many shading points (16 arrays: shading_points) and many quad lights over one point
// (quad_lights), each a one-line wrapper over ltc::batch::shade (ltc/shading/batch_shade.hpp),
// whose results they are bit for bit (tests/test_batch_shade.cpp):
//
//   ltc::batch::shade_polygon_light(pts, radiance, vertices, n, side, res, count)
//     = ltc::batch::shade(surfaces, polygon_light, res)                     (ggx::ltc_and_cosine)
//   ltc::batch::shade_polygon_light_one_lobe(...)  = ltc::batch::shade<ltc::ggx::one_lobe>(...)
//   ltc::batch::shade_quad_lights(P, N, V, roughness, F0, albedo, lights, side, res, count)
//     = ltc::batch::shade(ltc::surface{P, N, V, roughness, F0, albedo}, polygon_lights, res)
//
// with the old sidedness (one-sided: the face from which the vertices turn clockwise,
// winding::clockwise_front) and horizon_clipping::ltc_space. Kernels, tolerances and bad input:
// ltc/shading/batch_shade.hpp (a zero or non-finite N, V or P gives 0).
#pragma once

#include <ltc/config.hpp>

#include <ltc/core/edge_policy.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/shading/batch.hpp>
#include <ltc/shading/batch_cosine_lobe.hpp>
#include <ltc/shading/batch_lobes.hpp>
#include <ltc/shading/batch_shade.hpp>
#include <ltc/shading/batch_soa.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/shading/polygon_light.hpp>

#include <glm/glm.hpp>

#include <cstddef>

LTC_NAMESPACE_BEGIN
namespace batch {

/// Deprecated: use ltc::batch::shade<ltc::ggx::one_lobe, Policy>(surfaces, polygon_light, out, which).
/// Shades count points with one polygonal light of n world-space vertices (n < 3: zeros).
template <typename Policy = edge_policy::automatic, typename T>
void shade_polygon_light_one_lobe(const shading_points<T>& points, const glm::vec<3, T>& radiance,
                                  const glm::vec<3, T>* vertices, std::size_t n, sidedness side,
                                  const shading_results<T>& out, std::size_t count, isa which = isa::automatic) {
    shade<ggx::one_lobe, Policy>(detail::surfaces_of(points, count),
                                 ltc::detail::polygon_light_access<T>::with_sidedness(vertices, n, side, radiance), out,
                                 which);
}

/// Deprecated: use ltc::batch::shade<ltc::ggx::ltc_and_cosine, Policy>(surfaces, polygon_light, out, which).
/// Shades count points with one polygonal light, the default table of an LTC and the cosine.
template <typename Policy = edge_policy::automatic, typename T>
void shade_polygon_light(const shading_points<T>& points, const glm::vec<3, T>& radiance,
                         const glm::vec<3, T>* vertices, std::size_t n, sidedness side, const shading_results<T>& out,
                         std::size_t count, isa which = isa::automatic) {
    shade<ggx::ltc_and_cosine, Policy>(detail::surfaces_of(points, count),
                                       ltc::detail::polygon_light_access<T>::with_sidedness(vertices, n, side, radiance),
                                       out, which);
}

/// Deprecated: use ltc::batch::shade<ltc::ggx::one_lobe, Policy>(surface, polygon_lights, out, which).
/// One point, count quad lights: light i's specular and diffuse at item i.
template <typename Policy = edge_policy::automatic, typename T>
void shade_quad_lights_one_lobe(const glm::vec<3, T>& P, const glm::vec<3, T>& N, const glm::vec<3, T>& V,
                                T roughness, const glm::vec<3, T>& F0, const glm::vec<3, T>& albedo,
                                const quad_lights<T>& lights, sidedness side, const shading_results<T>& out,
                                std::size_t count, isa which = isa::automatic) {
    shade<ggx::one_lobe, Policy>(surface<T>{P, N, V, roughness, F0, albedo}, detail::lights_of(lights, side, count), out,
                                 which);
}

/// Deprecated: use ltc::batch::shade<ltc::ggx::ltc_and_cosine, Policy>(surface, polygon_lights, out, which).
/// One point, count quad lights (the default table): light i's specular and diffuse at item i.
template <typename Policy = edge_policy::automatic, typename T>
void shade_quad_lights(const glm::vec<3, T>& P, const glm::vec<3, T>& N, const glm::vec<3, T>& V, T roughness,
                       const glm::vec<3, T>& F0, const glm::vec<3, T>& albedo, const quad_lights<T>& lights,
                       sidedness side, const shading_results<T>& out, std::size_t count, isa which = isa::automatic) {
    shade<ggx::ltc_and_cosine, Policy>(surface<T>{P, N, V, roughness, F0, albedo},
                                       detail::lights_of(lights, side, count), out, which);
}

}  // namespace batch
LTC_NAMESPACE_END
