// The fuzz harness's checks of the batch API (ltc/shading/batch.hpp), called by
// tests/fuzz/fuzz_shading.cpp for every input.
#pragma once

#include "fuzz_batch_items.hpp"
#include "fuzz_common.hpp"

#include <ltc/ltc.hpp>
#include <ltc/reference/splitmix64.hpp>
#include <ltc/shading/batch.hpp>

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

namespace ltc_fuzz {

// The batch API (ltc/shading/batch.hpp): out[i] is the scalar path's
//   transformed<clamped_cosine<T, Policy>>::from_inverse(M_i^-1).integrate(P_i, n, s)
// up to rounding, whatever the instruction set. Checked for every output of every isa:
//   - finite, >= 0 (both sidednesses are non-negative), and at most m / 2 (1 + 1e-3) with
//     m = clipped_capacity(n): eq. (11) sums at most m edge terms theta_j n_z, each of magnitude
//     <= theta_j <= pi, and divides by 2 pi (the kernel sums n edges and at most one horizon edge,
//     n + 1 <= m for n >= 2); 1e-3 is slack for rounding and the fits (relative error <= 4.1e-8);
//     only a gross error (an unbounded edge term) exceeds it. Mirrors what the harness checks of
//     the scalar integrals (finite), plus what the sidedness and eq. (11) guarantee.
//   - equal (bitwise) to the scalar path where the batch promises the scalar path itself: with
//     isa::scalar, for the last count % width items (the tail), and for items the kernel must hand
//     back (a vertex with |M^-1 p|^2 clearly outside the kernel's (1e-16, 1e16), see
//     must_fall_back);
//   - elsewhere within the per-item tolerance of tests/test_batch.cpp (batch_tolerance), where its
//     derivation applies.

// Of the item's first n vertices: whether one of them makes the kernel hand the item back to the
// scalar path, and the largest conditioning of M^-1 p, kappa_p = | |M^-1| |p| | / |M^-1 p| (long
// double; infinite where M^-1 p = 0 but p != 0).
// The kernel hands an item back where its (rounded) |M^-1 p|^2 is outside (1e-16, 1e16) or not
// finite; the rounding of M^-1 p (with or without FMA) is at most 3 u kappa_p relative, so with
// kappa_p <= 16 and a factor 4 margin on the range the kernel's decision is certain. p = 0 gives
// M^-1 p = 0 exactly in every path.
template <typename T>
void conditioning(const glm::mat<3, 3, T>& mi, const std::vector<glm::vec<3, T>>& p, std::size_t n,
                  bool& must_fall_back, long double& kappa_max) {
    must_fall_back = false;
    kappa_max = 1;
    for (std::size_t k = 0; k < n; ++k) {
        long double q[3] = {0, 0, 0}, a[3] = {0, 0, 0};
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
                q[r] += static_cast<long double>(mi[c][r]) * static_cast<long double>(p[k][c]);
                a[r] += std::abs(static_cast<long double>(mi[c][r]) * static_cast<long double>(p[k][c]));
            }
        const long double l2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2], a2 = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
        if (a2 == 0) {  // p = 0 (M^-1 is not singular): M^-1 p = 0 exactly in every path
            must_fall_back = true;
            continue;
        }
        const long double kappa = l2 > 0 ? std::sqrt(a2 / l2) : std::numeric_limits<long double>::infinity();
        kappa_max = std::max(kappa_max, kappa);
        if (kappa <= 16 && !(l2 > 0.25e-16L && l2 < 4e16L)) must_fall_back = true;
    }
}

// theta / sin(theta) of unit vectors a, b (as tests/support/clip_comparison.hpp).
inline double theta_over_sin(const glm::dvec3& a, const glm::dvec3& b) {
    const double s = glm::length(glm::cross(a, b)), c = glm::dot(a, b);
    return s > 0 ? std::atan2(s, c) / s : (c > 0 ? 1.0 : 1e30);
}

