// ltc/fitting/brdf/model.hpp -- deprecated path, kept through ltc 0.x: include <ltc/brdf/model.hpp>.
#pragma once
#include <ltc/brdf/model.hpp>
