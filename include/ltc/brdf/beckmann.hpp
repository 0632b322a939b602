// ltc/brdf/beckmann.hpp -- deprecated path, kept through ltc 0.x: include <ltc/fitting/brdf/beckmann.hpp>.
#pragma once
#include <ltc/fitting/brdf/beckmann.hpp>
