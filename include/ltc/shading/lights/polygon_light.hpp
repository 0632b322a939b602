// ltc/shading/lights/polygon_light.hpp -- a constant-radiance planar polygonal light (paper
// section 5.1), one-sided or two-sided, as ltc::shade takes it (ltc/shading/shade.hpp).
//
//   const glm::vec3 quad[4] = {...};
//   auto a = ltc::polygon_light<float>::one_sided(quad, 4, emission_normal, radiance);
//   auto b = ltc::polygon_light<float>::one_sided(quad, 4, ltc::winding::counter_clockwise_front, radiance);
//   auto c = ltc::polygon_light<float>::two_sided(quad, 4, radiance);
//
// Conventions: world space; a one-sided light emits towards its emission normal whatever the order
// of its vertices (polygon_light, "Facing"), a two-sided one from both faces (|signed integral|).
// The light refers to the caller's vertices, which must outlive its use. Degenerate cases: bad
// input throws ltc::invalid_light; n < 3 or zero area is a valid light that emits nothing.
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/shading/lights/light_error.hpp>
#include <ltc/shading/polygon_light_integrals.hpp>
#include <ltc/shading/shading_frame.hpp>
#include <ltc/shading/surface.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>

LTC_NAMESPACE_BEGIN

/// The two winding conventions of one-sided polygons, for vertices that already carry one:
///   counter_clockwise_front  the front is the side from which the vertices turn counter-clockwise
///                            (the right-hand normal (p1 - p0) x (p2 - p0) points towards it):
///                            three.js's LTC_Evaluate ("ccw winding order of light vertices"),
///                            OpenGL's default front face;
///   clockwise_front          the front is the side from which they turn clockwise: the paper's
///                            ltc_quad.fs and the library's old shade_*(..., sidedness::one_sided).
enum class winding { counter_clockwise_front, clockwise_front };

namespace detail {

/// Twice the vector area of a polygon (Newell's method, about vertex 0 for accuracy): its
/// right-hand normal (p1 - p0) x (p2 - p0) for a triangle.
template <typename T>
inline glm::vec<3, T> vector_area_x2(const glm::vec<3, T>* v, std::size_t n) {
    glm::vec<3, T> a(T(0));
    for (std::size_t i = 1; i + 1 < n; ++i) a += glm::cross(v[i] - v[0], v[i + 1] - v[0]);
    return a;
}

template <typename T>
class polygon_light_access;

}  // namespace detail

/// A constant-radiance planar polygon light.
///
/// Facing. A one-sided light emits towards the side its emission normal points to, whatever the
/// order of its vertices: the light walks them in the order that makes that side the front (the
/// side from which they turn clockwise, the orientation of the library's signed integrals,
/// ltc/core/polygon.hpp), so both orders of one polygon give the same bits. For vertices that
/// already carry a convention, `winding` names the two in use. A two-sided light emits from both
/// faces (|signed integral|).
///
/// Storage. The light refers to the caller's vertices (a pointer and a count, like std::span): no
/// copy and no allocation for any n, so they must outlive every call of shade with the light.
/// Build the light where its vertices live (not from a temporary array).
///
/// Checked construction (ltc::invalid_light, ltc/shading/lights/light_error.hpp): vertices null
/// with n > 0; an emission normal that is zero, not finite, or perpendicular to the polygon's
/// vector area (which side?). A polygon of n < 3 vertices, or of zero area, is a valid light that
/// emits nothing.
template <typename T>
class polygon_light {
public:
    using vec3 = glm::vec<3, T>;

    /// Emits towards emission_normal (any length; its side of the polygon's plane).
    static polygon_light one_sided(const vec3* vertices, std::size_t n, const vec3& emission_normal,
                                   const vec3& radiance) {
        check_vertices(vertices, n);
        if (!detail::finite(emission_normal) || emission_normal == vec3(T(0)))
            throw invalid_light("polygon_light::one_sided: the emission normal is zero or not finite");
        const vec3 area = n >= 3 ? detail::vector_area_x2(vertices, n) : vec3(T(0));
        const T facing = glm::dot(area, emission_normal);
        if (area != vec3(T(0)) && !(facing != T(0)))
            throw invalid_light("polygon_light::one_sided: the emission normal lies in the polygon's plane");
        // Front = the side from which the vertices turn clockwise = against the right-hand normal.
        return polygon_light(vertices, n, radiance, sidedness::one_sided, facing > T(0));
    }

