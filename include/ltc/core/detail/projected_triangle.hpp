// ltc/core/detail/projected_triangle.hpp -- sampling a spherical triangle in the upper hemisphere with
// density proportional to the clamped cosine w.z (projected solid angle), exactly: the triangle
// piece of ltc/core/projected_solid_angle_sampling.hpp (projected_polygon_sampler: the method).
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

LTC_NAMESPACE_BEGIN
namespace detail {

/// x - sin x for x >= 0, given sin x, without cancellation: its Taylor series below 1/2, the
/// plain difference above (relative error <= 24 epsilon). The series' terms go to x^15 in double
/// and x^9 in float (the first term left out is below 1e-17, resp. 1e-9, of the sum), with the
/// reciprocals of the factorial ratios as constants (no division).
template <typename T>
LTC_HOST_DEVICE inline T x_minus_sin(T x, T sin_x) {
    if (x < T(0.5)) {
        const T x2 = x * x;
        T s = T(1);
        if constexpr (sizeof(T) > sizeof(float)) {
            s = T(1) - x2 * T(1.0 / 210) * s;
            s = T(1) - x2 * T(1.0 / 156) * s;
            s = T(1) - x2 * T(1.0 / 110) * s;
        }
        s = T(1) - x2 * T(1.0 / 72) * s;
        s = T(1) - x2 * T(1.0 / 42) * s;
        s = T(1) - x2 * T(1.0 / 20) * s;
        return x * x2 * T(1.0 / 6) * s;
    }
    return x - sin_x;
}

/// W(s) = int_0^s (az cos t + pz sin t) sin t dt, the projected solid angle per unit psi of the
/// wedge's first s radians (file comment), and its first two derivatives; sn, cs = sin s, cos s.
template <typename T>
struct wedge {
    T mass, slope, curve;
    LTC_HOST_DEVICE wedge(T s, T sn, T cs, T az, T pz)
        : mass(az * sn * sn / T(2) + pz * x_minus_sin(T(2) * s, T(2) * sn * cs) / T(4)),
          slope(sn * (az * cs + pz * sn)),
          curve(az * (cs * cs - sn * sn) + pz * T(2) * sn * cs) {}
};

/// One step of Halley's method for f with derivatives f1, f2 (cubic convergence; the solves below
/// get within 4 epsilon of the target in 2 to 3 steps from their starting points), or Newton's
/// where Halley's correction is large (far from the root), inside the bracket (lo, hi) or its
/// midpoint when the step leaves it: every step shrinks the bracket, so the solve cannot diverge.
template <typename T>
LTC_HOST_DEVICE inline T halley_step(T x, T f, T f1, T f2, T lo, T hi) {
    T next = lo;
    if (f1 > T(0)) {
        const T newton = f / f1;
        const T d = T(1) - newton * f2 / (T(2) * f1);
        next = x - (d > T(0.5) && d < T(2) ? newton / d : newton);
    }
    return next > lo && next < hi ? next : (lo + hi) / T(2);
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
    T condition{0};       // (sum of the edge terms' magnitudes) / mass: F's relative error / epsilon
    T slope_0{0}, slope_alpha{0};  // F'(0), F'(alpha): the start of the psi solve

    struct point {
        T cos_psi, sin_psi;
        T length, sin_length, cos_length;  // L(psi)
        vec3 p;                            // P(psi)
        T value;                           // F(psi)
        T scale;  // the sum of the edge terms' magnitudes: F's rounding error is ~epsilon scale
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
        // Degenerate: a within rounding of the great circle bc (dist_a errs by up to 5 epsilon
        // |a - b|: n's direction 6 u, a - b and the dot 4 u), where L(psi) = atan2(dist_a, -P.n)
        // would be a ratio of rounding errors; the triangle is flat to rounding (mass 0).
        if (!(alpha > T(0)) || !(dist_a > T(8) * epsilon<T>() * glm::length(a - b)) || t_b == vec3(T(0))) return;
        theta_ab = arc(T(1), T(0));
        beta_b = position(T(1), T(0));
        const point end = signed_value(alpha);
        sign = end.value < T(0) ? T(-1) : T(1);
        mass = std::abs(end.value);
        if (!std::isfinite(mass)) mass = T(0);
        condition = mass > T(0) ? end.scale / mass : T(0);
        slope_0 = wedge<T>(theta_ab, std::sin(theta_ab), std::cos(theta_ab), a.z, t_b.z).mass;
        slope_alpha = wedge_at(end).mass;
    }

    LTC_HOST_DEVICE T arc(T cos_psi, T sin_psi) const {
        return std::atan2(dist_a, -(cos_psi * n_b + sin_psi * n_c));
    }

    /// S(psi) = 2 F(psi) up to the sign: theta_ab (a x b).z + theta(b, c(psi)) n_bc.z
    /// - L(psi) (a x P(psi)).z, the three edges a -> b -> c(psi) -> a.
    LTC_HOST_DEVICE point signed_value(T psi) const {
        point r;
        r.cos_psi = std::cos(psi);
        r.sin_psi = std::sin(psi);
        const T cp = r.cos_psi, sp = r.sin_psi;
        r.p = cp * t_b + sp * t_c;
        // tan L = a.n / -(P.n): sin L and cos L from the same two numbers, without a sine call.
        const T x = -(cp * n_b + sp * n_c), h = std::sqrt(x * x + dist_a * dist_a);
        r.length = std::atan2(dist_a, x);
        r.sin_length = h > T(0) ? dist_a / h : T(0);
        r.cos_length = h > T(0) ? x / h : T(1);
        const T t1 = theta_ab * k_b, t2 = side_angle(cp, sp) * n_bc_z, t3 = r.length * (cp * k_b + sp * k_c);
        r.value = (t1 + t2 - t3) / T(2);
        r.scale = (std::abs(t1) + std::abs(t2) + std::abs(t3)) / T(2);
        return r;
    }

    /// F'(psi) = W(L(psi)) with P.z = P(psi).z, and F''(psi) = W'(L) L'(psi) + dW/dP.z dP.z/dpsi
    /// (L' = (a.n) (dP/dpsi . n) / ((a.n)^2 + (P.n)^2), dW/dP.z = (2L - sin 2L) / 4).
    LTC_HOST_DEVICE wedge<T> wedge_at(const point& q) const { return wedge<T>(q.length, q.sin_length, q.cos_length, a.z, q.p.z); }

    LTC_HOST_DEVICE void derivatives(const point& q, T& f1, T& f2) const {
        const wedge<T> w = wedge_at(q);
        f1 = w.mass;
        const T dp_n = -q.sin_psi * n_b + q.cos_psi * n_c;
        const T x = q.cos_psi * n_b + q.sin_psi * n_c;
        const T dl = dist_a * dp_n / (dist_a * dist_a + x * x);
        const T dpz = -q.sin_psi * t_b.z + q.cos_psi * t_c.z;
        f2 = w.slope * dl + x_minus_sin(T(2) * q.length, T(2) * q.sin_length * q.cos_length) / T(4) * dpz;
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

    /// Solves F(psi) = u1 mass, then W(s) = u2 W(L(psi)); `evaluations` counts the evaluations
    /// of F and of W (each with its derivatives).
    LTC_HOST_DEVICE vec3 sample(T u1, T u2, int& evaluations) const {
        const point q = solve_psi(u1, evaluations);
        T sn, cs;
        solve_arc(q, u2, sn, cs, evaluations);
        return cs * a + sn * q.p;
    }

    /// (u1, u2) with sample(u1, u2) = w, for w in the triangle.
    LTC_HOST_DEVICE glm::vec<2, T> invert(const vec3& w) const {
        const vec3 wa = w - a;  // tangent coordinates, accurate near a
        const T x = glm::dot(wa, t_b), y = glm::dot(wa, t_c);
        const T psi = glm::clamp(std::atan2(y, x), T(0), alpha);
        const point q = at(psi);
        const T s = glm::min(std::atan2(std::sqrt(x * x + y * y), glm::dot(w, a)), q.length);
        const T total = wedge_at(q).mass;
        const T u1 = mass > T(0) ? q.value / mass : T(0);
        const T u2 = total > T(0) ? wedge<T>(s, std::sin(s), std::cos(s), a.z, q.p.z).mass / total : T(0);
        return glm::clamp(glm::vec<2, T>(u1, u2), T(0), T(1));
    }

  private:
    static constexpr int max_iterations = 40;

    LTC_HOST_DEVICE point solve_psi(T u1, int& evaluations) const {
        const T target = u1 * mass;
        // Start: F' varying linearly from F'(0) to F'(alpha), rescaled so that the model ends at
        // the mass (x = psi / alpha solves q x^2 + r x = u1 (q + r)).
        const T r = slope_0, q = (slope_alpha - slope_0) / T(2), rhs = u1 * (q + r);
        const T den = r + safe_sqrt(r * r + T(4) * q * rhs);
        T lo = T(0), hi = alpha;
        T psi = den > T(0) ? alpha * glm::clamp(T(2) * rhs / den, T(0), T(1)) : u1 * alpha;
        point p = at(psi);
        for (int i = 0; i < max_iterations; ++i) {
            ++evaluations;
            const T f = p.value - target;
            // Within F's own rounding (epsilon / h relative for a triangle of size h): done.
            if (std::abs(f) <= T(4) * epsilon<T>() * glm::max(mass, p.scale)) break;
            (f < T(0) ? lo : hi) = psi;
            T f1, f2;
            derivatives(p, f1, f2);
            const T next = halley_step(psi, f, f1, f2, lo, hi);
            if (next == psi || hi - lo <= epsilon<T>() * alpha) break;
            psi = next;
            p = at(psi);
        }
        return p;
    }

    LTC_HOST_DEVICE void solve_arc(const point& q, T u2, T& sn, T& cs, int& evaluations) const {
        const T az = a.z, pz = q.p.z, length = q.length;
        const T target = u2 * wedge_at(q).mass;
        const T tol = T(4) * epsilon<T>() * target;
        // Start: uniform in solid angle along the arc, 1 - cos s = 2 sin^2(s / 2) proportional
        // to u2 (in half angles: no cancellation for short arcs).
        T s = T(2) * std::asin(glm::min(T(1), std::sqrt(u2) * std::sin(length / T(2))));
        T lo = T(0), hi = length;
        for (int i = 0; i < max_iterations; ++i) {
            sn = std::sin(s);
            cs = std::cos(s);
            const wedge<T> w(s, sn, cs, az, pz);
            ++evaluations;
            const T f = w.mass - target;
            if (std::abs(f) <= tol) break;
            (f < T(0) ? lo : hi) = s;
            const T next = halley_step(s, f, w.slope, w.curve, lo, hi);
            if (next == s || hi - lo <= epsilon<T>() * length) break;
            s = next;
        }
        if (s > length) s = length, sn = q.sin_length, cs = q.cos_length;
    }
};

}  // namespace detail
LTC_NAMESPACE_END
