// Tests of ltc/fitting/fit.hpp, ltc/shading/table.hpp and ltc/shading/ggx_fetch.hpp: the lookup of the shipped GGX table
// (exact at nodes, bilinear between them, clamped and finite everywhere), the table's consistency
// with a re-fit, the determinism of the fit across thread counts, and two properties of the
// fitted distributions (energy over the hemisphere, the cosine at roughness 1).
// No 64 x 64 fit happens here: the re-fits are a few rows, the thread test an 8 x 8 table.
#include <catch2/catch.hpp>

#include <ltc/fitting/brdf/ggx.hpp>
#include <ltc/core/clamped_cosine.hpp>
#include <ltc/fitting/fit.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/shading/table.hpp>
#include <ltc/core/transformed.hpp>

#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace {

constexpr int n = ltc::tables::ggx_size;
const ltc::ltc_table& shipped = ltc::ggx::table;

/// The table's own fit options (the defaults that ltc_fit uses).
ltc::fit::options table_options() {
    ltc::fit::options opt;
    opt.size = n;
    return opt;
}

template <typename T>
std::array<T, 6> channels_of(const ltc::ltc_coefficients<T>& c) {
    return {c.m_inv[0][0], c.m_inv[0][2], c.m_inv[2][0], c.m_inv[2][2], c.magnitude, c.fresnel};
}

template <typename T>
bool all_finite(const ltc::ltc_coefficients<T>& c) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (!std::isfinite(c.m_inv[i][j])) return false;
    return std::isfinite(c.magnitude) && std::isfinite(c.fresnel);
}

template <typename T>
bool same(const ltc::ltc_coefficients<T>& a, const ltc::ltc_coefficients<T>& b) {
    return channels_of(a) == channels_of(b) && a.m_inv == b.m_inv;
}

/// A quad that covers the upper hemisphere but for a band of 1e-6 rad above the horizon.
const glm::dvec3 hemisphere_quad[4] = {{1e6, 1e6, 1}, {-1e6, 1e6, 1}, {-1e6, -1e6, 1}, {1e6, -1e6, 1}};

}  // namespace

TEMPLATE_TEST_CASE("fetch returns the stored nodes exactly at node coordinates", "[fit][table]", float, double) {
    using T = TestType;
    REQUIRE(shipped.width() == 64);
    REQUIRE(shipped.height() == 64);
    int mismatches = 0;
    for (int a = 0; a < n; ++a)
        for (int t = 0; t < n; ++t) {
            const T x = T(t) / T(n - 1);
            const T cos_theta = T(1) - x * x;
            const T roughness = T(a) / T(n - 1);
            const auto c = channels_of(ltc::ggx::fetch(cos_theta, roughness));
            for (int k = 0; k < ltc::channel::count; ++k)
                if (c[std::size_t(k)] != T(shipped.node(t, a, k))) {
                    ++mismatches;
                    CAPTURE(t, a, k, c[std::size_t(k)], shipped.node(t, a, k));
                    CHECK(c[std::size_t(k)] == T(shipped.node(t, a, k)));
                }
        }
    CHECK(mismatches == 0);
    // The matrix layout: m_inv[1][1] = 1 and the four structural zeros.
    const auto c = ltc::ggx::fetch(T(0.5), T(0.5));
    CHECK(c.m_inv[1][1] == T(1));
    CHECK(c.m_inv[0][1] == T(0));
    CHECK(c.m_inv[1][0] == T(0));
    CHECK(c.m_inv[1][2] == T(0));
    CHECK(c.m_inv[2][1] == T(0));
}