    /// Emits from the face the convention names (winding).
    static polygon_light one_sided(const vec3* vertices, std::size_t n, winding front, const vec3& radiance) {
        check_vertices(vertices, n);
        return polygon_light(vertices, n, radiance, sidedness::one_sided, front == winding::counter_clockwise_front);
    }

    /// Emits from both faces.
    static polygon_light two_sided(const vec3* vertices, std::size_t n, const vec3& radiance) {
        check_vertices(vertices, n);
        return polygon_light(vertices, n, radiance, sidedness::two_sided, false);
    }

    LTC_HOST_DEVICE const vec3* vertices() const { return vertices_; }
    LTC_HOST_DEVICE std::size_t size() const { return n_; }
    LTC_HOST_DEVICE const vec3& radiance() const { return radiance_; }
    LTC_HOST_DEVICE sidedness sides() const { return side_; }
    /// The i-th vertex in the order the light walks them (its front: clockwise).
    LTC_HOST_DEVICE const vec3& vertex(std::size_t i) const { return first_[step_ * static_cast<std::ptrdiff_t>(i)]; }

    // The light interface of ltc::shade (ltc/shading/lobes.hpp): the sided integrals of the
    // clamped cosine (form factor, eq. 11) and of the LTC with inverse matrix m_inv (eq. 3), in
    // `frame` at P, and the radiance a lobe scale times an integral stands for.
    template <typename Policy>
    LTC_HOST_DEVICE polygon_light_integrals<T> integrals(const shading_frame<T>& frame, const vec3& P, const glm::mat<3, 3, T>& m_inv,
                                         const shade_options& o) const {
        polygon_light_integrals<T> I = detail::integrate_polygon_light_at<Policy>(frame, m_inv, P, at(), n_, o.clip);
        I.form_factor = apply_sidedness(I.form_factor, side_);
        I.ltc = apply_sidedness(I.ltc, side_);
        return I;
    }
    template <typename Policy>
    LTC_HOST_DEVICE T ltc_integral(const shading_frame<T>& frame, const vec3& P, const glm::mat<3, 3, T>& m_inv,
                   const shade_options& o) const {
        return apply_sidedness(detail::integrate_polygon_light_ltc_at<Policy>(frame, m_inv, P, at(), n_, o.clip), side_);
    }
    LTC_HOST_DEVICE vec3 emitted(const vec3& scale, T integral) const { return radiance_ * scale * integral; }

private:
    friend class detail::polygon_light_access<T>;
    LTC_HOST_DEVICE polygon_light(const vec3* v, std::size_t n, const vec3& radiance, sidedness side, bool reversed)
        : vertices_(v), first_(reversed && n > 0 ? v + (n - 1) : v), step_(reversed ? -1 : 1), n_(n), radiance_(radiance),
          side_(side) {}

    static void check_vertices(const vec3* vertices, std::size_t n) {
        if (vertices == nullptr && n > 0) throw invalid_light("polygon_light: null vertices with n > 0");
    }
    LTC_HOST_DEVICE auto at() const {
        return [this](std::size_t i) { return vertex(i); };
    }

    const vec3* vertices_;
    const vec3* first_;      // the walk: vertex(i) = first_[step_ i], the caller's order or its reverse
    std::ptrdiff_t step_;
    std::size_t n_;
    vec3 radiance_;
    sidedness side_;
};

namespace detail {

/// The lights of the old shade_*(..., sidedness) functions: one-sided emits from the face from
/// which the vertices turn clockwise (winding::clockwise_front), unchecked, host and device.
template <typename T>
class polygon_light_access {
public:
    LTC_HOST_DEVICE static polygon_light<T> with_sidedness(const glm::vec<3, T>* vertices, std::size_t n, sidedness side,
                                                           const glm::vec<3, T>& radiance) {
        return polygon_light<T>(vertices, n, radiance, side, false);
    }
};

}  // namespace detail

LTC_NAMESPACE_END
