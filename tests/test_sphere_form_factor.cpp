// Tests of ltc/core/sphere_form_factor.hpp and ltc/shading/sphere_table.hpp (namespace
// ltc::clipless): the analytic horizon-clipped sphere form factor (against the production note's
// literal formula, an independent closed form, and exact integrals of polygons that sandwich a
// spherical cap), and the 32 x 32 table (against a derived interpolation bound). The clipless
// approximation of polygons (ltc/shading/clipless.hpp) is tested in test_clipless.cpp.
#include <catch2/catch.hpp>

#include <ltc/shading/clipless.hpp>
#include <ltc/core/sphere_form_factor.hpp>
#include <ltc/shading/sphere_table.hpp>
#include <ltc/ltc.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ltc_test_sphere_form_factor {  // the file's own names, apart from the other files of a unity batch

namespace {

using glm::dvec3;
namespace cl = ltc::clipless;
constexpr double pi = 3.141592653589793;

/// The note's I_hemisphere / pi, transcribed literally (Snyder 1996), for the band only.
double note_formula(double f, double c) {
    const double sigma = std::asin(std::sqrt(f)), omega = std::acos(c);
    const double s2 = f;
    if (omega <= pi / 2 - sigma) return c * s2;
    if (omega >= pi / 2 + sigma) return 0;
    const double gamma = std::asin(std::cos(sigma) / std::sin(omega));
    const double G = -2 * std::sin(omega) * std::cos(sigma) * std::cos(gamma) + pi / 2 - gamma +
                     std::sin(gamma) * std::cos(gamma);
    const double H = std::cos(omega) * (std::cos(gamma) * std::sqrt(std::max(0.0, s2 - std::cos(gamma) * std::cos(gamma))) +
                                        s2 * std::asin(std::min(1.0, std::cos(gamma) / std::sin(sigma))));
    const double I = omega <= pi / 2 ? pi * c * s2 + G - H : G + H;
    return I / pi;
}

/// Illuminance of a sphere light, Lagarde and de Rousiers 2014 ("Moving Frostbite to PBR",
/// listing 7, after Snyder 1996), an independent closed form: divided by pi.
double frostbite_formula(double f, double c) {
    if (c * c > f) return std::max(0.0, c) * f;
    const double sin_theta = std::sqrt(1 - c * c);
    const double x = std::sqrt(1 / f - 1);
    const double y = -x * c / sin_theta;
    const double sin_theta_sqrt_y = sin_theta * std::sqrt(1 - y * y);
    const double e = (c * std::acos(y) - x * sin_theta_sqrt_y) * f + std::atan(sin_theta_sqrt_y / x);
    return std::max(0.0, e) / pi;
}

/// A regular k-gon whose vertices lie on the cone of half-angle `radius` around the direction
/// at angle omega from +z (in the xz-plane): inscribed in that cap. With circumscribed = true,
/// its edges touch the cap instead (the vertices at radius atan(tan(radius) / cos(pi / k))).
std::vector<dvec3> cap_polygon(double omega, double radius, int k, bool circumscribed) {
    const dvec3 c(std::sin(omega), 0, std::cos(omega));
    const dvec3 e1(0, 1, 0), e2 = glm::cross(c, e1);
    const double r = std::tan(radius) / (circumscribed ? std::cos(pi / k) : 1.0);
    std::vector<dvec3> v;
    for (int i = 0; i < k; ++i) {
        const double phi = 2 * pi * i / k;
        v.push_back(c + r * (std::cos(phi) * e1 + std::sin(phi) * e2));
    }
    if (glm::dot(v[0], glm::cross(v[1] - v[0], v[2] - v[0])) < 0) std::reverse(v.begin(), v.end());
    return v;
}

/// q(t, y) = I / sin^3(sigma) in the table's coordinates (clipless.hpp).
double table_q(double t, double y) {
    t = glm::clamp(t, -1.0, 1.0);
    y = glm::clamp(y, 0.0, 1.0);
    if (y <= 0) return cl::detail::small_sphere_limit(t);
    const double s2 = y * (2 - y), s = std::sqrt(s2);
    return cl::sphere_form_factor(s2, t * s) / (s2 * s);
}

}  // namespace

