// Tests of ltc/tables/ltc_table.hpp and ltc/shading/ggx_fetch.hpp: the lookup of the shipped GGX
// table, exact at nodes, bilinear between them, clamped and finite everywhere.
#include <catch2/catch.hpp>

#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/tables/ltc_table.hpp>

#include "support/ggx_table.hpp"

#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <limits>

namespace ltc_test_ggx_fetch {  // the file's own names, apart from the other files of a unity batch

using namespace ltc_test::table_checks;  // n, shipped

namespace {

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

}  // namespace ltc_test_ggx_fetch
