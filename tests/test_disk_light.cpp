// Disk lights (ltc/core/ellipse_integral.hpp) beyond the brute force of test_ellipse_integral.cpp:
// the equal-area polygon converging to the closed form, the 2017 approximation (where it is
// exact, its errors elsewhere), closed forms at the extremes (a far tiny disk, a point just off
// a disk), scale invariance and degenerate input.
#include <ltc/core/ellipse_integral.hpp>
#include <ltc/shading/ggx_fetch.hpp>

#include "support/rng.hpp"

#include <catch2/catch.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace ltc_test_disk_light {  // the file's own names, apart from the other files of a unity batch

namespace {

using glm::dvec3;
using dltc = ltc::transformed<ltc::clamped_cosine<double>>;
using fltc = ltc::transformed<ltc::clamped_cosine<float>>;
constexpr auto two = ltc::sidedness::two_sided;

struct disk_case {
    dltc d;
    dvec3 centre, normal;
    double radius;
    ltc::detail::disk_ellipse<double> image;  // M^-1 disk
};

disk_case random_case(ltc_test::rng& r) {
    const double cos_v = r.uniform(0.05, 1), roughness = r.uniform(0.05, 1);  // one draw per statement
    const auto c = ltc::ggx::fetch(cos_v, roughness);
    disk_case k{dltc::from_inverse(glm::dmat3(c.m_inv)), r.direction(), r.direction(), r.uniform(0.05, 1), {}};
    k.centre *= r.uniform(0.3, 3);
    k.image = ltc::detail::make_disk_ellipse(k.d.inverse_matrix(), k.d.inverse_determinant(), k.centre, k.normal,
                                             k.radius);
    return k;
}

}  // namespace

TEST_CASE("the equal-area polygon converges to integrate_disk: O(n^-4) unclipped, O(n^-2) or faster clipped",
          "[disk]") {
    ltc_test::rng r(0xc0417);
    double rate_unclipped = 1e9, rate_clipped = 1e9;
    for (int i = 0; i < 40; ++i) {
        const disk_case k = random_case(r);
        const double exact = ltc::integrate_disk(k.d, k.centre, k.normal, k.radius);
        const double zr = std::hypot(k.image.a.z, k.image.b.z);
        const bool clipped = std::abs(k.image.c.z) < zr;
        if (exact < 1e-6) continue;
        const auto error = [&](std::size_t n) {
            return std::abs(ltc::integrate_disk_polygon(k.d, k.centre, k.normal, k.radius, n) - exact);
        };
        // The rate between n = 32 and 256, where the errors are well above rounding (1e-13).
        const double e32 = error(32), e256 = error(256);
        CAPTURE(i, clipped, exact, e32, e256);
        CHECK(e256 <= 0.02 * exact);
        if (e256 < 1e-13) continue;
        const double rate = std::log2(e32 / e256) / 3;
        CAPTURE(rate);
        if (clipped) rate_clipped = std::min(rate_clipped, rate);
        else rate_unclipped = std::min(rate_unclipped, rate);
        CHECK(rate >= (clipped ? 1.9 : 3.8));
    }
    std::printf("disk polygon convergence, worst rate over n = 32..256: unclipped %.2f, clipped %.2f\n", rate_unclipped,
                rate_clipped);
}

TEST_CASE("the 2017 approximation: exact while its sphere is above the horizon, errors elsewhere", "[disk]") {
    ltc_test::rng r(0x2017);
    double worst_dip = 0, worst_across = 0, mean_across = 0, worst_below = 0;
    int n_across = 0;
    for (int i = 0; i < 4000; ++i) {
        const disk_case k = random_case(r);
        const auto& e = k.image;
        const dvec3 F = ltc::ellipse_vector_form_factor(e.c, e.a, e.b);
        const double f = glm::length(F), zr = std::hypot(e.a.z, e.b.z);
        if (!(f > 0)) continue;
        const double exact = ltc::integrate_disk(k.d, k.centre, k.normal, k.radius);
        const double approx = ltc::integrate_disk_2017(k.d, k.centre, k.normal, k.radius);
        const double facing = glm::dot(e.c, glm::cross(e.a, e.b)) > 0 ? 1 : -1;
        const double cos_omega = facing * F.z / f;  // elevation of the sphere, towards the disk
        CAPTURE(i, exact, approx, f, cos_omega);
        if (e.c.z - zr >= 0 && cos_omega >= std::sqrt(f) * (1 + 1e-12)) {  // (a margin for F's rounding)
            CHECK(approx == exact);  // both are F.z, from the same axis and |F|
        } else if (e.c.z - zr >= 0) {
            CHECK(approx >= exact);  // the clipped sphere keeps more than F.z
            worst_dip = std::max(worst_dip, (approx - exact) / exact);
        } else if (e.c.z + zr <= 0) {
            CHECK(exact == 0.0);
            worst_below = std::max(worst_below, approx / f);  // the sphere can poke above
        } else {
            CHECK(std::abs(approx - exact) <= 0.3 * f);
            worst_across = std::max(worst_across, std::abs(approx - exact) / f);
            mean_across += std::abs(approx - exact) / f;
            ++n_across;
        }
    }
    std::printf("2017 disk approximation: above, sphere dipping: worst relative error %.3g; across the horizon: "
                "worst %.3g, mean %.3g of |F|; below: up to %.3g of |F|\n",
                worst_dip, worst_across, mean_across / n_across, worst_below);
}