TEST_CASE("sphere form factor: the note's formula, an independent closed form, edge cases", "[clipless]") {
    double worst_note = 0, worst_frostbite = 0;
    int out_of_range = 0;
    for (int i = 1; i < 100; ++i)
        for (int j = 0; j <= 200; ++j) {
            const double f = i / 100.0, c = -1 + j / 100.0;
            const double v = cl::sphere_form_factor(f, c);
            worst_note = std::max(worst_note, std::abs(v - note_formula(f, c)));
            worst_frostbite = std::max(worst_frostbite, std::abs(v - frostbite_formula(f, c)));
            out_of_range += !(v >= 0.0 && v <= f);
        }
    CHECK(out_of_range == 0);
    CHECK(worst_note < 1e-12);
    CHECK(worst_frostbite < 1e-12);
    // Branch boundaries and limits.
    CHECK(cl::sphere_form_factor(0.0, 0.5) == 0.0);
    CHECK(cl::sphere_form_factor(0.0, -0.5) == 0.0);
    CHECK(cl::sphere_form_factor(0.25, 0.5) == 0.125);  // c = sin(sigma): just fully visible
    CHECK(cl::sphere_form_factor(0.25, -0.5) == 0.0);
    CHECK_THAT(cl::sphere_form_factor(1.0, 0.3), Catch::Matchers::WithinAbs(0.65, 1e-15));  // (1 + c) / 2
    CHECK_THAT(cl::sphere_form_factor(1.0, -0.3), Catch::Matchers::WithinAbs(0.35, 1e-15));
    const double sigma = 0.4;  // centred on the horizon: the segment (sigma - sin cos) / pi
    CHECK_THAT(cl::sphere_form_factor(std::sin(sigma) * std::sin(sigma), 0.0),
               Catch::Matchers::WithinAbs((sigma - std::sin(sigma) * std::cos(sigma)) / pi, 1e-15));
    // Out-of-domain inputs are clamped, never NaN.
    CHECK(cl::sphere_form_factor(2.0, 2.0) == 1.0);
    CHECK(cl::sphere_form_factor(-1.0, 0.5) == 0.0);
    CHECK(std::isfinite(cl::sphere_form_factor(1.0, 1.0)));
    CHECK(std::isfinite(cl::sphere_form_factor(1.0, -1.0)));
}

TEST_CASE("sphere form factor: float keeps a few ulps of sin^3(sigma), down to tiny spheres", "[clipless]") {
    // The note's form cancels O(sigma) terms to an O(sigma^3) result; the library's does not.
    for (const double s : {0.999, 0.9, 0.5, 0.1, 0.01, 1e-3, 1e-4}) {
        double worst = 0;
        for (int i = 0; i <= 400; ++i) {
            const float f = float(s * s), c = float(-s + 2 * s * i / 400.0);
            const double ref = cl::sphere_form_factor(double(f), double(c));
            worst = std::max(worst, std::abs(double(cl::sphere_form_factor(f, c)) - ref) / (double(f) * std::sqrt(double(f))));
        }
        CAPTURE(s);
        CHECK(worst < 1e-6);
    }
}

TEST_CASE("sphere form factor lies between the exact form factors of inscribed and circumscribed polygons",
          "[clipless]") {
    // A cap is sandwiched between an inscribed and a circumscribed regular k-gon (the integrand
    // max(0, z) / pi is non-negative), whose clipped form factors are exact (eq. 11). That
    // checks the formula against an independent exact computation, to within the gap.
    for (const double radius_deg : {2.0, 10.0, 30.0, 60.0, 85.0})
        for (const double omega_deg : {0.0, 20.0, 45.0, 80.0, 89.0, 90.0, 95.0, 110.0, 150.0}) {
            const double radius = radius_deg * pi / 180, omega = omega_deg * pi / 180;
            const double f = std::sin(radius) * std::sin(radius);
            const double v = cl::sphere_form_factor(f, std::cos(omega));
            const auto in = cap_polygon(omega, radius, 512, false);
            const auto out = cap_polygon(omega, radius, 512, true);
            const double lo = ltc::form_factor(in.data(), in.size(), ltc::sidedness::one_sided);
            const double hi = ltc::form_factor(out.data(), out.size(), ltc::sidedness::one_sided);
            CAPTURE(radius_deg, omega_deg, lo, v, hi);
            CHECK(lo <= v + 1e-13);
            CHECK(v <= hi + 1e-13);
            CHECK(hi - lo <= 1e-4 * f + 1e-15);  // the sandwich is tight: a real check
            // The clipless approximation of the polygon itself is then within the gap too, plus
            // the polygon's own departure from a cap (its vector form factor is a k-gon's).
            const double approx = cl::form_factor(in.data(), in.size(), ltc::sidedness::one_sided);
            CHECK(std::abs(approx - lo) <= 2e-4 * f + 1e-12);
        }
}

