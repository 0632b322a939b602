// ltc/core/detail/defined_later.hpp -- naming an exception class through a template parameter, so
// that the headers whose checked factories throw it need only its declaration: <stdexcept> and the
// class's definition (ltc/core/invalid_transform.hpp, invalid_polygon.hpp) are included by the
// callers of checked(), not by every user of the cheap constructors.
#pragma once

#include <ltc/config.hpp>

LTC_NAMESPACE_BEGIN

namespace detail {

/// X, named through T so that its completeness is required only where a checked factory is used.
template <typename X, typename T>
struct defined_later {
    using type = X;
};

}  // namespace detail

LTC_NAMESPACE_END
