// ltc/ltc.hpp -- umbrella header of the runtime: everything a renderer shades with (core, brdf,
// tables, shading); the references and the fitter have their own (ltc/reference.hpp,
// ltc/fitting.hpp).
//
//   #include <ltc/ltc.hpp>
//
// Linearly Transformed Spherical Distributions and Linearly Transformed Cosines
// (Heitz, Dupuy, Hill, Neubelt, "Real-Time Polygonal-Light Shading with Linearly Transformed
// Cosines", SIGGRAPH 2016). Header-only; depends on GLM only. Single headers parse less: each
// generated table is parsed only by its own fetch. The layers: below.
#pragma once

// The folders are the layers, lowest first (a header includes only its own layer and those
// below: cmake/check_layers.cmake):
//
//   ltc/config.hpp, ltc/detail/   version, ABI namespace, scalar helpers;
//   ltc/core/       the paper's mathematics: the original distributions, transformed<>, the
//                   polygon machinery (horizon clipping, edge terms, form factors, solid angles),
//                   the integrals over lines and ellipses (disks), the samplers of polygons;
//   ltc/brdf/       the BRDF models (GGX, anisotropic GGX, Beckmann, Schlick's Fresnel, the
//                   Charlie sheen);
//   ltc/tables/     the table format (ltc_table) and the generated GGX and Charlie sheen tables;
//                   the sheen and anisotropic GGX models are not in this umbrella (their tables
//                   would parse in every file): ltc/shading/sheen_models.hpp,
//                   ltc/shading/ggx_anisotropic_model.hpp;
//   ltc/shading/    what a renderer shades with: polygonal (also shadowed), textured, disk,
//                   sphere, line and tube lights, the tables' fetches, structure-of-arrays batches;
//   ltc/reference/  Monte Carlo ground truth (umbrella: ltc/reference.hpp);
//   ltc/fitting/    the offline fitter that makes the tables (umbrella: ltc/fitting.hpp).

#include <ltc/config.hpp>

#include <ltc/core/polygon.hpp>
#include <ltc/core/uniform_sphere.hpp>
#include <ltc/core/uniform_hemisphere.hpp>
#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/squared_clamped_cosine.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/core/invalid_transform.hpp>
#include <ltc/core/invalid_polygon.hpp>
#include <ltc/core/line_integral.hpp>
#include <ltc/core/ellipse_integral.hpp>
#include <ltc/core/spherical_triangle_sampling.hpp>
#include <ltc/core/spherical_polygon_sampling.hpp>
#include <ltc/core/projected_solid_angle_sampling.hpp>
#include <ltc/core/ltc_polygon_sampling.hpp>
#include <ltc/core/polygon_area_sampling.hpp>
#include <ltc/core/screen_order.hpp>

#include <ltc/brdf/model.hpp>
#include <ltc/brdf/ggx.hpp>
#include <ltc/brdf/ggx_anisotropic.hpp>
#include <ltc/brdf/beckmann.hpp>
#include <ltc/brdf/charlie.hpp>
#include <ltc/brdf/schlick.hpp>

#include <ltc/tables/ltc_table.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/shading/surface.hpp>
#include <ltc/shading/lobes.hpp>
#include <ltc/shading/ggx_models.hpp>
#include <ltc/shading/shade.hpp>
#include <ltc/shading/lights/light_error.hpp>
#include <ltc/shading/lights/polygon_light.hpp>
#include <ltc/shading/lights/disk_light.hpp>
#include <ltc/shading/lights/sphere_light.hpp>
#include <ltc/shading/lights/line_light.hpp>
#include <ltc/shading/lights/tube_light.hpp>
#include <ltc/shading/lights/textured_quad_light.hpp>
#include <ltc/shading/polygon_light.hpp>
#include <ltc/shading/two_lobe_polygon_light.hpp>
#include <ltc/shading/cosine_lobe_polygon_light.hpp>
#include <ltc/shading/clipless.hpp>
#include <ltc/shading/cell_pyramid.hpp>
#include <ltc/shading/light_texture.hpp>
#include <ltc/shading/quick_cells.hpp>
#include <ltc/shading/textured_cells.hpp>
#include <ltc/shading/textured_fetch.hpp>
#include <ltc/shading/textured_light.hpp>
#include <ltc/shading/disk_light.hpp>
#include <ltc/shading/sphere_light.hpp>
#include <ltc/shading/line_light.hpp>
#include <ltc/shading/tube_light.hpp>
#include <ltc/shading/batch.hpp>
#include <ltc/shading/batch_shade.hpp>
#include <ltc/shading/batch_shading.hpp>
#include <ltc/shading/batch_two_lobe.hpp>
#include <ltc/shading/batch_cosine_lobe.hpp>
#include <ltc/shading/shade_shadowed.hpp>
#include <ltc/shading/shadowed_polygon_light.hpp>
