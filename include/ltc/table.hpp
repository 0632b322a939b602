// ltc/table.hpp -- deprecated path, kept through ltc 0.x: include <ltc/shading/table.hpp>.
#pragma once
#include <ltc/shading/table.hpp>
