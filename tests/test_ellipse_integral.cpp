// The ellipse integral and disk lights of ltc/core/ellipse_integral.hpp against brute-force
// quadrature over the ellipse's area (support/disk_quadrature.hpp): ellipses above, across and
// below the horizon and next to the origin, and their vector form factor, in float and double;
// disks through GGX and random LTCs against quadrature of transformed<>::eval over the disk
// (test_disk_light.cpp has the rest: polygons, the 2017 approximation, degenerate input).
// Tolerance: the quadrature's estimate plus k u (S + |I| + sens), with S the angular diameter
// (the closed form's boundary terms are of that size, as a polygon's edge terms are of their
// angles) and sens the integral's sensitivity to relative perturbations of its inputs (finite
// differences in double), which bounds what rounding them, and the closed form's own rounding
// amplified likewise, can do (a point close to a thin ellipse's plane).
#include <ltc/core/ellipse_integral.hpp>
#include <ltc/shading/ggx_fetch.hpp>

#include "support/disk_quadrature.hpp"
#include "support/rng.hpp"

#include <catch2/catch.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace ltc_test_ellipse_integral {  // the file's own names, apart from the other files of a unity batch

namespace {

using glm::dvec3;
using dmat3 = glm::dmat3;
constexpr double pi = 3.141592653589793;
constexpr double rounding_k = 16;  // measured: 2.2 in float, 0.1 in double (printed below)

struct ellipse { dvec3 c, a, b; };
enum class place { above, across, below, near };

/// Random ellipse (semi-axes up to 1, aspect down to 1/50, conjugate pairs up to 45 degrees
/// skewed) at `where` relative to the horizon; `near`: its plane within 1e-3..1e-1 of the origin.
ellipse random_ellipse(ltc_test::rng& r, place where) {
    for (;;) {
        const dvec3 n = r.direction(), t = glm::normalize(glm::cross(n, r.direction())), s = glm::cross(n, t);
        const double e1 = r.uniform(0.05, 1), e2 = e1 * r.uniform(0.02, 1);
        ellipse e{dvec3(0), e1 * t, e2 * s + r.uniform(-1, 1) * e1 * t};
        // (one draw per statement: the order of evaluation of operands is unspecified)
        const double l = where == place::near ? e1 * std::pow(10.0, r.uniform(-3, -1)) : r.uniform(0.2, 3);
        const double offset = e1 * r.uniform(0, 1.5);
        e.c = l * n + offset * glm::normalize(glm::cross(n, r.direction()));
        const double zr = std::hypot(e.a.z, e.b.z);
        const place got = e.c.z - zr > 0 ? place::above : (e.c.z + zr < 0 ? place::below : place::across);
        if (got == where || (where == place::near && got == place::across)) return e;
    }
}

double angular_diameter(const ellipse& e) {
    double d = 0;
    for (int i = 0; i < 64; ++i) {
        const double p = pi * i / 64;
        const dvec3 x = e.c + std::cos(p) * e.a + std::sin(p) * e.b, y = 2.0 * e.c - x;
        d = std::max(d, std::atan2(glm::length(glm::cross(x, y)), glm::dot(x, y)));
    }
    return d;
}

/// max |f(perturbed) - f| / delta over relative perturbations delta = 1e-8 of every input.
template <typename F>
double sensitivity(ltc_test::rng& r, std::vector<double> in, const F& f) {
    const double base = f(in), delta = 1e-8;
    double s = 0;
    for (int k = 0; k < 4; ++k) {
        std::vector<double> p = in;
        for (double& x : p) x *= 1 + delta * (2 * r.uniform() - 1);
        s = std::max(s, std::abs(f(p) - base) / delta);
    }
    return s;
}

template <typename T>
double unit_roundoff() { return std::numeric_limits<T>::epsilon() / 2; }

template <typename T>
glm::vec<3, T> to(const dvec3& v) { return glm::vec<3, T>(v); }

// Worst error / (u (S + |I| + sens)) beyond the quadrature's estimate, and worst relative error
// where |I| >= S / 100 and sens <= 10 |I| (slivers and near-planar views aside), float and double.
double worst_q[2] = {0, 0}, worst_rel[2] = {0, 0};

void record(int type, double closed, double ref, double ref_error, double S, double sens, double bound) {
    worst_q[type] = std::max(worst_q[type], std::max(0.0, std::abs(closed - ref) - ref_error) / bound);
    if (std::abs(ref) >= S / 100 && sens <= 10 * std::abs(ref))
        worst_rel[type] = std::max(worst_rel[type], std::abs(closed - ref) / std::abs(ref));
}

void print_worst(const char* what) {
    std::printf("%s vs quadrature: worst (error - estimate) / (u (S + |I| + sens)): float %.2f, double %.2f; "
                "worst relative error (|I| >= S / 100, sens <= 10 |I|): float %.2g, double %.2g\n",
                what, worst_q[0], worst_q[1], worst_rel[0], worst_rel[1]);
    worst_q[0] = worst_q[1] = worst_rel[0] = worst_rel[1] = 0;
}

template <typename T>
void check_ellipse(ltc_test::rng& r, const ellipse& e0) {
    const ellipse e{dvec3(to<T>(e0.c)), dvec3(to<T>(e0.a)), dvec3(to<T>(e0.b))};  // inputs as T
    const ltc_test::disk_quadrature_result ref = ltc_test::cosine_over_ellipse(e.c, e.a, e.b);
    const double u = unit_roundoff<T>(), S = angular_diameter(e);
    const auto closed_double = [](const std::vector<double>& p) {
        return ltc::integrate_ellipse_cosine(dvec3(p[0], p[1], p[2]), dvec3(p[3], p[4], p[5]), dvec3(p[6], p[7], p[8]));
    };
    const double sens = sensitivity(r, {e.c.x, e.c.y, e.c.z, e.a.x, e.a.y, e.a.z, e.b.x, e.b.y, e.b.z}, closed_double);
    const double closed = ltc::integrate_ellipse_cosine(to<T>(e.c), to<T>(e.a), to<T>(e.b));
    const double reversed = ltc::integrate_ellipse_cosine(to<T>(e.c), to<T>(e.a), to<T>(-e.b));
    const double bound = u * (S + std::abs(ref.value) + sens), tol = ref.error + rounding_k * bound;
    CAPTURE(sizeof(T), e.c, e.a, e.b, closed, ref.value, ref.error, S, sens, tol);
    REQUIRE(ref.converged);
    CHECK(std::abs(closed - ref.value) <= tol);
    CHECK(std::abs(closed + reversed) <= 2 * rounding_k * bound);  // the orientation flips the sign
    record(sizeof(T) == 8, closed, ref.value, ref.error, S, sens, bound);
}

}  // namespace

