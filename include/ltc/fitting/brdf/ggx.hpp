// ltc/fitting/brdf/ggx.hpp -- deprecated path, kept through ltc 0.x: include <ltc/brdf/ggx.hpp>.
#pragma once
#include <ltc/brdf/ggx.hpp>
