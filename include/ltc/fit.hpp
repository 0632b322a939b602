// ltc/fit.hpp -- deprecated path, kept through ltc 0.x: include <ltc/fitting/fit.hpp>.
#pragma once
#include <ltc/fitting/fit.hpp>
