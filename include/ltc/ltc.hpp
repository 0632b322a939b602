// ltc/ltc.hpp -- umbrella header: everything public in the ltc library.
//
// Linearly Transformed Spherical Distributions and Linearly Transformed Cosines
// (Heitz, Dupuy, Hill, Neubelt, "Real-Time Polygonal-Light Shading with Linearly Transformed
// Cosines", SIGGRAPH 2016). Header-only; depends on GLM only. Including single headers instead
// keeps compile times down: ltc/shading/ggx_fetch.hpp (and what includes it) parses the 64 x 64 table.
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/polygon.hpp>
#include <ltc/core/uniform_sphere.hpp>
#include <ltc/core/uniform_hemisphere.hpp>
#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/squared_clamped_cosine.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/fitting/brdf/model.hpp>
#include <ltc/fitting/brdf/ggx.hpp>
#include <ltc/fitting/brdf/beckmann.hpp>
#include <ltc/shading/table.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/fitting/fit.hpp>
#include <ltc/shading/clipless.hpp>
#include <ltc/shading/polygon_light.hpp>
#include <ltc/reference/ground_truth.hpp>
#include <ltc/shading/light_texture.hpp>
#include <ltc/shading/textured_light.hpp>
#include <ltc/reference/textured_ground_truth.hpp>
#include <ltc/shading/batch.hpp>
