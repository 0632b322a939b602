// ltc/ltc.hpp -- umbrella header: everything public in the ltc library.
//
// Linearly Transformed Spherical Distributions and Linearly Transformed Cosines
// (Heitz, Dupuy, Hill, Neubelt, "Real-Time Polygonal-Light Shading with Linearly Transformed
// Cosines", SIGGRAPH 2016). Header-only; depends on GLM only. Including single headers instead
// keeps compile times down: ltc/ggx.hpp (and what includes it) parses the 64 x 64 table.
#pragma once

#include <ltc/config.hpp>
#include <ltc/polygon.hpp>
#include <ltc/uniform_sphere.hpp>
#include <ltc/uniform_hemisphere.hpp>
#include <ltc/clamped_cosine.hpp>
#include <ltc/squared_clamped_cosine.hpp>
#include <ltc/transformed.hpp>
#include <ltc/brdf/model.hpp>
#include <ltc/brdf/ggx.hpp>
#include <ltc/brdf/beckmann.hpp>
#include <ltc/table.hpp>
#include <ltc/ggx.hpp>
#include <ltc/fit.hpp>
#include <ltc/clipless.hpp>
#include <ltc/shading.hpp>
#include <ltc/ground_truth.hpp>
#include <ltc/light_texture.hpp>
#include <ltc/textured.hpp>
#include <ltc/textured_ground_truth.hpp>
#include <ltc/batch.hpp>
