// ltc/shading/batch_cosine_lobe.hpp -- the deprecated batch shading with the GGX table of an LTC
// and the clamped cosine (ltc::ggx::ltc_and_cosine, the default model): one polygonal light over
// many shading points, or one point under many quad lights, each a one-line wrapper over
// ltc::batch::shade (ltc/shading/batch_shade.hpp), whose results they are bit for bit
// (tests/test_batch_shade.cpp):
//
//   ltc::batch::shade_polygon_light_cosine_lobe(pts, radiance, vertices, n, side, res, count)
//     = ltc::batch::shade<ltc::ggx::ltc_and_cosine>(surfaces, polygon_light, res)
//   ltc::batch::shade_quad_lights_cosine_lobe(P, N, V, roughness, F0, albedo, lights, side, res, count)
//     = ltc::batch::shade<ltc::ggx::ltc_and_cosine>(ltc::surface{...}, polygon_lights, res)
//
// with the old sidedness (ltc/shading/batch_lobes.hpp) and horizon_clipping::ltc_space.
#pragma once

#include <ltc/config.hpp>

#include <ltc/shading/batch_lobes.hpp>
#include <ltc/shading/batch_shade.hpp>
#include <ltc/shading/cosine_lobe_polygon_light.hpp>
#include <ltc/shading/ggx_cosine_lobe_fetch.hpp>

#include <glm/glm.hpp>

#include <cstddef>

LTC_NAMESPACE_BEGIN
namespace batch {

/// Deprecated: use ltc::batch::shade<ltc::ggx::ltc_and_cosine, Policy>(surfaces, polygon_light, out, which).
/// Shades count points with one polygonal light of n world-space vertices (n < 3: zeros).
template <typename Policy = edge_policy::automatic, typename T>
void shade_polygon_light_cosine_lobe(const shading_points<T>& points, const glm::vec<3, T>& radiance,
                                     const glm::vec<3, T>* vertices, std::size_t n, sidedness side,
                                     const shading_results<T>& out, std::size_t count, isa which = isa::automatic) {
    shade<ggx::ltc_and_cosine, Policy>(detail::surfaces_of(points, count),
                                       ltc::detail::polygon_light_access<T>::with_sidedness(vertices, n, side, radiance),
                                       out, which);
}

/// Deprecated: use ltc::batch::shade<ltc::ggx::ltc_and_cosine, Policy>(surface, polygon_lights, out, which).
/// One point, count quad lights: light i's specular and diffuse at item i.
template <typename Policy = edge_policy::automatic, typename T>
void shade_quad_lights_cosine_lobe(const glm::vec<3, T>& P, const glm::vec<3, T>& N, const glm::vec<3, T>& V,
                                   T roughness, const glm::vec<3, T>& F0, const glm::vec<3, T>& albedo,
                                   const quad_lights<T>& lights, sidedness side, const shading_results<T>& out,
                                   std::size_t count, isa which = isa::automatic) {
    shade<ggx::ltc_and_cosine, Policy>(surface<T>{P, N, V, roughness, F0, albedo},
                                       detail::lights_of(lights, side, count), out, which);
}

}  // namespace batch
LTC_NAMESPACE_END