// The per-item tolerance of a batch result against the scalar path: ltc_test::clip_tolerance of
// tests/support/clip_comparison.hpp (derived in tests/test_batch.cpp's header comment), written
// for T (u = epsilon / 2: the derivation is linear in u; test_batch.cpp scales it the same way for
// double), over the scalar path's own clipped unit edges e_j and crossings X:
//   u / (2 pi) [ sum_j (32 + 2 m) |e_j| + 8 (1 + t_j)  +  sum_X 8 kappa_X (2 + t_X) ],
// with k_j = 0 (minimax_rational and polynomial take the sine from |a x b|), and three changes for
// input that test_batch.cpp's random polygons never give:
//   - times kappa_p (see conditioning): the derivation takes M^-1 p rounded to a few u relative to
//     |M^-1 p|, as both paths compute it in the same order; with FMA (the AVX2 kernel) the
//     rounding of M^-1 p differs between the paths by up to 3 u | |M^-1| |p| |, kappa_p times
//     that, and each term is (to first order) linear in the vertices' perturbation; the other
//     terms only grow. A vertex within that rounding of the horizon may be clipped differently by
//     the two paths: that moves it by as much, which the same terms cover (clipping is continuous);
//   - a horizon edge (both ends at z = 0: from the exit crossing to the entry crossing) has
//     endpoints perturbed by 8 kappa_X u, not 8 u: + 8 kappa_X,max (1 + t_j) for it;
//   - an edge whose unit endpoints are nearly opposite, c_j < 0 and sin_j < 64 delta with
//     delta = 8 u kappa_p max(1, kappa_X,max) (their perturbation), has no first-order bound: its
//     great circle is undefined within rounding (a polygon seen edge-on with the shading point
//     inside, or a horizon edge between nearly opposite crossings: the fuzzer found both), so its
//     term theta n_z may be anything in [-pi, pi] in either path: + 1 (2 pi / 2 pi) in place of its
//     first-order terms. Above 64 delta its normal moves by less than 1/32 and first order holds.
// The comparison is made where the derivation applies: a finite tolerance and kappa_p <= 1e3
// (first order: 1e3 u << 1); items the kernel must hand back must match exactly.
template <typename Policy, typename T>
double batch_tolerance(const glm::mat<3, 3, T>& mi, const std::vector<glm::vec<3, T>>& p, std::size_t n,
                       double kappa_p) {
    using vec3 = glm::vec<3, T>;
    if (n < 3) return 0;
    const double u = static_cast<double>(std::numeric_limits<T>::epsilon()) / 2;
    const double m = static_cast<double>(ltc::clipped_capacity(n));
    double sum = 0, kappa_x = 1, jumps = 0;
    const ltc::detail::transformed_vertices<T> at{mi, p.data()};
    for (std::size_t k = 0; k < n; ++k) {
        const glm::dvec3 a(at(k == 0 ? n - 1 : k - 1)), b(at(k));
        if ((a.z >= 0) == (b.z >= 0)) continue;
        const glm::dvec3 up = a.z >= 0 ? a : b, down = a.z >= 0 ? b : a;
        const glm::dvec3 x = up * (-down.z) + down * up.z;
        const double kappa = (std::abs(up.z) + std::abs(down.z)) / std::max(glm::length(x), 1e-300);
        kappa_x = std::max(kappa_x, kappa);
        sum += 8 * kappa * (2 + theta_over_sin(glm::normalize(glm::dvec3(x.x, x.y, 0)), up));
    }
    const double delta = 8 * u * kappa_p * kappa_x;
    ltc::detail::for_each_unit_edge<T, true>(at, n, [&](const vec3& a, const vec3& b, const vec3&) {
        const glm::dvec3 ad(a), bd(b);
        if (glm::dot(ad, bd) < 0 && glm::length(glm::cross(ad, bd)) < 64 * delta) {
            jumps += 1;
            return;
        }
        const double e = std::abs(static_cast<double>(ltc::edge_integral_z<Policy>(a, b)));
        const double t = theta_over_sin(ad, bd);
        sum += (32 + 2 * m) * e + 8 * (1 + t);
        if (a.z == T(0) && b.z == T(0)) sum += 8 * kappa_x * (1 + t);
    });
    return kappa_p * sum * u / (2 * 3.141592653589793) + jumps;
}

