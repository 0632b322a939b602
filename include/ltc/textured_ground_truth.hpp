// ltc/textured_ground_truth.hpp -- deprecated path, kept through ltc 0.x: include <ltc/reference/textured_ground_truth.hpp>.
#pragma once
#include <ltc/reference/textured_ground_truth.hpp>