TEST_CASE("ellipse cosine integral equals brute force over the ellipse's area", "[ellipse]") {
    ltc_test::rng r(0xe11105e);
    for (place where : {place::above, place::across, place::below, place::near})
        for (int i = 0; i < 30; ++i) {
            const ellipse e = random_ellipse(r, where);
            check_ellipse<float>(r, e);
            check_ellipse<double>(r, e);
            if (where == place::below) CHECK(ltc::integrate_ellipse_cosine(e.c, e.a, e.b) == 0.0);
        }
    print_worst("ellipse integral");
}

TEST_CASE("the ellipse's vector form factor equals brute force, and F.z the integral above the horizon",
          "[ellipse]") {
    ltc_test::rng r(0xf0f0);
    for (int i = 0; i < 20; ++i) {
        const ellipse e = random_ellipse(r, i % 2 ? place::above : place::near);
        const dvec3 F = ltc::ellipse_vector_form_factor(e.c, e.a, e.b);
        const double sign = glm::dot(e.c, glm::cross(e.a, e.b)) > 0 ? 1 : -1;
        const dvec3 toward = sign * glm::normalize(glm::cross(e.a, e.b));  // <x, toward> > 0 on the ellipse
        for (int k = 0; k < 3; ++k) {
            const auto ref = ltc_test::integrate_ellipse(e.c, e.a, e.b, toward,
                                                         [&](const dvec3& w, double) { return w[k] / pi; });
            const double tol = ref.error + rounding_k * unit_roundoff<double>() * (angular_diameter(e) + 1);
            CAPTURE(e.c, e.a, e.b, k, F, ref.value, ref.error);
            CHECK(std::abs(F[k] - sign * ref.value) <= tol);
        }
        if (i % 2) CHECK(std::abs(F.z - ltc::integrate_ellipse_cosine(e.c, e.a, e.b)) <= 1e-15);
    }
    // A centred circle of angular radius sigma: F = sin^2(sigma) along its axis.
    const dvec3 F = ltc::ellipse_vector_form_factor(dvec3(0, 0, 2), dvec3(1, 0, 0), dvec3(0, 1, 0));
    CHECK(std::abs(F.z - 0.2) <= 1e-16);
    CHECK(F.x == 0.0);
}

