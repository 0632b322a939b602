// ltc/textured.hpp -- deprecated path, kept through ltc 0.x: include <ltc/shading/textured_light.hpp>.
#pragma once
#include <ltc/shading/textured_light.hpp>
