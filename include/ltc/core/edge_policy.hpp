// ltc/core/edge_policy.hpp -- how the factor theta / sin(theta) of the edge term of eq. (11) is
// evaluated: exactly (atan2), by float-accurate fits (polynomial, minimax_rational), by the
// reference shader's rational fit, or by an FP16-friendly quadratic.
#pragma once

#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <type_traits>
#include <utility>

LTC_NAMESPACE_BEGIN

namespace detail {

/// theta / sin(theta) for theta = atan2(s, c), s = sin(theta) >= 0 computed accurately.
/// Where s is too small for the quotient to be representable, the edge has (almost) no
/// length (c > 0: the limit is 1) or passes through the shading point (c < 0: no great circle;
/// its cross product is ~0 and we return 0 so that the product stays finite).
template <typename T>
LTC_HOST_DEVICE LTC_INLINE T theta_over_sin(T s, T c) {
    if (s > min_normal<T>()) return std::atan2(s, c) / s;
    return c > T(0) ? T(1) : T(0);
}

/// theta / sin(theta) from p = f(|c|), a fit of f on c >= 0: p itself for c >= 0, and
/// f(c) = pi / s - f(-c) for c < 0 (theta = pi - theta', same sine), s = |a x b|.
template <typename T>
LTC_HOST_DEVICE LTC_INLINE T symmetric_extension(T c, const glm::vec<3, T>& axb, T p) {
    if (c >= T(0)) return p;
    const T s = glm::length(axb);
    return s > min_normal<T>() ? pi<T>() / s - p : T(0);  // s = 0, c < 0: see theta_over_sin
}

/// The element type of V: V itself for a scalar, the lane type for a compiler vector
/// (ltc/shading/detail/simd.hpp), so that a policy's positive_branch serves both.
template <typename V, typename = void>
struct scalar_of {
    using type = V;
};
template <typename V>
struct scalar_of<V, std::void_t<decltype(std::declval<V&>()[0])>> {
    using type = std::remove_cv_t<std::remove_reference_t<decltype(std::declval<V&>()[0])>>;
};
template <typename V>
using scalar_of_t = typename scalar_of<V>::type;

/// A policy made of a branch-free fit f of theta / sin(theta) on c >= 0, extended to c < 0 by
/// symmetric_extension. Fit::evaluate_positive_branch(y, f) takes y = 1 - |c| as a scalar or a
/// SIMD vector (ltc/shading/detail/simd.hpp: the batch kernels evaluate it lane-wise), by reference: a
/// vector wider than the baseline instruction set may not be passed by value to a function
/// compiled for it.
template <typename Fit>
struct symmetric_fit {
    template <typename T>
    LTC_HOST_DEVICE LTC_INLINE static T positive_branch(T y) {
        T f;
        Fit::evaluate_positive_branch(y, f);
        return f;
    }

    template <typename T>
    LTC_HOST_DEVICE LTC_INLINE static T theta_over_sin(T c, const glm::vec<3, T>& axb) {
        return symmetric_extension(c, axb, positive_branch(T(1) - glm::abs(c)));
    }
};

/// Whether Policy fits f on c >= 0 alone (Policy::positive_branch(1 - c)): edge_integral_z then
/// needs only the z component of a x b there.
template <typename Policy, typename T, typename = void>
struct has_positive_branch : std::false_type {};
template <typename Policy, typename T>
struct has_positive_branch<Policy, T, std::void_t<decltype(Policy::template positive_branch<T>(T(0)))>>
    : std::true_type {};

}  // namespace detail

