// ltc/fitting.hpp -- umbrella header of the offline fitter: fitting LTC tables to a BRDF
// (paper section 4) and writing them as headers like ltc/tables/ggx.hpp. Pulls in <thread>; a
// renderer includes ltc/ltc.hpp instead.
#pragma once

#include <ltc/config.hpp>

#include <ltc/fitting/fit.hpp>
