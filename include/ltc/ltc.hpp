// ltc/ltc.hpp -- umbrella header: everything public in the ltc library.
//
// Linearly Transformed Spherical Distributions and Linearly Transformed Cosines
// (Heitz, Dupuy, Hill, Neubelt, "Real-Time Polygonal-Light Shading with Linearly Transformed
// Cosines", SIGGRAPH 2016). Header-only; depends on GLM only.
#pragma once

#include <ltc/config.hpp>
#include <ltc/polygon.hpp>
#include <ltc/uniform_sphere.hpp>
#include <ltc/uniform_hemisphere.hpp>
#include <ltc/clamped_cosine.hpp>
#include <ltc/squared_clamped_cosine.hpp>
#include <ltc/transformed.hpp>