template <typename T>
[[noreturn]] void batch_failure(const char* what, const char* policy, bool quads, std::size_t n, ltc::sidedness s,
                                ltc::batch::isa which, std::size_t i, const batch_items<T>& it, T out, T ref,
                                double tol) {
    std::fprintf(stderr,
                 "batch %s: %s %s n=%zu %s isa=%d item %zu of %zu (%s matrix): out=%.9g scalar=%.9g |diff|=%.3g "
                 "tolerance=%.3g\n",
                 what, quads ? "integrate_quads" : "integrate_ngons", policy, n,
                 s == ltc::sidedness::two_sided ? "two_sided" : "one_sided", static_cast<int>(which), i, it.count,
                 it.shared ? "shared" : "per-item", static_cast<double>(out), static_cast<double>(ref),
                 std::abs(static_cast<double>(out) - static_cast<double>(ref)), tol);
    const auto& mi = it.m_inv[i];
    std::fprintf(stderr, "  M^-1 (columns): (%a %a %a) (%a %a %a) (%a %a %a)\n", static_cast<double>(mi[0][0]),
                 static_cast<double>(mi[0][1]), static_cast<double>(mi[0][2]), static_cast<double>(mi[1][0]),
                 static_cast<double>(mi[1][1]), static_cast<double>(mi[1][2]), static_cast<double>(mi[2][0]),
                 static_cast<double>(mi[2][1]), static_cast<double>(mi[2][2]));
    for (std::size_t k = 0; k < n; ++k)
        std::fprintf(stderr, "  p%zu = (%a, %a, %a)\n", k, static_cast<double>(it.p[i][k].x),
                     static_cast<double>(it.p[i][k].y), static_cast<double>(it.p[i][k].z));
    std::abort();
}

