// ltc/fitting/brdf/schlick.hpp -- deprecated path, kept through ltc 0.x: include <ltc/brdf/schlick.hpp>.
#pragma once
#include <ltc/brdf/schlick.hpp>
