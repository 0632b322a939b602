// Tests of ltc/reference/shape_ground_truth.hpp: the sphere, disk, tube and line estimators against
// closed forms with a Lambertian "BRDF" (Nusselt / Snyder's sphere form factor, the coaxial disk,
// a fine polygon for a tilted disk, tubes seen along their axis, the line integral (L2) of
// ltc/core/line_integral.hpp's derivation), the thin tube against the line, GGX over a sphere and a
// disk covering the same cone (MIS and each light sampler alone), the techniques against each other
// where an open tube is seen through its end, determinism and degenerate input.
//
// Every random test uses a fixed seed, so it is deterministic; the tolerances are 4 standard errors
// (combined in quadrature for two estimates), which a correct estimator fails with probability
// < 1e-4 per check, plus the bias terms derived next to each check.
#include <catch2/catch.hpp>

#include <ltc/core/form_factor.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/brdf/ggx.hpp>
#include <ltc/reference/shape_ground_truth.hpp>
#include <ltc/core/sphere_form_factor.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <vector>

namespace ltc_test_shape_ground_truth {  // the file's own names, apart from the other files of a unity batch

namespace {

using glm::dvec2;
using glm::dvec3;
namespace gt = ltc::ground_truth;
constexpr double pi = 3.141592653589793;
constexpr gt::techniques all_techniques[] = {gt::techniques::mis, gt::techniques::brdf_only,
                                             gt::techniques::polygon_only};

/// The clamped cosine as a "BRDF" (eval = max(0, L.z) / pi), cosine-sampled.
struct lambert {
    double eval(const dvec3&, const dvec3& L, double) const { return L.z > 0 ? L.z / pi : 0.0; }
    double pdf(const dvec3& V, const dvec3& L, double a) const { return eval(V, L, a); }
    dvec3 sample(const dvec3&, const dvec2& u, double) const {
        const double r = std::sqrt(u.x), phi = 2 * pi * u.y;
        return {r * std::cos(phi), r * std::sin(phi), std::sqrt(1 - u.x)};
    }
};

gt::options make_options(std::uint64_t samples, std::uint64_t seed, gt::techniques use = gt::techniques::mis) {
    gt::options opt;
    opt.samples = samples;
    opt.seed = seed;
    opt.use = use;
    return opt;
}

/// |a - b| <= 4 sigma combined (+ slack): two independent estimates of the same integral.
bool agree(const gt::estimate& a, const gt::estimate& b, double slack = 0.0) {
    return std::abs(a.mean - b.mean) <= 4 * std::hypot(a.standard_error, b.standard_error) + slack + 1e-15;
}

/// The clamped-cosine line integral (L2) of ltc/core/line_integral.hpp, clipped to z >= 0.
double line_cosine(dvec3 a, dvec3 b) {
    if (a.z <= 0 && b.z <= 0) return 0;
    const dvec3 span = b - a, t = glm::normalize(span);
    const dvec3 foot = a - glm::dot(a, t) * t;
    const double d = glm::length(foot);
    const dvec3 n = foot / d;
    if (a.z < 0) a += a.z / (a.z - b.z) * span;
    if (b.z < 0) b -= b.z / (b.z - a.z) * span;
    const auto F = [&](const dvec3& x) {
        const double th = std::atan2(glm::dot(x, t), d);
        return n.z * (th + std::sin(th) * std::cos(th)) + t.z * std::sin(th) * std::sin(th);
    };
    return (F(b) - F(a)) / (2 * pi * d);
}

}  // namespace

TEST_CASE("sphere ground truth of a Lambertian BRDF matches Snyder's form factor within 4 sigma", "[shape_ground_truth]") {
    struct sphere {
        dvec3 c;
        double r;
    };
    const sphere spheres[] = {{{0.3, -0.2, 1.5}, 0.5}, {{0.4, 0.1, 2.0}, 0.01}, {{1.0, 0.5, 0.2}, 0.6},
                              {{1.0, 0.0, -0.3}, 0.5}, {{0.0, 0.0, 1.2}, 1.0},  {{0.1, 0.0, 0.2}, 0.5}};
    const dvec3 V = glm::normalize(dvec3(0.5, 0, 0.8));
    for (const sphere& s : spheres) {
        const double d = glm::length(s.c), f = (s.r / d) * (s.r / d);
        const bool inside = d <= s.r;
        // Nusselt: (r/d)^2 cos(omega) entirely above the horizon; Snyder's closed form otherwise;
        // inside, every direction of the upper hemisphere: 1.
        const double exact = inside ? 1.0 : ltc::clipless::sphere_form_factor(f, s.c.z / d);
        const double omega = inside ? 4 * pi : 2 * pi * f / (1 + std::sqrt(1 - f));
        for (const gt::techniques use : all_techniques) {
            if (use == gt::techniques::brdf_only && omega < 0.01) continue;  // BRDF samples rarely hit
            const gt::estimate e = gt::integrate_sphere(lambert{}, V, 0.0, s.c, s.r, make_options(100000, 11, use));
            CAPTURE(s.c.x, s.c.y, s.c.z, s.r, int(use), e.mean, e.standard_error, exact);
            // ground_truth.hpp's caveat: BRDF hits of a tiny sphere are rarely seen; their MIS share
            // is at most omega max(p_brdf) = omega / pi of the integral.
            const double rare = use == gt::techniques::polygon_only || omega > 0.01 ? 0.0 : omega / pi * exact;
            CHECK(e.samples == 100000);
            CHECK(std::abs(e.mean - exact) <= 4 * e.standard_error + rare + 1e-12);
            if (use != gt::techniques::brdf_only) CHECK(e.standard_error <= 0.02 * exact + 1e-9);  // useful
        }
    }
    gt::options power = make_options(100000, 12);
    power.weighting = gt::heuristic::power;
    const gt::estimate e = gt::integrate_sphere(lambert{}, V, 0.0, spheres[2].c, spheres[2].r, power);
    CHECK(std::abs(e.mean - ltc::clipless::sphere_form_factor(0.36 / 1.29, 0.2 / std::sqrt(1.29))) <=
          4 * e.standard_error);
}

TEST_CASE("disk ground truth of a Lambertian BRDF matches the disk's form factor within 4 sigma", "[shape_ground_truth]") {
    const dvec3 V = glm::normalize(dvec3(0.3, 0, 0.9));
    // Coaxial and facing: r^2 / (r^2 + h^2), from either side when two-sided.
    for (const double r : {0.2, 1.0, 3.0}) {
        const double h = 1.5, exact = r * r / (r * r + h * h);
        for (const gt::techniques use : all_techniques)
            for (const bool two_sided : {false, true}) {
                const gt::options opt = make_options(50000, 21, use);
                const gt::estimate e = gt::integrate_disk(lambert{}, V, 0.0, {0, 0, h}, {0, 0, -1}, r, two_sided, opt);
                CAPTURE(r, int(use), two_sided, e.mean, e.standard_error, exact);
                CHECK(std::abs(e.mean - exact) <= 4 * e.standard_error + 1e-12);
                if (use != gt::techniques::brdf_only) CHECK(e.standard_error <= 0.02 * exact);
                const gt::estimate back = gt::integrate_disk(lambert{}, V, 0.0, {0, 0, h}, {0, 0, 2}, r, two_sided, opt);
                CHECK(std::abs(back.mean - (two_sided ? exact : 0.0)) <= 4 * back.standard_error + 1e-12);
            }
    }
    // Tilted disks (one straddling the horizon) against a 4096-gon: the inscribed polygon misses
    // a fraction 1 - sin(2 pi/N) N/(2 pi) ~ (2 pi/N)^2 / 6 = 4e-7 of the area; allow 1e-6.
    struct disk {
        dvec3 c, n;
        double r;
    };
    const disk disks[] = {{{0.5, -0.3, 1.2}, {-0.2, 0.4, -1}, 0.7}, {{1.0, 0.4, 0.1}, {-1, 0, -0.3}, 0.6}};
    for (const disk& k : disks) {
        const dvec3 n = glm::normalize(k.n), t1 = ltc::orthonormal_tangent(n), t2 = glm::cross(n, t1);
        std::vector<dvec3> poly;
        for (int i = 0; i < 4096; ++i) {
            const double phi = 2 * pi * i / 4096;
            poly.push_back(k.c + k.r * (std::cos(phi) * t1 + std::sin(phi) * t2));
        }
        const double exact = ltc::form_factor(poly.data(), poly.size(), ltc::sidedness::two_sided);
        for (const gt::techniques use : all_techniques) {
            const gt::options opt = make_options(50000, 22, use);
            const gt::estimate e = gt::integrate_disk(lambert{}, V, 0.0, k.c, k.n, k.r, false, opt);
            CAPTURE(k.c.z, int(use), e.mean, e.standard_error, exact);
            CHECK(std::abs(e.mean - exact) <= 4 * e.standard_error + 1e-6 * exact);
        }
    }
}

TEST_CASE("tube ground truth: closed forms along the axis, the techniques agree through an open end", "[shape_ground_truth]") {
    const dvec3 V = glm::normalize(dvec3(0.6, 0, 0.8));
    const double r = 0.5;
    // The shading point on the axis of a vertical tube, inside it: every upper direction but the
    // cone of half-angle beta through the top, sin^2(beta) = r^2 / (r^2 + 3^2): 1 - sin^2(beta).
    // Below the tube on its axis: the inner wall, seen through the bottom, between the two cones.
    const auto cap = [&](double h) { return r * r / (r * r + h * h); };
    struct tube {
        dvec3 p0, p1;
        double exact;
    };
    const tube tubes[] = {{{0, 0, -2}, {0, 0, 3}, 1 - cap(3)}, {{0, 0, 1}, {0, 0, 3}, cap(1) - cap(3)}};
    for (const tube& t : tubes)
        for (const gt::techniques use : all_techniques) {
            const gt::estimate e = gt::integrate_tube(lambert{}, V, 0.0, t.p0, t.p1, r, make_options(50000, 31, use));
            CAPTURE(t.p0.z, int(use), e.mean, e.standard_error, t.exact);
            CHECK(std::abs(e.mean - t.exact) <= 4 * e.standard_error + 1e-12);
            CHECK(e.standard_error <= 0.02 * t.exact);
        }
    // The shading point outside the infinite cylinder (distance 0.74 > r from a tilted axis),
    // seeing the outer wall and, through the lower end, the inner one: the BRDF technique alone
    // (ray intersection only) and the light sampler alone (first-hit test only) must agree.
    const dvec3 p0(0.9, 0.0, 0.3), p1 = p0 + 3.0 * glm::normalize(dvec3(0.4, 0.3, 1));
    for (const double alpha : {0.2, 1.0}) {
        const ltc::brdf::ggx<double> ggx;
        const gt::estimate mis = gt::integrate_tube(ggx, V, alpha, p0, p1, r, make_options(50000, 32));
        const gt::estimate brdf =
            gt::integrate_tube(ggx, V, alpha, p0, p1, r, make_options(50000, 33, gt::techniques::brdf_only));
        const gt::estimate light =
            gt::integrate_tube(ggx, V, alpha, p0, p1, r, make_options(50000, 34, gt::techniques::polygon_only));
        CAPTURE(alpha, mis.mean, mis.standard_error, brdf.mean, brdf.standard_error, light.mean, light.standard_error);
        CHECK(agree(mis, brdf));
        CHECK(agree(mis, light));
        CHECK(agree(brdf, light));
    }
}

TEST_CASE("line ground truth: the Lambertian closed form, and the limit of a thin tube / 2r", "[shape_ground_truth]") {
    const dvec3 V = glm::normalize(dvec3(0.7, 0, 0.7));
    struct segment {
        dvec3 p0, p1;
    };
    const segment segments[] = {
        {{-1, 0.3, 1}, {1.5, 0.3, 1}}, {{-0.5, 1, -0.5}, {0.5, 0.2, 1.5}}, {{0.2, 0.1, 0.5}, {0.6, 0.2, 4}}};
    for (const segment& s : segments) {
        const double exact = line_cosine(s.p0, s.p1);
        const gt::estimate e = gt::integrate_line(lambert{}, V, 0.0, s.p0, s.p1, make_options(50000, 41));
        CAPTURE(s.p0.z, e.mean, e.standard_error, exact);
        CHECK(std::abs(e.mean - exact) <= 4 * e.standard_error + 1e-12 * exact);
        CHECK(e.standard_error <= 0.01 * exact);
        // A tube of radius r: 2r I_line + O(r^2) (the ends and the horizon cut O(r) x O(r)
        // regions), so a relative bias of order r / d; allow 20 r / d_min.
        const double radius = 1e-4, d = glm::length(glm::cross(glm::normalize(s.p1 - s.p0), s.p0));
        const double d_min = glm::min(d, glm::min(glm::length(s.p0), glm::length(s.p1)));
        for (const double alpha : {0.0, 0.3}) {
            const ltc::brdf::ggx<double> ggx;
            const gt::options line_opt = make_options(50000, 42), tube_opt = make_options(100000, 43);
            const gt::estimate line = alpha > 0 ? gt::integrate_line(ggx, V, alpha, s.p0, s.p1, line_opt) : e;
            gt::estimate tube = alpha > 0 ? gt::integrate_tube(ggx, V, alpha, s.p0, s.p1, radius, tube_opt)
                                          : gt::integrate_tube(lambert{}, V, 0.0, s.p0, s.p1, radius, tube_opt);
            tube.mean /= 2 * radius;
            tube.standard_error /= 2 * radius;
            CAPTURE(alpha, line.mean, line.standard_error, tube.mean, tube.standard_error);
            CHECK(agree(line, tube, 20 * radius / d_min * line.mean));
        }
    }
}

TEST_CASE("GGX over a sphere and a disk covering the same cone agree within 4 sigma", "[shape_ground_truth]") {
    const ltc::brdf::ggx<double> ggx;
    for (const double elevation : {60.0, 15.0})
        for (const double half_angle : {0.3, 0.05}) {
            const double e = elevation * pi / 180;
            const dvec3 axis(std::cos(e) * 0.8, std::cos(e) * 0.6, std::sin(e));
            const dvec3 sphere_c = 2.0 * axis, disk_c = 1.5 * axis;
            const double sphere_r = 2.0 * std::sin(half_angle), disk_r = 1.5 * std::tan(half_angle);
            for (const double theta : {0.0, 60.0, 85.0})
                for (const double alpha : {0.05, 0.3, 1.0}) {
                    const dvec3 V = ltc::brdf::view_from_cos(std::cos(theta * pi / 180));
                    CAPTURE(elevation, half_angle, theta, alpha);
                    for (const gt::techniques use : {gt::techniques::mis, gt::techniques::polygon_only}) {
                        const gt::options s_opt = make_options(20000, 51, use), d_opt = make_options(20000, 52, use);
                        const gt::estimate s = gt::integrate_sphere(ggx, V, alpha, sphere_c, sphere_r, s_opt);
                        const gt::estimate d = gt::integrate_disk(ggx, V, alpha, disk_c, -axis, disk_r, false, d_opt);
                        CAPTURE(int(use), s.mean, s.standard_error, d.mean, d.standard_error);
                        CHECK(agree(s, d));
                    }
                }
        }
}

TEST_CASE("shape ground truth is deterministic and handles degenerate input", "[shape_ground_truth]") {
    const ltc::brdf::ggx<double> ggx;
    const dvec3 V = ltc::brdf::view_from_cos(0.6);
    const gt::options opt = make_options(1000, 7), other = make_options(1000, 8);
    const dvec3 c(0.2, 0.3, 1.5), n(0, 0, -1), p0(-1, 0.5, 1), p1(1, 0.5, 1.2);
    const auto same = [](const gt::estimate& a, const gt::estimate& b) {
        return a.mean == b.mean && a.standard_error == b.standard_error && a.samples == b.samples;
    };
    CHECK(same(gt::integrate_sphere(ggx, V, 0.2, c, 0.5, opt), gt::integrate_sphere(ggx, V, 0.2, c, 0.5, opt)));
    CHECK(!same(gt::integrate_sphere(ggx, V, 0.2, c, 0.5, opt), gt::integrate_sphere(ggx, V, 0.2, c, 0.5, other)));
    CHECK(same(gt::integrate_disk(ggx, V, 0.2, c, n, 0.5, false, opt),
               gt::integrate_disk(ggx, V, 0.2, c, n, 0.5, false, opt)));
    CHECK(same(gt::integrate_tube(ggx, V, 0.2, p0, p1, 0.1, opt), gt::integrate_tube(ggx, V, 0.2, p0, p1, 0.1, opt)));
    CHECK(same(gt::integrate_line(ggx, V, 0.2, p0, p1, opt), gt::integrate_line(ggx, V, 0.2, p0, p1, opt)));

    gt::options adaptive = make_options(2048, 9);
    adaptive.target_relative_error = 0.01;
    const gt::estimate a = gt::integrate_disk(ggx, V, 0.3, c, n, 0.5, false, adaptive);
    CHECK(a.standard_error <= 0.01 * a.mean);
    CHECK(a.samples % 2048 == 0);

    const gt::estimate zero{};
    const auto is_zero = [&](const gt::estimate& e) { return e.mean == 0.0 && e.standard_error == 0.0; };
    CHECK(same(gt::integrate_sphere(ggx, V, 0.2, c, 0.0, opt), zero));                   // no radius
    CHECK(same(gt::integrate_sphere(ggx, V, 0.2, {1, 0, -0.6}, 0.5, opt), zero));         // below
    CHECK(same(gt::integrate_disk(ggx, V, 0.2, c, -n, 0.5, false, opt), zero));           // its back
    CHECK(same(gt::integrate_disk(ggx, V, 0.2, c, dvec3(0), 0.5, true, opt), zero));      // no normal
    CHECK(same(gt::integrate_disk(ggx, V, 0.2, {1, 0, 0}, n, 0.5, true, opt), zero));     // edge-on
    CHECK(is_zero(gt::integrate_disk(ggx, V, 0.2, {0, 0, -1}, n, 0.5, true, opt)));       // below
    CHECK(same(gt::integrate_tube(ggx, V, 0.2, p0, p0, 0.1, opt), zero));                 // p0 = p1
    CHECK(same(gt::integrate_tube(ggx, V, 0.2, -p0, -p1, 0.1, opt), zero));               // below
    CHECK(same(gt::integrate_line(ggx, V, 0.2, p0, p0, opt), zero));                      // p0 = p1
    CHECK(same(gt::integrate_line(ggx, V, 0.2, {0, 0, 1}, {0, 0, 2}, opt), zero));        // end-on
    CHECK(same(gt::integrate_line(ggx, V, 0.2, {0, 0, -1}, {0, 0, 2}, opt), zero));       // through
    CHECK(same(gt::integrate_line(ggx, V, 0.2, -p0, -p1, opt), zero));                    // below
}

}  // namespace ltc_test_shape_ground_truth
