// ltc/shading/table.hpp -- deprecated path, kept through ltc 0.x: include <ltc/tables/ltc_table.hpp>.
#pragma once
#include <ltc/tables/ltc_table.hpp>