TEST_CASE("bilinear interpolation midway between nodes is the mean of the nodes", "[fit][table]") {
    for (int a = 0; a + 1 < n; a += 5)
        for (int t = 0; t + 1 < n; t += 3) {
            CAPTURE(t, a);
            double mid[6], edge_u[6], edge_v[6];
            // Both coordinates midway: the mean of four nodes.
            shipped.lookup((t + 0.5) / (n - 1), (a + 0.5) / (n - 1), mid);
            // One coordinate midway, the other on a node: the mean of two.
            shipped.lookup((t + 0.5) / (n - 1), double(a) / (n - 1), edge_u);
            shipped.lookup(double(t) / (n - 1), (a + 0.5) / (n - 1), edge_v);
            for (int k = 0; k < ltc::channel::count; ++k) {
                const double v00 = shipped.node(t, a, k), v10 = shipped.node(t + 1, a, k);
                const double v01 = shipped.node(t, a + 1, k), v11 = shipped.node(t + 1, a + 1, k);
                const double scale = std::abs(v00) + std::abs(v10) + std::abs(v01) + std::abs(v11);
                CHECK(mid[k] == Approx((v00 + v10 + v01 + v11) / 4).margin(1e-14 * scale));
                CHECK(edge_u[k] == Approx((v00 + v10) / 2).margin(1e-14 * scale));
                CHECK(edge_v[k] == Approx((v00 + v01) / 2).margin(1e-14 * scale));
            }
        }
    // fetch() interpolates along roughness the same way (cos theta_v on a node).
    const auto lo = ltc::ggx::fetch(0.75, 10.0 / 63), hi = ltc::ggx::fetch(0.75, 11.0 / 63);
    const auto mid = ltc::ggx::fetch(0.75, 10.5 / 63);
    CHECK(mid.magnitude == Approx((lo.magnitude + hi.magnitude) / 2).epsilon(1e-12));
    CHECK(mid.m_inv[0][0] == Approx((lo.m_inv[0][0] + hi.m_inv[0][0]) / 2).epsilon(1e-12));
}

TEMPLATE_TEST_CASE("fetch is finite and clamps its inputs to 0..1 (NaN to 0)", "[fit][table]", float, double) {
    using T = TestType;
    const T inf = std::numeric_limits<T>::infinity();
    const T nan = std::numeric_limits<T>::quiet_NaN();
    const T big = std::numeric_limits<T>::max();
    const T inputs[] = {-inf, -big, T(-1), T(-1e-30), T(0), T(1e-30), T(0.3), T(1), T(1.5), big, inf, nan};
    for (const T c : inputs)
        for (const T r : inputs) {
            CAPTURE(c, r);
            const auto k = ltc::ggx::fetch(c, r);
            CHECK(all_finite(k));
            const T cc = c > T(0) ? (c < T(1) ? c : T(1)) : T(0);
            const T rc = r > T(0) ? (r < T(1) ? r : T(1)) : T(0);
            CHECK(same(k, ltc::ggx::fetch(cc, rc)));
        }
    CHECK(same(ltc::ggx::fetch(nan, T(0.5)), ltc::ggx::fetch(T(0), T(0.5))));
    CHECK(same(ltc::ggx::fetch(T(0.5), nan), ltc::ggx::fetch(T(0.5), T(0))));
    // Everywhere in between: finite, a positive magnitude, 0 <= fresnel <= magnitude, and an
    // invertible matrix.
    for (int i = 0; i <= 100; ++i)
        for (int j = 0; j <= 100; ++j) {
            const auto k = ltc::ggx::fetch(T(i) / 100, T(j) / 100);
            REQUIRE(all_finite(k));
            REQUIRE(k.magnitude > T(0));
            REQUIRE(k.fresnel >= T(0));
            REQUIRE(k.fresnel <= k.magnitude);
            REQUIRE(std::abs(glm::determinant(k.m_inv)) > T(0));
        }
}

