// Degenerate and hostile input: every case documented in polygon.hpp and transformed.hpp gives
// a finite, documented result, never NaN or Inf, and bad matrices are rejected with a clear error.
#include <ltc/ltc.hpp>

#include "support/bad_input.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace ltc_test_bad_input {  // the file's own names, apart from the other files of a unity batch

namespace {

using ltc_test::edge_sum_bound;
using ltc_test::supplement_m;

template <typename T>
using vec3 = glm::vec<3, T>;

template <typename T>
struct integrals {
    T sphere, hemisphere, cosine, squared, form_factor_signed, solid_angle, clipped_solid_angle;
    vec3<T> vff;
};

template <typename T>
integrals<T> all_integrals(const vec3<T>* v, std::size_t n) {
    return {ltc::uniform_sphere<T>::integrate(v, n),
            ltc::uniform_hemisphere<T>::integrate(v, n),
            ltc::clamped_cosine<T>::integrate(v, n),
            ltc::squared_clamped_cosine<T>::integrate(v, n),
            ltc::form_factor_signed(v, n),
            ltc::solid_angle(v, n),
            ltc::clipped_solid_angle(v, n),
            ltc::vector_form_factor(v, n)};
}

template <typename T>
bool all_finite(const integrals<T>& r) {
    return std::isfinite(r.sphere) && std::isfinite(r.hemisphere) && std::isfinite(r.cosine) &&
           std::isfinite(r.squared) && std::isfinite(r.form_factor_signed) && std::isfinite(r.solid_angle) &&
           std::isfinite(r.clipped_solid_angle) && std::isfinite(r.vff.x) && std::isfinite(r.vff.y) &&
           std::isfinite(r.vff.z);
}

template <typename T>
bool all_zero(const integrals<T>& r) {
    return r.sphere == 0 && r.hemisphere == 0 && r.cosine == 0 && r.squared == 0 && r.form_factor_signed == 0 &&
           r.solid_angle == 0 && r.clipped_solid_angle == 0 && r.vff == vec3<T>(0);
}

}  // namespace

TEMPLATE_TEST_CASE("fewer than three vertices integrate to exactly 0", "[bad-input]", float, double) {
    using T = TestType;
    const vec3<T> v[2] = {{0, 0, 1}, {1, 0, 1}};
    for (std::size_t n = 0; n < 3; ++n) {
        CAPTURE(n);
        const auto r = all_integrals<T>(v, n < 3 ? n : 2);
        CHECK(all_zero(r));
        const auto d = ltc::transformed<ltc::clamped_cosine<T>>(supplement_m<T>());
        CHECK(d.integrate(v, n < 3 ? n : 2) == 0);
        vec3<T> out[3];
        CHECK(ltc::clip_to_horizon(v, n < 3 ? n : 2, out) == 0);
    }
}

TEMPLATE_TEST_CASE("a vertex at the shading point gives exactly 0", "[bad-input]", float, double) {
    using T = TestType;
    // The polygon's plane then contains the origin: it is seen edge-on and subtends no area.
    const vec3<T> v[4] = {{1, 0, 1}, {0, 0, 0}, {1, 1, 1}, {2, 1, 0.5}};
    CHECK(all_zero(all_integrals<T>(v, 4)));
    const auto d = ltc::transformed<ltc::squared_clamped_cosine<T>>(supplement_m<T>());
    CHECK(d.integrate(v, 4) == 0);
}

TEMPLATE_TEST_CASE("polygons below the horizon clip to nothing", "[bad-input]", float, double) {
    using T = TestType;
    const vec3<T> below[3] = {{0, 0, -1}, {1, 0, -1}, {1, 1, -1}};
    const auto r = all_integrals<T>(below, 3);
    CHECK(r.hemisphere == 0);
    CHECK(r.cosine == 0);
    CHECK(r.squared == 0);
    CHECK(r.clipped_solid_angle == 0);
    CHECK(r.sphere > 0);  // the uniform sphere is not clipped
    vec3<T> out[4];
    CHECK(ltc::clip_to_horizon(below, 3, out) == 0);

    // Touching the horizon from below: one edge on z = 0, the rest below. The clipped polygon
    // is that edge traversed forth and back, whose terms cancel to rounding.
    const vec3<T> touching[3] = {{0, 1, 0}, {1, 1, 0}, {1, 1, -1}};
    const auto t = all_integrals<T>(touching, 3);
    REQUIRE(all_finite(t));
    const T tol = edge_sum_bound<T>(4);
    CHECK(t.hemisphere <= tol);
    CHECK(t.cosine <= tol);
    CHECK(t.squared <= tol);
}

