// ltc/ground_truth.hpp -- deprecated path, kept through ltc 0.x: include <ltc/reference/ground_truth.hpp>.
#pragma once
#include <ltc/reference/ground_truth.hpp>
