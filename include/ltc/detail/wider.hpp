// ltc/detail/wider.hpp -- the wider type in which the samplers rebuild ill-conditioned polygons
// (tiny or grazing ones in float): double for float, T itself otherwise (no widening).
#pragma once

#include <ltc/config.hpp>

#include <type_traits>

LTC_NAMESPACE_BEGIN
namespace detail {

/// The wider type of the ill-conditioned fans: double for float.
template <typename T>
using wider_t = std::conditional_t<std::is_same_v<T, float>, double, T>;

}  // namespace detail
LTC_NAMESPACE_END
