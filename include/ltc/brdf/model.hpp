// ltc/brdf/model.hpp -- deprecated path, kept through ltc 0.x: include <ltc/fitting/brdf/model.hpp>.
#pragma once
#include <ltc/fitting/brdf/model.hpp>
