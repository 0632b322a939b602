// ltc/polygon.hpp -- deprecated path, kept through ltc 0.x: include <ltc/core/polygon.hpp>.
#pragma once
#include <ltc/core/polygon.hpp>
