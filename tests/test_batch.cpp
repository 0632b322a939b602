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
//   - the normalization: the kernel takes c = (p.q) r and (p x q).z r with one
//     r = rsqrt(|p|^2 |q|^2) per edge (hardware estimate and one Newton step: <= 4.5 u, measured
//     3.4 u) where the scalar path divides each vertex by its length; c and the term's factors
//     agree to a few u. A term changes by a few u relative to itself (|e_j - e_j'| <= 32 u |e_j|
//     with slack), plus, from the endpoints' directions, 8 u (1 + theta_j / sin theta_j)
//     absolute (the derivative of theta n_z with respect to an endpoint's direction);
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
#include <ltc/shading/batch.hpp>
#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/transformed.hpp>

#include "support/clip_comparison.hpp"
#include "support/rng.hpp"

#include <catch2/catch.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace {

using ltc_test::random_matrix;
using ltc_test::random_polygon;

// count items of n vertices, SoA, float; owns its arrays.
struct items {
    std::size_t n = 0, count = 0;
    std::vector<float> m[3][3];
    std::vector<std::vector<float>> x, y, z;

    items(std::size_t n_, std::size_t count_) : n(n_), count(count_), x(n_), y(n_), z(n_) {
        for (auto& col : m)
            for (auto& e : col) e.resize(count_);
        for (std::size_t k = 0; k < n; ++k) x[k].resize(count), y[k].resize(count), z[k].resize(count);
    }
    void set(std::size_t i, const glm::mat3& mi, const std::vector<glm::vec3>& v) {
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) m[c][r][i] = mi[c][r];
        for (std::size_t k = 0; k < n; ++k) x[k][i] = v[k].x, y[k][i] = v[k].y, z[k][i] = v[k].z;
    }
    glm::mat3 matrix(std::size_t i) const {
        glm::mat3 mi;
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) mi[c][r] = m[c][r][i];
        return mi;
    }
    std::vector<glm::vec3> polygon(std::size_t i) const {
        std::vector<glm::vec3> v(n);
        for (std::size_t k = 0; k < n; ++k) v[k] = glm::vec3(x[k][i], y[k][i], z[k][i]);
        return v;
    }
    ltc::batch::matrices<float> per_item() const {
        const float* e[3][3];
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) e[c][r] = m[c][r].data();
        return ltc::batch::matrices<float>::per_item(e);
    }
    template <std::size_t N>
    ltc::batch::polygon_soa<float, N> soa(const ltc::batch::matrices<float>& mats) const {
        ltc::batch::polygon_soa<float, N> p;
        p.m_inv = mats;
        for (std::size_t k = 0; k < N; ++k) p.x[k] = x[k].data(), p.y[k] = y[k].data(), p.z[k] = z[k].data();
        return p;
    }
};

// Pointer tables for the runtime-n API (kept alive by the caller).
struct ngon_view {
    std::vector<const float*> x, y, z;
    ltc::batch::ngon_soa<float> soa;
    ngon_view(const items& it, const ltc::batch::matrices<float>& mats) {
        for (std::size_t k = 0; k < it.n; ++k)
            x.push_back(it.x[k].data()), y.push_back(it.y[k].data()), z.push_back(it.z[k].data());
        soa.m_inv = mats;
        soa.n = it.n;
        soa.x = x.data(), soa.y = y.data(), soa.z = z.data();
    }
};

// The instruction sets to test here: every one this build and CPU run.
std::vector<ltc::batch::isa> isas() {
    std::vector<ltc::batch::isa> v;
    for (const auto i : {ltc::batch::isa::scalar, ltc::batch::isa::baseline, ltc::batch::isa::avx2})
        if (ltc::batch::available(i)) v.push_back(i);
    return v;
}

template <typename Policy>
float scalar_value(const glm::mat3& mi, const std::vector<glm::vec3>& v, ltc::sidedness s) {
    return ltc::transformed<ltc::clamped_cosine<float, Policy>>::from_inverse(mi).integrate(v.data(), v.size(), s);
}

