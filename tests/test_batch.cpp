// ltc/shading/batch.hpp against the scalar path it vectorizes:
//   transformed<clamped_cosine<T, Policy>>::from_inverse(m_inv).integrate(P, n, s)
// on thousands of random quads and n-gons crossing the horizon (convex and non-convex, both
// windings, every clip mask, per-item and shared matrices, one- and two-sided), on degenerate
// input, with every instruction set this machine runs (isa::scalar, baseline, avx2).
//
// Tolerance (derived, per item; see tolerance() below). Both paths clip the same polygon (the
// in/out tests see the sign of (M^-1 p).z, computed in the same order; with FMA a vertex within
// an ulp of the horizon may change sides, which moves the polygon by less than the bound) and sum
// the same edge terms e_j, j < m, in another order, so they differ only by rounding (u = 2^-24):
//   - the normalization: the kernel multiplies each vertex and crossing by rsqrt of its squared
//     length (hardware estimate and one Newton step: <= 4.5 u, measured 3.4 u) where the scalar
//     path divides by its length; the unit vectors agree to a few u. A term changes by a few u
//     relative to itself (|e_j - e_j'| <= 32 u |e_j| with slack), plus, from the endpoints'
//     directions, 8 u (1 + theta_j / sin theta_j) absolute (the derivative of theta n_z with
//     respect to an endpoint's direction);
//   - rational and fp16_quadratic take sin(theta) from sqrt(1 - c^2): for c < 0 the term's
//     relative change is |c| / (1 - c^2) times that of c (up to their clamps): + 8 k_j u |e_j|
//     (they run the scalar path in the batch, so they match exactly; the bound stays general);
//   - a horizon crossing X = in (-out.z) + out in.z cancels when in and out are nearly opposite;
//     X's direction then moves by kappa_X = (|in.z| + |out.z|) / |X| times the vertices' rounding,
//     and the two terms at X by (2 + theta / sin theta) times that: 8 kappa_X (2 + t_X) u;
//   - recursive summation of m <= n + n / 2 terms in each path: 2 m u sum_j |e_j|;
//   - / (2 pi), the sign and the sidedness are identical operations.
// Items the batch hands to the scalar path (tiny or huge vertices) must match it exactly; a vertex
// at the origin or a polygon entirely below the horizon gives exactly 0.
#include "support/batch_items.hpp"
#include "support/clip_comparison.hpp"
#include "support/rng.hpp"

#include <ltc/shading/batch.hpp>

#include <catch2/catch.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace ltc_test_batch {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test;  // support/batch_items.hpp

TEMPLATE_TEST_CASE("batch quads match the scalar path", "[batch]", ltc::edge_policy::polynomial,
                   ltc::edge_policy::minimax_rational,
                   ltc::edge_policy::rational, ltc::edge_policy::fp16_quadratic, ltc::edge_policy::exact) {
    using Policy = TestType;
    const std::size_t count = 4099;  // not a multiple of any vector width: the tail runs
    for (const auto isa : isas())
        for (const bool general : {false, true})
            for (const bool convex : {true, false})
                for (const auto s : {ltc::sidedness::two_sided, ltc::sidedness::one_sided}) {
                    const items it = random_items(4, count, 77 + 2 * general + convex, convex, general);
                    std::vector<float> out(count, -1.0f);
                    ltc::batch::integrate_quads<Policy>(it.soa<4>(it.per_item()), out.data(), count, s, isa);
                    const comparison c = compare<Policy>(it, out, s);
                    CAPTURE(static_cast<int>(isa), general, convex, s == ltc::sidedness::two_sided);
                    CHECK_COMPARISON(c, count);
                    // Every clip mask: the 14 a convex quad can have (not 0101, 1010), all 16 else.
                    CHECK(c.masks_seen == (convex ? 0xfbdfu : 0xffffu));
                }
}

