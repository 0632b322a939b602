// ltc/shading/clipless.hpp -- horizon clipping without clipping: the sphere approximation of Hill and
// Heitz 2016 ("Real-Time Area Lighting: a Journey from Research to Production", SIGGRAPH course).
//
//   #include <ltc/shading/clipless.hpp>
//   float e = ltc::clipless::integrate(d, vertices, n, ltc::sidedness::one_sided,
//                                      ltc::clipless::method::analytic);
//
// Instead of clipping M^-1 P to the horizon (a branchy polygon clip in a shader), compute the
// *unclipped* vector form factor F of M^-1 P (ltc::vector_form_factor), replace the polygon by the
// sphere with the same vector form factor (angular radius sigma around the unit direction u:
// F = sin^2(sigma) u) and return that sphere's horizon-clipped form factor, with
//
//   f = |F| = sin^2(sigma),   cos(omega) = u.z = +-F.z / |F|
//
// (the sign: "Orientation" in ltc/shading/equivalent_sphere.hpp; where it breaks down: integrate).
#pragma once

#include <ltc/shading/equivalent_sphere.hpp>   // equivalent_sphere, sphere_of_polygon
#include <ltc/core/sphere_form_factor.hpp>  // sphere_form_factor
#include <ltc/shading/sphere_table.hpp>        // sphere_table, fill_sphere_table, sphere_form_factor_table

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/core/polygon.hpp>
#include <ltc/core/transformed.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>

LTC_NAMESPACE_BEGIN

// The pieces, each of which can be included on its own:
//   ltc/core/sphere_form_factor.hpp  sphere_form_factor: the sphere's clipped form factor
//                                       (Snyder 1996), evaluated without cancellation
//   ltc/shading/sphere_table.hpp        the same as a 32 x 32 table (sphere_table,
//                                       fill_sphere_table, sphere_form_factor_table)
//   ltc/shading/equivalent_sphere.hpp   the sphere of a polygon and its orientation
//                                       (equivalent_sphere, sphere_of_polygon)
// This namespace joins them: form_factor(_signed) of a polygon, integrate(_signed) of a
// transformed clamped cosine (the sphere of M^-1 P).
namespace clipless {

/// How the horizon-clipped sphere form factor is evaluated.
enum class method { analytic, table };

namespace detail {

/// Signed clipless integral of the clamped cosine over M^-1 P, P given by at(i) in the local
/// frame, M^-1 = m_inv; Policy evaluates the edge terms of the vector form factor.
template <typename T, typename Policy, typename VertexAt>
LTC_HOST_DEVICE inline T integrate_signed(const glm::mat<3, 3, T>& m_inv, T det_inv, const VertexAt& at,
                                          std::size_t n, method how, const sphere_table* table) {
    using vec3 = glm::vec<3, T>;
    const T facing = orientation<T>(at, n);  // orientation of P
    if (facing == T(0)) return T(0);
    const auto transformed_at = [&](std::size_t i) {
        const vec3 p = at(i);
        const T s = glm::max(glm::max(std::abs(p.x), std::abs(p.y)), std::abs(p.z));
        // Unit vectors: every edge policy but exact assumes them.
        return s > T(0) ? ltc::detail::safe_normalize(m_inv * (p / s)) : vec3(T(0));
    };
    const vec3 F = ltc::detail::vector_form_factor<T, Policy>(transformed_at, n);
    const T facing_ltc = det_inv < T(0) ? -facing : facing;  // orientation of M^-1 P
    const equivalent_sphere<T> sph = sphere_of(F, facing_ltc);
    if (sph.sign == T(0)) return T(0);
    const T I = how == method::table && table ? table->lookup(sph.f, sph.cos_omega)
                                              : sphere_form_factor(sph.f, sph.cos_omega);
    return facing * I;
}

}  // namespace detail

/// Clipless approximation of form_factor_signed (the polygon's clipped cosine integral):
/// signed by the polygon's orientation.
template <typename T>
inline T form_factor_signed(const glm::vec<3, T>* vertices, std::size_t n, method how = method::analytic) {
    const auto at = [&](std::size_t i) { return glm::vec<3, T>(vertices[i]); };
    const sphere_table* table = how == method::table ? &sphere_table::instance() : nullptr;
    return detail::integrate_signed<T, edge_policy::exact>(glm::mat<3, 3, T>(T(1)), T(1), at, n, how, table);
}

/// Clipless approximation of ltc::form_factor.
template <typename T>
inline T form_factor(const glm::vec<3, T>* vertices, std::size_t n, sidedness side,
                     method how = method::analytic) {
    return apply_sidedness(form_factor_signed(vertices, n, how), side);
}

/// Clipless approximation of d.integrate_signed(vertices, n): the unclipped vector form factor
/// of M^-1 P, its equivalent sphere, and the sphere's horizon-clipped form factor. The edge
/// terms of the vector form factor use the distribution's edge policy.
template <typename T, typename Policy>
inline T integrate_signed(const transformed<clamped_cosine<T, Policy>>& d, const glm::vec<3, T>* vertices,
                          std::size_t n, method how = method::analytic) {
    const auto at = [&](std::size_t i) { return glm::vec<3, T>(vertices[i]); };
    const sphere_table* table = how == method::table ? &sphere_table::instance() : nullptr;
    return detail::integrate_signed<T, typename clamped_cosine<T, Policy>::EdgePolicy>(d.inverse_matrix(),
                                                                                   d.inverse_determinant(), at, n, how, table);
}

/// Clipless approximation of d.integrate(vertices, n, side).
///
/// Where it breaks down (tests/test_clipless.cpp and tools/ggx_error_report/ measure it): the
/// approximation is exact when the polygon and its sphere are both entirely above the horizon
/// (both integrals are then F.z; the sphere is above iff cos(omega) >= sin(sigma), i.e.
/// F.z >= |F|^(3/2)) or both entirely below (both 0), and for caps. Otherwise the sphere
/// replaces the polygon's own clipping by a cap's: a polygon above the horizon whose sphere
/// dips below it gets more than F.z (the clipped sphere integral exceeds its unclipped one), a
/// polygon that dips below the horizon under a sphere that does not gets F.z instead of more,
/// and a polygon straddling the horizon gets a cap's clipped share instead of its own. The
/// error grows with how un-cap-like the polygon is: a polygon elongated along the horizon has a
/// sphere much taller than itself, and the part above the horizon can be a thin sliver that
/// no cap represents (relative errors of several hundred percent of a small value). Compact
/// polygons (squares, equilateral triangles) stay closest; rectangles lying along the horizon
/// are off by a share of |F| that grows with their aspect ratio (docs/design_notes.md). After
/// M^-1 a sharp lobe (small roughness) stretches a light into a large, elongated polygon, so the
/// worst cases are low roughness with lights near the horizon.
template <typename T, typename Policy>
inline T integrate(const transformed<clamped_cosine<T, Policy>>& d, const glm::vec<3, T>* vertices, std::size_t n,
                   sidedness side, method how = method::analytic) {
    return apply_sidedness(integrate_signed(d, vertices, n, how), side);
}

}  // namespace clipless
LTC_NAMESPACE_END