struct comparison {
    std::size_t violations = 0, crossing = 0, nonfinite = 0;
    unsigned masks_seen = 0;  // quads: bit k set where some item has the clip mask k
    double worst_ratio = 0;  // max |batch - scalar| / tolerance, where it occurs, and the values there
    std::size_t worst = 0;
    double worst_batch = 0, worst_scalar = 0, worst_tol = 0;
};

template <typename Policy>
comparison compare(const items& it, const std::vector<float>& out, ltc::sidedness s, const glm::mat3* shared = nullptr) {
    comparison c;
    for (std::size_t i = 0; i < it.count; ++i) {
        const glm::mat3 mi = shared ? *shared : it.matrix(i);
        const auto v = it.polygon(i);
        const float ref = scalar_value<Policy>(mi, v, s);
        const double tol = ltc_test::clip_tolerance<Policy>(mi, v);
        const double err = std::abs(static_cast<double>(out[i]) - static_cast<double>(ref));
        if (!std::isfinite(out[i])) ++c.nonfinite;
        if (!(err <= tol)) ++c.violations;
        const double ratio = err == 0 ? 0 : err / tol;
        if (ratio > c.worst_ratio) c.worst_ratio = ratio, c.worst = i, c.worst_batch = out[i], c.worst_scalar = ref, c.worst_tol = tol;
        bool below = false, above = false;
        unsigned mask = 0;
        for (std::size_t k = 0; k < v.size(); ++k) {
            const float qz = (mi * v[k]).z;
            below = below || qz < 0, above = above || qz >= 0;
            mask |= (qz >= 0 ? 1u : 0u) << (k % 16);
        }
        if (v.size() == 4) c.masks_seen |= 1u << mask;
        c.crossing += below && above;
    }
    return c;
}

// A planar arrowhead quad (tip, wing, reflex vertex, wing) whose wings are below the horizon and
// tip and reflex vertex above (mask 0101; 1010 with `shift`): two runs above the horizon, which
// random_polygon's star-shaped quads never give. Random size, tilt and azimuth.
std::vector<glm::vec3> two_run_quad(ltc_test::rng& g, bool shift) {
    const double tilt = g.uniform(0.3, 1.3), phi = g.uniform(0, 2 * ltc_test::kPi), size = g.uniform(0.3, 1.5);
    const double uv[4][2] = {{0, 2}, {1, -1}, {0, 0}, {-1, -1}};  // horizon at v = -0.5
    const glm::dvec3 eu(std::cos(phi), std::sin(phi), 0);
    const glm::dvec3 ev(-std::sin(phi) * std::cos(tilt), std::cos(phi) * std::cos(tilt), std::sin(tilt));
    const glm::dvec3 o = g.uniform(0.5, 2) * glm::dvec3(-std::sin(phi), std::cos(phi), 0) + 0.5 * size * ev;
    std::vector<glm::vec3> v(4);
    for (std::size_t k = 0; k < 4; ++k) {
        const auto& p = uv[(k + shift) % 4];
        v[k] = glm::vec3(o + size * (p[0] * eu + p[1] * ev));
    }
    return v;
}

items random_items(std::size_t n, std::size_t count, std::uint64_t seed, bool convex, bool general_matrix) {
    ltc_test::rng g(seed);
    items it(n, count);
    for (std::size_t i = 0; i < count; ++i) {
        const glm::mat3 m = random_matrix(g, general_matrix);  // two statements: a fixed order of draws
        if (n == 4 && !convex && i % 8 == 0)
            it.set(i, glm::mat3(1.0f), two_run_quad(g, i % 16 == 0));
        else
            it.set(i, m, random_polygon(g, n, convex, i % 2 == 1));
    }
    return it;
}

#define CHECK_COMPARISON(c, count)                                   \
    do {                                                             \
        CAPTURE((c).worst_ratio, (c).worst, (c).crossing);           \
        CAPTURE((c).worst_batch, (c).worst_scalar, (c).worst_tol);   \
        CHECK((c).violations == 0);                                  \
        CHECK((c).nonfinite == 0);                                   \
        CHECK((c).crossing > (count) / 5); /* the clipper is exercised */ \
    } while (0)

}  // namespace

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
