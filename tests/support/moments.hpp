// Exact (to quadrature accuracy) moments of a linearly transformed distribution, computed in
// the ORIGINAL space: E_D[g(w)] = int D_o(w_o) g(M w_o / |M w_o|) dw_o over D_o's support. The
// integrand is analytic there (D_o's kink or jump lies on the support's boundary), so a product
// Gauss-Legendre rule in (cos theta, phi) converges geometrically; the difference between the
// N- and 2N-point rules is returned as an error estimate of the 2N-point result. Strongly
// anisotropic M make normalize(M w_o) vary quickly: the supplement's M needs n = 512 for 1e-12.
#pragma once

#include "support/gauss_legendre.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace ltc_test {

struct moment_result {
    double norm;          // integral of D (should be 1)
    glm::dvec3 first;     // E[w]
    glm::dvec3 second;    // E[w_i^2], the diagonal of E[w w^T]
    double error;         // estimate of the largest error of the above
};

/// Moments by an n x 2n product rule; `Do` is the original density (double(const dvec3&)) and
/// `full_sphere` says whether its support is the sphere (else the upper hemisphere).
template <typename Do>
moment_result moments_with(std::size_t n, const glm::dmat3& M, Do do_density, bool full_sphere) {
    const quadrature_rule rz = gauss_legendre(n), rp = gauss_legendre(2 * n);
    const double pi = 3.141592653589793238;
    const double z0 = full_sphere ? -1 : 0, dz = 1 - z0;
    moment_result r{0, glm::dvec3(0), glm::dvec3(0), 0};
    for (std::size_t i = 0; i < n; ++i) {
        const double z = z0 + dz * rz.x[i], s = std::sqrt(std::max(0.0, 1 - z * z));
        for (std::size_t j = 0; j < 2 * n; ++j) {
            const double phi = 2 * pi * rp.x[j];
            const glm::dvec3 wo(s * std::cos(phi), s * std::sin(phi), z);
            const double weight = rz.w[i] * dz * rp.w[j] * 2 * pi * do_density(wo);
            const glm::dvec3 w = glm::normalize(M * wo);
            r.norm += weight;
            r.first += weight * w;
            r.second += weight * w * w;
        }
    }
    return r;
}

template <typename Do>
moment_result moments(const glm::dmat3& M, Do do_density, bool full_sphere, std::size_t n = 512) {
    const moment_result lo = moments_with(n / 2, M, do_density, full_sphere);
    moment_result hi = moments_with(n, M, do_density, full_sphere);
    const glm::dvec3 d1 = glm::abs(hi.first - lo.first), d2 = glm::abs(hi.second - lo.second);
    hi.error = std::max({std::abs(hi.norm - lo.norm), d1.x, d1.y, d1.z, d2.x, d2.y, d2.z}) + 1e-15;
    return hi;
}

}  // namespace ltc_test