TEST_CASE("disk integrals at the extremes: a far tiny disk, a point just off a disk", "[disk]") {
    const dltc cosine(glm::dmat3(1.0));
    // A far tiny disk (r / d = 1e-7; a needle-thin cone) seen 60 degrees off the normal, its own
    // normal 30 degrees off the view: the point form factor r^2 cos_light cos_receiver / d^2, to
    // O(r^2 / d^2). In float, rounding the inputs alone moves it by a few 1e-7.
    const double d = 1e3, r = 1e-4;
    const dvec3 dir(std::sqrt(0.75), 0, 0.5), normal = -glm::normalize(dvec3(1, 0, 0));
    const double point = r * r * dir.z * std::abs(glm::dot(normal, dir)) / (d * d);
    CHECK_THAT(ltc::integrate_disk(cosine, d * dir, normal, r), Catch::Matchers::WithinRel(point, 1e-13));
    const fltc cosine_f(glm::mat3(1.0f));
    CHECK_THAT(ltc::integrate_disk(cosine_f, glm::vec3(d * dir), glm::vec3(normal), float(r)),
               Catch::Matchers::WithinRel(float(point), 1e-6f));
    // Coaxial disk just above the point (height h): sin^2(sigma) = 1 / (1 + h^2), even for
    // h = 1e-9 (a cone of half-angle just short of 90 degrees).
    for (double h : {1.0, 1e-3, 1e-9}) {
        CHECK_THAT(ltc::integrate_disk(cosine, dvec3(0, 0, h), dvec3(0, 0, -1), 1.0, ltc::sidedness::one_sided),
                   Catch::Matchers::WithinRel(1 / (1 + h * h), 1e-15));
        CHECK(ltc::integrate_disk(cosine, dvec3(0, 0, h), dvec3(0, 0, 1), 1.0, ltc::sidedness::one_sided) == 0.0);
    }
    // A tilted disk just off the point: nearly the hemisphere of directions towards it, clipped:
    // (1 - n.z) / 2 seen from the front (the disk towards -n), (1 + n.z) / 2 from behind.
    const dvec3 n = glm::normalize(dvec3(0.6, 0, 0.8));
    CHECK(std::abs(ltc::integrate_disk(cosine, -1e-12 * n, n, 1.0, ltc::sidedness::one_sided) - 0.1) <= 1e-11);
    CHECK(ltc::integrate_disk(cosine, 1e-12 * n, n, 1.0, ltc::sidedness::one_sided) == 0.0);
    CHECK(std::abs(ltc::integrate_disk(cosine, 1e-12 * n, n, 1.0, two) - 0.9) <= 1e-11);
}

