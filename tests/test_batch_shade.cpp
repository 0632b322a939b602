// ltc::batch::shade (ltc/shading/batch_shade.hpp) against the scalar ltc::shade item by item, for
// every instruction set this machine runs, every GGX model, polygon lights of each facing rule in
// both vertex orders, float and double; uniform fields against per-item arrays; many polygon
// lights over one point; the lights without a kernel; bad input; and each deprecated batch
// function against the new call, bit for bit.
//
// Tolerance (the derivation of tests/test_batch_shading.cpp's file comment, unchanged). An item
// the kernel hands back, the tail, isa::scalar, a policy without a SIMD kernel and every light
// but polygon_light go through ltc::shade itself: equal bit for bit. An item of the SIMD lanes
// over many points is compared with the scalar lobe shading (ltc::shade_lobes) at the very frame
// and coefficients the lanes computed (tests/support/batch_lanes.hpp runs the same lane stages;
// those stages against the scalar frame and fetch: tests/test_batch_lanes.cpp): the integrals
// differ, each within ltc_test::clip_tolerance plus the local vertices' rounding amplified by
// M^-1's conditioning, times the lobe's factor, plus 4 u of the value (tests/support/
// shading_tolerance.hpp); the lobes' terms add, and so do their tolerances, plus 2 u of the sum per added lobe. Over many
// lights the frame and the fetch are the scalar ones, and only the integrals differ, lobe by
// lobe within the same tolerance (the cosine lobe's: the LTC of M^-1 = I, whose integral is E).
// u is the unit roundoff of T (the kernel's double lanes normalize by 1 / sqrt).
#include "support/batch_lanes.hpp"
#include "support/batch_points.hpp"
#include "support/clip_comparison.hpp"
#include "support/rng.hpp"
#include "support/rounding_bound.hpp"
#include "support/shading_tolerance.hpp"

#include <ltc/shading/batch_cosine_lobe.hpp>
#include <ltc/shading/batch_lobes.hpp>
#include <ltc/shading/batch_shade.hpp>
#include <ltc/shading/batch_shading.hpp>
#include <ltc/shading/batch_two_lobe.hpp>
#include <ltc/shading/ggx_anisotropic_model.hpp>
#include <ltc/shading/lights/disk_light.hpp>
#include <ltc/shading/lights/line_light.hpp>
#include <ltc/shading/lights/sphere_light.hpp>
#include <ltc/shading/lights/tube_light.hpp>
#include <ltc/shading/shade.hpp>
#include <ltc/shading/textured_light.hpp>

#include <catch2/catch.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>
#include <vector>

