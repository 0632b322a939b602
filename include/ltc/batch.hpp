// ltc/batch.hpp -- deprecated path, kept through ltc 0.x: include <ltc/shading/batch.hpp>.
#pragma once
#include <ltc/shading/batch.hpp>
