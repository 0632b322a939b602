// ltc/reference.hpp -- umbrella header of the Monte Carlo ground truth: polygonal, textured and
// shaped lights integrated by sampling, to validate the approximations (and a renderer).
#pragma once

#include <ltc/config.hpp>

#include <ltc/reference/ground_truth.hpp>
#include <ltc/reference/shape_ground_truth.hpp>
#include <ltc/reference/textured_ground_truth.hpp>
