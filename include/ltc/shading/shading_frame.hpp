// ltc/shading/shading_frame.hpp -- the local frame of a shading point, the one in which the LTC
// tables are fitted (paper section 4: N = +z, V in the xz-plane); the lights (ltc/shading/lights/)
// rotate their vertices into it.
//
//   ltc::shading_frame<float> f = ltc::make_shading_frame(N, V);
//   glm::vec3 local = f.to_local(p - P);   // p - P in (T1, T2, N); f.cos_theta_v for the table
//   f = ltc::make_tangent_frame(N, V, tangent);  // anisotropic tables: T1 along the tangent,
//   float phi_v = ltc::view_azimuth(f, V);       // and V's azimuth from it
//
// Conventions: T1 = normalize(V - N (V.N)), T2 = N x T1, a right-handed rotation (orientations are
// preserved); cos theta_v = clamp(N.V, 0, 1). Degenerate cases: V parallel to N takes any T1
// orthogonal to N; a view from below the surface is shaded as grazing (shading_frame).
#pragma once

#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <cmath>

LTC_NAMESPACE_BEGIN

/// The local shading frame (T1, T2, N) and cos theta_v of a shading point.
///
/// Frame. The LTC table is fitted in the local frame N = +z, V = (sin theta_v, 0, cos theta_v),
/// so the polygon is rotated into (T1, T2, N) with T1 = normalize(V - N (V.N)), T2 = N x T1 (a
/// right-handed rotation: orientations are preserved). V - N (V.N) is computed as N x (V x N)
/// with a cancellation-free V x N, so T1 is accurate and orthogonal to N even when V is within
/// an ulp of N. When V is exactly parallel to N the projection is the zero vector; then any T1
/// orthogonal to N is right, because at normal incidence the isotropic lobe is symmetric about
/// N, and T1 comes from the branch-free orthonormal basis of Duff et al. 2017 ("Building an
/// orthonormal basis, revisited", JCGT 6(1)). cos theta_v = clamp(N.V, 0, 1): a view from below
/// the surface (interpolated normals) is shaded as grazing.
template <typename T>
struct shading_frame {
    glm::vec<3, T> t1{T(1), T(0), T(0)};
    glm::vec<3, T> t2{T(0), T(1), T(0)};
    glm::vec<3, T> n{T(0), T(0), T(1)};
    T cos_theta_v{1};
    bool valid{true};  ///< false when N is the zero vector

    /// Coordinates of the world-space vector d in the frame: (d.T1, d.T2, d.N).
    LTC_HOST_DEVICE glm::vec<3, T> to_local(const glm::vec<3, T>& d) const {
        return glm::vec<3, T>(glm::dot(d, t1), glm::dot(d, t2), glm::dot(d, n));
    }
};

/// Duff et al. 2017, listing 3: a unit vector orthogonal to the unit vector n, branch-free
/// (copysign), continuous except across n.z = 0's sign change.
template <typename T>
LTC_HOST_DEVICE inline glm::vec<3, T> orthonormal_tangent(const glm::vec<3, T>& n) {
    const T sign = std::copysign(T(1), n.z);
    const T a = T(-1) / (sign + n.z);
    return glm::vec<3, T>(T(1) + sign * n.x * n.x * a, sign * n.x * n.y * a, -sign * n.x);
}

/// The frame of ltc's tables at a shading point: N = +z, V in the half-plane x > 0 of y = 0.
template <typename T>
LTC_HOST_DEVICE LTC_INLINE shading_frame<T> make_shading_frame(const glm::vec<3, T>& N, const glm::vec<3, T>& V) {
    shading_frame<T> f;
    const glm::vec<3, T> n = detail::safe_normalize(N);
    if (n == glm::vec<3, T>(T(0))) {
        f.valid = false;
        return f;
    }
    const glm::vec<3, T> v = detail::safe_normalize(V);
    const T nv = glm::dot(n, v);
    // V - N (V.N) as N x (V x N), with V x N from the cancellation-free cross product of
    // polygon.hpp: accurate relative to its own length even for V within an ulp of +-N, and
    // orthogonal to N to rounding (the plain difference is neither, there).
    glm::vec<3, T> t1 = detail::safe_normalize(glm::cross(n, detail::stable_cross(v, n, nv)));
    if (t1 == glm::vec<3, T>(T(0))) t1 = orthonormal_tangent(n);  // V = +-N exactly (or V = 0)
    f.n = n;
    f.t1 = t1;
    f.t2 = glm::cross(n, t1);
    f.cos_theta_v = glm::clamp(nv, T(0), T(1));
    return f;
}

/// The frame of the anisotropic tables at a shading point (ltc/tables/anisotropic_table.hpp):
/// N = +z and T1 = +x along `tangent` projected onto N's plane (T1 = normalize(N x (tangent x
/// N)), cancellation-free as make_shading_frame's), T2 = N x T1; V anywhere, at azimuth
/// view_azimuth(frame, V) from T1; cos theta_v = clamp(N.V, 0, 1). Degenerate tangent (zero, not
/// finite, or parallel to N): T1 = orthonormal_tangent(N), a fixed direction of N's plane, so the
/// result stays finite. A zero or non-finite N: valid = false, as make_shading_frame.
template <typename T>
LTC_HOST_DEVICE LTC_INLINE shading_frame<T> make_tangent_frame(const glm::vec<3, T>& N, const glm::vec<3, T>& V,
                                                               const glm::vec<3, T>& tangent) {
    shading_frame<T> f;
    const glm::vec<3, T> n = detail::safe_normalize(N);
    if (n == glm::vec<3, T>(T(0))) {
        f.valid = false;
        return f;
    }
    glm::vec<3, T> t1(T(0));
    const glm::vec<3, T> z = tangent - tangent;  // (0, 0, 0) for a finite tangent, else NaN
    if (z.x + z.y + z.z == T(0)) {
        const glm::vec<3, T> t = detail::safe_normalize(tangent);
        t1 = detail::safe_normalize(glm::cross(n, detail::stable_cross(t, n, glm::dot(t, n))));
    }
    if (t1 == glm::vec<3, T>(T(0))) t1 = orthonormal_tangent(n);
    f.n = n;
    f.t1 = t1;
    f.t2 = glm::cross(n, t1);
    f.cos_theta_v = glm::clamp(glm::dot(n, detail::safe_normalize(V)), T(0), T(1));
    return f;
}

/// phi_v, the azimuth of V from the frame's T1 towards T2, in (-pi, pi]; 0 for V along N.
template <typename T>
LTC_HOST_DEVICE inline T view_azimuth(const shading_frame<T>& f, const glm::vec<3, T>& V) {
    return std::atan2(glm::dot(V, f.t2), glm::dot(V, f.t1));
}

LTC_NAMESPACE_END
