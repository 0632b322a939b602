// The documented integrate() entry points and their default (ltc/core/transformed.hpp and the
// original distributions): integrate(v, n) is integrate(v, n, sidedness::two_sided), the same path
// and the same bits, for transformed<D> over each original distribution and for each distribution's
// own integrate(); and the default it states: the integral of D over the polygon whatever the
// winding, |signed|, equal to the one-sided value for the winding that faces the shading point and
// positive where the one-sided value of the other winding is 0.
#include "support/rng.hpp"

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/squared_clamped_cosine.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/core/uniform_hemisphere.hpp>
#include <ltc/core/uniform_sphere.hpp>

#include <catch2/catch.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <vector>

namespace ltc_test_integrate_defaults {  // the file's own names, apart from the other files of a unity batch

namespace {

/// Bit patterns compared, so that a NaN or the sign of a zero would count as a difference.
template <typename T>
bool same_bits(T a, T b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

/// A GGX-like M^-1 = [a 0 b; 0 c 0; d 0 1] (row-major, as the table stores it), with a random
/// rotation about z folded in for the general case.
template <typename T>
glm::mat<3, 3, T> random_m_inv(ltc_test::rng& g) {
    const double a = 0.05 + g.uniform(), b = g.uniform(-0.5, 0.5), c = 0.05 + g.uniform(), d = g.uniform(-0.5, 0.5);
    const double phi = g.uniform(0, 6.283185307179586);
    const glm::dmat3 lobe = glm::transpose(glm::dmat3(a, 0, b, 0, c, 0, d, 0, 1));
    const glm::dmat3 rot(std::cos(phi), std::sin(phi), 0, -std::sin(phi), std::cos(phi), 0, 0, 0, 1);
    return glm::mat<3, 3, T>(lobe * rot);
}

/// A regular n-gon in a random plane in front of or behind the shading point, crossing the horizon
/// in about half the draws; either winding.
template <typename T>
std::vector<glm::vec<3, T>> random_polygon(ltc_test::rng& g, std::size_t n) {
    const glm::dvec3 centre(g.uniform(-1, 1), g.uniform(-1, 1), g.uniform(-0.3, 1));
    const glm::dvec3 normal = g.direction();
    const glm::dvec3 helper = std::abs(normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 ex = glm::normalize(glm::cross(normal, helper)), ey = glm::cross(normal, ex);
    const double radius = g.uniform(0.1, 1.0), phase = g.uniform(0, 6.283185307179586);
    std::vector<glm::vec<3, T>> v(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double t = phase + 6.283185307179586 * double(i) / double(n);
        v[i] = glm::vec<3, T>(centre + radius * (std::cos(t) * ex + std::sin(t) * ey));
    }
    return v;
}

template <typename Dist>
void check_same_bits_as_two_sided(std::uint64_t seed) {
    using T = typename Dist::scalar;
    ltc_test::rng g(seed);
    long compared = 0, different = 0, crossing = 0;
    for (int k = 0; k < 4000; ++k) {
        const std::size_t n = k % 2 == 0 ? 4 : 3 + std::size_t(k / 2) % 6;  // half quads, then 3..8
        const auto m_inv = random_m_inv<T>(g);
        const auto v = random_polygon<T>(g, n);
        const auto d = ltc::transformed<Dist>::from_inverse(m_inv);
        const T two_arguments = d.integrate(v.data(), n);
        const T two_sided = d.integrate(v.data(), n, ltc::sidedness::two_sided);
        ++compared;
        if (!same_bits(two_arguments, two_sided)) {
            ++different;
            UNSCOPED_INFO("n = " << n << ": integrate(v, n) = " << two_arguments << ", two_sided = " << two_sided);
        }
        int above = 0;
        for (const auto& p : v) above += (m_inv * p).z >= T(0) ? 1 : 0;
        crossing += above > 0 && above < int(n) ? 1 : 0;
        // The distribution's own integrate(), on the same polygon in D_o's space.
        const T own = Dist::integrate(v.data(), n), own_two = Dist::integrate(v.data(), n, ltc::sidedness::two_sided);
        ++compared;
        if (!same_bits(own, own_two) || !same_bits(own, std::abs(Dist::signed_integral(v.data(), n)))) {
            ++different;
            UNSCOPED_INFO("n = " << n << ": D_o::integrate(v, n) = " << own << ", two_sided = " << own_two);
        }
    }
    INFO(compared << " pairs compared, " << crossing << " of 4000 polygons crossing D_o's horizon");
    CHECK(different == 0);
    CHECK(crossing > 400);  // the clipped cases are exercised
}

}  // namespace

TEMPLATE_TEST_CASE("integrate(v, n) gives the bits of integrate(v, n, two_sided): random quads and n-gons",
                   "[integrate][sidedness]", float, double) {
    using T = TestType;
    SECTION("clamped cosine, default edge policy") { check_same_bits_as_two_sided<ltc::clamped_cosine<T>>(37); }
    SECTION("clamped cosine, exact") { check_same_bits_as_two_sided<ltc::clamped_cosine<T, ltc::edge_policy::exact>>(38); }
    SECTION("clamped cosine, polynomial") {
        check_same_bits_as_two_sided<ltc::clamped_cosine<T, ltc::edge_policy::polynomial>>(39);
    }
    SECTION("squared clamped cosine") { check_same_bits_as_two_sided<ltc::squared_clamped_cosine<T>>(40); }
    SECTION("uniform sphere") { check_same_bits_as_two_sided<ltc::uniform_sphere<T>>(41); }
    SECTION("uniform hemisphere") { check_same_bits_as_two_sided<ltc::uniform_hemisphere<T>>(42); }
}

TEMPLATE_TEST_CASE("the default of integrate() is two-sided: |signed|, whatever the winding", "[integrate][sidedness]",
                   float, double) {
    using T = TestType;
    using vec3 = glm::vec<3, T>;
    using D = ltc::transformed<ltc::clamped_cosine<T>>;
    // A handful of edge terms of a few roundings each, of the size of the sum (no cancellation in
    // these polygons), summed in the other order: 32 epsilon bounds the difference.
    const double reversal_tolerance = 32 * double(std::numeric_limits<T>::epsilon());
    // A quad above the shading point, clockwise as seen from it (signed integral > 0), and reversed.
    const vec3 facing[4] = {{-1, -1, 2}, {1, -1, 2}, {1, 1, 2}, {-1, 1, 2}};
    const vec3 reversed[4] = {facing[3], facing[2], facing[1], facing[0]};
    const auto m_inv = glm::mat<3, 3, T>(glm::transpose(glm::dmat3(0.5, 0, 0.2, 0, 0.7, 0, -0.1, 0, 1)));
    // The same lobe mirrored in x (|M^-1| < 0): the signs still refer to P's own winding.
    const auto mirrored = m_inv * glm::mat<3, 3, T>(vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1));
    for (const D& d : {D::from_inverse(m_inv), D::from_inverse(mirrored)}) {
        INFO("|M^-1| = " << d.inverse_determinant());
        const T front = d.integrate_signed(facing, 4);
        REQUIRE(front > T(0));
        // Reversed, the edge terms are summed in another order: the same value up to rounding.
        const T back = d.integrate_signed(reversed, 4);
        CHECK(back == Approx(-front).epsilon(reversal_tolerance));
        // Default = two-sided = |signed| for both windings; one-sided only for the facing one.
        CHECK(same_bits(d.integrate(facing, 4), front));
        CHECK(same_bits(d.integrate(reversed, 4), -back));
        CHECK(same_bits(d.integrate(facing, 4, ltc::sidedness::one_sided), front));
        CHECK(d.integrate(reversed, 4, ltc::sidedness::one_sided) == T(0));
    }
    // Each distribution's own integrate(): the same default.
    const vec3 tri_v[3] = {{0, 0, 1}, {0, 1, 1}, {1, 0, 1}};
    const vec3 tri_r[3] = {tri_v[2], tri_v[1], tri_v[0]};
    const vec3 *tri = tri_v, *tri_reversed = tri_r;  // pointers: signed_integral takes any Vertices
    const auto check_default = [&](auto dist) {
        using Dist = decltype(dist);
        const T s = Dist::signed_integral(tri, 3);
        CHECK(s != T(0));
        CHECK(same_bits(Dist::integrate(tri, 3), std::abs(s)));
        const T back = Dist::signed_integral(tri_reversed, 3);
        CHECK(back == Approx(-s).epsilon(reversal_tolerance));
        CHECK(same_bits(Dist::integrate(tri_reversed, 3), std::abs(back)));
        CHECK(Dist::integrate(s > T(0) ? tri_reversed : tri, 3, ltc::sidedness::one_sided) == T(0));
    };
    check_default(ltc::clamped_cosine<T>{});
    check_default(ltc::squared_clamped_cosine<T>{});
    check_default(ltc::uniform_sphere<T>{});
    check_default(ltc::uniform_hemisphere<T>{});
}

}  // namespace ltc_test_integrate_defaults