template <typename Policy, typename T>
void check_batch_policy(const batch_items<T>& it, bool quads, std::size_t n, const char* policy,
                        ltc::batch::isa which, ltc::sidedness s) {
    const auto mats = it.matrices();
    ltc::batch::quad_soa<T> quad;
    ltc::batch::ngon_soa<T> ngon;
    quad.m_inv = ngon.m_inv = mats;
    for (std::size_t k = 0; k < 4 && k < it.nv; ++k) quad.x[k] = it.px[k], quad.y[k] = it.py[k], quad.z[k] = it.pz[k];
    ngon.n = n, ngon.x = it.px.data(), ngon.y = it.py.data(), ngon.z = it.pz.data();
    const double bound = static_cast<double>(ltc::clipped_capacity(n)) / 2 * (1 + 1e-3);
    // Each item's tolerance, whether it must match exactly, and whether the comparison applies:
    // computed where first needed (a result that differs from the scalar path's), as they cost
    // more than the integrals (long double, per vertex), and most results match.
    struct bounds {
        bool known = false, exact = false, comparable = false;
        double tol = 0;
    };
    std::vector<bounds> b(it.count);
    const auto at = [&](std::size_t i) -> const bounds& {
        bounds& r = b[i];
        if (!r.known) {
            long double kappa = 1;
            conditioning(it.m_inv[i], it.p[i], n, r.exact, kappa);
            r.tol = batch_tolerance<Policy>(it.m_inv[i], it.p[i], n, static_cast<double>(kappa));
            r.comparable = std::isfinite(r.tol) && kappa <= 1e3L;
            r.known = true;
        }
        return r;
    };
    std::vector<T> ref(it.count);
    for (std::size_t i = 0; i < it.count; ++i) {
        const auto d = ltc::transformed<ltc::clamped_cosine<T, Policy>>::from_inverse(it.m_inv[i]);
        ref[i] = d.integrate(it.p[i].data(), n, s);
        if (!std::isfinite(ref[i]) || !(ref[i] >= T(0)) || !(static_cast<double>(ref[i]) <= bound))
            batch_failure("scalar path out of range", policy, quads, n, s, ltc::batch::isa::scalar, i, it, ref[i],
                          ref[i], 0.0);
        // The reference only sees directions: each vertex brought to a largest component in
        // [1, 2) by an exact power of two (rescale_pow2) gives the same integral, up to the
        // normalization's rounding, which tol covers. Else the comparisons below would accept
        // a batch that shares an error of the scalar path (one that depends on the vertices'
        // lengths, say).
        std::vector<glm::vec<3, T>> unit_scale(it.p[i].begin(), it.p[i].begin() + static_cast<std::ptrdiff_t>(n));
        for (auto& q : unit_scale) q = ltc::detail::rescale_pow2(q);
        const T same = d.integrate(unit_scale.data(), n, s);
        if (same != ref[i] && at(i).comparable &&
            !(std::abs(static_cast<double>(ref[i]) - static_cast<double>(same)) <= at(i).tol))
            batch_failure("scalar path depends on the vertices' lengths (out: as given, scalar: rescaled)", policy,
                          quads, n, s, ltc::batch::isa::scalar, i, it, ref[i], same, at(i).tol);
    }
    std::vector<T> out(it.count, T(-1));
    if (quads)
        ltc::batch::integrate_quads<Policy>(quad, out.data(), it.count, s, which);
    else
        ltc::batch::integrate_ngons<Policy>(ngon, out.data(), it.count, s, which);
    const std::size_t vectorized = kernel_items<T>(which, it.count);
    for (std::size_t i = 0; i < it.count; ++i) {
        const T o = out[i];
        if (!std::isfinite(o)) batch_failure("non-finite", policy, quads, n, s, which, i, it, o, ref[i], at(i).tol);
        if (!(o >= T(0))) batch_failure("negative", policy, quads, n, s, which, i, it, o, ref[i], at(i).tol);
        if (!(static_cast<double>(o) <= bound))
            batch_failure("above m / 2", policy, quads, n, s, which, i, it, o, ref[i], at(i).tol);
        if (o == ref[i]) continue;
        if (i >= vectorized || at(i).exact)
            batch_failure("differs from the scalar path it must be", policy, quads, n, s, which, i, it, o, ref[i],
                          0.0);
        if (at(i).comparable && !(std::abs(static_cast<double>(o) - static_cast<double>(ref[i])) <= at(i).tol))
            batch_failure("beyond tolerance", policy, quads, n, s, which, i, it, o, ref[i], at(i).tol);
    }
}

// Quads (integrate_quads, the fixed-N kernel) or a runtime-n batch (integrate_ngons, n in
// 0..18: n < 3, the unrolled and rolled edge loops, and the scalar path's heap buffer for n > 16),
// per-item or shared matrices, either sidedness, either SIMD policy, any instruction set this CPU
// runs.
template <typename T>
void check_batch(FuzzedDataProvider& in, const glm::mat<3, 3, T>& m, const std::vector<glm::vec<3, T>>& v) {
    const std::size_t n = (in.ConsumeIntegral<std::uint8_t>() + 5u) % 19u;  // 5 for input that has run out
    const batch_items<T> it = make_items<T>(in, m, v, std::max<std::size_t>(n, 4));
    // One shape, one policy, one instruction set and one sidedness per input (a fuzzed choice):
    // four batch checks per input slowed the whole harness, the scalar checks included, 13-fold;
    // over a run the choices cover every combination.
    const unsigned choice = in.ConsumeIntegral<std::uint8_t>();
    const bool quads = (choice & 1u) == 0u;
    const std::size_t nk = quads ? 4 : n;
    const std::vector<ltc::batch::isa> isas = batch_isas();
    const ltc::batch::isa which = isas[((choice >> 2) & 3u) % isas.size()];
    const ltc::sidedness side = (choice & 16u) == 0u ? ltc::sidedness::two_sided : ltc::sidedness::one_sided;
    if ((choice & 2u) == 0u)
        check_batch_policy<ltc::edge_policy::minimax_rational>(it, quads, nk, "minimax_rational", which, side);
    else
        check_batch_policy<ltc::edge_policy::polynomial>(it, quads, nk, "polynomial", which, side);
}

}  // namespace ltc_fuzz
