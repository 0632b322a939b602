// libFuzzer harness of the core integrals: for any finite polygon (0..15 vertices, any
// magnitudes, degenerate or not), the solid angle, the clipped solid angle, the (vector) form
// factor and the horizon clip are finite; and for any matrix accepted by the checked factory
// (direct or inverse), every integral (both sidednesses), sample, density and evaluation of the
// uniform sphere, uniform hemisphere, clamped cosine and squared clamped cosine and of their
// transformed lobes is finite, and a sample's density is > 0.
// Input: fuzz_common.hpp's read_scene. Build and run: tests/fuzz/run.sh (README.md there).
#include "fuzz_common.hpp"

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/form_factor.hpp>
#include <ltc/core/horizon_clip.hpp>
#include <ltc/core/solid_angle.hpp>
#include <ltc/core/squared_clamped_cosine.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/core/uniform_hemisphere.hpp>
#include <ltc/core/uniform_sphere.hpp>

#include <fuzzer/FuzzedDataProvider.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

using namespace ltc_fuzz;

template <typename T, typename Dist>
void check_distribution(const glm::vec<3, T>* v, std::size_t n, const glm::mat<3, 3, T>& m, bool use_inverse,
                        const glm::vec<2, T>& u) {
    require_finite(Dist::integrate(v, n), "D_o integral");
    try {
        const auto d =
            use_inverse ? ltc::transformed<Dist>::checked_from_inverse(m) : ltc::transformed<Dist>::checked(m);
        require_finite(d.integrate(v, n), "integral");
        require_finite(d.integrate(v, n, ltc::sidedness::one_sided), "one-sided integral");
        const glm::vec<3, T> w = d.sample(u);
        require_finite(w, "sample");
        const T p = d.pdf(w);
        require_finite(p, "pdf");
        if (!(p > T(0))) {
            std::fprintf(stderr, "sample with zero pdf\n");
            std::abort();
        }
        for (std::size_t i = 0; i < n; ++i) require_finite(d.eval(ltc::detail::safe_normalize(v[i])), "eval");
    } catch (const ltc::invalid_transform&) {
        // rejected matrices are the checked factory's job
    }
}

template <typename T>
void run(FuzzedDataProvider& in) {
    using vec3 = glm::vec<3, T>;
    const scene<T> s = read_scene<T>(in);
    const vec3* pv = s.v.data();
    const std::size_t n = s.v.size();

    require_finite(ltc::solid_angle(pv, n), "solid angle");
    require_finite(ltc::clipped_solid_angle(pv, n), "clipped solid angle");
    require_finite(ltc::form_factor_signed(pv, n), "form factor");
    require_finite(ltc::vector_form_factor(pv, n), "vector form factor");
    std::vector<vec3> clipped(ltc::clipped_capacity(n));
    const std::size_t k = ltc::clip_to_horizon(pv, n, clipped.data());
    if (k > ltc::clipped_capacity(n)) std::abort();
    for (std::size_t i = 0; i < k; ++i) require_finite(clipped[i], "clipped vertex");

    check_distribution<T, ltc::uniform_sphere<T>>(pv, n, s.m, s.use_inverse, s.u);
    check_distribution<T, ltc::uniform_hemisphere<T>>(pv, n, s.m, s.use_inverse, s.u);
    check_distribution<T, ltc::clamped_cosine<T>>(pv, n, s.m, s.use_inverse, s.u);
    check_distribution<T, ltc::squared_clamped_cosine<T>>(pv, n, s.m, s.use_inverse, s.u);
}

}  // namespace

LTC_FUZZ_ENTRY(run)
