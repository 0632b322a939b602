// ltc/fitting/anisotropic_parameters.hpp -- the matrix that the anisotropic fit adjusts
// (anisotropic_parameters) and the canonical form of its inverse that a table stores
// (canonical_inverse), after Kt, Heitz, Dupuy and Narayanan 2022, "Bringing Linearly Transformed
// Cosines to Anisotropic GGX" (section 4: a full 3x3 matrix per node, made unique before
// interpolation).
#pragma once

#include <ltc/config.hpp>

#include <glm/glm.hpp>

#include <cmath>

// Invariances. The LTC of M (eq. 1 of Heitz et al. 2016) does not change under M -> s M (s > 0)
// nor under M -> M Q for Q a rotation about z or a mirror through a vertical plane (the clamped
// cosine is invariant under both). So 7 of M's 9 numbers matter: the fit writes
//
//   M = R * B,  B = [m11 m12 m13; 0 m22 m23; m31 m32 1]   (rows; m11, m22 > 0, det B > 0)
//
// with R the rotation about the axis z x a that takes +z to the BRDF's average direction a (the
// right rotation about z is spent on B[1][0] = 0; the isotropic fitter's matrix is the case
// m12 = m23 = m32 = 0, a in the xz-plane).
//
// Canonical form of the inverse (canonical_inverse; a table stores its inverse, canonical_matrix): of the matrices
// Q m_inv (Q a rotation about z, or a mirror, acting on the rows) of one LTC, the one with
// det > 0 whose upper-left 2x2 block is symmetric with the largest trace, scaled so that trace
// is 2. Unique unless that block is 0 (never for an invertible LTC of a lobe above the horizon),
// continuous in m_inv, and equivariant under the BRDF's symmetries: for a lobe rotated by
// R_z(phi), R m_inv R^T is canonical when m_inv is, so the isotropic table rotated by phi_v is
// already in this form, and so are the mirrors F m_inv F and the swap S m_inv S of
// ltc/tables/anisotropic_table.hpp. Kt et al. instead search the rotation that brings M closest
// to the identity; this closed form needs no search.
//
// Degenerate cases: canonical_inverse of a matrix whose block is 0 only fixes det > 0 and scales
// the third row to unit length; full_inverse reports a singular or non-finite input (ok = false).

LTC_NAMESPACE_BEGIN
namespace fit {

/// Inverse and |det| of a general 3x3 matrix by cofactors (the fit's own arithmetic, so that the
/// table's bits depend on the fitting headers and the BRDF only).
struct full_inverse_result {
    glm::dmat3 inverse{1.0};
    double abs_determinant = 1;  ///< |det| of the input
    bool ok = true;              ///< false for a singular or non-finite input
};

inline full_inverse_result full_inverse(const glm::dmat3& m) {
    const glm::dvec3 r0 = glm::cross(m[1], m[2]);
    const glm::dvec3 r1 = glm::cross(m[2], m[0]);
    const glm::dvec3 r2 = glm::cross(m[0], m[1]);
    const double det = glm::dot(m[0], r0);
    full_inverse_result r;
    r.inverse = glm::transpose(glm::dmat3(r0, r1, r2)) * (1.0 / det);
    r.abs_determinant = std::abs(det);
    r.ok = det != 0 && std::isfinite(det);
    for (int c = 0; c < 3; ++c)
        for (int w = 0; w < 3; ++w) r.ok = r.ok && std::isfinite(r.inverse[c][w]);
    return r;
}

/// The rotation about z x a (the shortest one) that takes +z to the unit vector a (a.z > -1):
/// I + K + K^2 / (1 + a.z), K the cross-product matrix of (-a.y, a.x, 0).
inline glm::dmat3 rotation_to(const glm::dvec3& a) {
    const double k = 1.0 / (1.0 + a.z);
    // GLM columns: R e_x, R e_y, R e_z = a.
    return glm::dmat3(glm::dvec3(1.0 - a.x * a.x * k, -a.x * a.y * k, -a.x),
                      glm::dvec3(-a.x * a.y * k, 1.0 - a.y * a.y * k, -a.y), a);
}

/// M = rotation_to(axis) * [m11 m12 m13; 0 m22 m23; m31 m32 1] (rows): the file comment.
struct anisotropic_parameters {
    double m11 = 1, m22 = 1, m12 = 0, m13 = 0, m23 = 0, m31 = 0, m32 = 0;
    glm::dvec3 axis{0, 0, 1};  ///< unit, axis.z > 0

    glm::dmat3 block() const {
        return glm::dmat3(glm::dvec3(m11, 0, m31), glm::dvec3(m12, m22, m32), glm::dvec3(m13, m23, 1));
    }
    glm::dmat3 matrix() const { return rotation_to(axis) * block(); }
};

/// The canonical form of an inverse LTC matrix (the file comment): det > 0 (else row 1 negated),
/// then the rotation about z on the rows that makes the upper-left block symmetric with the
/// largest trace, then the scale that makes that trace 2.
inline glm::dmat3 canonical_inverse(glm::dmat3 m) {
    if (glm::determinant(m) < 0)
        for (int c = 0; c < 3; ++c) m[c][1] = -m[c][1];
    // Row-major block A(r, c) = m[c][r]; Q = [cs sn; -sn cs] on rows 0 and 1.
    const double ct = m[0][0] + m[1][1];
    const double st = m[0][1] - m[1][0];
    const double h = std::sqrt(ct * ct + st * st);
    if (!(h > 0) || !std::isfinite(h)) {
        const double l = std::sqrt(m[0][2] * m[0][2] + m[1][2] * m[1][2] + m[2][2] * m[2][2]);
        return l > 0 ? m * (1.0 / l) : m;
    }
    const double cs = ct / h, sn = st / h;
    glm::dmat3 r;
    for (int c = 0; c < 3; ++c) {
        r[c][0] = cs * m[c][0] + sn * m[c][1];
        r[c][1] = cs * m[c][1] - sn * m[c][0];
        r[c][2] = m[c][2];
    }
    return r * (2.0 / h);
}

/// What a table stores of a canonical inverse m_inv: M = m_inv^-1 scaled to |M e_z| = 1 (Kt et
/// al.'s normalization: M's third column, the direction of the cosine's peak, is a unit vector).
/// Interpolating M rather than m_inv (as their shader does) follows the lobe's shape more
/// linearly between nodes (tools/anisotropic_error_report measures both).
inline glm::dmat3 canonical_matrix(const glm::dmat3& m_inv) {
    const glm::dmat3 M = full_inverse(m_inv).inverse;
    const double l = glm::length(M[2]);
    return l > 0 ? M * (1.0 / l) : M;
}

}  // namespace fit
LTC_NAMESPACE_END
