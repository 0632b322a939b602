// Tests of ltc::shade<Model>(surface, light[, options]) (ltc/shading/shade.hpp): every light with
// every model in float and double against a Monte Carlo integral of the model's own lobes over the
// real light shape; one-sided lights from either vertex order and from behind; the deprecated
// functions against the new calls and against the composition they used to compute; a model
// written outside the library; and the bad-input conventions.
//
// The Monte Carlo reference checks the shading itself, not the fit: each lobe (an LTC D_i, or the
// clamped cosine) is sampled exactly (transformed::sample) and a sample counts when its ray hits
// the light, so the hit fraction p_i estimates int_light D_i (eq. 3) without bias and with binomial
// variance p_i (1 - p_i) / n. The fit's error against the real GGX is measured elsewhere
// (test_shading_ggx.cpp, tools/ggx_error_report).
#include <catch2/catch.hpp>

#include <ltc/ltc.hpp>
#include <ltc/shading/ggx_anisotropic_model.hpp>

#include "support/rng.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace ltc_test_shade {  // the file's own names, apart from the other files of a unity batch

namespace {

using glm::dvec3;

// ---------------------------------------------------------------------------------------------
// Lights described in double, each with the ray test of its real shape and its ltc light in T.

struct polygon_desc {
    std::vector<dvec3> v;
    bool one_sided = true;
    dvec3 emission{0.0};  // one-sided: the side it emits to
    double radiance = 2.0;

