// ltc/transformed.hpp -- deprecated path, kept through ltc 0.x: include <ltc/core/transformed.hpp>.
#pragma once
#include <ltc/core/invalid_transform.hpp>
#include <ltc/core/transformed.hpp>