TEST_CASE("disk integrals: scale invariance and degenerate input", "[disk][bad_input]") {
    ltc_test::rng r(0xbad);
    for (int i = 0; i < 20; ++i) {
        const disk_case k = random_case(r);
        const double base = ltc::integrate_disk(k.d, k.centre, k.normal, k.radius);
        const double base_2017 = ltc::integrate_disk_2017(k.d, k.centre, k.normal, k.radius);
        for (int e : {-1000, -300, -60, 61, 300, 1000}) {
            const double s = std::ldexp(1.0, e);
            CAPTURE(i, e);
            CHECK(ltc::integrate_disk(k.d, s * k.centre, k.normal, s * k.radius) == base);
            CHECK(ltc::integrate_disk_2017(k.d, s * k.centre, k.normal, s * k.radius) == base_2017);
        }
        // Orientation: the reversed normal flips the sign (one-sided: 0 on one side).
        const double a = ltc::integrate_disk(k.d, k.centre, k.normal, k.radius, ltc::sidedness::one_sided);
        const double b = ltc::integrate_disk(k.d, k.centre, -k.normal, k.radius, ltc::sidedness::one_sided);
        CHECK(std::min(a, b) == 0.0);
        CHECK(std::abs(std::max(a, b) - base) <= 1e-15);
    }
    const dltc d = dltc::from_inverse(glm::dmat3(ltc::ggx::fetch(0.5, 0.3).m_inv));
    const dvec3 c(0.2, 0.1, 1), n(0, 0, -1);
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    for (double radius : {0.0, -1.0, nan, inf}) CHECK(ltc::integrate_disk(d, c, n, radius) == 0.0);
    CHECK(ltc::integrate_disk(d, c, dvec3(0), 1.0) == 0.0);
    CHECK(ltc::integrate_disk(d, dvec3(nan, 0, 1), n, 1.0) == 0.0);
    CHECK(ltc::integrate_disk_polygon(d, c, n, 1.0, 2) == 0.0);
    // Edge-on: the shading point in the disk's plane, outside it: 0 (every method).
    const dvec3 side(1, 0, 0);
    CHECK(ltc::integrate_disk(d, dvec3(0, 2, 0.5), side, 1.0) == 0.0);
    CHECK(ltc::integrate_disk_2017(d, dvec3(0, 2, 0.5), side, 1.0) == 0.0);
    // On the disk (inside, in its plane): the mean of the two one-sided limits (the signed
    // integrals just in front and just behind); the 2017 approximation gives 0.
    // (exact coordinates: centre.normal == 0 holds in floating point, with or without FMA)
    const dvec3 tilted(1, 2, 4), on_disk(0.25, -0.125, 0);
    const auto signed_disk = [&](const dvec3& centre) {
        const double one = ltc::integrate_disk(d, centre, tilted, 1.0, ltc::sidedness::one_sided);
        return one > 0 ? one : -ltc::integrate_disk(d, centre, tilted, 1.0, two);
    };
    const double on = signed_disk(on_disk);
    const double front = signed_disk(on_disk - 1e-12 * tilted), back = signed_disk(on_disk + 1e-12 * tilted);
    CAPTURE(on, front, back);
    CHECK(std::abs(on - (front + back) / 2) <= 1e-10);
    CHECK(front - back > 0.99);  // the limits differ by 1 (the chord flips past the origin)
    CHECK(ltc::integrate_disk_2017(d, on_disk, tilted, 1.0) == 0.0);
    // A singular M^-1 (rank 2): the disk's image is flat; finite, and as the polygon.
    glm::dmat3 singular = d.inverse_matrix();
    singular[2] = singular[0] + singular[1];
    const dltc ds = dltc::from_inverse(singular);
    const double flat = ltc::integrate_disk(ds, c, n, 1.0);
    CHECK(std::isfinite(flat));
    CHECK(std::abs(flat - ltc::integrate_disk_polygon(ds, c, n, 1.0, 256)) <= 1e-9);
    CHECK(std::isfinite(ltc::integrate_disk_2017(ds, c, n, 1.0)));
    // Ellipses: a segment (a x b = 0), non-finite input, entirely below, in the plane z = 0.
    CHECK(ltc::integrate_ellipse_cosine(dvec3(0, 0, 1), dvec3(1, 0, 0), dvec3(2, 0, 0)) == 0.0);
    CHECK(ltc::integrate_ellipse_cosine(dvec3(0, 0, inf), dvec3(1, 0, 0), dvec3(0, 1, 0)) == 0.0);
    CHECK(ltc::integrate_ellipse_cosine(dvec3(0, 0, -2), dvec3(1, 0, 0), dvec3(0, 1, 0)) == 0.0);
    CHECK(ltc::integrate_ellipse_cosine(dvec3(0.1, 0, 0), dvec3(1, 0, 0), dvec3(0, 1, 0)) == 0.0);
    CHECK(ltc::ellipse_vector_form_factor(dvec3(0.1, 0, 0), dvec3(1, 0, 0), dvec3(0, 1, 0)) == dvec3(0, 0, 1));
    // A disk (the clamped cosine: its ellipse is the disk) whose rim passes 2^-24 of its radius
    // from the shading point, its plane as close (NaN before make_cone_axis floored its step
    // from above; test_ellipse_integral.cpp): every integral in [0, 1].
    const fltc cosine_f(glm::mat3(1.0f));
    const glm::vec3 centre(-0x1.000004p-2f, 0x1p-3f, 0.0f), normal(1, 2, 4);
    const float radius = 0x1.1e377ap-2f;
    for (const ltc::sidedness side : {ltc::sidedness::one_sided, ltc::sidedness::two_sided}) {
        const float i = ltc::integrate_disk(cosine_f, centre, normal, radius, side);
        const float j = ltc::integrate_disk_2017(cosine_f, centre, normal, radius, side);
        CAPTURE(i, j);
        CHECK((i >= 0.0f && i <= 1.0f));
        CHECK((j >= 0.0f && j <= 1.0f));
    }
}

}  // namespace ltc_test_disk_light
