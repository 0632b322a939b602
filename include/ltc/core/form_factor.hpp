// ltc/core/form_factor.hpp -- the clamped-cosine integral over a polygon: the vector form factor
// of the unclipped polygon (Snyder 1996, Hill 2016) and the form factor of the horizon-clipped one,
// the paper's eq. (11), signed or for a one- or two-sided emitter. Quads take the fast path of
// ltc/core/quad_path.hpp.
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/edge_integral.hpp>
#include <ltc/core/edge_policy.hpp>
#include <ltc/core/horizon_clip.hpp>
#include <ltc/core/quad_path.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <cstddef>

LTC_NAMESPACE_BEGIN

namespace detail {

/// vector_form_factor for any Vertices (a pointer, or a callable i -> unit vector).
template <typename T, typename Policy, typename Vertices>
LTC_HOST_DEVICE LTC_INLINE glm::vec<3, T> vector_form_factor(const Vertices& v, std::size_t n) {
    glm::vec<3, T> f(T(0));
    const bool ok = for_each_unit_edge<T, false>(
        v, n, [&](const glm::vec<3, T>& a, const glm::vec<3, T>& b, const glm::vec<3, T>&) {
            f += edge_integral<Policy>(a, b);
        });
    return ok ? f / (T(2) * pi<T>()) : glm::vec<3, T>(T(0));
}

}  // namespace detail

/// Vector form factor F = 1/(2 pi) sum_i edge_integral(p_i, p_i+1) of the unclipped polygon
/// (eq. 11 before the dot with z; Snyder 1996 / Hill 2016). Its z component is the cosine
/// integral without horizon clipping; |F| and its direction define the equivalent sphere of the
/// horizon-clipping approximation.
template <typename Policy = edge_policy::exact, typename T>
LTC_HOST_DEVICE LTC_INLINE glm::vec<3, T> vector_form_factor(const glm::vec<3, T>* v, std::size_t n) {
    return detail::vector_form_factor<T, Policy>(v, n);
}

namespace detail {

template <typename T, typename Policy = edge_policy::exact, typename Vertices>
LTC_HOST_DEVICE LTC_INLINE T form_factor(const Vertices& v, std::size_t n) {
    T sum(0);
    if (n == 4 && quad_form_factor<T, Policy>(v, sum)) return sum / (T(2) * pi<T>());
    const bool ok = for_each_unit_edge<T, true>(
        v, n, [&](const glm::vec<3, T>& a, const glm::vec<3, T>& b, const glm::vec<3, T>&) {
            sum += edge_integral_z<Policy>(a, b);
        });
    return ok ? sum / (T(2) * pi<T>()) : T(0);
}

}  // namespace detail

/// Signed integral of cos(theta) / pi over the horizon-clipped polygon: eq. (11) of the paper,
/// E = 1/(2 pi) sum_i theta_i (p_i x p_j / |p_i x p_j|).z, on the clipped polygon.
/// Policy selects the evaluation of theta / sin(theta) (see edge_policy).
template <typename Policy = edge_policy::exact, typename T>
LTC_HOST_DEVICE LTC_INLINE T form_factor_signed(const glm::vec<3, T>* v, std::size_t n) {
    return detail::form_factor<T, Policy>(v, n);
}

/// form_factor_signed made non-negative for a one-sided or two-sided emitter.
template <typename Policy = edge_policy::exact, typename T>
LTC_HOST_DEVICE LTC_INLINE T form_factor(const glm::vec<3, T>* v, std::size_t n, sidedness s) {
    return apply_sidedness(form_factor_signed<Policy>(v, n), s);
}

LTC_NAMESPACE_END