namespace {

/// A disk in the LTC's frame and the brute force of d.eval over it (signed by its facing).
struct disk { dvec3 centre, normal; double radius; };

/// A disk at distance 0.3-3, or (near) with its plane 1e-3..1e-1 of its radius from the point.
disk random_disk(ltc_test::rng& r, bool near) {
    disk k{r.direction(), r.direction(), r.uniform(0.05, 1)};  // braced: evaluated in order
    k.centre *= r.uniform(0.3, 3);
    if (near) {
        const dvec3 along = glm::normalize(glm::cross(k.normal, r.direction()));
        const double height = std::pow(10.0, r.uniform(-3, -1)), offset = r.uniform(0, 1.5);
        k.centre = k.radius * (height * k.normal + offset * along);
    }
    return k;
}

/// (t, s): an orthonormal pair in the disk's plane.
void disk_basis(const disk& k, dvec3& t, dvec3& s) {
    const dvec3 n = glm::normalize(k.normal);
    t = glm::normalize(glm::cross(n, dvec3(0.3, -0.7, 0.5)));
    s = glm::cross(n, t);
}

ltc_test::disk_quadrature_result disk_reference(const dmat3& m_inv, const disk& k) {
    const auto d = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(m_inv);
    dvec3 t, s;
    disk_basis(k, t, s);
    auto ref = ltc_test::integrate_ellipse(k.centre, k.radius * t, k.radius * s, glm::transpose(m_inv)[2],
                                           [&](const dvec3& w, double) { return d.eval(w); });
    if (glm::dot(k.centre, k.normal) > 0) ref.value = -ref.value;  // seen from behind
    return ref;
}

std::vector<dmat3> test_matrices(ltc_test::rng& r) {
    std::vector<dmat3> m;
    for (double cos_v : {0.2, 0.6, 0.95})
        for (double rough : {0.1, 0.4, 0.9}) m.push_back(dmat3(ltc::ggx::fetch(cos_v, rough).m_inv));
    for (int i = 0; i < 3; ++i) {
        dmat3 a(1.0);
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k) a[c][k] += r.uniform(-0.6, 0.6);
        m.push_back(a);
    }
    return m;
}

template <typename T>
void check_disk(ltc_test::rng& r, const dmat3& m0, const disk& k0) {
    const dmat3 m = dmat3(glm::mat<3, 3, T>(m0));  // the inputs as T
    const disk k{dvec3(to<T>(k0.centre)), dvec3(to<T>(k0.normal)), double(T(k0.radius))};
    const auto ref = disk_reference(m, k);
    const auto d = ltc::transformed<ltc::clamped_cosine<T>>::from_inverse(glm::mat<3, 3, T>(m));
    const double two = ltc::integrate_disk(d, to<T>(k.centre), to<T>(k.normal), T(k.radius));
    const double one =
        ltc::integrate_disk(d, to<T>(k.centre), to<T>(k.normal), T(k.radius), ltc::sidedness::one_sided);
    const auto closed_double = [](const std::vector<double>& p) {  // one-sided: signed for the facing side
        const auto dd = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(
            dmat3(p[7], p[8], p[9], p[10], p[11], p[12], p[13], p[14], p[15]));
        const dvec3 centre(p[0], p[1], p[2]), normal(p[3], p[4], p[5]);
        return ltc::integrate_disk(dd, centre, normal, p[6], ltc::sidedness::one_sided);
    };
    const std::vector<double> inputs{k.centre.x, k.centre.y, k.centre.z, k.normal.x, k.normal.y, k.normal.z, k.radius,
                                     m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1], m[2][2]};
    const double sens = sensitivity(r, inputs, closed_double);
    dvec3 t, s;
    disk_basis(k, t, s);
    const double S = angular_diameter({m * k.centre, m * (k.radius * t), m * (k.radius * s)});  // of M^-1 disk
    const double bound = unit_roundoff<T>() * (S + std::abs(ref.value) + sens), tol = ref.error + rounding_k * bound;
    CAPTURE(sizeof(T), m, k.centre, k.normal, k.radius, two, one, ref.value, ref.error, sens, tol);
    REQUIRE(ref.converged);
    CHECK(std::abs(two - std::abs(ref.value)) <= tol);
    CHECK(std::abs(one - std::max(ref.value, 0.0)) <= tol);
    record(sizeof(T) == 8, two, std::abs(ref.value), ref.error, S, sens, bound);
}

}  // namespace