TEST_CASE("batch n-gons (fixed and runtime n) match the scalar path", "[batch]") {
    using Policy = ltc::edge_policy::minimax_rational;
    const std::size_t count = 2053;
    for (const auto isa : isas())
        for (std::size_t n = 3; n <= 12; ++n)
            for (const bool convex : {true, false}) {
                if (!convex && n < 4) continue;
                const items it = random_items(n, count, 1000 + 10 * n + convex, convex, true);
                const auto mats = it.per_item();
                const ngon_view view(it, mats);
                for (const auto s : {ltc::sidedness::two_sided, ltc::sidedness::one_sided}) {
                    CAPTURE(static_cast<int>(isa), n, convex, s == ltc::sidedness::two_sided);
                    std::vector<float> out(count, -1.0f);
                    ltc::batch::integrate_ngons<Policy>(view.soa, out.data(), count, s, isa);
                    const comparison c = compare<Policy>(it, out, s);
                    CHECK_COMPARISON(c, count);
                    std::vector<float> blocked(count, -1.0f);
                    ltc::batch::integrate_ngons_blocked<Policy>(view.soa, blocked.data(), count, s, isa);
                    CHECK(blocked == out);
                }
            }
    // Fixed-n API with n as a template parameter, polynomial policy.
    const items it = random_items(6, count, 4242, false, false);
    std::vector<float> out(count);
    for (const auto isa : isas()) {
        ltc::batch::integrate_polygons<ltc::edge_policy::polynomial>(it.soa<6>(it.per_item()), out.data(), count,
                                                                     ltc::sidedness::two_sided, isa);
        const comparison c = compare<ltc::edge_policy::polynomial>(it, out, ltc::sidedness::two_sided);
        CHECK_COMPARISON(c, count);
    }
}

TEST_CASE("batch with one shared matrix", "[batch]") {
    using Policy = ltc::edge_policy::minimax_rational;  // the batch's default
    const std::size_t count = 3001;
    ltc_test::rng g(99);
    const glm::mat3 shared = random_matrix(g, true);
    items it = random_items(4, count, 98, true, false);
    const auto mats = ltc::batch::matrices<float>::same_for_all(shared);
    const ngon_view view(it, mats);
    for (const auto isa : isas()) {
        CAPTURE(static_cast<int>(isa));
        std::vector<float> out(count);
        ltc::batch::integrate_quads(it.soa<4>(mats), out.data(), count, ltc::sidedness::two_sided, isa);
        const comparison c = compare<Policy>(it, out, ltc::sidedness::two_sided, &shared);
        CHECK_COMPARISON(c, count);
        ltc::batch::integrate_ngons(view.soa, out.data(), count, ltc::sidedness::one_sided, isa);
        const comparison cb = compare<Policy>(it, out, ltc::sidedness::one_sided, &shared);
        CHECK_COMPARISON(cb, count);
    }
}

TEST_CASE("batch degenerate input: origin, below, touching, tiny and huge", "[batch]") {
    using Policy = ltc::edge_policy::minimax_rational;
    ltc_test::rng g(5);
    const glm::mat3 id(1.0f);
    std::vector<glm::mat3> ms;
    std::vector<std::vector<glm::vec3>> ps;
    std::vector<std::string> what;
    const auto add = [&](const std::string& w, const glm::mat3& m, std::vector<glm::vec3> v) {
        what.push_back(w), ms.push_back(m), ps.push_back(std::move(v));
    };
    for (int rep = 0; rep < 50; ++rep) {
        const glm::mat3 m = random_matrix(g, rep % 2 == 1);
        auto v = random_polygon(g, 4, true, rep % 3 == 0);
        auto at_origin = v;
        at_origin[static_cast<std::size_t>(rep % 4)] = glm::vec3(0.0f);
        add("vertex at origin", m, at_origin);
        auto below = v;
        for (auto& p : below) p.z = -std::abs(p.z) - 0.1f;
        add("all below", id, below);
        auto touching = v;  // one vertex exactly on the horizon, the others below
        for (auto& p : touching) p.z = -std::abs(p.z) - 0.1f;
        touching[1].z = 0.0f;
        add("vertex touching from below", id, touching);
        auto edge_on = v;  // an edge lying on the horizon, the rest above
        for (auto& p : edge_on) p.z = std::abs(p.z) + 0.1f;
        edge_on[0].z = edge_on[1].z = 0.0f;
        add("edge on the horizon", id, edge_on);
        auto flat = v;  // the whole polygon in the horizon plane
        for (auto& p : flat) p.z = 0.0f;
        add("polygon in the horizon plane", id, flat);
        auto tiny = v, huge = v;
        for (auto& p : tiny) p *= 1e-20f;
        for (auto& p : huge) p *= 1e20f;
        add("tiny (scalar fallback)", m, tiny);
        add("huge (scalar fallback)", m, huge);
        auto repeated = v;
        repeated[2] = repeated[1];
        add("repeated vertex", m, repeated);
        add("whole polygon above", id, [&] { auto a = v; for (auto& p : a) p.z = std::abs(p.z) + 0.2f; return a; }());
        auto through = v;  // an edge whose line passes through the shading point
        through[1] = -through[0];
        add("edge through the origin", id, through);
    }
    const std::size_t count = ps.size();
    items it(4, count);
    for (std::size_t i = 0; i < count; ++i) it.set(i, ms[i], ps[i]);
    for (const auto isa : isas())
    for (const auto s : {ltc::sidedness::two_sided, ltc::sidedness::one_sided}) {
        std::vector<float> out(count, -1.0f);
        ltc::batch::integrate_quads<Policy>(it.soa<4>(it.per_item()), out.data(), count, s, isa);
        for (std::size_t i = 0; i < count; ++i) {
            const float ref = scalar_value<Policy>(ms[i], ps[i], s);
            CAPTURE(static_cast<int>(isa), what[i], i, out[i], ref);
            REQUIRE(std::isfinite(out[i]));
            if (what[i] == "vertex at origin" || what[i] == "all below") {
                CHECK(out[i] == 0.0f);
                CHECK(ref == 0.0f);
            } else if (what[i].find("fallback") != std::string::npos) {
                CHECK(out[i] == ref);  // recomputed by the scalar path: identical
            } else {
                const double tol = ltc_test::clip_tolerance<Policy>(ms[i], ps[i]);
                CHECK(std::abs(static_cast<double>(out[i]) - ref) <= tol);
            }
        }
    }
}

