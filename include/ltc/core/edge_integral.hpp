// ltc/core/edge_integral.hpp -- the edge term of the paper's eq. (11) (Baum et al. 1989),
// theta (a x b) / |a x b| for the unit vertices a, b of an edge, and its z component, with the
// factor theta / sin(theta) evaluated by an edge policy (ltc/core/edge_policy.hpp).
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/edge_policy.hpp>
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

LTC_NAMESPACE_BEGIN

/// Exact edge term of eq. (11) for unit vectors a, b: theta * (a x b) / |a x b|, theta the angle
/// between them. With the default policy, computed as atan2(|a x b|, a.b) with a
/// cancellation-free cross product, so it is accurate for nearly parallel and nearly opposite
/// vertices (no acos of a dot product near +-1, no division by a vanishing sine).
template <typename Policy = edge_policy::exact, typename T>
LTC_HOST_DEVICE LTC_INLINE glm::vec<3, T> edge_integral(const glm::vec<3, T>& a, const glm::vec<3, T>& b) {
    const T c = glm::dot(a, b);
    const glm::vec<3, T> axb = detail::stable_cross(a, b, c);
    return axb * Policy::theta_over_sin(c, axb);
}

/// z component of edge_integral(a, b): the edge's contribution to the clamped-cosine integral
/// (times 2 pi).
template <typename Policy = edge_policy::exact, typename T>
LTC_HOST_DEVICE LTC_INLINE T edge_integral_z(const glm::vec<3, T>& a, const glm::vec<3, T>& b) {
    const T c = glm::dot(a, b);
    if constexpr (detail::has_positive_branch<Policy, T>::value) {
        // c >= 0: the z component of a x b = a x (b - a) alone (what stable_cross computes).
        if (c >= T(0)) return (a.x * (b.y - a.y) - a.y * (b.x - a.x)) * Policy::positive_branch(T(1) - c);
    }
    const glm::vec<3, T> axb = detail::stable_cross(a, b, c);
    return axb.z * Policy::theta_over_sin(c, axb);
}

LTC_NAMESPACE_END
