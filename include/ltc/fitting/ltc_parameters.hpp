// ltc/fitting/ltc_parameters.hpp -- the matrix that the fit adjusts (ltc_parameters, paper
// section 4), and the fit's own arithmetic on it: the closed-form inverse of its structure
// (invert_structured, normalized_inverse), the cosine sampler of Algorithm 1 (sample_cosine),
// the LTC's density (ltc_density) and normalize_or_zero.
//
// M = R * [m11 0 m13; 0 m22 0; m31 0 1] (rows; GLM stores M[column][row]), R the rotation about y
// that takes +z to the BRDF's average direction: the paper's 4-parameter matrix [a 0 b; 0 c 0;
// d 0 1] written in the rotated frame, the general matrix of an isotropic BRDF up to scale.
//
// This arithmetic is the fit's own, rather than the library's (ltc/core/), so that changes
// elsewhere in the library do not move the bits of a generated table.
#pragma once

#include <ltc/config.hpp>

#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

LTC_NAMESPACE_BEGIN
namespace fit {

/// v / |v|, or 0 for v = 0 (local, so that the fit depends on no other header's rounding).
inline glm::dvec3 normalize_or_zero(const glm::dvec3& v) {
    const double l2 = glm::dot(v, v);
    return l2 > 0 ? v / std::sqrt(l2) : glm::dvec3(0.0);
}

/// M = R * [m11 0 m13; 0 m22 0; m31 0 1] with R the rotation about y taking +z to `axis`.
///
/// What is fitted. For a view direction V = (sin theta_v, 0, cos theta_v) (local frame N = +z)
/// and a roughness alpha, the spherical function f(L) = rho(V, L) cos(theta_L) (Brdf::eval) is
/// approximated by magnitude * D(L), D the linearly transformed cosine of the matrix
///
///   M = R * [m11 0 m13; 0 m22 0; m31 0 1]     (rows; GLM stores M[column][row])
///
/// where R is the rotation about y that takes +z to the BRDF's average direction (the direction
/// of the integral of f(L) L, y component zeroed). That is the paper's 4-parameter matrix
/// [a 0 b; 0 c 0; d 0 1] written in the rotated frame: the general matrix of an isotropic BRDF
/// up to scale. (The paper's code release keeps m31 = 0 and fits 3 parameters; options::
/// parameters = 3 does the same.) At normal incidence the lobe is rotationally symmetric and
/// M = diag(m, m, 1) has one parameter.
struct ltc_parameters {
    double m11 = 1, m22 = 1, m13 = 0, m31 = 0;
    glm::dvec3 axis{0, 0, 1};  ///< unit, in the xz-plane

    glm::dmat3 matrix() const {
        const glm::dmat3 R(glm::dvec3(axis.z, 0, -axis.x), glm::dvec3(0, 1, 0), axis);
        const glm::dmat3 B(glm::dvec3(m11, 0, m31), glm::dvec3(0, m22, 0), glm::dvec3(m13, 0, 1));
        return R * B;
    }
};

/// Inverse and |det| of a matrix with the structure of an isotropic LTC, [a 0 b; 0 c 0; d 0 e]
/// (rows; GLM: a = m[0][0], b = m[2][0], c = m[1][1], d = m[0][2], e = m[2][2], the other four
/// elements 0): [e 0 -b; 0 (ae - bd)/c 0; -d 0 a] / (ae - bd). Closed form, so that the fit's
/// numbers (and the shipped table's bits) depend on nothing but the fitting headers and the BRDF.
struct structured_inverse {
    glm::dmat3 inverse{1.0};
    double abs_determinant = 1;  ///< |det| of the *input* matrix
    bool ok = true;              ///< false for a singular or non-finite input
};

inline structured_inverse invert_structured(const glm::dmat3& m) {
    const double a = m[0][0], b = m[2][0], c = m[1][1], d = m[0][2], e = m[2][2];
    const double det2 = a * e - b * d;
    structured_inverse r;
    r.inverse = glm::dmat3(0.0);
    r.inverse[0][0] = e / det2;
    r.inverse[2][0] = -b / det2;
    r.inverse[0][2] = -d / det2;
    r.inverse[2][2] = a / det2;
    r.inverse[1][1] = 1.0 / c;
    r.abs_determinant = std::abs(det2 * c);
    r.ok = det2 != 0 && c != 0 && std::isfinite(r.abs_determinant) && std::isfinite(r.inverse[0][0]) &&
           std::isfinite(r.inverse[2][0]) && std::isfinite(r.inverse[0][2]) && std::isfinite(r.inverse[2][2]) &&
           std::isfinite(r.inverse[1][1]) && r.abs_determinant > 0;
    return r;
}

/// The inverse of M (structured, see invert_structured) divided by its middle element
/// M^-1[1][1] = 1 / M[1][1]: [e c, -b c; -d c, a c] / (ae - bd) in the xz-block, 1 in the middle.
inline glm::dmat3 normalized_inverse(const glm::dmat3& M) {
    glm::dmat3 mi = invert_structured(M).inverse;
    const double c = M[1][1];
    mi[0][0] *= c;
    mi[2][0] *= c;
    mi[0][2] *= c;
    mi[2][2] *= c;
    mi[1][1] = 1;
    return mi;
}

/// Direction of the clamped cosine for u in [0, 1)^2 (Algorithm 1's D_o sampler, as
/// ltc::clamped_cosine): cos theta = sqrt(1 - u.x), phi = 2 pi u.y.
inline glm::dvec3 sample_cosine(const glm::dvec2& u) {
    const double cos_theta = std::sqrt(1.0 - u.x);
    const double sin_theta = std::sqrt(u.x);
    const double phi = 2.0 * pi<double>() * u.y;
    return glm::dvec3(std::cos(phi) * sin_theta, std::sin(phi) * sin_theta, cos_theta);
}

/// Density of the LTC of m_inv at the unit direction L (1 for the normalized distribution).
inline double ltc_density(const glm::dmat3& m_inv, double abs_det_inv, const glm::dvec3& L) {
    const glm::dvec3 w = m_inv * L;
    const double l2 = glm::dot(w, w);
    return l2 > 0 ? std::max(w.z, 0.0) * abs_det_inv / (pi<double>() * l2 * l2) : 0.0;
}

}  // namespace fit
LTC_NAMESPACE_END
