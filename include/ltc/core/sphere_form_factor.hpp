// ltc/core/sphere_form_factor.hpp -- the horizon-clipped form factor of a sphere (a spherical
// cap), in closed form: what the clipless approximation of ltc/shading/clipless.hpp evaluates
// in place of a clipped polygon (Hill and Heitz 2016, "Real-Time Area Lighting: a Journey from
// Research to Production", SIGGRAPH course; the formula is Snyder 1996's I_hemisphere).
//
//   #include <ltc/core/sphere_form_factor.hpp>
//   float I = ltc::clipless::sphere_form_factor(f, cos_omega);   // f = sin^2(sigma)
//
// Conventions: sigma the cap's angular radius, omega its centre's angle from the normal z; the
// result in [0, f], f cos(omega) where the cap lies above the horizon, 0 where it lies below.
// Degenerate cases: f clamped to [0, 1], cos(omega) to [-1, 1]; no cancellation for small caps
// near the horizon (a few ulps of sin^3(sigma)).
#pragma once

#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <cmath>

LTC_NAMESPACE_BEGIN
namespace clipless {

namespace detail {

/// x - sin x without cancellation: its Taylor series for x <= 1/2 (the first omitted term is
/// below 1e-18 x^3 / 6), the direct difference above (relative error <= 24 eps there).
template <typename T>
LTC_HOST_DEVICE inline T x_minus_sin(T x) {
    if (x > T(0.5)) return x - std::sin(x);
    const T x2 = x * x;
    return x * x2 *
           (T(1) / T(6) -
            x2 * (T(1) / T(120) -
                  x2 * (T(1) / T(5040) -
                        x2 * (T(1) / T(362880) -
                              x2 * (T(1) / T(39916800) -
                                    x2 * (T(1) / T(6227020800.0) - x2 * (T(1) / T(1307674368000.0))))))));
}

}  // namespace detail

/// The horizon-clipped form factor (1/pi) int_{cap, z >= 0} z dw of a spherical cap of angular
/// radius sigma around a direction at angle omega from the normal, given f = sin^2(sigma) and
/// c = cos(omega): Snyder's I_hemisphere / pi, in [0, f]. Inputs are clamped to f in [0, 1],
/// c in [-1, 1].
///
/// The sphere's clipped form factor is analytic (Snyder 1996, "Area light sources for real-time
/// graphics", Microsoft Research MSR-TR-96-11, its I_hemisphere; Hill and Heitz 2016 use it):
///
///   pi * I(omega, sigma) = pi cos(omega) sin^2(sigma)           omega in [0, pi/2 - sigma]
///                          pi cos(omega) sin^2(sigma) + G - H   omega in [pi/2 - sigma, pi/2]
///                          G + H                                omega in [pi/2, pi/2 + sigma]
///                          0                                    omega in [pi/2 + sigma, pi]
///   gamma = asin(cos(sigma) / sin(omega))
///   G = -2 sin(omega) cos(sigma) cos(gamma) + pi/2 - gamma + sin(gamma) cos(gamma)
///   H = cos(omega) (cos(gamma) sqrt(sin^2(sigma) - cos^2(gamma))
///                   + sin^2(sigma) asin(cos(gamma) / sin(sigma)))
///
/// Domain. sigma in [0, pi/2] and omega in [0, pi]; in terms of the inputs, f in [0, 1] and
/// cos(omega) in [-1, 1] (both are clamped). f <= 1 always holds for a polygon: |F| =
/// max_u (1/pi) int_P w.u dw <= (1/pi) int_S2 max(0, w.u) dw = 1. The first and last branches are
/// cos(omega) >= sin(sigma) (the sphere is entirely above the horizon) and cos(omega) <=
/// -sin(sigma) (entirely below). In the band |cos(omega)| < sin(sigma) both inverse sines are
/// defined: cos(sigma) / sin(omega) <= 1 because sin^2(omega) = 1 - cos^2(omega) > cos^2(sigma),
/// and cos^2(gamma) = (sin^2(sigma) - cos^2(omega)) / sin^2(omega) <= sin^2(sigma). The four
/// branches join continuously (G = H = 0 at omega = pi/2 -+ sigma, H = 0 at omega = pi/2, where
/// pi I = sigma - sin(sigma) cos(sigma), the circular segment that the horizon cuts off the
/// projected disk).
///
/// How it is evaluated. With c = cos(omega), s = sin(sigma), A = sqrt(s^2 - c^2) and
/// sin^2(omega) = 1 - c^2, the identities sin(gamma) = cos(sigma)/sin(omega), cos(gamma) =
/// A/sin(omega) and sqrt(s^2 - cos^2(gamma)) = |c| cos(sigma)/sin(omega) turn G -+ H into
///
///   G -+ H = S(phi) + c^2 cos(sigma) A / (1 - c^2) - |c| s^2 psi,
///   phi = atan2(A, cos(sigma)),  psi = atan2(A, |c| cos(sigma)),  S(phi) = phi - sin phi cos phi
///
/// (the sign of H folds into |c|). Every term is O(sigma^3), as the result (no O(sigma) terms
/// cancel), and S is evaluated by its series for small phi, so the absolute error stays a few
/// ulps of sin^3(sigma) for every sigma (tests/test_sphere_form_factor.cpp).
template <typename T>
LTC_HOST_DEVICE inline T sphere_form_factor(T f, T cos_omega) {
    const T s2 = glm::clamp(f, T(0), T(1));
    const T c = glm::clamp(cos_omega, T(-1), T(1));
    const T s = std::sqrt(s2);
    if (c >= s) return c * s2;  // entirely above the horizon (also f = 0, c >= 0)
    if (c <= -s) return T(0);   // entirely below
    const T ac = std::abs(c);
    const T cos_sigma = std::sqrt(T(1) - s2);
    const T sin2_omega = (T(1) - c) * (T(1) + c);  // > cos^2(sigma) >= 0 in the band
    const T A = ltc::detail::safe_sqrt(std::fma(-ac, ac, s2));  // sqrt(s^2 - c^2), one rounding
    const T phi = std::atan2(A, cos_sigma);
    const T psi = std::atan2(A, ac * cos_sigma);
    const T g_minus_h = detail::x_minus_sin(T(2) * phi) / T(2) + c * c * cos_sigma * A / sin2_omega -
                        ac * s2 * psi;
    const T r = (c > T(0) ? c * s2 : T(0)) + g_minus_h / pi<T>();
    return glm::clamp(r, T(0), s2);
}

}  // namespace clipless
LTC_NAMESPACE_END