TEST_CASE("the shipped table is what the fit computes (re-fit of three rows)", "[fit][table]") {
    const ltc::fit::options opt = table_options();
    // The table is deterministic: re-running the fit's sequence for a row (the normal-incidence
    // chain from roughness 1 down, then the row from normal incidence to grazing) gives its
    // nodes again. Same compiler semantics give the same floats; across platforms (another
    // libm, FMA contraction) Nelder-Mead may stop elsewhere within its tolerance, so the
    // requirement is derived from the fit instead: each stored matrix is a minimizer of the
    // node's L3 objective to the fit's tolerance (estimator of the re-fit, same samples).
    const std::vector<ltc::fit::node_result> normal = ltc::fit::fit_normal_incidence<ltc::brdf::ggx>(opt);
    int exact = 0, total = 0;
    for (const int a : {n - 1, 40, 12}) {
        const std::vector<ltc::fit::node_result> row = ltc::fit::fit_row<ltc::brdf::ggx>(a, normal[std::size_t(a)], opt);
        const double alpha = ltc::fit::node_alpha(a, n, opt.alpha_min);
        for (int t = 0; t < n; ++t) {
            CAPTURE(a, t);
            const ltc::fit::node_result& r = row[std::size_t(t)];
            const float refit[6] = {float(r.m_inv[0][0]), float(r.m_inv[0][2]), float(r.m_inv[2][0]),
                                    float(r.m_inv[2][2]), float(r.magnitude), float(r.fresnel)};
            bool all = true;
            for (int k = 0; k < 6; ++k) all = all && refit[k] == shipped.node(t, a, k);
            exact += all ? 1 : 0;
            ++total;
            // Magnitude and Fresnel term: deterministic quadratures, no minimization.
            CHECK(shipped.node(t, a, ltc::channel::magnitude) == Approx(r.magnitude).epsilon(1e-6));
            CHECK(shipped.node(t, a, ltc::channel::fresnel) == Approx(r.fresnel).epsilon(1e-6).margin(1e-12));
            // The stored matrix is as good a fit as the re-fit's.
            const double cos_theta = ltc::fit::node_cos_theta(t, n, opt.cos_theta_min);
            const glm::dvec3 V = ltc::brdf::view_from_cos(cos_theta);
            ltc::fit::sample_set s;
            ltc::fit::make_sample_set<ltc::brdf::ggx>(V, alpha, ltc::fit::invert_structured(r.m_inv).inverse,
                                                      opt.error_samples, s);
            glm::dmat3 stored(0.0);
            stored[0][0] = shipped.node(t, a, 0);
            stored[0][2] = shipped.node(t, a, 1);
            stored[2][0] = shipped.node(t, a, 2);
            stored[2][2] = shipped.node(t, a, 3);
            stored[1][1] = 1;
            const double e_refit = s.l3(r.m_inv, r.magnitude);
            const double e_stored = s.l3(stored, r.magnitude);
            CHECK(e_stored <= e_refit * (1 + 1e-3));
        }
    }
    // On the platform that generated the table every node is identical; elsewhere, say so.
    if (exact != total) WARN("re-fit: " << exact << " of " << total << " nodes identical to the last bit");
}