TEST_CASE("batch n < 3 and empty batches give 0 / do nothing", "[batch]") {
    items it(2, 5);
    std::vector<float> out(5, -1.0f);
    const auto mats = ltc::batch::matrices<float>::same_for_all(glm::mat3(1.0f));
    const ngon_view view(it, mats);
    ltc::batch::integrate_ngons(view.soa, out.data(), 5, ltc::sidedness::two_sided);
    for (float v : out) CHECK(v == 0.0f);
    ltc::batch::integrate_quads(ltc::batch::quad_soa<float>{}, static_cast<float*>(nullptr), 0, ltc::sidedness::two_sided);
}

TEST_CASE("batch in double matches the double scalar path", "[batch]") {
    // The float tolerance of the same item scaled from float's u to double's (2^-53 / 2^-24): the
    // derivation above is linear in u; the items are the float test items, widened exactly.
    using Policy = ltc::edge_policy::minimax_rational;
    const std::size_t count = 1031;
    const items it = random_items(4, count, 2024, true, true);
    std::vector<double> m[3][3], x[4], y[4], z[4];
    for (std::size_t i = 0; i < count; ++i) {
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) m[c][r].push_back(it.m[c][r][i]);
        for (std::size_t k = 0; k < 4; ++k) x[k].push_back(it.x[k][i]), y[k].push_back(it.y[k][i]), z[k].push_back(it.z[k][i]);
    }
    const double* e[3][3];
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) e[c][r] = m[c][r].data();
    ltc::batch::quad_soa<double> soa;
    soa.m_inv = ltc::batch::matrices<double>::per_item(e);
    for (std::size_t k = 0; k < 4; ++k) soa.x[k] = x[k].data(), soa.y[k] = y[k].data(), soa.z[k] = z[k].data();
    for (const auto isa : isas())
        for (const auto s : {ltc::sidedness::two_sided, ltc::sidedness::one_sided}) {
            std::vector<double> out(count, -1.0);
            ltc::batch::integrate_quads<Policy>(soa, out.data(), count, s, isa);
            std::size_t violations = 0;
            double worst = 0;
            for (std::size_t i = 0; i < count; ++i) {
                const auto v = it.polygon(i);
                std::vector<glm::dvec3> vd(v.begin(), v.end());
                const double ref = ltc::transformed<ltc::clamped_cosine<double, Policy>>::from_inverse(glm::dmat3(it.matrix(i)))
                                       .integrate(vd.data(), 4, s);
                const double tol = ltc_test::clip_tolerance<Policy>(it.matrix(i), v) * 0x1p-29;
                const double err = std::abs(out[i] - ref);
                violations += !(err <= tol);
                worst = std::max(worst, err / tol);
            }
            CAPTURE(static_cast<int>(isa), s == ltc::sidedness::two_sided, worst);
            CHECK(violations == 0);
        }
}

TEST_CASE("batch instruction sets: resolve falls back to the widest available one", "[batch]") {
    using ltc::batch::isa;
    CHECK(ltc::batch::available(isa::automatic));
    CHECK(ltc::batch::available(isa::scalar));
    CHECK(ltc::batch::resolve(isa::scalar) == isa::scalar);
    isa widest = isa::scalar;
    for (const isa i : ltc::batch::instruction_sets) {
        if (!ltc::batch::available(i)) continue;
        CHECK(ltc::batch::resolve(i) == i);
        widest = i;
    }
    CHECK(ltc::batch::resolve(isa::automatic) == widest);
    // An unavailable request runs the next narrower set that is available.
    isa below = isa::scalar;
    for (const isa i : ltc::batch::instruction_sets) {
        if (!ltc::batch::available(i)) CHECK(ltc::batch::resolve(i) == below);
        else below = i;
    }
    const std::size_t widths[] = {1, 4, 8, 16};
    for (std::size_t k = 0; k < std::size(widths); ++k) {
        const isa i = ltc::batch::instruction_sets[k];
        if (!ltc::batch::available(i)) continue;
        CHECK(ltc::batch::lane_count<float>(i) == widths[k]);
        CHECK(ltc::batch::lane_count<double>(i) == std::max<std::size_t>(widths[k] / 2, 1));
    }
}

