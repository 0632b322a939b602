// ltc/shading/lights/line_light.hpp -- a constant-radiance thin tube (line) light: Heitz and Hill
// 2017's line lights, the LTC integral of a thin cylinder around the segment p0-p1
// (ltc/core/line_integral.hpp) times its diameter.
//
//   ltc::line_light<float> line{p0, p1, radius, radiance};
//   ltc::shading_result<float> r = ltc::shade(surface, line);   // ltc/shading/shade.hpp
//
//   diffuse  = albedo * radiance * 2 r I_line,cos                   (integrate_line_cosine)
//   specular = radiance * (F0 magnitude + (1 - F0) fresnel) * 2 r I_line   (integrate_line)
//
// Conventions: world space, an aggregate; a tube glows all around (no sidedness), no end caps.
// I_line is exact in the limit of a thin tube (line_light). Degenerate cases: finite results;
// radius <= 0 or NaN, p0 = p1, an axis through the shading point give 0.
#pragma once

#include <ltc/config.hpp>

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/line_integral.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/shading/polygon_light_integrals.hpp>  // polygon_light_integrals
#include <ltc/shading/shading_frame.hpp>
#include <ltc/shading/surface.hpp>

#include <glm/glm.hpp>

#include <limits>

LTC_NAMESPACE_BEGIN

/// A constant-radiance thin tube light. World space: the tube's axis p0-p1, its radius and
/// radiance; an aggregate. A tube glows all around: no sidedness; no end caps. I_line is exact in
/// the limit of a thin tube (r small against the distance to the point: the cylinder's solid
/// angle is 2r d/|x|^3 dl + O(r^2) per axis element); a point close to the tube (distance ~ r)
/// sees it wider than that, an error tools/shape_error_report (docs/results/shape_error.md)
/// compares with Monte Carlo of the real cylinder, with the GGX fit's. For close or wide tubes:
/// ltc/shading/lights/tube_light.hpp. Degenerate input gives finite results: radius <= 0 or NaN,
/// p0 = p1, an axis through the shading point give 0.
template <typename T>
struct line_light {
    using vec3 = glm::vec<3, T>;
    vec3 p0{T(0)}, p1{T(0)};
    T radius{0};
    vec3 radiance{T(0)};

    // The light interface of ltc::shade (ltc/shading/lights/polygon_light.hpp).
    template <typename Policy>
    polygon_light_integrals<T> integrals(const shading_frame<T>& frame, const vec3& P, const glm::mat<3, 3, T>& m_inv,
                                         const shade_options&) const {
        polygon_light_integrals<T> I;
        if (!usable(frame)) return I;
        const vec3 a = frame.to_local(p0 - P), b = frame.to_local(p1 - P);
        I.ltc = width(integrate_line(transformed<clamped_cosine<T>>::from_inverse(m_inv), a, b));
        I.form_factor = width(integrate_line_cosine(a, b));
        return I;
    }
    template <typename Policy>
    T ltc_integral(const shading_frame<T>& frame, const vec3& P, const glm::mat<3, 3, T>& m_inv,
                   const shade_options&) const {
        if (!usable(frame)) return T(0);
        return width(integrate_line(transformed<clamped_cosine<T>>::from_inverse(m_inv), frame.to_local(p0 - P),
                                    frame.to_local(p1 - P)));
    }
    vec3 emitted(const vec3& scale, T integral) const { return radiance * scale * integral; }

private:
    bool usable(const shading_frame<T>& frame) const {
        return frame.valid && radius > T(0) && radius <= std::numeric_limits<T>::max();
    }
    // 2 r I, saturated at the largest finite value (a huge r times I; 0 times an infinite 2r
    // would be NaN).
    T width(T i) const {
        if (!(i > T(0))) return T(0);
        const T w = radius * i;
        return w < std::numeric_limits<T>::max() / T(2) ? T(2) * w : std::numeric_limits<T>::max();
    }
};

LTC_NAMESPACE_END