TEST_CASE("fit_table is bitwise identical whatever the thread count", "[fit]") {
    ltc::fit::options opt;
    opt.size = 8;
    opt.threads = 1;
    std::size_t last_done = 0, calls = 0;
    const ltc::fit::table one = ltc::fit::fit_table<ltc::brdf::ggx>(opt, [&](std::size_t done, std::size_t total) {
        CHECK(total == 64);
        CHECK(done >= last_done);
        last_done = done;
        ++calls;
    });
    CHECK(last_done == 64);
    CHECK(calls >= 1);
    opt.threads = 2;
    const ltc::fit::table two = ltc::fit::fit_table<ltc::brdf::ggx>(opt);
    opt.threads = 3;
    const ltc::fit::table three = ltc::fit::fit_table<ltc::brdf::ggx>(opt);
    const std::vector<float> a = one.packed(), b = two.packed(), c = three.packed();
    REQUIRE(a.size() == 8 * 8 * 6);
    REQUIRE(b.size() == a.size());
    REQUIRE(c.size() == a.size());
    CHECK(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
    CHECK(std::memcmp(a.data(), c.data(), a.size() * sizeof(float)) == 0);
    for (std::size_t i = 0; i < a.size(); ++i) REQUIRE(std::isfinite(a[i]));
}

TEST_CASE("magnitude times the fitted LTC's integral over the hemisphere is the albedo", "[fit][table]") {
    // The LTC integrates to 1 over the sphere; what leaks below the horizon is error that the
    // L3 fit keeps small (here at most ~1.2%), so magnitude * (integral over the upper
    // hemisphere) matches the directional albedo, computed independently on a 256 x 256 grid.
    double worst = 0;
    for (int a = 8; a < n; a += 11)
        for (int t = 0; t < n; t += 9) {
            CAPTURE(a, t);
            const double cos_theta = ltc::fit::node_cos_theta(t, n, table_options().cos_theta_min);
            const double alpha = ltc::fit::node_alpha(a, n, table_options().alpha_min);
            const double albedo = ltc::fit::compute_moments<ltc::brdf::ggx>(ltc::brdf::view_from_cos(cos_theta), alpha, 256)
                                      .magnitude;
            const auto c = ltc::ggx::fetch(cos_theta, double(a) / (n - 1));
            const auto d = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(c.m_inv);
            const double e = c.magnitude * d.integrate(hemisphere_quad, 4);
            CHECK(e == Approx(albedo).epsilon(0.02));
            CHECK(e <= albedo * 1.002);  // the LTC only loses energy (the albedo is known to ~1e-3)
            worst = std::max(worst, std::abs(e / albedo - 1));
        }
    INFO("largest relative deviation " << worst);
    CHECK(worst < 0.02);
}

TEST_CASE("magnitude times the fetched LTC's polygon integral approximates rho cos over the polygon", "[fit][table]") {
    // The public contract, conventions included (local frame, V in the xz-plane with V.x >= 0,
    // m_inv rather than M): for any polygon P, |magnitude I_ltc(P) - integral over P of f| <=
    // integral of |f - magnitude D| = relative_l1 * albedo. The integral of f over P is computed
    // by 256 x 256 BRDF samples; the bound by measure_error (128 x 128 per distribution).
    struct node {
        int t, a;
    };
    for (const node nd : {node{10, 20}, node{30, 35}, node{45, 50}, node{20, 60}, node{55, 15}}) {
        const double x = double(nd.t) / (n - 1);
        const double cos_theta = 1 - x * x;
        const double alpha = ltc::fit::node_alpha(nd.a, n, 1e-4);
        const glm::dvec3 V = ltc::brdf::view_from_cos(cos_theta);
        const auto c = ltc::ggx::fetch(cos_theta, double(nd.a) / (n - 1));
        const auto d = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(c.m_inv);
        const ltc::fit::node_error bound = ltc::fit::measure_error<ltc::brdf::ggx>(cos_theta, alpha, c.m_inv, c.magnitude, 128);
        // Quads of half-size h at unit distance around a few directions near the lobe.
        const glm::dvec3 mirror(-V.x, 0, V.z);
        for (const glm::dvec3& centre : {mirror, glm::normalize(mirror + glm::dvec3(0.3, 0.2, 0)),
                                         glm::normalize(mirror + glm::dvec3(-0.4, -0.3, 0.1)), glm::dvec3(0, 0, 1)})
            for (const double h : {0.05, 0.2, 0.6}) {
                CAPTURE(nd.t, nd.a, centre.x, centre.y, centre.z, h);
                const glm::dvec3 t1 = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), centre));
                const glm::dvec3 t2 = glm::cross(centre, t1);
                const glm::dvec3 quad[4] = {centre + h * (t1 + t2), centre + h * (-t1 + t2), centre + h * (-t1 - t2),
                                            centre + h * (t1 - t2)};
                const double shaded = c.magnitude * d.integrate(quad, 4);
                const int m = 256;
                double truth = 0;
                for (int j = 0; j < m; ++j)
                    for (int i = 0; i < m; ++i) {
                        const glm::dvec3 L = ltc::brdf::ggx<double>::sample(V, glm::dvec2((i + 0.5) / m, (j + 0.5) / m), alpha);
                        const double cl = glm::dot(L, centre);
                        if (!(cl > 0) || !(L.z > 0)) continue;
                        const glm::dvec3 hit = L / cl - centre;
                        if (std::abs(glm::dot(hit, t1)) > h || std::abs(glm::dot(hit, t2)) > h) continue;
                        truth += ltc::brdf::ggx<double>::eval(V, L, alpha) / ltc::brdf::ggx<double>::pdf(V, L, alpha);
                    }
                truth /= double(m) * m;
                CHECK(std::abs(shaded - truth) <= bound.relative_l1 * bound.albedo + 0.01 * bound.albedo);
            }
    }
}

