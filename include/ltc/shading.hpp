// ltc/shading.hpp -- deprecated path, kept through ltc 0.x: include <ltc/shading/polygon_light.hpp>.
#pragma once
#include <ltc/shading/polygon_light.hpp>
