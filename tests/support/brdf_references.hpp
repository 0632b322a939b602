// Shared pieces of the BRDF model tests (test_brdf.cpp, test_brdf_sampling.cpp,
// test_brdf_eval.cpp): the configurations, the rounding bound of the models, the quadrature
// references of each (model, alpha, theta_v), computed once per process, and the lune integrals.
//
// Configurations: both models, float and double, alpha in {0.05, 0.2, 0.5, 1}, theta_v in
// {0, 30, 60, 85} degrees, V = view_from_cos(cos theta_v) (in the xz-plane).
//
// Tolerances.
//   - Quadrature (support/brdf_quadrature.hpp: product Gauss-Legendre rules of n and 2n points
//     on quadtree cells, refined until the summed |Q_n - Q_2n| of the double model is <= 1e-10
//     or 1e-11): the error of the 2n-point value is bounded by that sum (geometric convergence
//     on cells where the integrand is analytic; every jump or kink is on a cell boundary). The
//     tests require convergence, so an unresolved integrand cannot pass with a wide error bar.
//   - Rounding of the model in precision T (the quadrature itself runs in double): rho_T(alpha)
//     = (256 + 16 / alpha) eps_T relative, a worst-case bound per node, hence for the integral:
//       * the node direction is rounded to T, which moves it by ~eps_T; D's logarithmic
//         derivative along theta is <= 2 / alpha for GGX and ~2 k / alpha for Beckmann at
//         tan theta = k alpha, and the tail beyond k = 8 carries < e^-64 of the mass: <= 16 / alpha;
//       * ~10 roundings in the rational parts, and Beckmann's exp(-e) with e <= 64 (beyond,
//         the mass is negligible) computed from an e with ~4 eps_T relative error: 256 eps_T.
//   - Monte Carlo: 4 standard errors, the variance estimated from the same samples. Acceptable
//     here: N = 10^5 samples of a bounded weight (GGX: eval / pdf = G2 / G1(V) <= 1; Beckmann:
//     G2 V.h / (V.z h.z) <= 4 / V.z^2, as L.z > 0 needs h.z > V.z / (2 V.h)), so the variance
//     estimate's own relative error is ~ sqrt(2 / N) ~ 0.5%. (A run with 2e7 samples agrees
//     with the quadrature albedos within 1.3 standard errors.)
//   - Chi-square: below the p = 1e-4 critical value (Wilson-Hilferty approximation).
#pragma once

#include <ltc/brdf/beckmann.hpp>
#include <ltc/brdf/ggx.hpp>

#include "support/brdf_quadrature.hpp"

#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <type_traits>