TEST_CASE("integrate_disk equals brute force of the LTC's density over the disk", "[ellipse][disk]") {
    ltc_test::rng r(0xd15c);
    for (const dmat3& m : test_matrices(r))
        for (int i = 0; i < 8; ++i) {
            const disk k = random_disk(r, i % 4 == 3);
            check_disk<float>(r, m, k);
            check_disk<double>(r, m, k);
        }
    print_worst("disk integral (quadrature of eval)");
}

namespace {

/// c = b with one coordinate moved by 1-2 ulps: the origin (c - b, the boundary point phi =
/// -pi/2) is on the ellipse's rim and within rounding of its plane, where the cone's secular
/// equation loses every digit (make_cone_axis's floored step).
template <typename T>
void check_rim_and_plane(ltc_test::rng& r) {
    using vec3 = glm::vec<3, T>;
    for (int i = 0; i < 2000; ++i) {
        vec3 a, b;
        for (int j = 0; j < 3; ++j) a[j] = T(r.uniform(-1, 1));  // one draw per statement
        for (int j = 0; j < 3; ++j) b[j] = T(r.uniform(-1, 1));
        vec3 c = b;
        const int k = i % 3, ulps = i % 5 - 2;
        for (int j = 0; j < std::abs(ulps); ++j) c[k] = std::nextafter(c[k], ulps > 0 ? T(2) : T(-2));
        const T e = ltc::integrate_ellipse_cosine(c, a, b);
        const vec3 F = ltc::ellipse_vector_form_factor(c, a, b);
        CAPTURE(sizeof(T), c, a, b, e, F);
        CHECK(std::abs(e) <= T(1));
        CHECK((std::abs(F.x) <= T(1) && std::abs(F.y) <= T(1) && std::abs(F.z) <= T(1)));
    }
}

}  // namespace

TEST_CASE("the origin next to both an ellipse's rim and its plane: finite, in [-1, 1] (fuzzer's NaN)",
          "[ellipse][bad_input]") {
    // Found by the fuzzer (float): b = c but for c.z's last bit, scaled near float's maximum.
    // The frame puts the origin within rounding of the plane (l = 2^-24 in its units) and of the
    // rim; a lower bound of the secular equation's root mu ~ 3e-8 rounded above it, and the
    // Newton step from there (g ~ +epsilon, g' ~ 2) made mu negative: NaN through sqrt(mu).
    const glm::vec3 c(-0x1.4b4b4ap+127f, -0x1.4b4b4ap+127f, -0x1.4b4b48p+127f);
    const glm::vec3 a(-0x1.174118p+127f, 0x1.7e4dfep+127f, 0x1.fffdfep+127f);
    const glm::vec3 b(-0x1.4b4b4ap+127f, -0x1.4b4b4ap+127f, -0x1.4b4b4ap+127f);
    const float e = ltc::integrate_ellipse_cosine(c, a, b);
    const glm::vec3 F = ltc::ellipse_vector_form_factor(c, a, b);
    CAPTURE(e, F);
    CHECK(std::abs(e) <= 1.0f);
    CHECK((std::abs(F.x) <= 1.0f && std::abs(F.y) <= 1.0f && std::abs(F.z) <= 1.0f));
    // The same at unit scale, in float and double (about 5% of such cases were NaN before).
    ltc_test::rng r(0x5111);
    check_rim_and_plane<float>(r);
    check_rim_and_plane<double>(r);
}

}  // namespace ltc_test_ellipse_integral
