// ltc/brdf/ggx.hpp -- deprecated path, kept through ltc 0.x: include <ltc/fitting/brdf/ggx.hpp>.
#pragma once
#include <ltc/fitting/brdf/ggx.hpp>