/// How the factor theta / sin(theta) of the edge term is evaluated, from c = cos(theta) and
/// the cross product a x b of the edge's unit vertices (|a x b| = sin(theta), accurate: it comes
/// from a cancellation-free cross product; a policy takes its length only where it needs it).
/// Selected at compile time; the plain integrals and the shading functions default to
/// `automatic` (minimax_rational in float, exact in double), the lower-level polygon functions
/// (edge_integral, form_factor, vector_form_factor) to `exact`. A policy may also
/// expose positive_branch(y), its fit of theta / sin(theta) at c = 1 - y >= 0: edge_integral_z
/// then skips the x and y components of a x b there. The maximum relative errors of the factor
/// over c in [-1, 1], in float and double: docs/precision.md and tests/test_edge_policies.cpp.
namespace edge_policy {

/// atan2(s, c) / s: correct to a few ulps at every angle.
struct exact {
    template <typename T>
    LTC_HOST_DEVICE LTC_INLINE static T theta_over_sin(T c, const glm::vec<3, T>& axb) {
        return detail::theta_over_sin(glm::length(axb), c);
    }
};

/// Degree-9 polynomial in y = 1 - c, interpolating f(c) = acos(c) / sqrt(1 - c^2) at the
/// Chebyshev nodes of [0, 1] (near-minimax: 1.3e-8 relative error in exact arithmetic, below
/// float rounding), extended to c < 0 by the symmetry f(c) = pi / s - f(-c).
struct polynomial : detail::symmetric_fit<polynomial> {
    /// f(|c|) for y = 1 - |c|, branch-free. Estrin's scheme: four levels of independent
    /// multiply-adds instead of a chain of nine.
    template <typename V>
    LTC_HOST_DEVICE LTC_INLINE static void evaluate_positive_branch(const V& y, V& f) {
        using T = detail::scalar_of_t<V>;
        const V y2 = y * y, y4 = y2 * y2;
        const V a01 = T(0.99999999) + T(0.333335381) * y, a23 = T(0.133266572) + T(0.0579778015) * y;
        const V a45 = T(0.0201634898) + T(0.030059176) * y, a67 = T(-0.0335529978) + T(0.0509757585) * y;
        const V a89 = T(-0.0325916887) + T(0.0111628242) * y;
        f = (a01 + a23 * y2) + ((a45 + a67 * y2) + a89 * y4) * y4;
    }
};

/// A (3, 2) rational function of y = 1 - c, the relative-error minimax fit of
/// f(c) = acos(c) / sqrt(1 - c^2) on c in [0, 1] (linearized Loeb iteration on 400 Chebyshev
/// points, checked on 4001 points: 4.1e-8 in exact arithmetic, below float's half ulp of 6e-8),
/// extended to c < 0 by f(c) = pi / s - f(-c). Five multiply-adds and one division per edge,
/// against the degree-9 polynomial's nine multiply-adds and two products: the fastest
/// float-accurate policy.
struct minimax_rational : detail::symmetric_fit<minimax_rational> {
    template <typename V>
    LTC_HOST_DEVICE LTC_INLINE static void evaluate_positive_branch(const V& y, V& f) {
        using T = detail::scalar_of_t<V>;
        const V p = T(0.999999965867) + y * (T(-0.44145776482) + y * (T(0.0170912151505) + y * T(0.00123519700345)));
        const V q = T(1) + y * (T(-0.774792977409) + y * T(0.142038957683));
        f = p / q;
    }
};

/// Degree-21 polynomial in y = 1 - c, the Chebyshev interpolant of f(c) = acos(c) / sqrt(1 - c^2)
/// on c in [0, 1] (22 nodes; coefficients computed in long double, with acos(1 - y) as
/// 2 asin(sqrt(y / 2)) so that the reference is accurate near y = 0; with the coefficients rounded
/// to double, within 2e-17 of f in exact arithmetic), extended to c < 0 by f(c) = pi / s - f(-c):
/// accurate to double rounding (15 u derived; tests/test_edge_policies.cpp) without atan2, and for
/// c >= 0 without a square root or a division. In float it is no better than `polynomial`. The
/// two-lobe fit's objective uses it (ltc/fitting/fit_two_lobes.hpp).
struct polynomial_double : detail::symmetric_fit<polynomial_double> {
    template <typename V>
    LTC_HOST_DEVICE LTC_INLINE static void evaluate_positive_branch(const V& y, V& f) {
        using T = detail::scalar_of_t<V>;
        constexpr T c[22] = {T(1.0),
                             T(0.33333333333333715),
                             T(0.13333333333268454),
                             T(0.057142857185552724),
                             T(0.02539682392733603),
                             T(0.01154404228846063),
                             T(0.005327577998404975),
                             T(0.0024905834816810303),
                             T(0.0011401075923545),
                             T(0.0007160351200951709),
                             T(-0.000407509460495703),
                             T(0.0022976170305582856),
                             T(-0.005459382236540478),
                             T(0.011105962639703648),
                             T(-0.017526375815214122),
                             T(0.021811556952889076),
                             T(-0.021036443306365983),
                             T(0.015452524367719888),
                             T(-0.008355646766722203),
                             T(0.003145507723093033),
                             T(-0.0007384032011032105),
                             T(8.222460746765137e-05)};
        // Estrin's scheme: Horner's 21 dependent multiply-adds made 5 levels.
        const V y2 = y * y, y4 = y2 * y2, y8 = y4 * y4, y16 = y8 * y8;
        V q[11];
        for (int i = 0; i < 11; ++i) q[i] = c[2 * i] + c[2 * i + 1] * y;
        const V r0 = q[0] + q[1] * y2, r1 = q[2] + q[3] * y2, r2 = q[4] + q[5] * y2, r3 = q[6] + q[7] * y2,
                r4 = q[8] + q[9] * y2;
        const V s0 = r0 + r1 * y4, s1 = r2 + r3 * y4, s2 = r4 + q[10] * y4;
        f = (s0 + s1 * y8) + s2 * y16;
    }
};

/// The rational fit of the paper's reference shader code (Heitz et al. 2016, ltc.glsl,
/// IntegrateEdgeVec), times 2 pi (the shader folds 1 / (2 pi) into it); for c < 0 it uses
/// 1 / sqrt(max(1 - c^2, 1e-7)) as the shader does.
struct rational {
    template <typename T>
    LTC_HOST_DEVICE LTC_INLINE static T theta_over_sin(T c, const glm::vec<3, T>&) {
        const T y = glm::abs(c);
        const T a = T(0.8543985) + (T(0.4965155) + T(0.0145206) * y) * y;
        const T b = T(3.4175940) + (T(4.1616724) + y) * y;
        const T v = a / b;
        const T r = c > T(0) ? v : T(0.5) / std::sqrt(glm::max(T(1) - c * c, T(1e-7))) - v;
        return T(2) * pi<T>() * r;
    }
};

/// An FP16-friendly quadratic, as used by half-precision production shaders:
/// 0.33735186 c^2 - 0.89665001 c + pi / 2 for c >= 0, extended to c < 0 by
/// pi / sqrt(1 - c^2) - f(-c). Every operation fits in half precision.
/// Instantiable with T = _Float16 (real half-precision arithmetic; sqrt through float).
struct fp16_quadratic {
    template <typename T>
    LTC_HOST_DEVICE LTC_INLINE static T theta_over_sin(T c, const glm::vec<3, T>&) {
        const T x = c < T(0) ? -c : c;
        const T v = (T(0.33735186f) * x - T(0.89665001f)) * x + T(1.5707963f);
        if (c >= T(0)) return v;
        const T one_minus_c2 = T(1) - c * c;
        return T(3.1415927f) / T(std::sqrt(static_cast<float>(one_minus_c2 > T(1e-4f) ? one_minus_c2 : T(1e-4f)))) - v;
    }
};

/// The default of the plain integrals and of the shading functions (clamped_cosine,
/// integrate_polygon_light, shade_polygon_light): not a policy itself, but resolved per scalar
/// type by resolve_t: minimax_rational in float (the fastest float-accurate fit: within a few
/// ulps of theta / sin(theta), tests/test_edge_policies.cpp), exact in double and any other type.
struct automatic {};

/// Policy itself, or what `automatic` stands for in T.
template <typename Policy, typename T>
struct resolve {
    using type = Policy;
};
template <typename T>
struct resolve<automatic, T> {
    using type = std::conditional_t<std::is_same_v<T, float>, minimax_rational, exact>;
};
template <typename Policy, typename T>
using resolve_t = typename resolve<Policy, T>::type;

}  // namespace edge_policy

LTC_NAMESPACE_END