TEMPLATE_TEST_CASE("a polygon lying in the horizon plane is finite", "[bad-input]", float, double) {
    using T = TestType;
    // Edge-on: its plane contains the origin. Outside the origin the edges along the horizon
    // cancel (winding 0); around the origin they add up to the limit from above.
    const vec3<T> outside[4] = {{1, 1, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0}};
    const auto r = all_integrals<T>(outside, 4);
    REQUIRE(all_finite(r));
    CHECK(r.cosine <= edge_sum_bound<T>(4));
    const vec3<T> around[4] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    const auto a = all_integrals<T>(around, 4);
    REQUIRE(all_finite(a));
    // Approached from z = 0+, the square covers the whole upper hemisphere: D_o integrates to 1.
    CHECK(a.cosine == Approx(1).margin(edge_sum_bound<T>(4)));
    CHECK(a.hemisphere == Approx(1).margin(edge_sum_bound<T>(4)));
}

TEMPLATE_TEST_CASE("repeated and collinear vertices change nothing", "[bad-input]", float, double) {
    using T = TestType;
    const vec3<T> tri[3] = {{0.2f, -0.3f, 1}, {1.5f, 0.1f, 0.4f}, {0.3f, 1.2f, -0.6f}};
    const vec3<T> rep[5] = {tri[0], tri[0], tri[1], tri[2], tri[2]};
    const vec3<T> mid = (tri[1] + tri[2]) / T(2);
    const vec3<T> col[4] = {tri[0], tri[1], mid, tri[2]};
    const auto a = all_integrals<T>(tri, 3);
    const auto b = all_integrals<T>(rep, 5);
    const auto c = all_integrals<T>(col, 4);
    REQUIRE(all_finite(b));
    REQUIRE(all_finite(c));
    // Zero-length edges contribute exactly 0; a split edge adds terms equal to the original
    // one up to rounding: the bound is that of a 4- or 5-term edge sum.
    const T tol = edge_sum_bound<T>(5);
    for (const auto* x : {&b, &c}) {
        CHECK(x->sphere == Approx(a.sphere).margin(tol));
        CHECK(x->hemisphere == Approx(a.hemisphere).margin(tol));
        CHECK(x->cosine == Approx(a.cosine).margin(tol));
        CHECK(x->squared == Approx(a.squared).margin(tol));
    }
    // A degenerate triangle (two equal vertices) has no area.
    const vec3<T> flat[3] = {tri[0], tri[1], tri[0]};
    const auto f = all_integrals<T>(flat, 3);
    REQUIRE(all_finite(f));
    CHECK(f.sphere <= tol);
    CHECK(f.cosine <= tol);
    CHECK(f.squared <= tol);
}

TEMPLATE_TEST_CASE("an edge through the shading point stays finite", "[bad-input]", float, double) {
    using T = TestType;
    // The origin lies on the edge from (-1, 0, 0) to (1, 0, 0): its great circle is undefined.
    const vec3<T> v[3] = {{-1, 0, 0}, {1, 0, 0}, {0, 1, 1}};
    const auto r = all_integrals<T>(v, 3);
    CHECK(all_finite(r));
    const vec3<T> w[3] = {{-1, 0, 0.5f}, {1, 0, -0.5f}, {0, 1, 1}};  // through the origin, crossing the horizon
    CHECK(all_finite(all_integrals<T>(w, 3)));
}