TEST_CASE("sphere table: bilinear error within the derived bound, cell by cell", "[clipless]") {
    // In each cell of the 32 x 32 grid over (t, y), bilinear interpolation of a C^1 function
    // errs by at most h_t/4 osc(q_t) + h_y/4 osc(q_y) (1D: e' = f' - mean slope, so e(x) <=
    // h osc(f') / 4; the tensor product adds the two), osc the oscillation of the partial
    // derivative over the cell, estimated here on a 13 x 13 sub-grid by central differences.
    // (q is only C^1 at the corner t = 1, y = 1, where its second derivative in t grows like
    // cos(sigma)^(-3/2): a second-derivative bound would be infinite there.)
    const int N = int(cl::sphere_table_size);
    const double ht = 2.0 / (N - 1), hy = 1.0 / (N - 1), d = 1e-5;
    const int S = 12;
    const cl::sphere_table& table = cl::sphere_table::instance();
    double max_bound = 0, max_error = 0;
    int violations = 0;
    for (int j = 0; j < N - 1; ++j)
        for (int i = 0; i < N - 1; ++i) {
            const double t0 = -1 + i * ht, y0 = j * hy;
            double osc_t = 0, osc_y = 0;
            for (int b = 0; b <= S; ++b) {
                double lo = 1e300, hi = -1e300, lo_y = 1e300, hi_y = -1e300;
                for (int a = 0; a <= S; ++a) {
                    const double t = t0 + ht * a / S, y = y0 + hy * b / S;
                    const double tl = std::max(-1.0, t - d), tr = std::min(1.0, t + d);
                    const double gt = (table_q(tr, y) - table_q(tl, y)) / (tr - tl);
                    lo = std::min(lo, gt), hi = std::max(hi, gt);
                    // transposed: q_y along the line t = t0 + ht b / S
                    const double tt = t0 + ht * b / S, yy = y0 + hy * a / S;
                    const double yl = std::max(0.0, yy - d), yr = std::min(1.0, yy + d);
                    const double gy = (table_q(tt, yr) - table_q(tt, yl)) / (yr - yl);
                    lo_y = std::min(lo_y, gy), hi_y = std::max(hi_y, gy);
                }
                osc_t = std::max(osc_t, hi - lo);
                osc_y = std::max(osc_y, hi_y - lo_y);
            }
            const double bound = ht / 4 * osc_t + hy / 4 * osc_y + 1e-6;  // + float storage
            max_bound = std::max(max_bound, bound);
            for (int b = 0; b < 9; ++b)
                for (int a = 0; a < 9; ++a) {
                    const double t = t0 + ht * (a + 0.37) / 9, y = y0 + hy * (b + 0.61) / 9;
                    const double s2 = y * (2 - y), s = std::sqrt(s2);
                    const double e = std::abs(table.lookup(s2, t * s) - cl::sphere_form_factor(s2, t * s)) / (s2 * s);
                    max_error = std::max(max_error, e);
                    violations += e > bound;
                }
        }
    CAPTURE(max_bound, max_error);
    CHECK(violations == 0);
    CHECK(max_bound < 8.1e-3);  // derived: |table - analytic| <= 8.1e-3 sin^3(sigma) <= 8.1e-3 f
    CHECK(max_error < 2.3e-3);  // measured: 2.23e-3 (at t ~ 0.97, y ~ 0.88)

    // Outside the band the table is exact; over the whole (f, cos omega) square the error is
    // at most the measured 2.3e-3 f.
    double worst = 0, worst_outside = 0;
    for (int i = 0; i <= 400; ++i)
        for (int j = 0; j <= 400; ++j) {
            const double f = i / 400.0, c = -1 + j / 200.0;
            const double e = std::abs(cl::sphere_form_factor_table(f, c) - cl::sphere_form_factor(f, c));
            worst = std::max(worst, f > 0 ? e / f : e);
            if (c * c >= f) worst_outside = std::max(worst_outside, e);
        }
    CHECK(worst < 2.3e-3);
    CHECK(worst_outside == 0.0);
    CHECK(cl::sphere_form_factor_table(0.3f, 0.1f) == Approx(cl::sphere_form_factor(0.3f, 0.1f)).margin(2.3e-3 * 0.3));
}

}  // namespace ltc_test_sphere_form_factor
