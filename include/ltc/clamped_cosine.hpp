// ltc/clamped_cosine.hpp -- deprecated path, kept through ltc 0.x: include <ltc/core/clamped_cosine.hpp>.
#pragma once
#include <ltc/core/clamped_cosine.hpp>
