// ltc/uniform_hemisphere.hpp -- deprecated path, kept through ltc 0.x: include <ltc/core/uniform_hemisphere.hpp>.
#pragma once
#include <ltc/core/uniform_hemisphere.hpp>
