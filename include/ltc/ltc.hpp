// ltc/ltc.hpp -- umbrella header: everything public in the ltc library.
//
// Linearly Transformed Spherical Distributions and Linearly Transformed Cosines
// (Heitz, Dupuy, Hill, Neubelt, "Real-Time Polygonal-Light Shading with Linearly Transformed
// Cosines", SIGGRAPH 2016). Header-only; depends on GLM only. The folders are the layers:
//
//   ltc/core/       the paper's mathematics: the original distributions, transformed<>, the
//                   polygon machinery (horizon clipping, edge terms, form factors, solid angles),
//                   the integrals over lines and ellipses (disks), and the samplers of polygons
//                   (solid angle, projected solid angle, an LTC restricted to a polygon, area);
//   ltc/shading/    what a renderer shades with: polygonal (also shadowed: the ratio estimator),
//                   textured, disk, sphere and tube lights, the GGX tables' fetches (the
//                   default's, an LTC and the cosine; the paper's single LTC; two LTCs), the
//                   clipless approximation, structure-of-arrays batches;
//   ltc/fitting/    offline: BRDF models and the fitter that makes the tables;
//   ltc/reference/  Monte Carlo ground truth, to validate the approximations (and a renderer);
//   ltc/tables/     generated data (the GGX tables); ltc/detail/: internals.
//
// Including single headers instead keeps compile times down: ltc/shading/ggx_fetch.hpp (and what
// includes it) parses the 64 x 64 table, ltc/fitting/ pulls in <thread>.
#pragma once

#include <ltc/config.hpp>

#include <ltc/core/polygon.hpp>
#include <ltc/core/uniform_sphere.hpp>
#include <ltc/core/uniform_hemisphere.hpp>
#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/squared_clamped_cosine.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/core/line_integral.hpp>
#include <ltc/core/ellipse_integral.hpp>
#include <ltc/core/spherical_triangle_sampling.hpp>
#include <ltc/core/spherical_polygon_sampling.hpp>
#include <ltc/core/projected_solid_angle_sampling.hpp>
#include <ltc/core/ltc_polygon_sampling.hpp>
#include <ltc/core/polygon_area_sampling.hpp>
#include <ltc/core/screen_order.hpp>

#include <ltc/tables/ltc_table.hpp>
#include <ltc/shading/ggx_fetch.hpp>
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
#include <ltc/shading/batch_shading.hpp>
#include <ltc/shading/batch_two_lobe.hpp>
#include <ltc/shading/batch_cosine_lobe.hpp>
#include <ltc/shading/shadowed_polygon_light.hpp>

#include <ltc/brdf/model.hpp>
#include <ltc/brdf/ggx.hpp>
#include <ltc/brdf/beckmann.hpp>
#include <ltc/fitting/fit.hpp>

#include <ltc/reference/ground_truth.hpp>
#include <ltc/reference/textured_ground_truth.hpp>
#include <ltc/reference/shape_ground_truth.hpp>