TEMPLATE_TEST_CASE("huge and tiny vertices give the same integrals as unit ones", "[bad-input]", float, double) {
    using T = TestType;
    const vec3<T> tri[3] = {{0.2f, -0.3f, 1}, {1.5f, 0.1f, 0.4f}, {0.3f, 1.2f, -0.6f}};
    const auto ref = all_integrals<T>(tri, 3);
    const auto d = ltc::transformed<ltc::clamped_cosine<T>>(supplement_m<T>());
    const T ref_d = d.integrate(tri, 3);
    // Powers of two near the ends of the exponent range (including subnormals): scaling the
    // polygon by them is exact, and the integrals only depend on directions.
    const T huge = std::ldexp(T(1), std::numeric_limits<T>::max_exponent - 2);
    const T tiny = std::numeric_limits<T>::denorm_min() * T(64);
    for (T s : {huge, tiny}) {
        CAPTURE(s);
        const vec3<T> v[3] = {tri[0] * s, tri[1] * s, tri[2] * s};
        const auto r = all_integrals<T>(v, 3);
        REQUIRE(all_finite(r));
        // Subnormal coordinates keep fewer significant bits: 64 * denorm_min has 7, so its
        // direction is only known to 2^-6. Only the huge scale keeps full precision.
        const T tol = s == huge ? T(0) : T(0.1);
        CHECK(r.sphere == Approx(ref.sphere).epsilon(tol));
        CHECK(r.cosine == Approx(ref.cosine).epsilon(tol));
        CHECK(r.squared == Approx(ref.squared).epsilon(tol));
        const T rd = d.integrate(v, 3);
        CHECK(std::isfinite(rd));
        CHECK(rd == Approx(ref_d).epsilon(tol));
    }
}

