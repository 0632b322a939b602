// ltc/fitting/moments.hpp -- the per-node quantities of the BRDF that the fit needs (paper
// section 4): magnitude (directional albedo), Fresnel term (Hill 2016) and average direction.
//
// All by deterministic quadrature (the midpoint rule on an n x n grid of u in [0, 1)^2 pushed
// through Brdf::sample, i.e. stratified importance sampling without random numbers;
// n = options::moment_samples), for f(L) = rho(V, L) cos(theta_L) (Brdf::eval):
//   magnitude = integral of f(L) dL                                  (directional albedo)
//   fresnel   = integral of f(L) (1 - V.H)^5 dL, H = (V + L)/|V + L| (Hill 2016: with Schlick's
//               F = F0 + (1 - F0)(1 - V.H)^5, integral of f F = F0 magnitude + (1 - F0) fresnel)
//   average direction = integral of f(L) L dL, y set to 0, normalized.
#pragma once

#include <ltc/config.hpp>

#include <ltc/fitting/ltc_parameters.hpp>  // normalize_or_zero

#include <glm/glm.hpp>

#include <cmath>

LTC_NAMESPACE_BEGIN
namespace fit {

struct moments {
    double magnitude = 0;                   ///< integral of f
    double fresnel = 0;                     ///< integral of f (1 - V.H)^5
    glm::dvec3 average_direction{0, 0, 1};  ///< integral of f L, y zeroed, normalized
};

namespace detail {
/// The quadrature of the file comment for any parameter type (a scalar alpha, or an anisotropic
/// pair); keep_y: the average direction keeps its y (no plane of symmetry: anisotropic BRDFs).
template <template <typename> class Brdf, typename Alpha>
moments moments_by_quadrature(const glm::dvec3& V, const Alpha& alpha, int n, bool keep_y) {
    using B = Brdf<double>;
    double m = 0, fr = 0;
    glm::dvec3 dir(0);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::dvec2 u((i + 0.5) / n, (j + 0.5) / n);
            const glm::dvec3 L = B::sample(V, u, alpha);
            const double p = B::pdf(V, L, alpha);
            if (!(p > 0) || !(L.z > 0)) continue;
            const double e = B::eval(V, L, alpha);
            const double w = e / p;
            if (!(w > 0) || !std::isfinite(w)) continue;
            const glm::dvec3 H = normalize_or_zero(V + L);
            const double c = 1.0 - glm::clamp(glm::dot(V, H), 0.0, 1.0);
            const double c2 = c * c;
            m += w;
            fr += w * c2 * c2 * c;
            dir += w * L;
        }
    moments r;
    const double inv = 1.0 / (double(n) * double(n));
    r.magnitude = m * inv;
    r.fresnel = fr * inv;
    if (!keep_y) dir.y = 0;
    const double len = glm::length(dir);
    r.average_direction = len > 0 ? dir / len : glm::dvec3(0, 0, 1);
    return r;
}
}  // namespace detail

/// Magnitude, Fresnel term and average direction of f(L) = Brdf<double>::eval(V, L, alpha) by the
/// midpoint rule on an n x n grid through Brdf's importance sampler.
template <template <typename> class Brdf>
moments compute_moments(const glm::dvec3& V, double alpha, int n) {
    return detail::moments_by_quadrature<Brdf>(V, alpha, n, false);
}

}  // namespace fit
LTC_NAMESPACE_END
