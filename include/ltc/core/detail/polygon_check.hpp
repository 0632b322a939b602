// ltc/core/detail/polygon_check.hpp -- the test of the polygon samplers' checked factories: the
// input holds at least 3 and at most max_vertices finite vertices (ltc/core/invalid_polygon.hpp).
#pragma once

#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/core/detail/defined_later.hpp>

#include <glm/glm.hpp>

#include <cstddef>

LTC_NAMESPACE_BEGIN

class invalid_polygon;

namespace detail {

/// Throws ltc::invalid_polygon where vertices[0..n) is no polygon a sampler of capacity
/// max_vertices holds. Host code only (it throws).
template <typename T>
inline void require_polygon(const char* sampler, const glm::vec<3, T>* vertices, std::size_t n,
                            std::size_t max_vertices) {
    using error = typename defined_later<invalid_polygon, T>::type;
    if (n > max_vertices) error::raise(error::too_many_vertices, sampler, n, max_vertices);
    if (n < 3) error::raise(error::too_few_vertices, sampler, n, max_vertices);
    for (std::size_t i = 0; i < n; ++i)
        if (!is_finite(vertices[i])) error::raise(error::non_finite, sampler, i, max_vertices);
}

}  // namespace detail

LTC_NAMESPACE_END