TEMPLATE_TEST_CASE("from_inverse with entries near the largest finite value integrates as with unit ones",
                   "[bad-input][matrix]", float, double) {
    // M^-1 times a power of two is the same distribution, and the scaling is exact: the integral of
    // the huge M^-1 (whose products M^-1 p and determinant overflow) equals that of the unit one
    // (found by the fuzzer: NaN two-sided, 0 one-sided, before the rescaled slow path).
    using T = TestType;
    const glm::mat<3, 3, T> unit(glm::vec<3, T>(1, 1, 0), glm::vec<3, T>(1, -1, 0), glm::vec<3, T>(0, 0, 1));
    const T big = std::ldexp(T(1), std::numeric_limits<T>::max_exponent - 1);  // the largest power of two
    const vec3<T> quad[4] = {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
    for (const auto s : {ltc::sidedness::two_sided, ltc::sidedness::one_sided}) {
        const T ref = ltc::transformed<ltc::clamped_cosine<T>>::from_inverse(unit).integrate(quad, 4, s);
        const T got = ltc::transformed<ltc::clamped_cosine<T>>::from_inverse(unit * big).integrate(quad, 4, s);
        CAPTURE(s == ltc::sidedness::two_sided, ref, got);
        CHECK(ref > T(0.5));
        CHECK(got == ref);
    }
}

TEMPLATE_TEST_CASE("edge integral is accurate for nearly parallel and nearly opposite vertices", "[bad-input][edge]",
                   float, double) {
    using T = TestType;
    // a, b in the plane spanned by x and a tilted axis, at angle theta; the exact edge term is
    // theta * n with n the unit normal of that plane. Compare with a long double evaluation of
    // the same closed form from the same (rounded) inputs: the error of the library's formula
    // must stay within a few ulps of |term| at every angle, down to theta = 1e-30.
    for (long double theta : {1e-30L, 1e-12L, 1e-6L, 1e-3L, 0.5L, 2.0L, 3.141592653589793238L - 1e-3L,
                              3.141592653589793238L - 1e-6L}) {
        CAPTURE(static_cast<double>(theta));
        const long double c = std::cos(theta), s = std::sin(theta);
        // tilt the plane so that the z component of the normal is neither 0 nor 1
        const vec3<T> a(T(0.6L), T(0), T(0.8L));
        const vec3<T> b(T(0.6L * c), T(s), T(0.8L * c));
        const vec3<T> e = ltc::edge_integral(a, b);
        // reference in long double from the rounded inputs
        using L = long double;
        const glm::vec<3, L> al(a), bl(b);
        // a x b = a x (b -+ a): the difference of the two rounded inputs is exact in long double,
        // so this reference has no cancellation (a plain cross product would lose 1e-13 here).
        const glm::vec<3, L> cr = glm::cross(al, glm::dot(al, bl) >= 0 ? bl - al : bl + al);
        const L sl = glm::length(cr), cl = glm::dot(al, bl);
        const glm::vec<3, L> ref = cr * (std::atan2(sl, cl) / sl);
        const L mag = glm::length(ref);
        const L err = glm::length(glm::vec<3, L>(e) - ref);
        // The reference inputs are unit only up to rounding; the library assumes unit input, so
        // the comparison is with the same formula. Bound: ~16 roundings (stable cross, length,
        // atan2, division, product) of relative size u each.
        CHECK(static_cast<double>(err / mag) <= 16 * std::numeric_limits<T>::epsilon() / 2);
        CHECK(ltc::edge_integral_z(a, b) == Approx(static_cast<T>(ref.z)).epsilon(16 * std::numeric_limits<T>::epsilon()));
    }
}

TEMPLATE_TEST_CASE("evaluation and sampling stay finite at the ends of their domains", "[bad-input]", float, double) {
    using T = TestType;
    const auto d = ltc::transformed<ltc::squared_clamped_cosine<T>>(supplement_m<T>());
    CHECK(d.eval(vec3<T>(0)) == 0);
    CHECK(d.jacobian(vec3<T>(0)) == 0);
    const T below_one = T(1) - std::numeric_limits<T>::epsilon() / 2;
    for (T ux : {T(0), below_one})
        for (T uy : {T(0), below_one}) {
            const vec3<T> w = d.sample(glm::vec<2, T>(ux, uy));
            CAPTURE(ux, uy, w.x, w.y, w.z);
            CHECK(std::abs(glm::length(w) - 1) <= 4 * std::numeric_limits<T>::epsilon());
            CHECK(std::isfinite(d.pdf(w)));
        }
}

TEMPLATE_TEST_CASE("sidedness: one-sided keeps the front, two-sided both", "[bad-input][sides]", float, double) {
    using T = TestType;
    const vec3<T> front[3] = {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}};  // dot(p0, (p1-p0)x(p2-p0)) = 1 > 0
    const vec3<T> back[3] = {front[0], front[2], front[1]};
    const T e = ltc::form_factor_signed(front, 3);
    CHECK(e > 0);
    CHECK(ltc::form_factor_signed(back, 3) == Approx(-e).epsilon(edge_sum_bound<T>(3)));
    CHECK(ltc::form_factor(front, 3, ltc::sidedness::one_sided) == e);
    CHECK(ltc::form_factor(back, 3, ltc::sidedness::one_sided) == 0);
    CHECK(ltc::form_factor(back, 3, ltc::sidedness::two_sided) == Approx(e).epsilon(edge_sum_bound<T>(3)));
    const auto d = ltc::transformed<ltc::clamped_cosine<T>>(supplement_m<T>());  // det(M) = 0.2 > 0
    CHECK(d.integrate_signed(front, 3) > 0);
    CHECK(d.integrate(back, 3, ltc::sidedness::one_sided) == 0);
    // M' = S M with S a mirror: det < 0, and M'^-1 (S P) = M^-1 P is the same polygon with the
    // same orientation. But S P, seen from the origin, winds the other way than P: the sign of
    // integrate_signed refers to the polygon's own orientation, so it must flip.
    const auto mirrored = ltc::transformed<ltc::clamped_cosine<T>>(glm::mat<3, 3, T>(1, 0, 0, 0, -1, 0, 0, 0, 1) * supplement_m<T>());
    const vec3<T> mirror_front[3] = {{0, 0, 1}, {1, 0, 1}, {1, -1, 1}};
    CHECK(mirrored.integrate_signed(mirror_front, 3) == Approx(-d.integrate_signed(front, 3)).epsilon(edge_sum_bound<T>(3) * 4));
}

}  // namespace ltc_test_bad_input
