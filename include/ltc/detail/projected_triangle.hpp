// ltc/detail/projected_triangle.hpp -- sampling a spherical triangle in the upper hemisphere with
// density proportional to the clamped cosine w.z (projected solid angle), exactly: the triangle
// piece of ltc/core/projected_solid_angle_sampling.hpp, where the method is described.
//
// Geodesic polar coordinates about the apex a: the direction at angle psi from the side ab is
// P(psi) = cos psi t_b + sin psi t_c (t_b, t_c an orthonormal basis of a's tangent plane, t_b
// towards b), the point at arc length s along it w = cos s a + sin s P, and d omega = sin s ds
// d psi. With z(s) = a.z cos s + P.z sin s:
//   F(psi)  = projected solid angle of the sub-triangle (a, b, c(psi)), c(psi) on the arc bc:
//             Lambert's (1/2) sum over its three edges of theta_e n_e.z, the edge terms of the
//             paper's eq. (11), in closed form;
//   F'(psi) = W(L(psi)),  W(s) = int_0^s z sin = a.z sin^2 s / 2 + P.z (s - sin s cos s) / 2,
//   L(psi)  = the arc length from a to the great circle bc: tan L = -(a.n) / (P.n), n its normal.
// Sampling solves F(psi) = u.x F(alpha) and then W(s) = u.y W(L(psi)) by Newton's method kept
// inside a bisection bracket (both are monotone); inversion evaluates F and W directly.
#pragma once

#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <cmath>

namespace ltc {
namespace detail {

/// x - sin x for x >= 0 without cancellation: its Taylor series below 1/2 (terms to x^15; the
/// next is below 1e-17 of the sum), the plain difference above (relative error <= 24 epsilon).
template <typename T>
LTC_HOST_DEVICE inline T x_minus_sin(T x) {
    if (x < T(0.5)) {
        const T x2 = x * x;
        T s = T(1) - x2 / T(210);
        s = T(1) - x2 / T(156) * s;
        s = T(1) - x2 / T(110) * s;
        s = T(1) - x2 / T(72) * s;
        s = T(1) - x2 / T(42) * s;
        s = T(1) - x2 / T(20) * s;
        return x * x2 / T(6) * s;
    }
    return x - std::sin(x);
}

/// W(s) = int_0^s (az cos t + pz sin t) sin t dt: the projected solid angle per unit psi of the
/// wedge's first s radians (file comment).
template <typename T>
LTC_HOST_DEVICE inline T wedge_mass(T s, T az, T pz) {
    const T sn = std::sin(s);
    return az * sn * sn / T(2) + pz * x_minus_sin(T(2) * s) / T(4);
}

/// The precomputed triangle (a, b, c): everything the solves need that does not depend on u.
template <typename T>
struct projected_triangle {
    using vec3 = glm::vec<3, T>;
    vec3 a{T(0), T(0), T(1)};
    vec3 t_b{T(1), T(0), T(0)}, t_c{T(0), T(1), T(0)};  // tangent basis at a
    T alpha{0};           // interior angle at a
    T dist_a{0};          // |a . n|, n the unit normal of the great circle bc
    T n_b{0}, n_c{0};     // t_b . n and t_c . n, with n's sign making a . n >= 0
    T k_b{0}, k_c{0};     // (a x t_b).z and (a x t_c).z: (a x P(psi)).z is their combination
    T n_bc_z{0};          // z of the unit normal of b -> c
    T theta_ab{0};        // L(0), the side ab (so that F(0) = 0 exactly)
    T beta_b{0};          // position(1, 0): b on the great circle bc
    T sign{1};            // makes F increasing
    T mass{0};            // F(alpha): the triangle's projected solid angle

    struct point {
        T psi, length;  // psi, L(psi)
        vec3 p;         // P(psi)
        T value;        // F(psi)
        T scale;        // the sum of the edge terms' magnitudes: F's rounding error is ~epsilon scale
    };

    LTC_HOST_DEVICE projected_triangle() = default;

