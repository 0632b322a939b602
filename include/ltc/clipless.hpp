// ltc/clipless.hpp -- deprecated path, kept through ltc 0.x: include <ltc/shading/clipless.hpp>.
#pragma once
#include <ltc/shading/clipless.hpp>