namespace ltc_test_batch_shade {  // the file's own names, apart from the other files of a unity batch

namespace {

namespace tolerance = ltc_test::shading_tolerance;
using tolerance::violations;
using tolerance::walked;
using Policy = ltc::edge_policy::minimax_rational;

using ltc_test::points_of;

template <typename T>
struct results_of {
    std::vector<T> c[6];
    explicit results_of(std::size_t count) {
        for (auto& v : c) v.assign(count, T(-1));
    }
    ltc::batch::shading_results<T> view() {
        ltc::batch::shading_results<T> r;
        for (int k = 0; k < 3; ++k) r.specular[k] = c[k].data(), r.diffuse[k] = c[3 + k].data();
        return r;
    }
    ltc::shading_result<T> at(std::size_t i) const {
        ltc::shading_result<T> r;
        for (int k = 0; k < 3; ++k) r.specular[k] = c[k][i], r.diffuse[k] = c[3 + k][i];
        return r;
    }
};

template <typename T>
bool same_bits(const glm::vec<3, T>& a, const glm::vec<3, T>& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}
template <typename T>
bool same_bits(const ltc::shading_result<T>& a, const ltc::shading_result<T>& b) {
    return same_bits(a.specular, b.specular) && same_bits(a.diffuse, b.diffuse);
}
template <typename T>
bool same_bits(const results_of<T>& a, const results_of<T>& b) {
    for (int k = 0; k < 6; ++k)
        if (a.c[k].size() != b.c[k].size() || std::memcmp(a.c[k].data(), b.c[k].data(), a.c[k].size() * sizeof(T)) != 0)
            return false;
    return true;
}

// The coefficients the lanes computed for point i (lane stages of each of the model's tables).
template <typename T>
ltc::ltc_coefficients<T> lane_lobe(const ltc_test::lane_stage_results_of<T>& st, std::size_t i) {
    ltc::ltc_coefficients<T> lobe;
    lobe.m_inv = glm::mat<3, 3, T>(T(0));
    lobe.m_inv[0][0] = st.channel[0][i], lobe.m_inv[0][2] = st.channel[1][i];
    lobe.m_inv[2][0] = st.channel[2][i], lobe.m_inv[2][2] = st.channel[3][i];
    lobe.m_inv[1][1] = T(1);
    lobe.magnitude = st.channel[4][i], lobe.fresnel = st.channel[5][i];
    return lobe;
}
template <typename T>
ltc::lobes::one<T> lane_coefficients(const std::vector<ltc_test::lane_stage_results_of<T>>& st, std::size_t i,
                                     ltc::lobes::one<T>*) {
    return {lane_lobe(st[0], i)};
}
template <typename T>
ltc::lobes::two<T> lane_coefficients(const std::vector<ltc_test::lane_stage_results_of<T>>& st, std::size_t i,
                                     ltc::lobes::two<T>*) {
    return {lane_lobe(st[0], i), lane_lobe(st[1], i)};
}
template <typename T>
ltc::lobes::ltc_and_cosine<T> lane_coefficients(const std::vector<ltc_test::lane_stage_results_of<T>>& st,
                                                std::size_t i, ltc::lobes::ltc_and_cosine<T>*) {
    ltc::ltc_coefficients<T> cosine = lane_lobe(st[0], i);
    cosine.m_inv = glm::mat<3, 3, T>(T(1));
    return {ltc::ggx_cosine_lobe::unpremultiplied(lane_lobe(st[1], i)), cosine};  // the kernel's division
}

// The lights of the tests: a random polygon of n vertices (both orders), one of four facing rules.
enum class facing { emission_normal, counter_clockwise_front, clockwise_front, two_sided };
constexpr facing facings[] = {facing::emission_normal, facing::counter_clockwise_front, facing::clockwise_front,
                              facing::two_sided};

template <typename T>
ltc::polygon_light<T> make_light(const std::vector<glm::vec<3, T>>& v, facing f, const glm::vec<3, T>& normal,
                                 const glm::vec<3, T>& radiance) {
    switch (f) {
        case facing::emission_normal: return ltc::polygon_light<T>::one_sided(v.data(), v.size(), normal, radiance);
        case facing::counter_clockwise_front:
            return ltc::polygon_light<T>::one_sided(v.data(), v.size(), ltc::winding::counter_clockwise_front, radiance);
        case facing::clockwise_front:
            return ltc::polygon_light<T>::one_sided(v.data(), v.size(), ltc::winding::clockwise_front, radiance);
        case facing::two_sided:
        default: return ltc::polygon_light<T>::two_sided(v.data(), v.size(), radiance);
    }
}

template <typename T>
std::vector<glm::vec<3, T>> reversed(std::vector<glm::vec<3, T>> v) {
    return {v.rbegin(), v.rend()};
}

// The light's vertices by axis in its walking order, as batch::shade hands them to the kernel.
template <typename T>
struct kernel_light {
    std::vector<T> x, y, z;
    ltc::batch::detail::shading_light<T> view;
    explicit kernel_light(const ltc::polygon_light<T>& light) {
        for (const auto& p : walked(light)) x.push_back(p.x), y.push_back(p.y), z.push_back(p.z);
        const auto& L = light.radiance();
        view = {x.data(), y.data(), z.data(), light.size(), {L.x, L.y, L.z}, light.sides() == ltc::sidedness::two_sided};
    }
};

// One light over many points with Model, every isa, every facing rule, both vertex orders.
template <typename Model, typename T>
void check_points(std::uint64_t seed) {
    using vec3 = glm::vec<3, T>;
    using Lobes = typename Model::template coefficients<T>;
    const std::size_t count = 1031;  // not a multiple of any width: the tail runs
    const points_of<T> pts(count, seed);
    const auto surfaces = pts.view();
    const auto tables = ltc::batch::model_tables<Model>::of(Model{});
    const ltc::ltc_table* table_of[std::tuple_size<decltype(tables)>::value];
    for (std::size_t l = 0; l < tables.size(); ++l) table_of[l] = &tables[l];
    ltc_test::rng g(seed + 1);
    const vec3 radiance(3, 2, 1);
    std::size_t combination = 0;
    for (const auto isa : ltc::batch::instruction_sets) {
        if (!ltc::batch::available(isa)) continue;
        std::vector<T> stage_in[7];
        for (int k = 0; k < 7; ++k) stage_in[k] = pts.a[3 + k];
        std::vector<ltc_test::lane_stage_results_of<T>> stages(tables.size());
        if (isa != ltc::batch::isa::scalar)
            for (std::size_t l = 0; l < tables.size(); ++l)
                ltc_test::lane_stages(isa, stage_in, stages[l], count, tables[l]);
        std::size_t lanes = 0, crossings = 0;  // over the lights of this isa
        for (const facing f : facings) {
            const std::size_t sizes[] = {3, 4, 5, 7, 18};  // 18: beyond the kernel's stack buffer
            const std::size_t nv = sizes[combination++ % 5];
            std::vector<vec3> v;
            for (const auto& p : ltc_test::random_polygon(g, nv, true, combination % 2 == 0)) v.push_back(vec3(p));
            const vec3 normal = vec3(g.direction());
            results_of<T> orders[2] = {results_of<T>(count), results_of<T>(count)};
            for (int order = 0; order < 2; ++order) {
                const std::vector<vec3> vertices = order == 0 ? v : reversed(v);
                const auto light = make_light(vertices, f, normal, radiance);
                auto& out = orders[order];
                ltc::batch::shade<Model, Policy>(surfaces, light, out.view(), isa);
                results_of<T> kernel(count);
                const kernel_light<T> kl(light);
                const std::size_t vectorized =
                    isa == ltc::batch::isa::scalar
                        ? 0
                        : ltc_test::shading_kernel<Policy, Lobes>(isa, kl.view, surfaces, kernel.view(), table_of);
                const auto walk = walked(light);
                std::size_t bad = 0, handed_back = 0, crossing = 0, exact = 0;
                for (std::size_t i = 0; i < count; ++i) {
                    const auto got = out.at(i);
                    CAPTURE(static_cast<int>(isa), static_cast<int>(f), order, nv, i);
                    if (i >= vectorized || std::isnan(kernel.c[0][i])) {
                        handed_back += i < vectorized;
                        const auto want = ltc::shade<Model, Policy>(surfaces.at(i), light);
                        exact += !same_bits(got, want);
                        continue;
                    }
                    CHECK(same_bits(got, kernel.at(i)));  // the lanes' values, as batch::shade wrote them
                    const vec3 P = pts.vec(0, i), F0 = pts.vec(10, i), albedo = pts.vec(13, i);
                    ltc::shading_frame<T> frame;
                    const auto& st = stages[0];
                    frame.t1 = vec3(st.frame[0][i], st.frame[1][i], st.frame[2][i]);
                    frame.t2 = vec3(st.frame[3][i], st.frame[4][i], st.frame[5][i]);
                    frame.n = vec3(st.frame[6][i], st.frame[7][i], st.frame[8][i]);
                    frame.cos_theta_v = st.frame[9][i];
                    const ltc::shading_point<T> point{frame, P, F0, albedo};
                    const Lobes c = lane_coefficients(stages, i, static_cast<Lobes*>(nullptr));
                    const auto want = ltc::shade_lobes<Policy>(point, c, light, ltc::shade_options{});
                    const auto tol = tolerance::lobes<Policy>(point, c, light);
                    const std::size_t viol = violations(got, want, tol);
                    CAPTURE(got.specular.x, want.specular.x, tol.specular.x, got.diffuse.x, want.diffuse.x,
                            tol.diffuse.x);
                    CHECK(viol == 0);
                    bad += viol;
                    bool above = false, below = false;
                    for (const auto& p : walk) {
                        const T z = frame.to_local(p - P).z;
                        above = above || z >= 0, below = below || z < 0;
                    }
                    crossing += above && below;
                }
                CAPTURE(static_cast<int>(isa), static_cast<int>(f), order, nv, bad, handed_back, crossing);
                CHECK(exact == 0);
                if (isa != ltc::batch::isa::scalar) {
                    CHECK(vectorized > count / 2);
                    CHECK(handed_back < count / 50);  // V = N exactly is the kernel's (Duff's tangent)
                }
                lanes += vectorized - handed_back, crossings += crossing;
            }
            // A light that emits towards its normal walks its vertices in one order whichever the
            // caller gives: the same bits (the scalar light's promise).
            if (f == facing::emission_normal) CHECK(same_bits(orders[0], orders[1]));
        }
        CAPTURE(static_cast<int>(isa), lanes, crossings);
        CHECK(crossings * 10 >= lanes);  // the horizon clipping is exercised
    }
}

}  // namespace

TEST_CASE("batch::shade over many points matches ltc::shade item by item: every model, facing, vertex order, isa",
          "[batch][shade]") {
    SECTION("one_lobe") { check_points<ltc::ggx::one_lobe, float>(31); }
    SECTION("ltc_and_cosine") { check_points<ltc::ggx::ltc_and_cosine, float>(37); }
    SECTION("two_lobes") { check_points<ltc::ggx::two_lobes, float>(41); }
}

TEST_CASE("batch::shade over many points in double matches ltc::shade in double", "[batch][shade][double]") {
    // The kernel's double lanes with the minimax_rational policy; with the default policy (exact
    // in double, no SIMD kernel) every point is ltc::shade's, bit for bit.
    check_points<ltc::ggx::one_lobe, double>(43);
    check_points<ltc::ggx::ltc_and_cosine, double>(47);
    check_points<ltc::ggx::two_lobes, double>(53);
    const points_of<double> pts(67, 59);
    ltc_test::rng g(61);
    std::vector<glm::dvec3> v;
    for (const auto& p : ltc_test::random_polygon(g, 4, true, false)) v.push_back(glm::dvec3(p));
    const auto light = ltc::polygon_light<double>::two_sided(v.data(), 4, glm::dvec3(1, 2, 3));
    for (const auto isa : ltc::batch::instruction_sets) {
        if (!ltc::batch::available(isa)) continue;
        results_of<double> out(pts.count);
        ltc::batch::shade(pts.view(), light, out.view(), isa);
        std::size_t differ = 0;
        for (std::size_t i = 0; i < pts.count; ++i) differ += !same_bits(out.at(i), ltc::shade(pts.view().at(i), light));
        CAPTURE(static_cast<int>(isa));
        CHECK(differ == 0);
    }
}

namespace {

// Points ltc::shade leaves unshaded (0), and points the kernel hands back, every isa and model:
// batch::shade gives ltc::shade's bits there, the lanes themselves write the zeros (not NaN), and
// a roughness out of [0, 1] or NaN gives the bits of the clamped one.
template <typename Model, typename T>
void check_bad_points() {
    using vec3 = glm::vec<3, T>;
    using Lobes = typename Model::template coefficients<T>;
    const std::size_t count = 96;
    points_of<T> pts(count, 5);
    const T inf = std::numeric_limits<T>::infinity(), nan = std::numeric_limits<T>::quiet_NaN();
    const auto set = [&](int c, std::size_t i, const vec3& v) {
        for (int k = 0; k < 3; ++k) pts.a[c + k][i] = v[k];
    };
    enum kind { ordinary, unshaded, handed_back, clamped };
    std::vector<kind> what(count, ordinary);
    for (std::size_t i = 0; i < count; ++i) {
        switch (i % 16) {
            case 1: set(3, i, vec3(T(0))), what[i] = unshaded; break;                  // N = 0
            case 2: set(6, i, vec3(T(0))), what[i] = unshaded; break;                  // V = 0
            case 3: pts.a[0][i] = nan, what[i] = unshaded; break;                      // P not finite
            case 4: pts.a[4][i] = inf, what[i] = unshaded; break;                      // N not finite
            case 5: pts.a[8][i] = -inf, what[i] = unshaded; break;                     // V not finite
            case 6: pts.a[7][i] = nan, what[i] = unshaded; break;
            case 7: set(3, i, pts.vec(3, i) * T(1e-20)), what[i] = handed_back; break; // |N|^2 < 1e-30
            case 8: set(6, i, pts.vec(6, i) * T(1e-20)), what[i] = handed_back; break; // |V|^2 < 1e-30
            case 9: pts.a[0][i] *= T(1e25), what[i] = handed_back; break;              // far away
            case 10: set(0, i, vec3(-1, 0, 1)), what[i] = handed_back; break;          // P on a vertex
            case 11: pts.a[9][i] = T(-3), what[i] = clamped; break;                    // roughness clamped to 0
            case 12: pts.a[9][i] = nan, what[i] = clamped; break;                      // NaN read as 0
            case 13: pts.a[9][i] = T(7), what[i] = clamped; break;                     // clamped to 1
            default: break;
        }
    }
    points_of<T> clamp = pts;
    for (std::size_t i = 0; i < count; ++i)
        if (what[i] == clamped) clamp.a[9][i] = pts.a[9][i] > T(0) ? T(1) : T(0);
    const auto tables = ltc::batch::model_tables<Model>::of(Model{});
    const ltc::ltc_table* table_of[std::tuple_size<decltype(tables)>::value];
    for (std::size_t l = 0; l < tables.size(); ++l) table_of[l] = &tables[l];
    const std::vector<vec3> quad = {{-1, 0, 1}, {1, 0, 1}, {1, 1, T(1.5)}, {-1, 1, T(1.5)}};
    for (const auto isa : ltc::batch::instruction_sets) {
        if (!ltc::batch::available(isa)) continue;
        for (const std::size_t n : {2u, 4u}) {
            const auto light = ltc::polygon_light<T>::two_sided(quad.data(), n, vec3(1, 2, 3));
            results_of<T> out(count), kernel(count), clamped_out(count);
            ltc::batch::shade<Model, Policy>(pts.view(), light, out.view(), isa);
            ltc::batch::shade<Model, Policy>(clamp.view(), light, clamped_out.view(), isa);
            const kernel_light<T> kl(light);
            const std::size_t vectorized =
                isa == ltc::batch::isa::scalar || n < 3
                    ? 0
                    : ltc_test::shading_kernel<Policy, Lobes>(isa, kl.view, pts.view(), kernel.view(), table_of);
            std::size_t differ = 0, not_zero = 0, lanes_not_zero = 0, kept = 0, not_clamped = 0, nonfinite = 0;
            for (std::size_t i = 0; i < count; ++i) {
                const auto got = out.at(i), want = ltc::shade<Model, Policy>(pts.view().at(i), light);
                for (int c = 0; c < 3; ++c)
                    nonfinite += !std::isfinite(got.specular[c]) || !std::isfinite(got.diffuse[c]);
                const bool scalar = i >= vectorized || std::isnan(kernel.c[0][i]);
                if (scalar || what[i] == unshaded || what[i] == handed_back) differ += !same_bits(got, want);
                if (what[i] == unshaded) {
                    not_zero += !same_bits(got, ltc::shading_result<T>{});
                    if (i < vectorized) lanes_not_zero += !same_bits(kernel.at(i), ltc::shading_result<T>{});
                }
                if (what[i] == handed_back && i < vectorized) kept += !std::isnan(kernel.c[0][i]);
                if (what[i] == clamped) not_clamped += !same_bits(got, clamped_out.at(i));
            }
            CAPTURE(static_cast<int>(isa), n, vectorized);
            CHECK(differ == 0);
            CHECK(not_zero == 0);
            CHECK(lanes_not_zero == 0);
            CHECK(kept == 0);
            CHECK(not_clamped == 0);
            CHECK(nonfinite == 0);
        }
    }
}

}  // namespace

TEST_CASE("batch::shade: unshaded and handed-back points give ltc::shade's values, the lanes write the zeros",
          "[batch][shade][bad_input]") {
    check_bad_points<ltc::ggx::one_lobe, float>();
    check_bad_points<ltc::ggx::ltc_and_cosine, float>();
    check_bad_points<ltc::ggx::two_lobes, float>();
    check_bad_points<ltc::ggx::ltc_and_cosine, double>();
}

namespace {

// Each field of surfaces uniform (one at a time, then all six) against per-point arrays holding
// the same value: the same bits, every isa and model.
template <typename Model, typename T>
void check_uniform_fields() {
    using vec3 = glm::vec<3, T>;
    const std::size_t count = 203;
    const points_of<T> random(count, 71);
    ltc_test::rng g(73);
    std::vector<vec3> v;
    for (const auto& p : ltc_test::random_polygon(g, 4, true, false)) v.push_back(vec3(p));
    const auto light = ltc::polygon_light<T>::one_sided(v.data(), 4, vec3(g.direction()), vec3(2, 1, 3));
    // The uniform values: point 0's.
    for (int field = 0; field <= 6; ++field) {  // position, normal, view, roughness, f0, albedo; 6: all
        points_of<T> arrays = random;
        const auto same = [&](int f) { return field == 6 || field == f; };
        const ltc::surface<T> s0 = random.view().at(0);
        const int first[6] = {0, 3, 6, 9, 10, 13};
        for (int f = 0; f < 6; ++f) {
            if (!same(f)) continue;
            const int width = f == 3 ? 1 : 3;
            for (int k = 0; k < width; ++k)
                for (std::size_t i = 0; i < count; ++i) arrays.a[first[f] + k][i] = random.a[first[f] + k][0];
        }
        auto points = arrays.view();
        if (same(0)) points.position = ltc::batch::uniform(s0.position);
        if (same(1)) points.normal = ltc::batch::uniform(s0.normal);
        if (same(2)) points.view = ltc::batch::uniform(s0.view);
        if (same(3)) points.roughness = ltc::batch::uniform(s0.roughness);
        if (same(4)) points.f0 = ltc::batch::uniform(s0.f0);
        if (same(5)) points.albedo = ltc::batch::uniform(s0.albedo);
        for (const auto isa : ltc::batch::instruction_sets) {
            if (!ltc::batch::available(isa)) continue;
            results_of<T> a(count), b(count);
            ltc::batch::shade<Model, Policy>(arrays.view(), light, a.view(), isa);
            ltc::batch::shade<Model, Policy>(points, light, b.view(), isa);
            CAPTURE(field, static_cast<int>(isa));
            CHECK(same_bits(a, b));
        }
    }
}

}  // namespace

TEST_CASE("batch::surfaces: uniform fields give the bits of per-point arrays of the same value", "[batch][shade]") {
    check_uniform_fields<ltc::ggx::one_lobe, float>();
    check_uniform_fields<ltc::ggx::ltc_and_cosine, float>();
    check_uniform_fields<ltc::ggx::two_lobes, float>();
    check_uniform_fields<ltc::ggx::ltc_and_cosine, double>();
    // The defaults are ltc::surface's, and a scalar spreads over a vector field.
    const ltc::batch::surfaces<float> d{};
    const ltc::surface<float> s{};
    CHECK(same_bits(d.at(3).normal, s.normal));
    CHECK(same_bits(d.at(3).view, s.view));
    CHECK(same_bits(d.at(3).f0, s.f0));
    CHECK(d.at(3).roughness == s.roughness);
    const ltc::batch::vec3_field<float> grey = ltc::batch::uniform(0.25f);
    CHECK(same_bits(grey.at(7), glm::vec3(0.25f)));
}

namespace {

// count random polygon lights of N vertices in SoA, with per-light radiance and emission normals.
template <typename T, std::size_t N>
struct lights_of {
    using vec3 = glm::vec<3, T>;
    std::size_t count;
    std::vector<T> x[N], y[N], z[N], radiance[3], normal[3];
    // grazing: each emission normal nearly in its light's plane (an edge's direction plus 1e-6
    // to 1e-2 of the plane's normal, either side), where the facing's sign rests on few bits.
    lights_of(std::size_t n, std::uint64_t seed, bool reverse = false, bool grazing = false) : count(n) {
        ltc_test::rng g(seed);
        for (std::size_t j = 0; j < n; ++j) {
            const auto p = ltc_test::random_polygon(g, N, true, j % 2 == 0);
            for (std::size_t k = 0; k < N; ++k) {
                const auto& q = p[reverse ? N - 1 - k : k];
                x[k].push_back(T(q.x)), y[k].push_back(T(q.y)), z[k].push_back(T(q.z));
            }
            glm::dvec3 e = g.direction();
            if (grazing) {
                const glm::dvec3 edge = glm::normalize(glm::dvec3(p[1] - p[0]));
                const glm::dvec3 plane = glm::normalize(glm::cross(glm::dvec3(p[1] - p[0]), glm::dvec3(p[2] - p[0])));
                e = edge + (j % 2 ? 1.0 : -1.0) * std::pow(10.0, -double(2 + j % 5)) * plane;
            }
            for (int c = 0; c < 3; ++c)
                radiance[c].push_back(T(float(g.uniform(0.5, 4)))), normal[c].push_back(T(float(e[c])));
        }
    }
    ltc::batch::polygon_lights<T, N> view(facing f) const { return view(f, normals(), radiances()); }
    ltc::batch::polygon_lights<T, N> view(facing f, const ltc::batch::vec3_field<T>& n,
                                          const ltc::batch::vec3_field<T>& L) const {
        const T* xs[N];
        const T* ys[N];
        const T* zs[N];
        for (std::size_t k = 0; k < N; ++k) xs[k] = x[k].data(), ys[k] = y[k].data(), zs[k] = z[k].data();
        using lights = ltc::batch::polygon_lights<T, N>;
        switch (f) {
            case facing::emission_normal: return lights::one_sided(count, xs, ys, zs, n, L);
            case facing::counter_clockwise_front:
                return lights::one_sided(count, xs, ys, zs, ltc::winding::counter_clockwise_front, L);
            case facing::clockwise_front: return lights::one_sided(count, xs, ys, zs, ltc::winding::clockwise_front, L);
            case facing::two_sided:
            default: return lights::two_sided(count, xs, ys, zs, L);
        }
    }
    ltc::batch::vec3_field<T> normals() const { return {normal[0].data(), normal[1].data(), normal[2].data()}; }
    ltc::batch::vec3_field<T> radiances() const { return {radiance[0].data(), radiance[1].data(), radiance[2].data()}; }
};

// Many polygon lights over one point against ltc::shade light by light (file comment: the frame
// and the fetch are the scalar ones, the integrals within their tolerance lobe by lobe).
template <typename Model, typename T, std::size_t N>
void check_lights(std::uint64_t seed) {
    using vec3 = glm::vec<3, T>;
    const std::size_t count = 517;  // blocks of 16-multiples: the last count % width are the tail
    const lights_of<T, N> soa(count, seed), soa_reversed(count, seed, true), grazing(count, seed + 1, false, true);
    const vec3 P(T(0.1), T(-0.2), T(0.05)), Nrm(T(0.2), T(0.1), T(1)), V(T(0.7), T(-0.3), T(0.5)),
        F0(T(0.9), T(0.6), T(0.3)), albedo(T(0.5));
    for (const T roughness : {T(0.1), T(0.6)})
        for (const facing f : facings)
            for (const auto isa : ltc::batch::instruction_sets)
                for (int variant = 0; variant < 2; ++variant) {  // 1: the grazing emission normals
                    if (!ltc::batch::available(isa) || (variant == 1 && f != facing::emission_normal)) continue;
                    const ltc::surface<T> s{P, Nrm, V, roughness, F0, albedo, vec3(T(0.6), T(0.8), T(0.1)),
                                            T(1.1) - roughness};
                    const auto lights = (variant == 0 ? soa : grazing).view(f);
                    results_of<T> out(count);
                    ltc::batch::shade<Model, Policy>(s, lights, out.view(), isa);
                    // shade's frame and fetch (the tangent frame for anisotropic models).
                    const ltc::shading_point<T> point = ltc::detail::model_shading_point<Model>(s);
                    const auto c = ltc::detail::fetch_lobes(Model{}, point, s);
                    const std::size_t width = ltc::batch::lane_count<T>(isa);
                    std::size_t bad = 0, exact = 0;
                    for (std::size_t j = 0; j < count; ++j) {
                        vec3 buffer[N];
                        const auto light = lights.light(j, buffer);
                        const auto want = ltc::shade<Model, Policy>(s, light);
                        const auto got = out.at(j);
                        if (isa == ltc::batch::isa::scalar || j >= count - count % width) {
                            exact += !same_bits(got, want);
                            continue;
                        }
                        const auto tol = tolerance::lobes<Policy>(point, c, light);
                        const std::size_t viol = violations(got, want, tol);
                        CAPTURE(static_cast<int>(isa), static_cast<int>(f), roughness, j, got.specular.x, want.specular.x,
                                tol.specular.x, got.diffuse.x, want.diffuse.x, tol.diffuse.x);
                        CHECK(viol == 0);
                        bad += viol;
                    }
                    CAPTURE(static_cast<int>(isa), static_cast<int>(f), roughness, variant, bad);
                    CHECK(exact == 0);
                    if (variant == 1) continue;
                    // Uniform radiance and normal against arrays of the same values; the other vertex
                    // order of lights that emit towards their normals: the same bits.
                    if (f == facing::emission_normal) {
                        results_of<T> rev(count);
                        ltc::batch::shade<Model, Policy>(s, soa_reversed.view(f), rev.view(), isa);
                        CHECK(same_bits(out, rev));
                    }
                    lights_of<T, N> same = soa;
                    for (int k = 0; k < 3; ++k)
                        for (std::size_t j = 0; j < count; ++j)
                            same.radiance[k][j] = T(k + 1), same.normal[k][j] = T(k == 2);
                    results_of<T> a(count), b(count);
                    ltc::batch::shade<Model, Policy>(s, same.view(f), a.view(), isa);
                    ltc::batch::shade<Model, Policy>(
                        s, same.view(f, ltc::batch::uniform(vec3(0, 0, 1)), ltc::batch::uniform(vec3(1, 2, 3))),
                        b.view(), isa);
                    CHECK(same_bits(a, b));
                }
    // Points ltc::shade leaves unshaded: zeros for every light.
    const auto lights = soa.view(facing::two_sided);
    for (const auto& s : {ltc::surface<T>{P, vec3(T(0)), V, T(0.3), F0, albedo},
                          ltc::surface<T>{P, Nrm, vec3(T(0)), T(0.3), F0, albedo},
                          ltc::surface<T>{vec3(std::numeric_limits<T>::infinity()), Nrm, V, T(0.3), F0, albedo}})
        for (const auto isa : ltc::batch::instruction_sets) {
            if (!ltc::batch::available(isa)) continue;
            results_of<T> out(count);
            ltc::batch::shade<Model, Policy>(s, lights, out.view(), isa);
            std::size_t not_zero = 0;
            for (std::size_t j = 0; j < count; ++j) not_zero += !same_bits(out.at(j), ltc::shading_result<T>{});
            CHECK(not_zero == 0);
        }
}

}  // namespace

TEST_CASE("batch::shade over many polygon lights matches ltc::shade light by light", "[batch][shade][lights]") {
    check_lights<ltc::ggx::one_lobe, float, 4>(81);
    check_lights<ltc::ggx::ltc_and_cosine, float, 4>(83);
    check_lights<ltc::ggx::two_lobes, float, 4>(89);
    check_lights<ltc::ggx::ltc_and_cosine, float, 3>(97);
    check_lights<ltc::ggx::two_lobes, float, 5>(101);
    check_lights<ltc::ggx::ltc_and_cosine, double, 4>(103);
    check_lights<ltc::ggx::anisotropic, float, 4>(107);
    check_lights<ltc::ggx::anisotropic, double, 3>(109);
}

TEST_CASE("batch::polygon_lights: a bad emission normal or null arrays throw ltc::invalid_light",
          "[batch][shade][lights]") {
    lights_of<float, 4> soa(40, 107);
    soa.normal[0][17] = soa.normal[1][17] = soa.normal[2][17] = 0.0f;  // light 17: no side
    results_of<float> out(40);
    const ltc::surface<float> s{};
    for (const auto isa : ltc::batch::instruction_sets) {
        if (!ltc::batch::available(isa)) continue;
        CHECK_THROWS_AS(ltc::batch::shade(s, soa.view(facing::emission_normal), out.view(), isa), ltc::invalid_light);
        CHECK_NOTHROW(ltc::batch::shade(s, soa.view(facing::two_sided), out.view(), isa));
    }
    // In the light's plane (the polygon's vector area is perpendicular to it).
    lights_of<float, 4> flat = soa;
    for (std::size_t k = 0; k < 4; ++k) flat.z[k][3] = 1.0f;
    for (int c = 0; c < 3; ++c) flat.normal[c][3] = c == 0 ? 1.0f : 0.0f;
    CHECK_THROWS_AS(ltc::batch::shade(s, flat.view(facing::emission_normal), out.view()), ltc::invalid_light);
    const float* none[4] = {};
    CHECK_THROWS_AS(ltc::batch::polygon_lights<float>::two_sided(1, none, none, none, ltc::batch::uniform(1.0f)),
                    ltc::invalid_light);
    CHECK_NOTHROW(ltc::batch::polygon_lights<float>::two_sided(0, none, none, none, ltc::batch::uniform(1.0f)));
}

namespace {

// Each deprecated batch function against the new call it wraps, bit for bit: random points (some
// unshaded: N = 0, V = 0, P not finite) and lights, every isa, both sidednesses.
template <typename T, typename P>
void check_old_names() {
    using vec3 = glm::vec<3, T>;
    const std::size_t count = 203;
    points_of<T> pts(count, 109);
    for (std::size_t i = 0; i < count; i += 16) {
        pts.a[3][i] = pts.a[4][i] = pts.a[5][i] = T(0);
        if (i + 1 < count) pts.a[6][i + 1] = pts.a[7][i + 1] = pts.a[8][i + 1] = T(0);
        if (i + 2 < count) pts.a[1][i + 2] = std::numeric_limits<T>::quiet_NaN();
    }
    const lights_of<T, 4> quads(count, 113);
    ltc::batch::quad_lights<T> ql;
    for (std::size_t k = 0; k < 4; ++k)
        ql.x[k] = quads.x[k].data(), ql.y[k] = quads.y[k].data(), ql.z[k] = quads.z[k].data();
    for (int c = 0; c < 3; ++c) ql.radiance[c] = quads.radiance[c].data();
    ltc_test::rng g(127);
    const vec3 L(2, 1, T(0.5));
    const ltc::ltc_table table = ltc::ggx_two_lobe::lobe_table(1);
    for (const auto side : {ltc::sidedness::one_sided, ltc::sidedness::two_sided})
        for (const auto isa : ltc::batch::instruction_sets) {
            if (!ltc::batch::available(isa)) continue;
            std::vector<vec3> v;
            for (const auto& p : ltc_test::random_polygon(g, 5, true, false)) v.push_back(vec3(p));
            // The old sidedness: one-sided emits from the face from which the vertices turn clockwise.
            const auto light = side == ltc::sidedness::two_sided
                                   ? ltc::polygon_light<T>::two_sided(v.data(), 5, L)
                                   : ltc::polygon_light<T>::one_sided(v.data(), 5, ltc::winding::clockwise_front, L);
            const auto lights =
                quads.view(side == ltc::sidedness::two_sided ? facing::two_sided : facing::clockwise_front);
            const ltc::surface<T> s{pts.vec(0, 5), pts.vec(3, 5),  pts.vec(6, 5),
                                    pts.a[9][5],   pts.vec(10, 5), pts.vec(13, 5)};
            CAPTURE(static_cast<int>(isa), side == ltc::sidedness::two_sided);
            results_of<T> a(count), b(count);
            namespace batch = ltc::batch;
            const auto check = [&](const char* name) {
                CAPTURE(name);
                CHECK(same_bits(a, b));
            };
            batch::shade_polygon_light<P>(pts.old(), L, v.data(), 5, side, a.view(), count, isa);
            batch::shade<ltc::ggx::ltc_and_cosine, P>(pts.view(), light, b.view(), isa);
            check("shade_polygon_light");
            batch::shade_polygon_light_cosine_lobe<P>(pts.old(), L, v.data(), 5, side, a.view(), count, isa);
            check("shade_polygon_light_cosine_lobe");
            batch::shade_polygon_light_one_lobe<P>(pts.old(), L, v.data(), 5, side, a.view(), count, isa);
            batch::shade<ltc::ggx::one_lobe, P>(pts.view(), light, b.view(), isa);
            check("shade_polygon_light_one_lobe");
            batch::shade_polygon_light_two_lobe<P>(pts.old(), L, v.data(), 5, side, a.view(), count, isa);
            batch::shade<ltc::ggx::two_lobes, P>(pts.view(), light, b.view(), isa);
            check("shade_polygon_light_two_lobe");
            batch::shade_polygon_light_with_table<P>(table, pts.old(), L, v.data(), 5, side, a.view(), count, isa);
            batch::shade<batch::one_lobe_table, P>(batch::one_lobe_table(table), pts.view(), light, b.view(), isa);
            check("shade_polygon_light_with_table");
            batch::shade_quad_lights<P>(s.position, s.normal, s.view, s.roughness, s.f0, s.albedo, ql, side, a.view(),
                                        count, isa);
            batch::shade<ltc::ggx::ltc_and_cosine, P>(s, lights, b.view(), isa);
            check("shade_quad_lights");
            batch::shade_quad_lights_cosine_lobe<P>(s.position, s.normal, s.view, s.roughness, s.f0, s.albedo, ql, side,
                                                    a.view(), count, isa);
            check("shade_quad_lights_cosine_lobe");
            batch::shade_quad_lights_one_lobe<P>(s.position, s.normal, s.view, s.roughness, s.f0, s.albedo, ql, side,
                                                 a.view(), count, isa);
            batch::shade<ltc::ggx::one_lobe, P>(s, lights, b.view(), isa);
            check("shade_quad_lights_one_lobe");
            batch::shade_quad_lights_two_lobe<P>(s.position, s.normal, s.view, s.roughness, s.f0, s.albedo, ql, side,
                                                 a.view(), count, isa);
            batch::shade<ltc::ggx::two_lobes, P>(s, lights, b.view(), isa);
            check("shade_quad_lights_two_lobe");
        }
}

}  // namespace

TEST_CASE("the deprecated batch functions are batch::shade, bit for bit", "[batch][shade][deprecated]") {
    check_old_names<float, ltc::edge_policy::automatic>();
    check_old_names<float, ltc::edge_policy::polynomial>();
    check_old_names<double, ltc::edge_policy::automatic>();  // exact: ltc::shade point by point
    check_old_names<double, ltc::edge_policy::minimax_rational>();
}

namespace {

// A model without batch tables: ltc::shade point by point.
struct untabled : ltc::ggx::two_lobes {};

template <typename Model, typename T, typename Light>
std::size_t differences(const points_of<T>& pts, const Light& light, ltc::batch::isa isa,
                        const ltc::shade_options& o = {}) {
    results_of<T> out(pts.count);
    ltc::batch::shade<Model, Policy>(pts.view(), light, out.view(), isa, o);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < pts.count; ++i)
        differ += !same_bits(out.at(i), ltc::shade<Model, Policy>(pts.view().at(i), light, o));
    return differ;
}

// Every light without a kernel (and polygon lights with the other clippings, and models without
// tables): ltc::shade point by point, the same bits.
template <typename Model, typename T>
void check_other_lights() {
    using vec3 = glm::vec<3, T>;
    points_of<T> pts(67, 131);
    pts.a[6][3] = pts.a[7][3] = pts.a[8][3] = T(0);  // V = 0: 0
    const vec3 L(3, 2, 1), c(T(0.2), T(0.3), T(1.1)), n = glm::normalize(vec3(T(0.3), T(-0.2), T(-1)));
    const vec3 quad[4] = {{-1, 0, 1}, {1, 0, 1}, {1, 1, T(1.5)}, {-1, 1, T(1.5)}};
    std::vector<vec3> texels;
    for (int k = 0; k < 16; ++k) texels.push_back(vec3(T(k % 4) / 3, T(k / 4) / 3, T(1)));
    const ltc::light_texture<T> tex(4, 4, texels.data());
    for (const auto isa : ltc::batch::instruction_sets) {
        if (!ltc::batch::available(isa)) continue;
        CAPTURE(static_cast<int>(isa));
        CHECK(differences<Model>(pts, ltc::disk_light<T>::one_sided(c, n, T(0.4), L), isa) == 0);
        CHECK(differences<Model>(pts, ltc::disk_light<T>::two_sided(c, n, T(0.4), L), isa) == 0);
        CHECK(differences<Model>(pts, ltc::sphere_light<T>{c, T(0.3), L}, isa) == 0);
        CHECK(differences<Model>(pts, ltc::line_light<T>{quad[0], quad[2], T(0.01), L}, isa) == 0);
        CHECK(differences<Model>(pts, ltc::tube_light<T>{quad[0], quad[2], T(0.1), L}, isa) == 0);
        CHECK(differences<Model>(pts, ltc::textured_quad_light<T>::one_sided(quad, vec3(0, 0, -1), tex), isa) == 0);
        CHECK(differences<Model>(pts, ltc::textured_quad_light<T>::two_sided(quad, tex), isa) == 0);
        const auto polygon = ltc::polygon_light<T>::one_sided(quad, 4, vec3(0, 0, -1), L);
        for (const auto clip : {ltc::horizon_clipping::shading_first, ltc::horizon_clipping::sphere_analytic})
            CHECK(differences<Model>(pts, polygon, isa, ltc::shade_options{clip}) == 0);
        CHECK(differences<untabled>(pts, polygon, isa) == 0);
    }
}

}  // namespace