TEST_CASE("at roughness 1 and normal incidence the fitted LTC is close to a cosine", "[fit][table]") {
    const auto c = ltc::ggx::fetch(1.0, 1.0);
    CHECK(c.m_inv[0][2] == 0);
    CHECK(c.m_inv[2][0] == 0);
    CHECK(c.m_inv[0][0] == Approx(1));  // isotropic at normal incidence: m_inv = diag(1, 1, s)
    CHECK(c.m_inv[2][2] == Approx(1).epsilon(0.2));
    // L1 distance between the LTC and the clamped cosine (0 for equal, 2 for disjoint
    // distributions), by the LTC's own samples and the cosine's (MIS, 128 x 128 each): small
    // (0.12: GGX at alpha = 1 with Smith shadowing is a little flatter than a cosine).
    const auto d = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(c.m_inv);
    const int m = 128;
    double l1 = 0;
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
            const glm::dvec2 u((i + 0.5) / m, (j + 0.5) / m);
            for (const glm::dvec3& L : {d.sample(u), ltc::clamped_cosine<double>::sample(u)}) {
                const double p = d.pdf(L), q = ltc::clamped_cosine<double>::pdf(L);
                l1 += std::abs(p - q) / (double(m) * m * (p + q));
            }
        }
    CHECK(l1 < 0.2);
    // And the fit itself, from the cosine: it stays there.
    ltc::fit::options opt = table_options();
    const ltc::fit::node_result r = ltc::fit::fit_node<ltc::brdf::ggx>(1.0, 1.0, ltc::fit::ltc_parameters{}, opt);
    CHECK(r.parameters.m11 == r.parameters.m22);
    CHECK(r.parameters.m11 == Approx(1).epsilon(0.2));
    CHECK(r.relative_l1 < 0.05);
}

TEST_CASE("moments - magnitude and Fresnel term and average direction", "[fit]") {
    // Schlick: integral of f (F0 + (1 - F0)(1 - V.H)^5) = F0 magnitude + (1 - F0) fresnel, so
    // F0 = 1 is the magnitude and the Fresnel term is at most the magnitude; it grows towards
    // grazing angles, and at normal incidence with a sharp lobe (V.H ~ 1) it vanishes.
    const double alpha = 0.25;
    double previous = 0;
    for (const double c : {1.0, 0.8, 0.5, 0.2, 0.05}) {
        CAPTURE(c);
        const glm::dvec3 V = ltc::brdf::view_from_cos(c);
        const ltc::fit::moments m = ltc::fit::compute_moments<ltc::brdf::ggx>(V, alpha, 64);
        CHECK(m.magnitude > 0);
        CHECK(m.magnitude <= 1);
        CHECK(m.fresnel >= 0);
        CHECK(m.fresnel < m.magnitude);
        CHECK(m.fresnel > previous);
        previous = m.fresnel;
        CHECK(m.average_direction.y == 0);
        CHECK(glm::length(m.average_direction) == Approx(1));
        if (c == 1.0)  // normal incidence: x = 0 by symmetry, up to the rounding of a 64 x 64 sum
            CHECK(std::abs(m.average_direction.x) <= 64 * 64 * std::numeric_limits<double>::epsilon());
        else
            CHECK(m.average_direction.x < 0);  // the lobe is around the mirror direction (-x side)
    }
    const ltc::fit::moments sharp = ltc::fit::compute_moments<ltc::brdf::ggx>(glm::dvec3(0, 0, 1), 1e-3, 64);
    CHECK(sharp.fresnel < 1e-10);
    CHECK(sharp.magnitude == Approx(1).epsilon(1e-4));
}

TEST_CASE("nelder_mead minimizes a quadratic and the Rosenbrock function", "[fit]") {
    const auto quadratic = [](const std::array<double, 2>& x) {
        return (x[0] - 1) * (x[0] - 1) + 10 * (x[1] + 2) * (x[1] + 2) + 3;
    };
    const auto q = ltc::fit::nelder_mead<2>(quadratic, {0.0, 0.0}, {0.5, 0.5}, 1e-14, 2000);
    CHECK(q.x[0] == Approx(1).margin(1e-5));
    CHECK(q.x[1] == Approx(-2).margin(1e-5));
    CHECK(q.value == Approx(3));
    const auto rosenbrock = [](const std::array<double, 2>& x) {
        return 100 * (x[1] - x[0] * x[0]) * (x[1] - x[0] * x[0]) + (1 - x[0]) * (1 - x[0]);
    };
    const auto r = ltc::fit::nelder_mead<2>(rosenbrock, {-1.2, 1.0}, {0.1, 0.1}, 1e-16, 5000);
    CHECK(r.x[0] == Approx(1).margin(1e-4));
    CHECK(r.x[1] == Approx(1).margin(1e-4));
    CHECK(r.evaluations <= 5000);
    // The evaluation budget is respected.
    const auto capped = ltc::fit::nelder_mead<2>(rosenbrock, {-1.2, 1.0}, {0.1, 0.1}, 0.0, 50);
    CHECK(capped.evaluations <= 50 + 3);
}
