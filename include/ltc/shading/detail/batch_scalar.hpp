// ltc/shading/detail/batch_scalar.hpp -- the scalar path of the batch API (ltc/shading/batch.hpp): item i
// through transformed<clamped_cosine<T, Policy>>::from_inverse(M_i^-1).integrate(P_i, n, s)
// (eq. 11), for the items the SIMD kernel hands back (NaN), the tail shorter than a vector, and
// the policies and builds without a SIMD kernel.
#pragma once

#include <ltc/config.hpp>

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/shading/batch_soa.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

LTC_NAMESPACE_BEGIN
namespace batch {
namespace detail {

template <typename Policy, typename T>
inline T scalar_item(const matrices<T>& mats, const T* const* x, const T* const* y, const T* const* z, std::size_t n,
                     std::size_t i, sidedness s) {
    glm::mat<3, 3, T> mi = mats.shared;
    if (!mats.is_shared())
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) mi[c][r] = mats.entry[c][r][i];
    constexpr std::size_t stack = 16;
    glm::vec<3, T> buf[stack];
    std::vector<glm::vec<3, T>> heap(n > stack ? n : 0);
    glm::vec<3, T>* v = n > stack ? heap.data() : buf;
    for (std::size_t k = 0; k < n; ++k) v[k] = glm::vec<3, T>(x[k][i], y[k][i], z[k][i]);
    return transformed<clamped_cosine<T, Policy>>::from_inverse(mi).integrate(v, n, s);
}

/// Items [0, vectorized) where the kernel wrote NaN, and every item from `vectorized` on.
template <typename Policy, typename T>
inline void scalar_items(const matrices<T>& mats, const T* const* x, const T* const* y, const T* const* z, std::size_t n,
                         T* out, std::size_t vectorized, std::size_t count, sidedness s) {
    for (std::size_t i = 0; i < count; ++i)
        if (i >= vectorized || std::isnan(out[i])) out[i] = scalar_item<Policy>(mats, x, y, z, n, i, s);
}

}  // namespace detail
}  // namespace batch
LTC_NAMESPACE_END