    bool hit(const dvec3& P, const dvec3& w) const {
        const dvec3 n = glm::cross(v[1] - v[0], v[2] - v[0]);
        const double dn = glm::dot(w, n);
        if (dn == 0.0) return false;
        const double t = glm::dot(v[0] - P, n) / dn;
        if (!(t > 0.0)) return false;
        if (one_sided && !(glm::dot(w, emission) < 0.0)) return false;  // the ray meets the front
        const dvec3 q = P + t * w;
        int sign = 0;
        for (std::size_t i = 0; i < v.size(); ++i) {  // convex polygon: q on one side of every edge
            const double s = glm::dot(glm::cross(v[(i + 1) % v.size()] - v[i], q - v[i]), n);
            const int si = s > 0 ? 1 : -1;
            if (sign == 0) sign = si;
            if (si != sign) return false;
        }
        return true;
    }
};

template <typename T>
struct polygon_storage {
    std::vector<glm::vec<3, T>> v;
    explicit polygon_storage(const polygon_desc& d) {
        for (const dvec3& p : d.v) v.push_back(glm::vec<3, T>(p));
    }
    ltc::polygon_light<T> light(const polygon_desc& d) const {
        const glm::vec<3, T> L(static_cast<T>(d.radiance));
        return d.one_sided ? ltc::polygon_light<T>::one_sided(v.data(), v.size(), glm::vec<3, T>(d.emission), L)
                           : ltc::polygon_light<T>::two_sided(v.data(), v.size(), L);
    }
};

struct disk_desc {
    dvec3 c, n;
    double r;
    bool one_sided;
    double radiance = 2.0;
    bool hit(const dvec3& P, const dvec3& w) const {
        const double dn = glm::dot(w, n);
        if (dn == 0.0 || (one_sided && !(dn < 0.0))) return false;
        const double t = glm::dot(c - P, n) / dn;
        return t > 0.0 && glm::length(P + t * w - c) < r;
    }
    template <typename T>
    ltc::disk_light<T> light() const {
        using v3 = glm::vec<3, T>;
        const v3 L(static_cast<T>(radiance));
        return one_sided ? ltc::disk_light<T>::one_sided(v3(c), v3(n), T(r), L)
                         : ltc::disk_light<T>::two_sided(v3(c), v3(n), T(r), L);
    }
};

struct sphere_desc {
    dvec3 c;
    double r;
    double radiance = 2.0;
    bool hit(const dvec3& P, const dvec3& w) const {
        const dvec3 o = P - c;
        const double b = glm::dot(o, w), q = glm::dot(o, o) - r * r;
        return b * b - q > 0.0 && (q < 0.0 || b < 0.0);
    }
    template <typename T>
    ltc::sphere_light<T> light() const {
        return {glm::vec<3, T>(c), T(r), glm::vec<3, T>(static_cast<T>(radiance))};
    }
};

// The open cylinder of axis p0-p1 and radius r (no end caps), as the tube light.
struct tube_desc {
    dvec3 p0, p1;
    double r;
    double radiance = 2.0;
    bool hit(const dvec3& P, const dvec3& w) const {
        const double len = glm::length(p1 - p0);
        const dvec3 t = (p1 - p0) / len, o = P - p0;
        const dvec3 wp = w - glm::dot(w, t) * t, op = o - glm::dot(o, t) * t;
        const double a = glm::dot(wp, wp), b = glm::dot(wp, op), q = glm::dot(op, op) - r * r;
        const double disc = b * b - a * q;
        if (!(a > 0.0) || !(disc > 0.0)) return false;
        for (const double s : {(-b - std::sqrt(disc)) / a, (-b + std::sqrt(disc)) / a}) {
            const double along = glm::dot(o + s * w, t);
            if (s > 0.0 && along >= 0.0 && along <= len) return true;
        }
        return false;
    }
    template <typename T>
    ltc::tube_light<T> light() const {
        return {glm::vec<3, T>(p0), glm::vec<3, T>(p1), T(r), glm::vec<3, T>(static_cast<T>(radiance))};
    }
};

// ---------------------------------------------------------------------------------------------
// Scenes and the Monte Carlo reference.

struct scene {
    dvec3 P, N, V;
    double roughness;
    dvec3 tangent;               // anisotropic models only: not in N's plane, as a mesh's can be
    double roughness_bitangent;  // anisotropic models only
};

const scene scenes[] = {
    {{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, {0.3, 0.1, 1.0}, 0.3, {1.0, 0.0, 0.0}, 0.6},
    {{0.2, -0.1, 0.1}, {0.1, 0.2, 1.0}, {1.0, -0.4, 1.0}, 0.55, {0.3, 1.0, 0.2}, 0.25},
    {{-0.1, 0.2, 0.0}, {-0.05, 0.0, 1.0}, {-1.0, 0.3, 0.3}, 0.8, {1.0, 1.0, -0.5}, 0.45},
};

constexpr double F0 = 0.3, albedo = 0.6;

template <typename T>
ltc::surface<T> surface_of(const scene& s) {
    using v3 = glm::vec<3, T>;
    return {v3(s.P), v3(s.N), v3(s.V), T(s.roughness), v3(T(F0)), v3(T(albedo)), v3(s.tangent), T(s.roughness_bitangent)};
}

struct reference {
    double specular = 0, specular_sigma = 0, diffuse = 0, diffuse_sigma = 0;
};

// p and its standard deviation for one lobe: the fraction of n samples of the LTC with inverse
// matrix m_inv (in the frame) whose rays hit the light.
template <typename Light>
void hit_fraction(const Light& light, const ltc::shading_frame<double>& f, const dvec3& P, const glm::dmat3& m_inv,
                  ltc_test::rng& rng, int n, double& p, double& sigma) {
    const auto d = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(m_inv);
    int hits = 0;
    for (int i = 0; i < n; ++i) {
        const dvec3 l = d.sample(rng.uniform2<double>());
        if (light.hit(P, l.x * f.t1 + l.y * f.t2 + l.z * f.n)) ++hits;
    }
    p = double(hits) / n;
    sigma = std::sqrt(std::max(p * (1 - p), 1.0 / n) / n);  // at least one hit's worth
}

template <typename Light>
void add_lobe(reference& r, const Light& light, const ltc::shading_frame<double>& f, const dvec3& P,
              const ltc::ltc_coefficients<double>& c, double radiance, ltc_test::rng& rng, int n) {
    double p, s;
    hit_fraction(light, f, P, c.m_inv, rng, n, p, s);
    const double scale = radiance * (F0 * c.magnitude + (1 - F0) * c.fresnel);
    r.specular += scale * p;
    r.specular_sigma = std::sqrt(r.specular_sigma * r.specular_sigma + scale * s * scale * s);
}

template <typename Model, typename Light>
reference monte_carlo(const scene& sc, const Light& light, double radiance, std::uint64_t seed, int n = 100000) {
    ltc_test::rng rng(seed);
    reference r;
    // The frame and the lobes of shade's own steps (the tangent frame for anisotropic models).
    const ltc::surface<double> surf = surface_of<double>(sc);
    const ltc::shading_point<double> at = ltc::detail::model_shading_point<Model>(surf);
    const auto& f = at.frame;
    const auto c = ltc::detail::fetch_lobes(Model{}, at, surf);
    const glm::dmat3 identity(1.0);
    double p, s;
    hit_fraction(light, f, sc.P, identity, rng, n, p, s);
    r.diffuse = radiance * albedo * p;
    r.diffuse_sigma = radiance * albedo * s;
    if constexpr (std::is_same_v<decltype(c), const ltc::lobes::one<double>>) {
        add_lobe(r, light, f, sc.P, c.ltc, radiance, rng, n);
    } else if constexpr (std::is_same_v<decltype(c), const ltc::lobes::ltc_and_cosine<double>>) {
        add_lobe(r, light, f, sc.P, c.ltc, radiance, rng, n);
        ltc::ltc_coefficients<double> cosine = c.cosine;
        cosine.m_inv = identity;
        add_lobe(r, light, f, sc.P, cosine, radiance, rng, n);
    } else {
        add_lobe(r, light, f, sc.P, c.first, radiance, rng, n);
        add_lobe(r, light, f, sc.P, c.second, radiance, rng, n);
    }
    return r;
}

// double: within 4 sigma of the reference. float: within 4 sigma plus the float path's rounding,
// bounded by comparing with the double result: 2^-14 relative (a few hundred float roundings
// through the table fetch, the rotation, M^-1 and the edge terms) plus 2^-24 absolute.
template <typename T>
void check_against(const ltc::shading_result<T>& got, const ltc::shading_result<double>& exact, const reference& r,
                   const std::string& what) {
    CAPTURE(what, got.specular.x, r.specular, r.specular_sigma, got.diffuse.x, r.diffuse, r.diffuse_sigma);
    for (int ch = 0; ch < 3; ++ch) {
        REQUIRE(std::isfinite(got.specular[ch]));
        REQUIRE(std::isfinite(got.diffuse[ch]));
    }
    CHECK(std::abs(exact.specular.x - r.specular) <= 4 * r.specular_sigma);
    CHECK(std::abs(exact.diffuse.x - r.diffuse) <= 4 * r.diffuse_sigma);
    if (std::is_same_v<T, float>) {
        const double rel = std::ldexp(1.0, -14), abs_tol = std::ldexp(1.0, -24);
        CHECK(std::abs(double(got.specular.x) - exact.specular.x) <= rel * exact.specular.x + abs_tol);
        CHECK(std::abs(double(got.diffuse.x) - exact.diffuse.x) <= rel * exact.diffuse.x + abs_tol);
    }
}

template <typename Model, typename T, typename MakeLight, typename Desc>
void check_light(const Desc& desc, const MakeLight& make, const std::string& what, std::uint64_t seed) {
    for (std::size_t k = 0; k < std::size(scenes); ++k) {
        const scene& sc = scenes[k];
        const reference r = monte_carlo<Model>(sc, desc, desc.radiance, seed + k);
        const auto exact = ltc::shade<Model>(surface_of<double>(sc), make(double()));
        const auto got = ltc::shade<Model>(surface_of<T>(sc), make(T()));
        check_against(got, exact, r, what + ", scene " + std::to_string(k));
    }
}

const polygon_desc quad_front{{{-1.0, 0.5, 0.3}, {1.0, 0.5, 0.3}, {1.2, 1.5, 1.6}, {-0.8, 1.5, 1.6}}, true,
                              {0.0, -1.3, 1.0}};
// Planar (the ray test intersects the plane of its first three vertices): -5 y - z = -4.5.
const polygon_desc straddling{{{-1.0, 1.0, -0.5}, {1.5, 1.0, -0.5}, {1.0, 0.6, 1.5}, {-0.5, 0.6, 1.5}, {-1.2, 0.8, 0.5}},
                              false};

template <typename Model, typename T>
void check_every_light(const char* model) {
    const std::string m = model;
    for (const polygon_desc& d : {quad_front, straddling}) {
        const polygon_storage<T> vt(d);
        const polygon_storage<double> vd(d);
        check_light<Model, T>(
            d,
            [&](auto x) {
                if constexpr (std::is_same_v<decltype(x), double>)
                    return vd.light(d);
                else
                    return vt.light(d);
            },
            m + (d.one_sided ? ": one-sided quad" : ": two-sided pentagon across the horizon"), 11);
    }
    for (const bool one_sided : {true, false}) {
        const disk_desc d{{0.3, 1.2, 1.0}, {0.1, -1.0, -0.4}, 0.6, one_sided};
        check_light<Model, T>(d, [&](auto x) { return d.template light<decltype(x)>(); },
                              m + (one_sided ? ": one-sided disk" : ": two-sided disk"), 23);
    }
    const sphere_desc sphere{{0.5, 1.5, 0.4}, 0.5};
    check_light<Model, T>(sphere, [&](auto x) { return sphere.template light<decltype(x)>(); }, m + ": sphere", 37);
    // The tube is integrated as its ribbon, the quad that covers the same directions across the
    // axis but not quite at the open ends (ltc/shading/lights/tube_light.hpp: a sliver O(r / L),
    // measured by tools/shape_error_report): the reference is the ribbon seen from each point.
    const tube_desc tube{{-1.0, 1.0, 0.8}, {1.0, 1.2, 0.2}, 0.15};
    for (std::size_t k = 0; k < std::size(scenes); ++k) {
        const scene& sc = scenes[k];
        const auto q = ltc::make_tube_ribbon(sc.P, tube.p0, tube.p1, tube.r);
        REQUIRE(q.kind == ltc::tube_ribbon<double>::ribbon);
        REQUIRE(q.scale == 1.0);
        const polygon_desc ribbon{{q.corner[0], q.corner[1], q.corner[2], q.corner[3]}, false};
        const reference r = monte_carlo<Model>(sc, ribbon, tube.radiance, 41 + k);
        const auto exact = ltc::shade<Model>(surface_of<double>(sc), tube.light<double>());
        const auto got = ltc::shade<Model>(surface_of<T>(sc), tube.light<T>());
        check_against(got, exact, r, m + ": tube, scene " + std::to_string(k));
        // ...and the real cylinder, the ends' sliver aside: within r / L of it.
        const reference cylinder = monte_carlo<Model>(sc, tube, tube.radiance, 43 + k);
        CHECK(std::abs(exact.diffuse.x - cylinder.diffuse) <= 4 * cylinder.diffuse_sigma + (0.15 / 2.0) * cylinder.diffuse);
    }
    // A constant texture: the textured light integrates exactly what the polygon light does
    // (ltc/shading/lights/textured_quad_light.hpp), so the same reference holds.
    const std::vector<glm::vec<3, T>> texels(8 * 8, glm::vec<3, T>(T(quad_front.radiance)));
    const ltc::light_texture<T> tex(8, 8, texels.data());
    const std::vector<glm::dvec3> texels_d(8 * 8, glm::dvec3(quad_front.radiance));
    const ltc::light_texture<double> tex_d(8, 8, texels_d.data());
    const polygon_storage<T> qt(quad_front);
    const polygon_storage<double> qd(quad_front);
    check_light<Model, T>(
        quad_front,
        [&](auto x) {
            if constexpr (std::is_same_v<decltype(x), double>)
                return ltc::textured_quad_light<double>::one_sided(qd.v.data(), quad_front.emission, tex_d);
            else
                return ltc::textured_quad_light<T>::one_sided(qt.v.data(), glm::vec<3, T>(quad_front.emission), tex);
        },
        m + ": textured quad (constant texture)", 53);
}

}  // namespace

TEST_CASE("shade: every light with every model against Monte Carlo of the model's lobes", "[shade][ground_truth]") {
    SECTION("float") {
        check_every_light<ltc::ggx::one_lobe, float>("one_lobe");
        check_every_light<ltc::ggx::ltc_and_cosine, float>("ltc_and_cosine");
        check_every_light<ltc::ggx::two_lobes, float>("two_lobes");
        check_every_light<ltc::ggx::anisotropic, float>("anisotropic");
    }
    SECTION("double") {
        check_every_light<ltc::ggx::one_lobe, double>("one_lobe");
        check_every_light<ltc::ggx::ltc_and_cosine, double>("ltc_and_cosine");
        check_every_light<ltc::ggx::two_lobes, double>("two_lobes");
        check_every_light<ltc::ggx::anisotropic, double>("anisotropic");
    }
}

// The thin line light is the limit of the tube for r -> 0 (ltc/shading/lights/line_light.hpp):
// the cylinder's solid angle per axis element is 2 r d / |x|^3 dl + O(r^2), so the two differ by
// O(r / d) relatively, d the distance from P to the axis.
TEMPLATE_TEST_CASE("shade: the line light is the thin tube's limit", "[shade][line]", float, double) {
    using T = TestType;
    using v3 = glm::vec<3, T>;
    const v3 p0(-1, 1, 0.8), p1(1, 1.2, 0.2), L(2);
    for (const scene& sc : scenes) {
        for (const double r : {1e-2, 1e-3}) {
            const ltc::line_light<T> line{p0, p1, T(r), L};
            const ltc::tube_light<T> tube{p0, p1, T(r), L};
            const auto s = surface_of<T>(sc);
            const auto a = ltc::shade<ltc::ggx::two_lobes>(s, line), b = ltc::shade<ltc::ggx::two_lobes>(s, tube);
            const double d = 0.9;  // below the distance from each scene's P to the axis
            CAPTURE(r, a.specular.x, b.specular.x, a.diffuse.x, b.diffuse.x);
            CHECK(std::abs(double(a.specular.x) - b.specular.x) <= 4 * (r / d) * b.specular.x + 1e-6 * r);
            CHECK(std::abs(double(a.diffuse.x) - b.diffuse.x) <= 4 * (r / d) * b.diffuse.x + 1e-6 * r);
        }
    }
}

/// A random convex n-gon in a plane z = h in [0.2, 2] above the origin's neighbourhood, its
/// vertices counter-clockwise seen from above (right-hand normal +z).
template <typename T>
std::vector<glm::vec<3, T>> overhead_polygon(ltc_test::rng& rng, std::size_t n) {
    const double h = rng.uniform(0.2, 2.0), cx = rng.uniform(-1, 1), cy = rng.uniform(-1, 1);
    std::vector<glm::vec<3, T>> v;
    for (std::size_t i = 0; i < n; ++i) {
        const double a = 2 * glm::pi<double>() * (double(i) + 0.3 * rng.uniform()) / double(n);
        v.push_back(glm::vec<3, T>(T(cx + std::cos(a)), T(cy + std::sin(a)), T(h)));
    }
    return v;
}

/// A random surface point on z = 0 facing +z, roughness in [min_roughness, 1].
template <typename T>
ltc::surface<T> surface_below(ltc_test::rng& rng, double min_roughness) {
    using v3 = glm::vec<3, T>;
    const v3 position(T(rng.uniform(-0.5, 0.5)), T(rng.uniform(-0.5, 0.5)), T(0));
    const v3 view(T(rng.uniform(-1, 1)), T(rng.uniform(-1, 1)), T(1));
    return {position, v3(0, 0, 1), view, T(rng.uniform(min_roughness, 1)), v3(T(0.04)), v3(T(0.5))};
}

TEMPLATE_TEST_CASE("shade: a one-sided polygon light gives the same bits for either vertex order, and 0 from behind",
                   "[shade][winding]", float, double) {
    using T = TestType;
    using v3 = glm::vec<3, T>;
    ltc_test::rng rng(5);
    for (int trial = 0; trial < 200; ++trial) {
        const std::size_t n = 3 + trial % 4;
        const std::vector<v3> ccw = overhead_polygon<T>(rng, n);
        const std::vector<v3> cw(ccw.rbegin(), ccw.rend());
        const ltc::surface<T> s = surface_below<T>(rng, 0.05);
        const v3 down(0, 0, -1), L(T(1.5));
        const auto a = ltc::polygon_light<T>::one_sided(ccw.data(), n, down, L);
        const auto b = ltc::polygon_light<T>::one_sided(cw.data(), n, down, L);
        const auto check_model = [&](auto model) {
            using M = decltype(model);
            const auto ra = ltc::shade<M>(s, a), rb = ltc::shade<M>(s, b);
            CAPTURE(trial, n);
            CHECK(ra.specular == rb.specular);
            CHECK(ra.diffuse == rb.diffuse);
            CHECK(ra.specular.x > T(0));
            CHECK(ra.diffuse.x > T(0));
            // The winding names: seen from the point below, ccw (right-hand normal +z, away from
            // it) turns clockwise, so clockwise_front lights it and counter_clockwise_front not.
            const auto front = ltc::shade<M>(s, ltc::polygon_light<T>::one_sided(ccw.data(), n, ltc::winding::clockwise_front, L));
            CHECK(front.specular == ra.specular);
            const auto cw_named = ltc::shade<M>(s, ltc::polygon_light<T>::one_sided(cw.data(), n, ltc::winding::counter_clockwise_front, L));
            CHECK(cw_named.specular == ra.specular);
            for (const auto& light : {ltc::polygon_light<T>::one_sided(ccw.data(), n, -down, L),
                                      ltc::polygon_light<T>::one_sided(cw.data(), n, -down, L),
                                      ltc::polygon_light<T>::one_sided(ccw.data(), n, ltc::winding::counter_clockwise_front, L)}) {
                const auto behind = ltc::shade<M>(s, light);
                CHECK(behind.specular == v3(0));
                CHECK(behind.diffuse == v3(0));
            }
            const auto two = ltc::shade<M>(s, ltc::polygon_light<T>::two_sided(ccw.data(), n, L));
            CHECK(two.specular == ltc::shade<M>(s, ltc::polygon_light<T>::one_sided(ccw.data(), n, ltc::winding::clockwise_front, L)).specular);
        };
        check_model(ltc::ggx::one_lobe{});
        check_model(ltc::ggx::ltc_and_cosine{});
        check_model(ltc::ggx::two_lobes{});
    }
}

namespace {

// Random shading points and polygons, one seed per old name (the deprecated functions' checks).
template <typename T>
struct random_case {
    glm::vec<3, T> P, N, V, F0, albedo, radiance;
    T roughness;
    std::vector<glm::vec<3, T>> v;
    ltc::sidedness side;
    ltc::horizon_clipping clip;
};

template <typename T>
random_case<T> draw(ltc_test::rng& rng) {
    using v3 = glm::vec<3, T>;
    const auto vec = [&](double lo, double hi) {
        const T x = T(rng.uniform(lo, hi));
        const T y = T(rng.uniform(lo, hi));
        const T z = T(rng.uniform(lo, hi));
        return v3(x, y, z);
    };
    random_case<T> c;
    c.P = vec(-1, 1);
    c.N = vec(-1, 1) + v3(0, 0, 1.5);
    c.V = vec(-1, 1) + v3(0, 0, 0.5);
    c.F0 = vec(0, 1);
    c.albedo = vec(0, 1);
    c.radiance = vec(0, 4);
    c.roughness = T(rng.uniform(0, 1));
    const std::size_t n = 3 + rng.next_u64() % 4;
    const v3 centre = vec(-2, 2) + v3(0, 0, 1.5);
    for (std::size_t i = 0; i < n; ++i) {
        const double a = 2 * 3.141592653589793 * double(i) / double(n);
        c.v.push_back(centre + v3(T(std::cos(a)), T(std::sin(a)), T(0.3 * rng.uniform(-1, 1))));
    }
    c.side = rng.uniform() < 0.5 ? ltc::sidedness::one_sided : ltc::sidedness::two_sided;
    const ltc::horizon_clipping modes[] = {ltc::horizon_clipping::ltc_space, ltc::horizon_clipping::shading_first,
                                           ltc::horizon_clipping::sphere_analytic, ltc::horizon_clipping::sphere_table};
    c.clip = modes[rng.next_u64() % 4];
    return c;
}

template <typename T>
void require_same(const ltc::shading_result<T>& a, const ltc::shading_result<T>& b) {
    for (int ch = 0; ch < 3; ++ch) {
        // Bit for bit: equal values and equal signs of zero.
        REQUIRE(a.specular[ch] == b.specular[ch]);
        REQUIRE(std::signbit(a.specular[ch]) == std::signbit(b.specular[ch]));
        REQUIRE(a.diffuse[ch] == b.diffuse[ch]);
        REQUIRE(std::signbit(a.diffuse[ch]) == std::signbit(b.diffuse[ch]));
    }
}

}  // namespace

// Each deprecated name against (a) the new call it wraps and (b) the composition of the
// unchanged building blocks (integrate_polygon_light, integrate_disk, the tables' fetches,
// brdf_scale) that it computed before the new interface: the same bits.
TEMPLATE_TEST_CASE("shade: the deprecated functions give the new calls' bits and their old composition's",
                   "[shade][deprecated]", float, double) {
    using T = TestType;
    using v3 = glm::vec<3, T>;
    ltc_test::rng rng(2024);
    for (int trial = 0; trial < 500; ++trial) {
        const random_case<T> c = draw<T>(rng);
        const std::size_t n = c.v.size();
        const ltc::surface<T> s{c.P, c.N, c.V, c.roughness, c.F0, c.albedo};
        const auto light = ltc::detail::polygon_light_access<T>::with_sidedness(c.v.data(), n, c.side, c.radiance);
        const ltc::shade_options o{c.clip};
        const auto frame = ltc::make_shading_frame(c.N, c.V);
        CAPTURE(trial, n, int(c.side), int(c.clip));

        // The old composition: integrals, then radiance = L scale I per lobe, facing applied.
        const auto old_one = [&](const ltc::ltc_coefficients<T>& k) {
            return ltc::polygon_light_radiance(ltc::integrate_polygon_light(frame, k.m_inv, c.P, c.v.data(), n, c.clip), k,
                                               c.F0, c.albedo, c.radiance, c.side);
        };
        const auto k1 = ltc::ggx::fetch<T>(frame.cos_theta_v, c.roughness);
        const auto kc = ltc::ggx_cosine_lobe::fetch<T>(frame.cos_theta_v, c.roughness);
        const auto k2 = ltc::ggx_two_lobe::fetch<T>(frame.cos_theta_v, c.roughness);
        auto want_one = old_one(k1);
        auto want_cosine = old_one(kc[1]);
        want_cosine.specular +=
            c.radiance * ltc::brdf_scale(c.F0, kc[0]) *
            ltc::apply_sidedness(ltc::integrate_polygon_light(frame, kc[1].m_inv, c.P, c.v.data(), n, c.clip).form_factor,
                                 c.side);
        auto want_two = old_one(k2[0]);
        want_two.specular +=
            c.radiance * ltc::brdf_scale(c.F0, k2[1]) *
            ltc::apply_sidedness(ltc::integrate_polygon_light_ltc(frame, k2[1].m_inv, c.P, c.v.data(), n, c.clip), c.side);

        const auto new_one = ltc::shade<ltc::ggx::one_lobe>(s, light, o);
        const auto new_cosine = ltc::shade<ltc::ggx::ltc_and_cosine>(s, light, o);
        const auto new_two = ltc::shade<ltc::ggx::two_lobes>(s, light, o);
        require_same(new_one, want_one);
        require_same(new_cosine, want_cosine);
        require_same(new_two, want_two);
        require_same(ltc::shade(s, light, o), new_cosine);  // the default model

        require_same(ltc::shade_polygon_light_one_lobe(c.P, c.N, c.V, c.roughness, c.F0, c.albedo, c.radiance, c.v.data(),
                                                       n, c.side, c.clip),
                     new_one);
        require_same(ltc::shade_polygon_light(c.P, c.N, c.V, c.roughness, c.F0, c.albedo, c.radiance, c.v.data(), n,
                                              c.side, c.clip),
                     new_cosine);
        require_same(ltc::shade_polygon_light_cosine_lobe(c.P, c.N, c.V, c.roughness, c.F0, c.albedo, c.radiance,
                                                          c.v.data(), n, c.side, c.clip),
                     new_cosine);
        require_same(ltc::shade_polygon_light_two_lobe(c.P, c.N, c.V, c.roughness, c.F0, c.albedo, c.radiance,
                                                       c.v.data(), n, c.side, c.clip),
                     new_two);
        const ltc::shading_point<T> p{frame, c.P, c.F0, c.albedo};
        require_same(ltc::shade_polygon_light(frame, k1, c.P, c.F0, c.albedo, c.radiance, c.v.data(), n, c.side, c.clip),
                     ltc::shade_lobes<ltc::edge_policy::automatic>(p, ltc::lobes::one<T>{k1}, light, o));
        require_same(ltc::shade_polygon_light_cosine_lobe(frame, kc, c.P, c.F0, c.albedo, c.radiance, c.v.data(), n,
                                                          c.side, c.clip),
                     new_cosine);
        require_same(ltc::shade_polygon_light_two_lobe(frame, k2, c.P, c.F0, c.albedo, c.radiance, c.v.data(), n,
                                                       c.side, c.clip),
                     new_two);
        const v3 second = ltc::second_lobe_specular(frame, k2[1], c.P, c.F0, c.radiance, c.v.data(), n, c.side, c.clip);
        // The old two-lobe result: the first lobe's shading plus this term.
        auto first = ltc::shade_polygon_light(frame, k2[0], c.P, c.F0, c.albedo, c.radiance, c.v.data(), n, c.side, c.clip);
        first.specular += second;
        require_same(first, new_two);

        // The shapes, with the one-lobe table as before: disk (one- and two-sided), sphere, line, tube.
        const v3 centre = c.v[0], axis = c.v[1] - c.v[0];
        const T radius = T(rng.uniform(0.05, 1.0));
        const auto k = k1;
        const auto shape_old = [&](T ltc_integral, T form_factor) {
            ltc::shading_result<T> r;
            r.specular = c.radiance * ltc::brdf_scale(c.F0, k) * ltc_integral;
            r.diffuse = c.albedo * c.radiance * form_factor;
            return r;
        };
        {
            const v3 lc = frame.to_local(centre - c.P), ln = frame.to_local(axis);
            const auto spec = ltc::transformed<ltc::clamped_cosine<T>>::from_inverse(k.m_inv);
            const auto cosine = ltc::transformed<ltc::clamped_cosine<T>>::from_inverse(glm::mat<3, 3, T>(T(1)));
            const auto want = shape_old(ltc::integrate_disk(spec, lc, ln, radius, c.side),
                                        ltc::integrate_disk(cosine, lc, ln, radius, c.side));
            const auto disk = c.side == ltc::sidedness::one_sided
                                  ? ltc::disk_light<T>::one_sided(centre, axis, radius, c.radiance)
                                  : ltc::disk_light<T>::two_sided(centre, axis, radius, c.radiance);
            require_same(ltc::shade<ltc::ggx::one_lobe>(s, disk), want);
            require_same(ltc::shade_disk_light(c.P, c.N, c.V, c.roughness, c.F0, c.albedo, c.radiance, centre, axis,
                                               radius, c.side),
                         want);
            require_same(ltc::shade_disk_light(frame, k, c.P, c.F0, c.albedo, c.radiance, centre, axis, radius, c.side),
                         want);
        }
        const ltc::sphere_light<T> sphere{centre, radius, c.radiance};
        require_same(ltc::shade_sphere_light(c.P, c.N, c.V, c.roughness, c.F0, c.albedo, c.radiance, centre, radius),
                     ltc::shade<ltc::ggx::one_lobe>(s, sphere));
        require_same(ltc::shade_sphere_light(frame, k, c.P, c.F0, c.albedo, c.radiance, centre, radius),
                     ltc::shade<ltc::ggx::one_lobe>(s, sphere));
        const ltc::line_light<T> line{c.v[0], c.v[1], radius, c.radiance};
        require_same(ltc::shade_line_light(c.P, c.N, c.V, c.roughness, c.F0, c.albedo, c.radiance, c.v[0], c.v[1], radius),
                     ltc::shade<ltc::ggx::one_lobe>(s, line));
        require_same(ltc::shade_line_light(frame, k, c.P, c.F0, c.albedo, c.radiance, c.v[0], c.v[1], radius),
                     ltc::shade<ltc::ggx::one_lobe>(s, line));
        const ltc::tube_light<T> tube{c.v[0], c.v[1], radius, c.radiance};
        require_same(ltc::shade_tube_light(c.P, c.N, c.V, c.roughness, c.F0, c.albedo, c.radiance, c.v[0], c.v[1], radius),
                     ltc::shade<ltc::ggx::one_lobe>(s, tube));
        require_same(ltc::shade_tube_light(frame, k, c.P, c.F0, c.albedo, c.radiance, c.v[0], c.v[1], radius),
                     ltc::shade<ltc::ggx::one_lobe>(s, tube));
    }
}

TEMPLATE_TEST_CASE("shade: the deprecated textured function gives the new call's bits and its old composition's",
                   "[shade][deprecated][textured]", float, double) {
    using T = TestType;
    using v3 = glm::vec<3, T>;
    ltc_test::rng rng(77);
    std::vector<v3> texels(16 * 8);
    for (v3& t : texels) {
        const T r = T(rng.uniform());
        const T g = T(rng.uniform());
        const T b = T(rng.uniform());
        t = v3(r, g, b);
    }
    const ltc::light_texture<T> tex(16, 8, texels.data());
    for (int trial = 0; trial < 100; ++trial) {
        const random_case<T> c = draw<T>(rng);
        const v3 quad[4] = {c.v[0], c.v[1], c.v[2], c.v[0] + (c.v[2] - c.v[1])};
        const ltc::textured_policy policies[] = {{}, {ltc::textured_method::quick_cells, {}},
                                                 {ltc::textured_method::exact_cells, {16}}};
        const ltc::textured_policy& policy = policies[trial % 3];
        const ltc::surface<T> s{c.P, c.N, c.V, c.roughness, c.F0, c.albedo};
        const auto frame = ltc::make_shading_frame(c.N, c.V);
        v3 local[4];
        for (int i = 0; i < 4; ++i) local[i] = frame.to_local(quad[i] - c.P);
        const auto k = ltc::ggx::fetch<T>(frame.cos_theta_v, c.roughness);
        ltc::shading_result<T> want;
        want.specular = ltc::brdf_scale(c.F0, k) *
                        ltc::integrate_textured_quad(ltc::transformed<ltc::clamped_cosine<T>>::from_inverse(k.m_inv), local,
                                                     tex, c.side, policy);
        want.diffuse = c.albedo * ltc::integrate_textured_quad(
                                      ltc::transformed<ltc::clamped_cosine<T>>::from_inverse(glm::mat<3, 3, T>(T(1))),
                                      local, tex, c.side, policy);
        const auto light = c.side == ltc::sidedness::one_sided
                               ? ltc::textured_quad_light<T>::one_sided(quad, ltc::winding::clockwise_front, tex, policy)
                               : ltc::textured_quad_light<T>::two_sided(quad, tex, policy);
        CAPTURE(trial, int(c.side), int(policy.method));
        require_same(ltc::shade<ltc::ggx::one_lobe>(s, light), want);
        require_same(ltc::shade_textured_quad_light(c.P, c.N, c.V, c.roughness, c.F0, c.albedo, quad, tex, c.side, policy),
                     want);
    }
}

namespace {

// A model written outside the library: a user's own 2 x 2 table whose every node is the clamped
// cosine (M^-1 = I) with magnitude 1 and Fresnel 0, so that its specular term is F0 L E: the
// diffuse term's form factor with F0 for the albedo.
const float user_nodes[2 * 2 * ltc::channel::count] = {
    1, 0, 0, 1, 1, 0,  1, 0, 0, 1, 1, 0,  1, 0, 0, 1, 1, 0,  1, 0, 0, 1, 1, 0,
};

struct cosine_model {
    static constexpr ltc::ltc_table table{user_nodes, 2, 2};
    template <typename T>
    using coefficients = ltc::lobes::one<T>;
    template <typename T>
    static coefficients<T> fetch(T cos_theta_v, T roughness) {
        return {table.fetch(cos_theta_v, roughness)};
    }
};

}  // namespace

TEMPLATE_TEST_CASE("shade: a model written outside the library plugs in like the library's", "[shade][model]", float,
                   double) {
    using T = TestType;
    using v3 = glm::vec<3, T>;
    const v3 quad[4] = {{-1, 0.5, 0.3}, {1, 0.5, 0.3}, {1.2, 1.5, 1.6}, {-0.8, 1.5, 1.6}};
    const auto light = ltc::polygon_light<T>::two_sided(quad, 4, v3(2));
    const ltc::disk_light<T> disk = ltc::disk_light<T>::two_sided(v3(0.3, 1.2, 1.0), v3(0.1, -1.0, -0.4), T(0.6), v3(2));
    for (const scene& sc : scenes) {
        ltc::surface<T> s = surface_of<T>(sc);
        s.f0 = v3(T(0.25), T(0.5), T(0.75));
        const auto r = ltc::shade<cosine_model>(s, light);
        ltc::surface<T> as_diffuse = s;
        as_diffuse.albedo = s.f0;
        CHECK(r.specular == ltc::shade<cosine_model>(as_diffuse, light).diffuse);
        const auto rd = ltc::shade<cosine_model>(s, disk);
        CHECK(rd.specular == ltc::shade<cosine_model>(as_diffuse, disk).diffuse);
        CHECK(r.specular.x > T(0));
    }
}

TEMPLATE_TEST_CASE("shade: bad input, the same answer for every light and model", "[shade][bad_input]", float, double) {
    using T = TestType;
    using v3 = glm::vec<3, T>;
    const T inf = std::numeric_limits<T>::infinity(), nan = std::numeric_limits<T>::quiet_NaN();
    const v3 quad[4] = {{-1, 0.5, 0.3}, {1, 0.5, 0.3}, {1.2, 1.5, 1.6}, {-0.8, 1.5, 1.6}};
    const std::vector<v3> texels(4, v3(1));
    const ltc::light_texture<T> tex(2, 2, texels.data());
    const auto polygon = ltc::polygon_light<T>::two_sided(quad, 4, v3(2));
    const auto disk = ltc::disk_light<T>::two_sided(v3(0.3, 1.2, 1.0), v3(0.1, -1.0, -0.4), T(0.6), v3(2));
    const ltc::sphere_light<T> sphere{v3(0.5, 1.5, 0.4), T(0.5), v3(2)};
    const ltc::line_light<T> line{v3(-1, 1, 0.8), v3(1, 1.2, 0.2), T(0.1), v3(2)};
    const ltc::tube_light<T> tube{v3(-1, 1, 0.8), v3(1, 1.2, 0.2), T(0.1), v3(2)};
    const auto textured = ltc::textured_quad_light<T>::two_sided(quad, tex);
    const ltc::surface<T> good{v3(0), v3(0, 0, 1), v3(0.3, 0.1, 1), T(0.4), v3(0.04), v3(0.5)};

    const auto for_each = [&](auto&& f) {
        const auto models = [&](const auto& light) {
            f(light, ltc::ggx::one_lobe{});
            f(light, ltc::ggx::ltc_and_cosine{});
            f(light, ltc::ggx::two_lobes{});
            f(light, ltc::ggx::anisotropic{});
        };
        models(polygon), models(disk), models(sphere), models(line), models(tube), models(textured);
    };

    SECTION("a zero or non-finite normal, view or position gives 0") {
        std::vector<ltc::surface<T>> bad;
        for (const v3 w : {v3(0), v3(inf, 0, 1), v3(nan, 0, 1)}) {
            ltc::surface<T> s = good;
            s.normal = w;
            bad.push_back(s);
            s = good;
            s.view = w;
            bad.push_back(s);
            if (w != v3(0)) {
                s = good;
                s.position = w;
                bad.push_back(s);
            }
        }
        for_each([&](const auto& light, auto model) {
            using M = decltype(model);
            CHECK(ltc::shade<M>(good, light).specular.x > T(0));
            for (const auto& s : bad) {
                const auto r = ltc::shade<M>(s, light);
                CHECK(r.specular == v3(0));
                CHECK(r.diffuse == v3(0));
            }
        });
    }
    SECTION("roughness is clamped to [0, 1], NaN read as 0") {
        for_each([&](const auto& light, auto model) {
            using M = decltype(model);
            const auto at = [&](T r) {
                ltc::surface<T> s = good;
                s.roughness = r;
                return ltc::shade<M>(s, light);
            };
            require_same(at(T(-3)), at(T(0)));
            require_same(at(nan), at(T(0)));
            require_same(at(-inf), at(T(0)));
            require_same(at(T(7)), at(T(1)));
            require_same(at(inf), at(T(1)));
        });
    }
    SECTION("a view from below the surface is shaded as grazing") {
        for_each([&](const auto& light, auto model) {
            using M = decltype(model);
            ltc::surface<T> below = good, grazing = good;
            below.view = v3(0.3, 0.1, -0.5);
            grazing.view = v3(0.3, 0.1, 0);
            // The same cos theta_v (0) and tangent T1 to rounding: the two views' projections on
            // the surface are normalized from different vectors (a few ulps apart). The integrals
            // (at most 1) are sums of O(1) edge terms, so they move by a few ulps of 1: times the
            // radiance 2 (the lobes' scales and the albedo are at most 1).
            const auto a = ltc::shade<M>(below, light), b = ltc::shade<M>(grazing, light);
            const T tol = 64 * std::numeric_limits<T>::epsilon() * T(2);
            for (int ch = 0; ch < 3; ++ch) {
                CHECK(std::abs(a.specular[ch] - b.specular[ch]) <= tol);
                CHECK(std::abs(a.diffuse[ch] - b.diffuse[ch]) <= tol);
            }
        });
    }
    SECTION("lights check what they cannot answer: an emission normal that is zero, not finite or in the plane") {
        CHECK_THROWS_AS(ltc::polygon_light<T>::one_sided(quad, 4, v3(0), v3(1)), ltc::invalid_light);
        CHECK_THROWS_AS(ltc::polygon_light<T>::one_sided(quad, 4, v3(nan, 0, 1), v3(1)), ltc::invalid_light);
        const v3 in_plane = quad[1] - quad[0];
        CHECK_THROWS_AS(ltc::polygon_light<T>::one_sided(quad, 4, in_plane, v3(1)), ltc::invalid_light);
        CHECK_THROWS_AS(ltc::polygon_light<T>::two_sided(nullptr, 4, v3(1)), ltc::invalid_light);
        CHECK_THROWS_AS(ltc::textured_quad_light<T>::one_sided(quad, v3(0), tex), ltc::invalid_light);
        CHECK_THROWS_WITH(ltc::polygon_light<T>::one_sided(quad, 4, v3(0), v3(1)),
                          Catch::Contains("emission normal is zero or not finite"));
    }
    SECTION("geometry that encloses nothing emits nothing") {
        const v3 line_quad[4] = {quad[0], quad[1], quad[0], quad[1]};
        const auto degenerate = {ltc::shade(good, ltc::polygon_light<T>::one_sided(quad, 2, v3(0, 0, -1), v3(1))),
                                 ltc::shade(good, ltc::polygon_light<T>::one_sided(line_quad, 4, v3(0, 0, -1), v3(1))),
                                 ltc::shade(good, ltc::disk_light<T>::one_sided(v3(0, 1, 1), v3(0, -1, 0), T(0), v3(1))),
                                 ltc::shade(good, ltc::disk_light<T>::one_sided(v3(0, 1, 1), v3(0, -1, 0), nan, v3(1))),
                                 ltc::shade(good, ltc::disk_light<T>::two_sided(v3(0, 1, 1), v3(0), T(1), v3(1))),
                                 ltc::shade(good, ltc::sphere_light<T>{v3(0, 1, 1), T(-1), v3(1)}),
                                 ltc::shade(good, ltc::line_light<T>{v3(0, 1, 1), v3(0, 1, 1), T(0.1), v3(1)}),
                                 ltc::shade(good, ltc::tube_light<T>{v3(0, 1, 1), v3(1, 1, 1), T(0), v3(1)})};
        for (const auto& r : degenerate) {
            CHECK(r.specular == v3(0));
            CHECK(r.diffuse == v3(0));
        }
    }
}

TEMPLATE_TEST_CASE("shade(model, s, light): a model object, e.g. ggx::one_lobe_of over a user's own table, gives "
                   "shade<Model>'s bits",
                   "[shade][model_object]", float, double) {
    using T = TestType;
    using v3 = glm::vec<3, T>;
    // The user's own copy of the shipped data (another address: what a device copy would be).
    const std::vector<float> data(std::begin(ltc::tables::ggx_data), std::end(ltc::tables::ggx_data));
    const ltc::ggx::one_lobe_of own{ltc::ltc_table(data.data(), ltc::tables::ggx_size, ltc::tables::ggx_size)};
    ltc_test::rng rng(11);
    for (int trial = 0; trial < 200; ++trial) {
        const std::size_t n = 3 + trial % 4;
        const std::vector<v3> v = overhead_polygon<T>(rng, n);
        const ltc::surface<T> s = surface_below<T>(rng, 0.0);
        const auto light = trial % 2 == 0 ? ltc::polygon_light<T>::one_sided(v.data(), n, v3(0, 0, -1), v3(T(1.5)))
                                          : ltc::polygon_light<T>::two_sided(v.data(), n, v3(T(1.5)));
        const ltc::shade_options o{trial % 3 == 0 ? ltc::horizon_clipping::shading_first : ltc::horizon_clipping::ltc_space};
        CAPTURE(trial, n);
        const auto want = ltc::shade<ltc::ggx::one_lobe>(s, light, o);
        const auto got = ltc::shade(own, s, light, o);
        CHECK(got.specular == want.specular);
        CHECK(got.diffuse == want.diffuse);
        CHECK(want.diffuse.x > T(0));
        const auto shipped = ltc::shade(ltc::ggx::one_lobe_of{ltc::ggx::table}, s, light, o);
        CHECK(shipped.specular == want.specular);
        // A model whose fetch is static, as an object; and an explicit edge policy.
        const auto two = ltc::shade(ltc::ggx::two_lobes{}, s, light, o);
        CHECK(two.specular == ltc::shade<ltc::ggx::two_lobes>(s, light, o).specular);
        const auto exact = ltc::shade<ltc::edge_policy::exact>(own, s, light);
        CHECK(exact.specular == ltc::shade<ltc::ggx::one_lobe, ltc::edge_policy::exact>(s, light).specular);
    }
    // Bad input: the same 0 as shade<Model>.
    const v3 quad[4] = {v3(-1, -1, 1), v3(1, -1, 1), v3(1, 1, 1), v3(-1, 1, 1)};
    const auto light = ltc::polygon_light<T>::two_sided(quad, 4, v3(1));
    const ltc::surface<T> zero_normal{v3(0), v3(0), v3(0, 0, 1), T(0.5), v3(T(0.04)), v3(T(0.5))};
    const auto r = ltc::shade(own, zero_normal, light);
    CHECK(r.specular == v3(0));
    CHECK(r.diffuse == v3(0));
}

}  // namespace ltc_test_shade
