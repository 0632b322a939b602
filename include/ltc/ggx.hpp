// ltc/ggx.hpp -- deprecated path, kept through ltc 0.x: include <ltc/shading/ggx_fetch.hpp>.
#pragma once
#include <ltc/shading/ggx_fetch.hpp>
