// ltc/light_texture.hpp -- deprecated path, kept through ltc 0.x: include <ltc/shading/light_texture.hpp>.
#pragma once
#include <ltc/shading/light_texture.hpp>
