// ltc/reference/spherical_triangle.hpp -- uniform sampling of a spherical triangle by Arvo's
// method (Arvo 1995; pbrt-v4's arrangement): how the ground truth samples each fan triangle of
// a polygon light (ltc/reference/spherical_polygon.hpp).
//
//   ltc::ground_truth::spherical_triangle_sampler s(a, b, c);   // unit vectors
//   glm::dvec3 w = s.sample(u);                                 // density 1 / s.solid_angle()
#pragma once

#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <cmath>

namespace ltc {
namespace ground_truth {

/// Uniform sampling of the spherical triangle (a, b, c) of unit vectors by Arvo's method (Arvo
/// 1995; pbrt-v4's arrangement), with everything that does not depend on the sample computed
/// once. Either orientation; the density is 1 / (solid angle).
class spherical_triangle_sampler {
  public:
    spherical_triangle_sampler(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) : a_(a), b_(b) {
        using glm::dvec3;
        dvec3 n_ab = glm::cross(a, b), n_bc = glm::cross(b, c), n_ca = glm::cross(c, a);
        const double lab = glm::length(n_ab), lbc = glm::length(n_bc), lca = glm::length(n_ca);
        if (!(lab > 0.0) || !(lbc > 0.0) || !(lca > 0.0)) return;  // coincident vertices
        n_ab /= lab;
        n_bc /= lbc;
        n_ca /= lca;
        // Angle between unit vectors by 2 asin(|x -+ y| / 2) (accurate at every angle).
        const auto angle = [](const dvec3& x, const dvec3& y) {
            return glm::dot(x, y) < 0.0 ? pi<double>() - 2.0 * std::asin(glm::min(1.0, glm::length(x + y) / 2.0))
                                        : 2.0 * std::asin(glm::min(1.0, glm::length(x - y) / 2.0));
        };
        const double alpha = angle(n_ab, -n_ca);  // interior angles at a, b, c
        const double beta = angle(n_bc, -n_ab);
        const double gamma = angle(n_ca, -n_bc);
        area_ = alpha + beta + gamma - pi<double>();
        cos_alpha_ = std::cos(alpha);
        sin_alpha_ = std::sin(alpha);
        cos_c_ = glm::dot(a, b);
        c_perp_ = detail::safe_normalize(c - glm::dot(c, a) * a);
        valid_ = true;
    }

    /// Solid angle from the interior angles (Girard's theorem).
    double solid_angle() const { return valid_ ? area_ : 0.0; }

    /// u.x sets the solid angle of the sub-triangle (a, b, c') with c' on the arc from a to c,
    /// u.y the position on the arc from b to c'. Degenerate triangles return a.
    glm::dvec3 sample(const glm::dvec2& u) const {
        if (!valid_) return a_;
        const double sub_pi = pi<double>() + u.x * area_;  // sampled area + pi
        const double s = std::sin(sub_pi), c = std::cos(sub_pi);
        const double sin_phi = s * cos_alpha_ - c * sin_alpha_;
        const double cos_phi = c * cos_alpha_ + s * sin_alpha_;
        const double k1 = cos_phi + cos_alpha_;
        const double k2 = sin_phi - sin_alpha_ * cos_c_;
        const double den = (k2 * sin_phi + k1 * cos_phi) * sin_alpha_;
        double cos_bp = den != 0.0 ? (k2 + (k2 * cos_phi - k1 * sin_phi) * cos_alpha_) / den : 1.0;
        cos_bp = glm::clamp(cos_bp, -1.0, 1.0);
        const double sin_bp = std::sqrt(glm::max(0.0, 1.0 - cos_bp * cos_bp));
        const glm::dvec3 cp = cos_bp * a_ + sin_bp * c_perp_;  // c' on the arc from a towards c
        // Uniform in the sub-triangle's new area: cos(theta) along the arc from b to c'.
        const double cos_theta = 1.0 - u.y * (1.0 - glm::dot(cp, b_));
        const double sin_theta = std::sqrt(glm::max(0.0, 1.0 - cos_theta * cos_theta));
        const glm::dvec3 cp_perp = detail::safe_normalize(cp - glm::dot(cp, b_) * b_);
        return detail::safe_normalize(cos_theta * b_ + sin_theta * cp_perp);
    }

  private:
    glm::dvec3 a_, b_, c_perp_{0.0};
    double area_ = 0.0, cos_alpha_ = 1.0, sin_alpha_ = 0.0, cos_c_ = 1.0;
    bool valid_ = false;
};

/// A uniformly distributed direction in the spherical triangle (a, b, c) of unit vectors, for
/// u in [0, 1)^2 (spherical_triangle_sampler, for a single sample).
inline glm::dvec3 sample_spherical_triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                                            const glm::dvec2& u) {
    return spherical_triangle_sampler(a, b, c).sample(u);
}

}  // namespace ground_truth
}  // namespace ltc
