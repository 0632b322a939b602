// ltc/uniform_sphere.hpp -- deprecated path, kept through ltc 0.x: include <ltc/core/uniform_sphere.hpp>.
#pragma once
#include <ltc/core/uniform_sphere.hpp>