namespace ltc_test::brdf_checks {

inline constexpr double pi = 3.141592653589793238462643383279502884;
inline constexpr std::size_t n_alpha = 4, n_theta = 4;
inline constexpr double alphas[n_alpha] = {0.05, 0.2, 0.5, 1.0};
inline constexpr double theta_v_deg[n_theta] = {0, 30, 60, 85};

inline double theta_v(std::size_t it) { return theta_v_deg[it] * pi / 180; }

template <typename T>
glm::vec<3, T> view(std::size_t it) {
    return ltc::brdf::view_from_cos<T>(static_cast<T>(std::cos(theta_v(it))));
}

template <typename T>
double eps() {
    return static_cast<double>(std::numeric_limits<T>::epsilon());
}

/// Relative rounding bound of the model in precision T (the comment at the top of this file).
template <typename T>
double rho(double alpha) {
    return (256 + 16 / alpha) * eps<T>();
}

template <typename T>
bool finite(const glm::vec<3, T>& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// ---------------------------------------------------------------------------------------------
// Model families: TestType is M<T>; the references are computed once per family.

/// Quadrature reference of one (model, alpha, theta_v): the integrals over the sphere of L of
/// pdf(V, L) and eval(V, L), in double and float, by the adaptive rule of
/// support/brdf_quadrature.hpp in (theta, phi). Coarse grid: theta breaks at pi / 2 (eval's
/// horizon) and at pi - theta_v, the circle (V + L).z = 0 where the half vector crosses the
/// horizon (GGX's pdf jumps there; Beckmann's flips h); that circle goes through L = -V, a mesh
/// corner (theta = pi - theta_v, phi = pi) where GGX's pdf has a bounded direction-dependent
/// limit and Beckmann's an integrable 1 / |V + L| singularity; theta_v too (the lobe's peak, the
/// mirror direction, is the corner (theta_v, pi)). Every integrand is even in L.y (isotropic
/// model, V in the xz-plane; checked by the reciprocity test), so only phi in [0, pi] is
/// integrated, and each leaf stands for itself and its mirror image in phi in [pi, 2 pi].
/// The double pdf and eval steer the refinement, to a summed |Q_n - Q_2n| <= 1e-10 each.
struct reference {
    ltc_test::quadtree_integral<4> q;  // components: pdf, eval (double); pdf, eval (float)
    double pdf_total[2], pdf_error[2], albedo[2], albedo_error[2];  // [0]: double, [1]: float
};

inline constexpr double reference_tol = 1e-10;

template <typename T>
constexpr int precision_index() {
    return std::is_same<T, float>::value ? 1 : 0;
}

template <template <typename> class M>
reference make_reference(double alpha, double tv) {
    using Bd = M<double>;
    using Bf = M<float>;
    const glm::dvec3 Vd = ltc::brdf::view_from_cos<double>(std::cos(tv));
    const glm::vec3 Vf = ltc::brdf::view_from_cos<float>(static_cast<float>(std::cos(tv)));
    const float af = static_cast<float>(alpha);
    const auto f = [&](const glm::dvec3& L) -> std::array<double, 4> {
        const glm::vec3 Lf(L);
        return {Bd::pdf(Vd, L, alpha), Bd::eval(Vd, L, alpha), static_cast<double>(Bf::pdf(Vf, Lf, af)),
                static_cast<double>(Bf::eval(Vf, Lf, af))};
    };
    reference r;
    r.q = ltc_test::integrate_adaptive<4>(f, ltc_test::z_frame(),
                                          ltc_test::breakpoints(0, pi, {tv, pi / 2, pi - tv}, pi / 8),
                                          ltc_test::breakpoints(0, pi, {}, pi / 8), 5, 2, reference_tol);
    for (int p = 0; p < 2; ++p) {
        r.pdf_total[p] = 2 * r.q.value[2 * p];
        r.pdf_error[p] = 2 * r.q.error[2 * p];
        r.albedo[p] = 2 * r.q.value[2 * p + 1];
        r.albedo_error[p] = 2 * r.q.error[2 * p + 1];
    }
    return r;
}

template <template <typename> class M>
const reference& reference_for(std::size_t ia, std::size_t it) {
    static std::unique_ptr<reference> cache[n_alpha][n_theta];
    std::unique_ptr<reference>& p = cache[ia][it];
    if (!p) p.reset(new reference(make_reference<M>(alphas[ia], theta_v(it))));
    return *p;
}

template <typename B>
struct family;
template <template <typename> class M, typename T>
struct family<M<T>> {
    using as_double = M<double>;
    static const reference& ref(std::size_t ia, std::size_t it) { return reference_for<M>(ia, it); }
};
template <typename B>
using rebind_double = typename family<B>::as_double;

// ---------------------------------------------------------------------------------------------
// Hemisphere integrals in the lune frame (support/brdf_quadrature.hpp): h = cos(b) y +
// sin(b) (cos(p) x + sin(p) z); h.z > 0 is p in (0, pi), and V.h > 0 is p in (-theta_v,
// pi - theta_v). D peaks at h = z, the grid corner b = p = pi / 2. The integrand returns the
// double model (which steers the refinement, to 1e-11) and the model in T.

inline constexpr double lune_tol = 1e-11;

template <typename F>
ltc_test::quadtree_integral<2> lune_integral(const F& f, double psi_max) {
    return ltc_test::integrate_adaptive<2>(f, ltc_test::lune_frame(), ltc_test::breakpoints(0, pi, {pi / 2}, pi / 8),
                                           ltc_test::breakpoints(0, psi_max, {pi / 2}, pi / 8), 6, 1, lune_tol);
}

#define LTC_BRDF_TYPES \
    ltc::brdf::ggx<float>, ltc::brdf::ggx<double>, ltc::brdf::beckmann<float>, ltc::brdf::beckmann<double>

}  // namespace ltc_test::brdf_checks
