// Tests of ltc/shading/clipless.hpp: the analytic horizon-clipped sphere form factor (against the
// production note's literal formula, an independent closed form, and exact integrals of
// polygons that sandwich a spherical cap), the 32 x 32 table (against a derived interpolation
// bound), and the error of the clipless approximation against exact clipping over a
// documented set of polygons.
#include <catch2/catch.hpp>

#include <ltc/shading/clipless.hpp>
#include <ltc/ltc.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

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

/// The documented polygon set for the clipless error: a rectangle of aspect 1, 4 or 16 (long
/// side 2 tan(half)) or an isosceles-ish triangle squashed by the aspect, facing the origin,
/// centred at elevation `elevation` (azimuth 0), rolled by `roll` about its axis (roll 0: the
/// long side parallel to the horizon).
std::vector<dvec3> documented_light(int shape, double aspect, double half_deg, double elevation_deg, double roll_deg) {
    const double e = elevation_deg * pi / 180, r = roll_deg * pi / 180, s = std::tan(half_deg * pi / 180);
    const dvec3 c(std::cos(e), 0, std::sin(e)), e1(0, 1, 0), e2 = glm::cross(c, e1);
    const dvec3 u = std::cos(r) * e1 + std::sin(r) * e2, w = -std::sin(r) * e1 + std::cos(r) * e2;
    std::vector<glm::dvec2> p;
    if (shape == 0)
        p = {{-s, -s / aspect}, {s, -s / aspect}, {s, s / aspect}, {-s, s / aspect}};
    else
        for (int i = 0; i < 3; ++i) {
            const double phi = 2 * pi * i / 3 + 0.2;
            p.push_back({s * std::cos(phi), s * std::sin(phi) / aspect});
        }
    std::vector<dvec3> v;
    for (const auto& q : p) v.push_back(c + q.x * u + q.y * w);
    if (glm::dot(v[0], glm::cross(v[1] - v[0], v[2] - v[0])) < 0) std::reverse(v.begin(), v.end());
    return v;
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

TEST_CASE("clipless is exact above and below the horizon, and follows the orientation", "[clipless]") {
    const dvec3 above[4] = {{-1, 0, 0.5}, {1, 0, 0.5}, {1, 2, 1.5}, {-1, 2, 1.5}};
    const dvec3 below[3] = {{0, 0, -1}, {1, 0, -1.5}, {0, 1, -1}};
    dvec3 reversed[4];
    std::reverse_copy(above, above + 4, reversed);
    for (const auto how : {cl::method::analytic, cl::method::table}) {
        const double exact = ltc::form_factor_signed(above, 4);
        REQUIRE(exact > 0);
        CHECK_THAT(cl::form_factor_signed(above, 4, how), Catch::Matchers::WithinRel(exact, 1e-12));
        CHECK_THAT(cl::form_factor_signed(reversed, 4, how), Catch::Matchers::WithinRel(-exact, 1e-12));
        CHECK(cl::form_factor(reversed, 4, ltc::sidedness::one_sided, how) == 0.0);
        CHECK_THAT(cl::form_factor(reversed, 4, ltc::sidedness::two_sided, how), Catch::Matchers::WithinRel(exact, 1e-12));
        CHECK(cl::form_factor(below, 3, ltc::sidedness::two_sided, how) == 0.0);
        // Degenerate input: nothing, a vertex at the origin.
        CHECK(cl::form_factor(above, 2, ltc::sidedness::two_sided, how) == 0.0);
        const dvec3 at_origin[3] = {{0, 0, 0}, {1, 0, 1}, {0, 1, 1}};
        CHECK(cl::form_factor(at_origin, 3, ltc::sidedness::two_sided, how) == 0.0);
    }
    // Through an LTC: exact when M^-1 P is above the LTC's horizon; a matrix with negative
    // determinant flips the orientation of M^-1 P but not the sign of the result.
    const glm::dmat3 m_inv = glm::transpose(glm::dmat3(1.2, 0, 0.3, 0, 0.8, 0, -0.2, 0, 1));
    for (const double flip : {1.0, -1.0}) {
        glm::dmat3 mi = m_inv;
        mi[1] *= flip;  // negate the y column
        const auto d = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(mi);
        const double exact = d.integrate_signed(above, 4);
        CAPTURE(flip);
        CHECK_THAT(cl::integrate_signed(d, above, 4), Catch::Matchers::WithinRel(exact, 1e-12));
        CHECK_THAT(cl::integrate(d, reversed, 4, ltc::sidedness::two_sided), Catch::Matchers::WithinRel(exact, 1e-12));
        CHECK(cl::integrate(d, reversed, 4, ltc::sidedness::one_sided) == 0.0);
    }
    // float
    const glm::vec3 above_f[4] = {{-1, 0, 0.5f}, {1, 0, 0.5f}, {1, 2, 1.5f}, {-1, 2, 1.5f}};
    CHECK_THAT(cl::form_factor(above_f, 4, ltc::sidedness::one_sided), Catch::Matchers::WithinRel(float(ltc::form_factor_signed(above, 4)), 1e-5f));
}

TEST_CASE("clipless vs exact clipping over the documented set of straddling polygons", "[clipless]") {
    // Documented set: rectangles (aspect 1, 4, 16) and triangles (squashed by the same aspect)
    // of half-size 5, 20, 45 and 75 degrees, centred at elevations -30 to 30 degrees in steps of
    // 2.5, rolled by 0, 30, 60 and 90 degrees (roll 0: long side along the horizon). The error
    // is measured relative to f = |F| (the unclipped magnitude, which scales what a pixel
    // shows), and relative to the exact value where that is >= 1e-3 f.
    struct group {
        double aspect;
        double max_abs_measured;   // max |clipless - exact| / f over the group (measured, rounded up)
        double mean_rel_measured;  // mean |clipless - exact| / exact over the group (same)
    };
    // Measured: aspect 1: 0.01190, 4.72%; aspect 4: 0.09614, 32.4%; aspect 16: 0.19304, 48.4%.
    const group groups[] = {{1, 0.0120, 0.0473}, {4, 0.0962, 0.325}, {16, 0.1931, 0.484}};
    for (const group& g : groups) {
        double worst = 0, sum_rel = 0, worst_table_gap = 0, worst_exact_case = 0;
        int n_rel = 0, n_exact_cases = 0;
        for (int shape = 0; shape < 2; ++shape)
            for (const double half : {5.0, 20.0, 45.0, 75.0})
                for (int k = -12; k <= 12; ++k)
                    for (const double roll : {0.0, 30.0, 60.0, 90.0}) {
                        const auto v = documented_light(shape, g.aspect, half, 2.5 * k, roll);
                        const double exact = ltc::form_factor(v.data(), v.size(), ltc::sidedness::one_sided);
                        const double approx = cl::form_factor(v.data(), v.size(), ltc::sidedness::one_sided);
                        const double tab = cl::form_factor(v.data(), v.size(), ltc::sidedness::one_sided, cl::method::table);
                        const double f = cl::sphere_of_polygon(v.data(), v.size()).f;
                        worst = std::max(worst, std::abs(approx - exact) / f);
                        worst_table_gap = std::max(worst_table_gap, std::abs(tab - approx) / f);
                        if (exact >= 1e-3 * f) sum_rel += std::abs(approx - exact) / exact, ++n_rel;
                        // The polygon and its sphere (cos omega >= sin sigma) entirely above the
                        // horizon: exact.
                        const auto sph = cl::sphere_of_polygon(v.data(), v.size());
                        bool above = sph.cos_omega >= std::sqrt(sph.f);
                        for (const auto& p : v) above = above && p.z >= 0;
                        if (above) {
                            ++n_exact_cases;
                            worst_exact_case = std::max(worst_exact_case, std::abs(approx - exact) / exact);
                        }
                    }
        CAPTURE(g.aspect, worst, sum_rel / n_rel, worst_table_gap, n_exact_cases);
        CHECK(n_exact_cases > 0);
        CHECK(worst_exact_case <= 1e-12);
        CHECK(worst <= g.max_abs_measured);
        CHECK(sum_rel / n_rel <= g.mean_rel_measured);
        CHECK(worst_table_gap <= 2.3e-3);
    }
}

TEST_CASE("clipless through an LTC with any edge policy: invariant to the scale of M^-1", "[clipless]") {
    // Every edge policy but exact assumes unit vertices (c = a.b is a cosine only for them). The
    // LTC, hence the clipless result, does not depend on the scale of M^-1: scaling it by a power
    // of two scales M^-1 p exactly, and the normalized vertices, the edge terms and the result
    // are bitwise those of the unscaled matrix. Without the normalization the polynomial policy
    // was off by up to 0.4 on bench_polygon's configurations.
    const glm::vec3 straddling[4] = {{-1, -0.5f, -0.1f}, {1, -0.5f, -0.1f}, {1, 1.5f, 1.5f}, {-1, 1.5f, 1.5f}};
    const glm::vec3 above[4] = {{-1, 0, 0.5f}, {1, 0, 0.5f}, {1, 2, 1.5f}, {-1, 2, 1.5f}};
    const glm::mat3 m_inv = glm::transpose(glm::mat3(0.4f, 0, 0.3f, 0, 0.6f, 0, -0.2f, 0, 1));
    using poly = ltc::transformed<ltc::clamped_cosine<float, ltc::edge_policy::polynomial>>;
    for (const glm::vec3* quad : {straddling, above})
        for (const auto how : {cl::method::analytic, cl::method::table})
            for (const float scale : {1024.0f, 1.0f / 1024.0f}) {
                CAPTURE(scale, static_cast<int>(how), quad == above);
                const float unit = cl::integrate(poly::from_inverse(m_inv), quad, 4, ltc::sidedness::two_sided, how);
                REQUIRE(unit > 0.0f);
                CHECK(cl::integrate(poly::from_inverse(m_inv * scale), quad, 4, ltc::sidedness::two_sided, how) == unit);
            }
    // And the polynomial result is the exact policy's up to float rounding: the two edge terms
    // differ by 2.6e-7 relative at most (tests/test_edge_policies.cpp) and each path rounds its
    // vertices and sums: 1e-5 relative leaves a wide margin over both.
    using exact = ltc::transformed<ltc::clamped_cosine<float>>;
    for (const glm::vec3* quad : {straddling, above})
        CHECK_THAT(cl::integrate(poly::from_inverse(m_inv), quad, 4, ltc::sidedness::two_sided),
                   Catch::Matchers::WithinRel(cl::integrate(exact::from_inverse(m_inv), quad, 4, ltc::sidedness::two_sided), 1e-5f));
}