    /// Unit a, b, c with z >= 0, the sides shorter than pi (the projection of a planar triangle
    /// that does not contain the origin). A degenerate triangle gets mass 0.
    LTC_HOST_DEVICE projected_triangle(const vec3& a_, const vec3& b, const vec3& c) : a(a_) {
        // Tangents from a x b and differences c - a: accurate for tiny triangles too.
        t_b = safe_normalize(glm::cross(stable_cross(a, b, glm::dot(a, b)), a));
        t_c = glm::cross(a, t_b);
        const vec3 ca = c - a;
        if (glm::dot(ca, t_c) < T(0)) t_c = -t_c;
        alpha = std::atan2(glm::dot(ca, t_c), glm::dot(ca, t_b));
        vec3 n = safe_normalize(stable_cross(b, c, glm::dot(b, c)));
        n_bc_z = n.z;
        dist_a = glm::dot(a - b, n);
        if (dist_a < T(0)) n = -n, dist_a = -dist_a;
        n_b = glm::dot(t_b, n);
        n_c = glm::dot(t_c, n);
        k_b = glm::cross(a, t_b).z;
        k_c = glm::cross(a, t_c).z;
        if (!(alpha > T(0)) || !(dist_a > T(0)) || t_b == vec3(T(0))) return;  // degenerate
        theta_ab = arc(T(1), T(0));
        beta_b = position(T(1), T(0));
        const T s = signed_value(alpha).value;
        sign = s < T(0) ? T(-1) : T(1);
        mass = std::abs(s);
        if (!std::isfinite(mass)) mass = T(0);
    }

    LTC_HOST_DEVICE T arc(T cos_psi, T sin_psi) const {
        return std::atan2(dist_a, -(cos_psi * n_b + sin_psi * n_c));
    }

    /// S(psi) = 2 F(psi) up to the sign: theta_ab (a x b).z + theta(b, c(psi)) n_bc.z
    /// - L(psi) (a x P(psi)).z, the three edges a -> b -> c(psi) -> a.
    LTC_HOST_DEVICE point signed_value(T psi) const {
        const T cp = std::cos(psi), sp = std::sin(psi);
        point r;
        r.psi = psi;
        r.p = cp * t_b + sp * t_c;
        r.length = arc(cp, sp);
        const T t1 = theta_ab * k_b, t2 = side_angle(cp, sp) * n_bc_z, t3 = r.length * (cp * k_b + sp * k_c);
        r.value = (t1 + t2 - t3) / T(2);
        r.scale = (std::abs(t1) + std::abs(t2) + std::abs(t3)) / T(2);
        return r;
    }

    /// Position of c(psi) along the great circle bc: the angle beta from the foot f of the
    /// perpendicular from a (Napier's rule for the right triangle a f c(psi): tan beta = sin(d)
    /// tan(phi), d = |af|, phi the angle at a from af). theta(b, c(psi)) = |beta(psi) - beta(0)|
    /// is then a difference of two angles of size h with relative errors epsilon: epsilon / h
    /// relative to the projected solid angle of a triangle of size h, where the chord from b to
    /// c(psi) in absolute coordinates gives epsilon / h^2 (0.2 in float for h = 5e-4, found by
    /// the tests), and exactly 0 at psi = 0.
    LTC_HOST_DEVICE T position(T cos_psi, T sin_psi) const {
        return std::atan2(dist_a * (cos_psi * n_c - sin_psi * n_b), -(cos_psi * n_b + sin_psi * n_c));
    }

    LTC_HOST_DEVICE T side_angle(T cos_psi, T sin_psi) const {
        T d = position(cos_psi, sin_psi) - beta_b;
        if (d > pi<T>()) d -= T(2) * pi<T>();
        if (d < -pi<T>()) d += T(2) * pi<T>();
        return std::abs(d);
    }

    LTC_HOST_DEVICE point at(T psi) const {
        point r = signed_value(psi);
        r.value *= sign;
        return r;
    }

    /// The direction at arc length s along P from a.
    LTC_HOST_DEVICE vec3 direction(const point& q, T s) const { return std::cos(s) * a + std::sin(s) * q.p; }

    /// Solves F(psi) = u1 mass, then W(s) = u2 W(L(psi)); `evaluations` counts the evaluations
    /// of F (each with its derivative) and of W.
    LTC_HOST_DEVICE vec3 sample(T u1, T u2, int& evaluations) const {
        const point q = solve_psi(u1, evaluations);
        const T s = solve_arc(q, u2, evaluations);
        return direction(q, s);
    }

