// Tests of the microfacet BRDF models of ltc/brdf (ggx, beckmann) that the LTC fit is made
// against: normalization of D, of the visible normals and of the pdf, and energy, against the
// quadrature references of support/brdf_references.hpp (which explains the tolerances). The
// sampler is tested in test_brdf_sampling.cpp; reciprocity, the closed forms and degenerate
// input in test_brdf_eval.cpp.
#include <ltc/brdf/beckmann.hpp>
#include <ltc/brdf/ggx.hpp>

#include <catch2/catch.hpp>

#include "support/brdf_references.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>

namespace ltc_test_brdf {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::brdf_checks;  // configurations, references, LTC_BRDF_TYPES

// (a) int D(h) cos(theta_h) dh = 1 over the upper hemisphere.
TEMPLATE_TEST_CASE("brdf: the NDF is normalized", "[brdf]", LTC_BRDF_TYPES) {
    using B = TestType;
    using Bd = rebind_double<B>;
    using T = typename B::scalar;
    for (const double alpha : alphas) {
        const auto f = [&](const glm::dvec3& h) -> std::array<double, 2> {
            const double dt = static_cast<double>(B::ndf(glm::vec<3, T>(h), static_cast<T>(alpha)));
            return {Bd::ndf(h, alpha) * h.z, dt * h.z};
        };
        const auto q = lune_integral(f, pi);
        INFO(B::name << " alpha " << alpha << ": " << q.value[1] << " +- " << q.error[1] << " (" << q.leaves.size()
                     << " cells)");
        CHECK(q.converged);
        CHECK(std::abs(q.value[1] - 1) <= q.error[1] + rho<T>(alpha));
    }
}

// (b) Smith's visible-normal normalization: int G1(V) max(0, V.h) D(h) dh = V.z, the projected
// area of the visible microsurface equals that of the macrosurface (Heitz 2014, JCGT 3(2); it
// is why D_V of Heitz 2018 is a density). Integrated over the lune {h.z > 0, V.h > 0}.
TEMPLATE_TEST_CASE("brdf: the visible normals are normalized", "[brdf]", LTC_BRDF_TYPES) {
    using B = TestType;
    using Bd = rebind_double<B>;
    using T = typename B::scalar;
    for (const double alpha : alphas)
        for (std::size_t it = 0; it < n_theta; ++it) {
            const glm::vec<3, T> V = view<T>(it);
            const glm::dvec3 Vd(V);
            const T a = static_cast<T>(alpha);
            const double g1 = static_cast<double>(B::g1(V, a)), g1d = Bd::g1(Vd, alpha);
            const auto f = [&](const glm::dvec3& h) -> std::array<double, 2> {
                const glm::vec<3, T> ht(h);
                const double vh = std::max(0.0, static_cast<double>(glm::dot(V, ht)));
                const double dt = static_cast<double>(B::ndf(ht, a));
                return {g1d * std::max(0.0, glm::dot(Vd, h)) * Bd::ndf(h, alpha), g1 * vh * dt};
            };
            const auto q = lune_integral(f, pi - std::atan2(Vd.x, Vd.z));
            INFO(B::name << " alpha " << alpha << " theta_v " << theta_v_deg[it] << ": " << q.value[1] << " +- "
                         << q.error[1] << ", V.z " << Vd.z);
            CHECK(q.converged);
            CHECK(std::abs(q.value[1] - Vd.z) <= q.error[1] + rho<T>(alpha) * Vd.z);
        }
}

// (c) int pdf(V, L) dL = 1 over the whole sphere (sample() may go below the horizon).
TEMPLATE_TEST_CASE("brdf: the pdf integrates to one over the sphere", "[brdf]", LTC_BRDF_TYPES) {
    using B = TestType;
    using T = typename B::scalar;
    const int p = precision_index<T>();
    for (std::size_t ia = 0; ia < n_alpha; ++ia)
        for (std::size_t it = 0; it < n_theta; ++it) {
            const reference& r = family<B>::ref(ia, it);
            INFO(B::name << " alpha " << alphas[ia] << " theta_v " << theta_v_deg[it] << ": "
                         << r.pdf_total[p] << " +- " << r.pdf_error[p]);
            // The mesh resolves the double pdf. In float, Beckmann's pdf ~ 1 / |V + L| next to
            // L = -V has a relative condition number ~ eps / |V + L| in L, so rounding the nodes
            // to float shows as noise in |Q_n - Q_2n|, which its tolerance includes.
            CHECK(r.q.converged);
            CHECK(std::abs(r.pdf_total[p] - 1) <= r.pdf_error[p] + rho<T>(alphas[ia]));
        }
}

// (g) energy: the directional albedo int eval dL <= 1 (no Fresnel, G2 <= G1: the white furnace
// loses energy to single-scattering), and for GGX at normal incidence it decreases with alpha.
TEMPLATE_TEST_CASE("brdf: energy conservation", "[brdf]", LTC_BRDF_TYPES) {
    using B = TestType;
    using T = typename B::scalar;
    const int p = precision_index<T>();
    for (std::size_t ia = 0; ia < n_alpha; ++ia)
        for (std::size_t it = 0; it < n_theta; ++it) {
            const reference& r = family<B>::ref(ia, it);
            INFO(B::name << " alpha " << alphas[ia] << " theta_v " << theta_v_deg[it] << ": albedo "
                         << r.albedo[p] << " +- " << r.albedo_error[p]);
            CHECK(r.albedo[p] > 0);
            CHECK(r.albedo[p] <= 1 + r.albedo_error[p] + rho<T>(alphas[ia]));
        }
    if (std::string(B::name) == "ggx")
        for (std::size_t ia = 0; ia + 1 < n_alpha; ++ia) {
            const reference &r0 = family<B>::ref(ia, 0), &r1 = family<B>::ref(ia + 1, 0);
            INFO("alpha " << alphas[ia] << " -> " << alphas[ia + 1] << ": " << r0.albedo[p] << " -> "
                          << r1.albedo[p]);
            CHECK(r0.albedo[p] - r1.albedo[p] >
                  r0.albedo_error[p] + r1.albedo_error[p] + rho<T>(alphas[ia]) + rho<T>(alphas[ia + 1]));
        }
}

}  // namespace ltc_test_brdf
