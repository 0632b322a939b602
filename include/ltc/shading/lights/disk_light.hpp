// ltc/shading/lights/disk_light.hpp -- a constant-radiance disk light: each lobe's LTC
// (paper section 4) integrated exactly over the disk (Heitz and Hill 2017's
// disk lights, with ltc/core/ellipse_integral.hpp's exact clipped ellipse in place of their
// sphere approximation, which integrate_disk_2017 keeps for comparison).
//
//   auto disk = ltc::disk_light<float>::one_sided(centre, normal, radius, radiance);
//   ltc::shading_result<float> r = ltc::shade(surface, disk);   // ltc/shading/shade.hpp
//
//   diffuse  = albedo * radiance * E,   E = int_disk cos / pi        (integrate_disk, M = I)
//   specular = radiance * (F0 magnitude + (1 - F0) fresnel) * I_ltc  (integrate_disk, the GGX LTC)
//
// Conventions: world space; one-sided disks emit towards +normal, two-sided ones from both faces.
// Degenerate cases: finite results; radius <= 0 or NaN, a zero normal, or the point in the disk's
// plane (edge-on) give 0 (ltc/core/ellipse_integral.hpp).
#pragma once

#include <ltc/config.hpp>

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/ellipse_integral.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/shading/polygon_light_integrals.hpp>  // polygon_light_integrals
#include <ltc/shading/shading_frame.hpp>
#include <ltc/shading/surface.hpp>

#include <glm/glm.hpp>

LTC_NAMESPACE_BEGIN

/// A constant-radiance disk light. World space: the disk's centre, normal (any length) and
/// radius, and its radiance. One-sided disks emit towards +normal, two-sided ones from both
/// faces. Radius <= 0 or NaN, or a zero normal, is a disk that emits nothing. Both integrals are
/// exact to rounding (the horizon clipped exactly); the shading's error is the GGX fit's
/// (tools/shape_error_report, docs/results/shape_error.md: against Monte Carlo of the real
/// GGX). Degenerate input gives finite results: radius <= 0, the point in the disk's plane
/// (edge-on) give 0; see ltc/core/ellipse_integral.hpp.
template <typename T>
class disk_light {
public:
    using vec3 = glm::vec<3, T>;

    static disk_light one_sided(const vec3& centre, const vec3& normal, T radius, const vec3& radiance) {
        return disk_light(centre, normal, radius, radiance, sidedness::one_sided);
    }
    static disk_light two_sided(const vec3& centre, const vec3& normal, T radius, const vec3& radiance) {
        return disk_light(centre, normal, radius, radiance, sidedness::two_sided);
    }

    const vec3& centre() const { return centre_; }
    const vec3& normal() const { return normal_; }
    T radius() const { return radius_; }
    const vec3& radiance() const { return radiance_; }
    sidedness sides() const { return side_; }

    // The light interface of ltc::shade (ltc/shading/lights/polygon_light.hpp).
    template <typename Policy>
    polygon_light_integrals<T> integrals(const shading_frame<T>& frame, const vec3& P, const glm::mat<3, 3, T>& m_inv,
                                         const shade_options&) const {
        return integrals(frame, P, m_inv, centre_, normal_, radius_, side_);
    }
    template <typename Policy>
    T ltc_integral(const shading_frame<T>& frame, const vec3& P, const glm::mat<3, 3, T>& m_inv,
                   const shade_options&) const {
        if (!frame.valid) return T(0);
        return integrate_disk(transformed<clamped_cosine<T>>::from_inverse(m_inv), frame.to_local(centre_ - P),
                              frame.to_local(normal_), radius_, side_);
    }
    vec3 emitted(const vec3& scale, T integral) const { return radiance_ * scale * integral; }

    /// Both integrals of a disk (centre, normal, radius) seen from P (the sphere light's, too).
    static polygon_light_integrals<T> integrals(const shading_frame<T>& frame, const vec3& P,
                                                const glm::mat<3, 3, T>& m_inv, const vec3& centre, const vec3& normal,
                                                T radius, sidedness side) {
        polygon_light_integrals<T> I;
        if (!frame.valid) return I;
        const vec3 c = frame.to_local(centre - P), n = frame.to_local(normal);
        I.ltc = integrate_disk(transformed<clamped_cosine<T>>::from_inverse(m_inv), c, n, radius, side);
        I.form_factor =
            integrate_disk(transformed<clamped_cosine<T>>::from_inverse(glm::mat<3, 3, T>(T(1))), c, n, radius, side);
        return I;
    }

private:
    disk_light(const vec3& centre, const vec3& normal, T radius, const vec3& radiance, sidedness side)
        : centre_(centre), normal_(normal), radius_(radius), radiance_(radiance), side_(side) {}

    vec3 centre_, normal_;
    T radius_;
    vec3 radiance_;
    sidedness side_;
};

LTC_NAMESPACE_END