    /// (u1, u2) with sample(u1, u2) = w, for w in the triangle.
    LTC_HOST_DEVICE glm::vec<2, T> invert(const vec3& w) const {
        const vec3 wa = w - a;  // tangent coordinates, accurate near a
        const T x = glm::dot(wa, t_b), y = glm::dot(wa, t_c);
        const T psi = glm::clamp(std::atan2(y, x), T(0), alpha);
        const point q = at(psi);
        const T s = std::atan2(std::sqrt(x * x + y * y), glm::dot(w, a));
        const T total = wedge_mass(q.length, a.z, q.p.z);
        const T u1 = mass > T(0) ? q.value / mass : T(0);
        const T u2 = total > T(0) ? wedge_mass(glm::min(s, q.length), a.z, q.p.z) / total : T(0);
        return glm::clamp(glm::vec<2, T>(u1, u2), T(0), T(1));
    }

  private:
    static constexpr int max_iterations = 40;

    // Both functions are increasing; Newton steps that leave the bracket are replaced by
    // bisection, so every iteration shrinks the bracket and the solve cannot diverge.
    LTC_HOST_DEVICE point solve_psi(T u1, int& evaluations) const {
        const T target = u1 * mass;
        // Start: F' varying linearly from F'(0) to F'(alpha), rescaled so that the model ends at
        // the mass (x = psi / alpha solves q x^2 + r x = u1 (q + r)).
        const T d0 = wedge_mass(theta_ab, a.z, t_b.z);
        const point end{alpha, arc(std::cos(alpha), std::sin(alpha)), std::cos(alpha) * t_b + std::sin(alpha) * t_c, mass, mass};
        const T d1 = wedge_mass(end.length, a.z, end.p.z);
        const T r = d0, q = (d1 - d0) / T(2), rhs = u1 * (q + r);
        const T den = r + safe_sqrt(r * r + T(4) * q * rhs);
        T lo = T(0), hi = alpha;
        T psi = den > T(0) ? alpha * glm::clamp(T(2) * rhs / den, T(0), T(1)) : u1 * alpha;
        point p = end;
        for (int i = 0; i < max_iterations; ++i) {
            p = at(psi);
            ++evaluations;
            const T f = p.value - target;
            // Within F's own rounding (epsilon / h relative for a triangle of size h): done.
            if (std::abs(f) <= T(4) * epsilon<T>() * glm::max(mass, p.scale)) break;
            (f < T(0) ? lo : hi) = psi;
            const T slope = wedge_mass(p.length, a.z, p.p.z);
            T next = slope > T(0) ? psi - f / slope : T(0);
            if (!(next > lo && next < hi)) next = (lo + hi) / T(2);
            if (next == psi || hi - lo <= epsilon<T>() * alpha) break;
            psi = next;
        }
        return p;
    }

    LTC_HOST_DEVICE T solve_arc(const point& q, T u2, int& evaluations) const {
        const T az = a.z, pz = q.p.z, length = q.length;
        const T target = u2 * wedge_mass(length, az, pz);
        const T tol = T(4) * epsilon<T>() * target;
        // Start: uniform in solid angle along the arc, 1 - cos s = 2 sin^2(s / 2) proportional
        // to u2 (in half angles: no cancellation for short arcs).
        T s = T(2) * std::asin(glm::min(T(1), std::sqrt(u2) * std::sin(length / T(2))));
        T lo = T(0), hi = length;
        for (int i = 0; i < max_iterations; ++i) {
            const T f = wedge_mass(s, az, pz) - target;
            ++evaluations;
            if (std::abs(f) <= tol) break;
            (f < T(0) ? lo : hi) = s;
            const T sn = std::sin(s);
            const T slope = sn * (az * std::cos(s) + pz * sn);
            T next = slope > T(0) ? s - f / slope : T(0);
            if (!(next > lo && next < hi)) next = (lo + hi) / T(2);
            if (next == s || hi - lo <= epsilon<T>() * length) break;
            s = next;
        }
        return glm::clamp(s, T(0), length);
    }
};

}  // namespace detail
}  // namespace ltc
