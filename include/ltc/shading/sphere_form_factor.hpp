// ltc/shading/sphere_form_factor.hpp -- deprecated path, kept through ltc 0.x: include <ltc/core/sphere_form_factor.hpp>.
#pragma once
#include <ltc/core/sphere_form_factor.hpp>
