// ltc/fitting/brdf/beckmann.hpp -- deprecated path, kept through ltc 0.x: include <ltc/brdf/beckmann.hpp>.
#pragma once
#include <ltc/brdf/beckmann.hpp>