TEST_CASE("batch::shade with the other lights, clippings and untabled models is ltc::shade point by point",
          "[batch][shade]") {
    check_other_lights<ltc::ggx::ltc_and_cosine, float>();
    check_other_lights<ltc::ggx::one_lobe, float>();
    check_other_lights<ltc::ggx::two_lobes, double>();
    check_other_lights<ltc::ggx::anisotropic, float>();
}

TEST_CASE("batch::one_lobe_table: a model of any table, its state passed first", "[batch][shade]") {
    // With the GGX table it is ggx::one_lobe bit for bit (the same lanes, and its scalar path
    // ltc::shade's steps with the object's fetch); with another table, ltc::shade_lobes of that
    // table's lobe where the kernel hands back.
    const points_of<float> pts(131, 137);
    ltc_test::rng g(139);
    std::vector<glm::vec3> v = ltc_test::random_polygon(g, 4, true, false);
    const auto light = ltc::polygon_light<float>::two_sided(v.data(), 4, glm::vec3(1.0f));
    for (const auto isa : ltc::batch::instruction_sets) {
        if (!ltc::batch::available(isa)) continue;
        results_of<float> a(pts.count), b(pts.count);
        ltc::batch::shade(ltc::batch::one_lobe_table(ltc::ggx::table), pts.view(), light, a.view(), isa);
        ltc::batch::shade<ltc::ggx::one_lobe>(pts.view(), light, b.view(), isa);
        CAPTURE(static_cast<int>(isa));
        CHECK(same_bits(a, b));
    }
    const ltc::ltc_table table = ltc::ggx_two_lobe::lobe_table(0);
    results_of<float> out(pts.count);
    ltc::batch::shade(ltc::batch::one_lobe_table(table), pts.view(), light, out.view(), ltc::batch::isa::scalar);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < pts.count; ++i) {
        const auto s = pts.view().at(i);
        const auto p = ltc::make_shading_point(s);
        differ += !same_bits(out.at(i), ltc::shade_lobes<ltc::edge_policy::automatic>(
                                            p, ltc::lobes::one<float>{table.fetch(p.frame.cos_theta_v, s.roughness)},
                                            light, ltc::shade_options{}));
    }
    CHECK(differ == 0);
}

}  // namespace ltc_test_batch_shade
