// ltc/reference/spherical_triangle.hpp -- uniform sampling of a spherical triangle by Arvo's
// method (Arvo 1995; pbrt-v4's arrangement): how the ground truth samples each fan triangle of
// a polygon light (ltc/reference/spherical_polygon.hpp). The sampler is the library's own
// (ltc/core/spherical_triangle_sampling.hpp) in double.
//
//   ltc::ground_truth::spherical_triangle_sampler s(a, b, c);   // unit vectors
//   glm::dvec3 w = s.sample(u);                                 // density 1 / s.solid_angle()
#pragma once

#include <ltc/config.hpp>

#include <ltc/core/spherical_triangle_sampling.hpp>

#include <glm/glm.hpp>

LTC_NAMESPACE_BEGIN
namespace ground_truth {

/// Uniform sampling of the spherical triangle (a, b, c) of unit vectors by Arvo's method: the
/// library's sampler in double (ltc/core/spherical_triangle_sampling.hpp), so that the method is
/// written once. Either orientation; the density is 1 / solid_angle(); a flat triangle samples a.
using spherical_triangle_sampler = ltc::spherical_triangle_sampler<double>;

/// A uniformly distributed direction in the spherical triangle (a, b, c) of unit vectors, for
/// u in [0, 1)^2 (spherical_triangle_sampler, for a single sample).
inline glm::dvec3 sample_spherical_triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                                            const glm::dvec2& u) {
    return spherical_triangle_sampler(a, b, c).sample(u);
}

}  // namespace ground_truth
LTC_NAMESPACE_END