#if LTC_SIMD
namespace {

// simd::<isa>::gather through a function compiled for that instruction set (the primitives are
// always inlined, so their caller must carry the same target; arrays in and out, since a vector
// passed to a function of another target changes the ABI): out[k] = base[index[k]], widened to T.
template <typename T, std::size_t Bytes>
struct gather_lanes {
    using types = ltc::simd::vector_types<T, Bytes>;
    using vf = typename types::vf;
    using vi = typename types::vi;
    static constexpr std::size_t width = types::width;
};

template <typename T>
void gather_baseline(const float* base, const int* index, T* out) {
    using L = gather_lanes<T, 16>;
    typename L::vi idx{};
    for (std::size_t k = 0; k < L::width; ++k) idx[k] = index[k];
    const typename L::vf v = ltc::simd::baseline::gather<typename L::vf>(base, idx);
    for (std::size_t k = 0; k < L::width; ++k) out[k] = v[k];
}
#if LTC_SIMD_AVX2
template <typename T>
LTC_SIMD_AVX2_TARGET void gather_avx2(const float* base, const int* index, T* out) {
    using L = gather_lanes<T, 32>;
    typename L::vi idx{};
    for (std::size_t k = 0; k < L::width; ++k) idx[k] = index[k];
    const typename L::vf v = ltc::simd::avx2::gather<typename L::vf>(base, idx);
    for (std::size_t k = 0; k < L::width; ++k) out[k] = v[k];
}
#endif
#if LTC_SIMD_AVX512
template <typename T>
LTC_SIMD_AVX512_TARGET void gather_avx512(const float* base, const int* index, T* out) {
    using L = gather_lanes<T, 64>;
    typename L::vi idx{};
    for (std::size_t k = 0; k < L::width; ++k) idx[k] = index[k];
    const typename L::vf v = ltc::simd::avx512::gather<typename L::vf>(base, idx);
    for (std::size_t k = 0; k < L::width; ++k) out[k] = v[k];
}
#endif

template <typename T, std::size_t Bytes>
void check_gather(const char* name, const std::vector<float>& table, const std::vector<int>& index) {
    constexpr std::size_t width = ltc::simd::vector_types<T, Bytes>::width;
    std::vector<T> got(width, T(1234));
    if constexpr (Bytes == 16) gather_baseline<T>(table.data(), index.data(), got.data());
#if LTC_SIMD_AVX2
    if constexpr (Bytes == 32) gather_avx2<T>(table.data(), index.data(), got.data());
#endif
#if LTC_SIMD_AVX512
    if constexpr (Bytes == 64) gather_avx512<T>(table.data(), index.data(), got.data());
#endif
    INFO(name << (std::is_same_v<T, float> ? " float" : " double"));
    for (std::size_t k = 0; k < width; ++k) {  // exact, the sign of zero included
        CHECK(got[k] == T(table[std::size_t(index[k])]));
        CHECK(std::signbit(got[k]) == std::signbit(table[std::size_t(index[k])]));
    }
}

}  // namespace

TEST_CASE("simd gather: lane k loads base[index[k]], widened exactly, on every instruction set", "[batch]") {
    // Distinct values, a subnormal, a negative zero and the largest float among them; indices
    // out of order, repeated, and at both ends of the array (the kernel's table fetch).
    std::vector<float> table(97);
    for (std::size_t i = 0; i < table.size(); ++i) table[i] = float(i) * 1.25f - 40.0f + 1.0f / float(i + 3);
    table[5] = std::numeric_limits<float>::denorm_min();
    table[6] = -0.0f;
    table[96] = std::numeric_limits<float>::max();
    const std::vector<int> index = {96, 0, 5, 6, 17, 17, 95, 1, 42, 96, 3, 60, 2, 88, 6, 0};
    check_gather<float, 16>("baseline", table, index);
    check_gather<double, 16>("baseline", table, index);
    if (ltc::batch::available(ltc::batch::isa::avx2)) {
        check_gather<float, 32>("avx2", table, index);
        check_gather<double, 32>("avx2", table, index);
    }
    if (ltc::batch::available(ltc::batch::isa::avx512)) {
        check_gather<float, 64>("avx512", table, index);
        check_gather<double, 64>("avx512", table, index);
    }
}
#endif

}  // namespace ltc_test_batch
