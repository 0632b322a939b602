// ltc/shading/batch_lobes.hpp -- the deprecated batch shading with any one-lobe LTC table
// (shade_polygon_light_with_table) and the deprecated quad lights of shade_quad_lights
// (ltc/shading/batch_shading.hpp, batch_cosine_lobe.hpp, batch_two_lobe.hpp), each a one-line
// wrapper over ltc::batch::shade (ltc/shading/batch_shade.hpp), whose results they are bit for
// bit (tests/test_batch_shade.cpp): the kernels, the tolerances and the bad-input conventions
// are that header's.
//
//   ltc::batch::shade(ltc::batch::one_lobe_table(table), pts, light, out);   // for _with_table
//   ltc::batch::shade(point, ltc::batch::polygon_lights<float>::two_sided(count, x, y, z, radiance), out);
//
// Old sidedness, as the scalar deprecated functions (ltc::detail::polygon_light_access): a one-sided
// light emits from the face from which its vertices turn clockwise (winding::clockwise_front).
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/edge_policy.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/shading/batch.hpp>
#include <ltc/shading/batch_shade.hpp>
#include <ltc/shading/batch_soa.hpp>
#include <ltc/shading/lights/polygon_light.hpp>
#include <ltc/tables/ltc_table.hpp>

#include <glm/glm.hpp>

#include <cstddef>

LTC_NAMESPACE_BEGIN
namespace batch {

/// Deprecated: use ltc::batch::shade(one_lobe_table(table), surfaces, polygon_light, out, which).
/// The one-lobe batch shading with any LTC table (ltc/tables/ltc_table.hpp) in place of the GGX
/// table: item i as ltc::shade_lobes with lobes::one{table.fetch(cos theta_v, roughness)}.
template <typename Policy = edge_policy::automatic, typename T>
void shade_polygon_light_with_table(const ltc_table& table, const shading_points<T>& points,
                                    const glm::vec<3, T>& radiance, const glm::vec<3, T>* vertices, std::size_t n,
                                    sidedness side, const shading_results<T>& out, std::size_t count,
                                    isa which = isa::automatic) {
    shade<one_lobe_table, Policy>(one_lobe_table(table), detail::surfaces_of(points, count),
                                  ltc::detail::polygon_light_access<T>::with_sidedness(vertices, n, side, radiance), out,
                                  which);
}

/// Deprecated: use ltc::batch::polygon_lights<T, 4>. count quad lights: vertex k of light i is
/// (x[k][i], y[k][i], z[k][i]) in world space, its radiance (radiance[0][i], radiance[1][i],
/// radiance[2][i]).
template <typename T>
struct quad_lights {
    const T* x[4] = {};
    const T* y[4] = {};
    const T* z[4] = {};
    const T* radiance[3] = {};
};

namespace detail {

/// The old quad lights with the old sidedness (file comment) as polygon_lights.
template <typename T>
polygon_lights<T, 4> lights_of(const quad_lights<T>& l, sidedness side, std::size_t count) {
    return side == sidedness::two_sided
               ? polygon_lights<T, 4>::two_sided(count, l.x, l.y, l.z, l.radiance)
               : polygon_lights<T, 4>::one_sided(count, l.x, l.y, l.z, winding::clockwise_front, l.radiance);
}

}  // namespace detail

}  // namespace batch
LTC_NAMESPACE_END
