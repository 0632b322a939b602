// ltc/shading/batch_shading.hpp against ltc::shade_polygon_light, item by item, for every
// instruction set this machine runs: one light over many points (the shading kernel) and many
// quad lights over one point.
//
// Tolerance. The kernel's frame and table fetch are compared with the scalar ones in
// tests/test_batch_lanes.cpp; here the scalar function shades each point with the very frame and
// coefficients the kernel computed (tests/support/batch_lanes.hpp runs the same lane code), so
// only the two integrals differ: each by at most the tolerance derived in tests/test_batch.cpp
// (ltc_test::clip_tolerance of the light in the local frame), plus the effect of the local
// vertices themselves differing by a few u (the scalar path divides p - P by its largest
// coordinate before the rotation, the kernel rotates p - P with FMA), which M^-1 amplifies by its
// conditioning at each vertex (tolerance() below; without it a light seen nearly edge-on through
// an anisotropic lobe fails at -O1, where GCC contracts no FMA). specular = radiance (F0 magnitude + (1 - F0) fresnel) I and
// diffuse = albedo radiance E then differ by the factor times the integral's tolerance, plus the
// factor's 4 u relative rounding (the same operations on both sides, up to FMA contraction).
// Points the kernel hands back, and the tail, are shaded by the scalar function: equal exactly.
// In double (the kernel on double lanes against the scalar shading in double) the same
// derivation holds with double's u = 2^-53 (the kernel normalizes by 1 / sqrt there, closer than
// float's estimate and Newton step).
#include "support/batch_lanes.hpp"
#include "support/clip_comparison.hpp"
#include "support/rng.hpp"
#include "support/rounding_bound.hpp"
#include "support/shading_tolerance.hpp"

#include <ltc/shading/batch_shading.hpp>
#include <ltc/shading/batch_cosine_lobe.hpp>
#include <ltc/shading/batch_two_lobe.hpp>
#include <ltc/shading/polygon_light.hpp>
#include <ltc/shading/two_lobe_polygon_light.hpp>

#include <catch2/catch.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace ltc_test_batch_shading {  // the file's own names, apart from the other files of a unity batch

namespace {

using Policy = ltc::edge_policy::minimax_rational;
constexpr double kU = 0x1.0p-24;

// The unit roundoff of T (kU for float).
template <typename T>
constexpr double unit_roundoff = std::numeric_limits<T>::epsilon() / 2;

// count random shading points in SoA (P near the origin, N and V random, V mostly in front),
// rounded to float (then widened exactly for T = double: the same points in both).
template <typename T>
struct points_soa_of {
    using vec3 = glm::vec<3, T>;
    std::vector<T> a[16];  // px py pz nx ny nz vx vy vz roughness f0 rgb albedo rgb
    explicit points_soa_of(std::size_t count, std::uint64_t seed) {
        ltc_test::rng g(seed);
        for (std::size_t i = 0; i < count; ++i) {
            const glm::dvec3 P(g.uniform(-1, 1), g.uniform(-1, 1), g.uniform(-0.5, 0.5));
            const glm::dvec3 N = g.direction() * g.uniform(0.5, 2.0);
            glm::dvec3 V = g.direction();
            if (glm::dot(V, N) < 0 && i % 8 != 0) V = -V;  // some views from below the surface
            if (i % 101 == 0) V = N;                        // normal incidence exactly
            const double v[16] = {P.x, P.y, P.z, N.x, N.y, N.z, V.x, V.y, V.z, g.uniform(0.02, 1.0),
                                  g.uniform(), g.uniform(), g.uniform(), g.uniform(), g.uniform(), g.uniform()};
            for (int k = 0; k < 16; ++k) a[k].push_back(T(float(v[k])));
        }
    }
    vec3 vec(int c, std::size_t i) const { return vec3(a[c][i], a[c + 1][i], a[c + 2][i]); }
    ltc::batch::shading_points<T> view() const {
        const T* c[16];
        for (int k = 0; k < 16; ++k) c[k] = a[k].data();
        return ltc::batch::shading_points<T>::from_columns(c);
    }
};

using points_soa = points_soa_of<float>;

template <typename T>
struct results_soa_of {
    std::vector<T> c[6];
    explicit results_soa_of(std::size_t count) {
        for (auto& v : c) v.assign(count, T(-1));
    }
    ltc::batch::shading_results<T> view() {
        ltc::batch::shading_results<T> r;
        for (int k = 0; k < 3; ++k) r.specular[k] = c[k].data(), r.diffuse[k] = c[3 + k].data();
        return r;
    }
    ltc::polygon_light_result<T> at(std::size_t i) const {
        ltc::polygon_light_result<T> r;
        for (int k = 0; k < 3; ++k) r.specular[k] = c[k][i], r.diffuse[k] = c[3 + k][i];
        return r;
    }
};
using results_soa = results_soa_of<float>;

// The tolerance of the file comment for a point shaded in `frame` with `lobe`
// (tests/support/shading_tolerance.hpp: the batch kernels' bound, u the unit roundoff of T).
template <typename... Args>
auto tolerance(const Args&... args) {
    return ltc_test::shading_tolerance::lobe<Policy>(args...);
}
using ltc_test::shading_tolerance::violations;

}  // namespace

namespace {

// One light over many points with the sum of the LTCs of Lobes tables: one table (the one-lobe GGX
// table through batch::shade_polygon_light_one_lobe, or any through shade_polygon_light_with_table), or, with
// Lobes = 2, the two lobes of the GGX two-lobe table (batch::shade_polygon_light_two_lobe; tables
// must be its lobe tables), against the scalar shading with the kernel's frame and each lobe's
// coefficients. With two lobes the specular terms add: their tolerances add, plus 2 u of the sum
// (the kernel and the reference each round it once). With Cosine, the table of an LTC and the
// cosine (batch::shade_polygon_light_cosine_lobe; tables its lobe tables): lobe 1's reference is
// the LTC of M^-1 = I, whose integral is the form factor bit for bit (tests/test_cosine_lobe.cpp),
// lobe 2's the lookup with its premultiplied M^-1 divided out (ggx_cosine_lobe::unpremultiplied).
template <int Lobes, bool Cosine = false, typename T = float>
void check_lights_over_points(const ltc::ltc_table* const (&tables)[Lobes], bool ggx) {
    using vec3 = glm::vec<3, T>;
    constexpr double u = unit_roundoff<T>;
    const std::size_t count = 1031;  // not a multiple of any width: the tail runs
    const points_soa_of<T> pts(count, 12);
    ltc_test::rng g(13);
    const vec3 radiance(3, 2, 1);
    for (const std::size_t n : {3u, 4u, 5u, 7u, 18u})  // 18: the light beyond the stack buffer
        for (const auto side : {ltc::sidedness::one_sided, ltc::sidedness::two_sided})
            for (const auto isa : ltc::batch::instruction_sets) {
                if (isa == ltc::batch::isa::scalar) continue;
                if (!ltc::batch::available(isa)) continue;
                std::vector<vec3> light;
                for (const auto& p : ltc_test::random_polygon(g, n, true, n % 2 == 0)) light.push_back(vec3(p));
                // The kernel alone (NaN where it hands a point back), then the public function.
                std::vector<T> lx, ly, lz;
                for (const auto& p : light) lx.push_back(p.x), ly.push_back(p.y), lz.push_back(p.z);
                const ltc::batch::detail::shading_light<T> sl{lx.data(), ly.data(), lz.data(), n,
                                                              {radiance.x, radiance.y, radiance.z},
                                                              side == ltc::sidedness::two_sided};
                results_soa_of<T> kernel(count), out(count);
                const std::size_t vectorized =
                    ltc_test::shading_kernel<Policy, Lobes, Cosine>(isa, sl, pts.view(), kernel.view(), count, tables);
                if (Cosine)
                    ltc::batch::shade_polygon_light_cosine_lobe<Policy>(pts.view(), radiance, light.data(), n, side,
                                                                        out.view(), count, isa);
                else if (Lobes == 2)
                    ltc::batch::shade_polygon_light_two_lobe<Policy>(pts.view(), radiance, light.data(), n, side,
                                                                     out.view(), count, isa);
                else if (ggx)
                    ltc::batch::shade_polygon_light_one_lobe<Policy>(pts.view(), radiance, light.data(), n, side, out.view(),
                                                                     count, isa);
                else
                    ltc::batch::shade_polygon_light_with_table<Policy>(*tables[0], pts.view(), radiance, light.data(), n,
                                                                       side, out.view(), count, isa);
                std::vector<T> stage_in[7];
                for (int k = 0; k < 7; ++k) stage_in[k] = pts.a[3 + k];
                ltc_test::lane_stage_results_of<T> stages[Lobes];
                for (int l = 0; l < Lobes; ++l) ltc_test::lane_stages(isa, stage_in, stages[l], count, *tables[l]);
                std::size_t bad = 0, handed_back = 0, crossing = 0;
                for (std::size_t i = 0; i < count; ++i) {
                    const vec3 P = pts.vec(0, i), F0 = pts.vec(10, i), albedo = pts.vec(13, i);
                    const auto got = out.at(i);
                    if (i >= vectorized || std::isnan(kernel.c[0][i])) {
                        handed_back += i < vectorized;
                        const auto scalar_frame = ltc::make_shading_frame(pts.vec(3, i), pts.vec(6, i));
                        const T c = scalar_frame.cos_theta_v, r = pts.a[9][i];
                        const auto want =
                            Cosine ? ltc::shade_polygon_light_cosine_lobe<Policy>(scalar_frame, ltc::ggx_cosine_lobe::fetch(c, r),
                                                                                 P, F0, albedo, radiance, light.data(), n, side)
                            : Lobes == 2 ? ltc::shade_polygon_light_two_lobe<Policy>(scalar_frame, ltc::ggx_two_lobe::fetch(c, r),
                                                                                  P, F0, albedo, radiance, light.data(), n, side)
                                       : ltc::shade_polygon_light<Policy>(scalar_frame, tables[0]->fetch(c, r), P, F0,
                                                                          albedo, radiance, light.data(), n, side);
                        CHECK(got.specular == want.specular);
                        CHECK(got.diffuse == want.diffuse);
                        continue;
                    }
                    ltc::shading_frame<T> frame;
                    const auto& st = stages[0];
                    frame.t1 = vec3(st.frame[0][i], st.frame[1][i], st.frame[2][i]);
                    frame.t2 = vec3(st.frame[3][i], st.frame[4][i], st.frame[5][i]);
                    frame.n = vec3(st.frame[6][i], st.frame[7][i], st.frame[8][i]);
                    frame.cos_theta_v = st.frame[9][i];
                    ltc::polygon_light_result<T> want;
                    ltc::polygon_light_result<double> tol;
                    for (int l = 0; l < Lobes; ++l) {
                        ltc::ltc_coefficients<T> lobe;
                        lobe.m_inv = glm::mat<3, 3, T>(T(0));
                        lobe.m_inv[0][0] = stages[l].channel[0][i], lobe.m_inv[0][2] = stages[l].channel[1][i];
                        lobe.m_inv[2][0] = stages[l].channel[2][i], lobe.m_inv[2][2] = stages[l].channel[3][i];
                        lobe.m_inv[1][1] = T(1);
                        if (Cosine && l == 0) lobe.m_inv = glm::mat<3, 3, T>(T(1));  // the cosine: E
                        lobe.magnitude = stages[l].channel[4][i], lobe.fresnel = stages[l].channel[5][i];
                        if (Cosine && l == 1) lobe = ltc::ggx_cosine_lobe::unpremultiplied(lobe);  // the kernel's division
                        const auto one =
                            ltc::shade_polygon_light<Policy>(frame, lobe, P, F0, albedo, radiance, light.data(), n, side);
                        const auto t = tolerance(frame, lobe, P, F0, albedo, radiance, light, one);
                        if (l == 0) {
                            want = one, tol = t;
                        } else {
                            want.specular += one.specular;
                            // Both sides round the sum once: 2 u of it.
                            tol.specular += t.specular + 2 * u * glm::abs(glm::dvec3(want.specular));
                        }
                    }
                    const std::size_t v = violations(got, want, tol);
                    CAPTURE(static_cast<int>(isa), n, side == ltc::sidedness::two_sided, i);
                    CAPTURE(got.specular.x, want.specular.x, tol.specular.x, got.diffuse.x, want.diffuse.x, tol.diffuse.x);
                    CHECK(v == 0);
                    bad += v;
                    bool above = false, below = false;
                    for (const auto& p : light) {
                        const T z = frame.to_local(p - P).z;
                        above = above || z >= 0, below = below || z < 0;
                    }
                    crossing += above && below;
                }
                CAPTURE(static_cast<int>(isa), n, bad, handed_back, crossing);
                CHECK(handed_back < count / 50);  // V = N exactly is the kernel's (Duff's tangent)
                CHECK(crossing > count / 10);     // the horizon clipping is exercised
            }
}

}  // namespace

TEST_CASE("one-lobe batch shading of one light matches shade_polygon_light_one_lobe point by point", "[batch][shading]") {
    const ltc::ltc_table* const tables[1] = {&ltc::ggx::table};
    check_lights_over_points(tables, true);
}

TEST_CASE("batch shading with each lobe table of the two-lobe GGX table", "[batch][shading][two_lobe]") {
    for (int l = 0; l < 2; ++l) {
        CAPTURE(l);
        const ltc::ltc_table lobe = ltc::ggx_two_lobe::lobe_table(l);
        const ltc::ltc_table* const tables[1] = {&lobe};
        check_lights_over_points(tables, false);
    }
}

TEST_CASE("two-lobe batch shading matches shade_polygon_light_two_lobe point by point", "[batch][shading][two_lobe]") {
    // One pass of the kernel with both lobes: one frame, one form factor, an LTC integral per lobe.
    const ltc::ltc_table lobe_1 = ltc::ggx_two_lobe::lobe_table(0), lobe_2 = ltc::ggx_two_lobe::lobe_table(1);
    const ltc::ltc_table* const tables[2] = {&lobe_1, &lobe_2};
    check_lights_over_points(tables, false);
}

TEST_CASE("LTC-and-cosine batch shading matches shade_polygon_light_cosine_lobe point by point",
          "[batch][shading][cosine_lobe]") {
    // One pass of the kernel: one frame, one form factor (also the cosine's integral), one LTC integral.
    const ltc::ltc_table cosine = ltc::ggx_cosine_lobe::lobe_table(0), lobe = ltc::ggx_cosine_lobe::lobe_table(1);
    const ltc::ltc_table* const tables[2] = {&cosine, &lobe};
    check_lights_over_points<2, true>(tables, false);
}

TEST_CASE("double batch shading (one lobe, two lobes, the LTC and the cosine) matches the double scalar shading",
          "[batch][shading][double]") {
    // The kernel on double lanes, every instruction set (the 16-byte one holds two: GCC 12 at -O2
    // once failed to compile its sign flip, an internal compiler error), against the scalar
    // shading in double with the kernel's frame and coefficients: the float tests' tolerance
    // with double's u.
    const ltc::ltc_table* const one[1] = {&ltc::ggx::table};
    check_lights_over_points<1, false, double>(one, true);
    const ltc::ltc_table lobe_1 = ltc::ggx_two_lobe::lobe_table(0), lobe_2 = ltc::ggx_two_lobe::lobe_table(1);
    const ltc::ltc_table* const two[2] = {&lobe_1, &lobe_2};
    check_lights_over_points<2, false, double>(two, false);
    const ltc::ltc_table cosine = ltc::ggx_cosine_lobe::lobe_table(0), lobe = ltc::ggx_cosine_lobe::lobe_table(1);
    const ltc::ltc_table* const with_cosine[2] = {&cosine, &lobe};
    check_lights_over_points<2, true, double>(with_cosine, false);
    // The default, batch::shade_polygon_light, is the LTC and the cosine in double too.
    const std::size_t count = 67;
    const points_soa_of<double> pts(count, 23);
    ltc_test::rng g(29);
    std::vector<glm::dvec3> light;
    for (const auto& p : ltc_test::random_polygon(g, 5, true, false)) light.push_back(glm::dvec3(p));
    for (const auto isa : ltc::batch::instruction_sets) {
        if (!ltc::batch::available(isa)) continue;
        results_soa_of<double> a(count), b(count);
        ltc::batch::shade_polygon_light<Policy>(pts.view(), glm::dvec3(2, 1, 0.5), light.data(), 5,
                                                ltc::sidedness::one_sided, a.view(), count, isa);
        ltc::batch::shade_polygon_light_cosine_lobe<Policy>(pts.view(), glm::dvec3(2, 1, 0.5), light.data(), 5,
                                                            ltc::sidedness::one_sided, b.view(), count, isa);
        CAPTURE(static_cast<int>(isa));
        for (int k = 0; k < 6; ++k) CHECK(a.c[k] == b.c[k]);
    }
}

TEST_CASE("batch shading kernel: lobe tables of different sizes, each at its own position", "[batch][shading][two_lobe]") {
    // The kernel fetches the lobes' tables in one pass where they share a size (the shipped ones),
    // else each at its own position: the 64 x 64 GGX table with a 32 x 32 lobe must give the sum of
    // the one-table kernels' specular terms (the same operations per lobe; the sum rounded once
    // in the kernel and once here: 2 u of it) and their diffuse term bit for bit.
    const std::size_t count = 259;
    const points_soa pts(count, 17);
    ltc_test::rng g(19);
    const ltc::ltc_table lobe = ltc::ggx_two_lobe::lobe_table(1);
    const ltc::ltc_table* const both[2] = {&ltc::ggx::table, &lobe};
    const ltc::ltc_table* const first[1] = {&ltc::ggx::table};
    const ltc::ltc_table* const second[1] = {&lobe};
    for (const auto isa : ltc::batch::instruction_sets) {
        if (isa == ltc::batch::isa::scalar || !ltc::batch::available(isa)) continue;
        const auto light = ltc_test::random_polygon(g, 4, true, false);
        std::vector<float> lx, ly, lz;
        for (const auto& p : light) lx.push_back(p.x), ly.push_back(p.y), lz.push_back(p.z);
        const ltc::batch::detail::shading_light<float> sl{lx.data(), ly.data(), lz.data(), 4, {1.0f, 2.0f, 3.0f}, false};
        results_soa two(count), a(count), b(count);
        const std::size_t n2 = ltc_test::shading_kernel<Policy, 2>(isa, sl, pts.view(), two.view(), count, both);
        const std::size_t na = ltc_test::shading_kernel<Policy, 1>(isa, sl, pts.view(), a.view(), count, first);
        const std::size_t nb = ltc_test::shading_kernel<Policy, 1>(isa, sl, pts.view(), b.view(), count, second);
        REQUIRE(n2 == na);
        REQUIRE(n2 == nb);
        std::size_t bad = 0, checked = 0;
        for (std::size_t i = 0; i < n2; ++i) {
            if (std::isnan(two.c[0][i]) || std::isnan(a.c[0][i]) || std::isnan(b.c[0][i])) continue;  // handed back
            ++checked;
            for (int c = 0; c < 3; ++c) {
                const double sum = double(a.c[c][i]) + double(b.c[c][i]);
                bad += !(std::abs(double(two.c[c][i]) - sum) <= 2 * kU * std::abs(sum));
                bad += two.c[3 + c][i] != a.c[3 + c][i];
            }
        }
        CAPTURE(static_cast<int>(isa), checked);
        CHECK(bad == 0);
        CHECK(checked > count / 2);
    }
}

TEST_CASE("batch shading: degenerate points and lights give the scalar function's values", "[batch][shading][two_lobe]") {
    const std::size_t count = 64;
    points_soa pts(count, 5);
    for (std::size_t i = 0; i < count; ++i) {
        if (i % 8 == 1) pts.a[3][i] = pts.a[4][i] = pts.a[5][i] = 0.0f;  // N = 0
        if (i % 8 == 2) pts.a[6][i] = pts.a[7][i] = pts.a[8][i] = 0.0f;  // V = 0
        if (i % 8 == 3) pts.a[0][i] = -1.0f, pts.a[1][i] = 0.0f, pts.a[2][i] = 1.0f;  // P on a vertex
        if (i % 8 == 4) pts.a[0][i] *= 1e25f;                              // far away
        if (i % 8 == 5) pts.a[9][i] = -3.0f;                               // roughness clamped to 0
    }
    const std::vector<glm::vec3> light = {{-1, 0, 1}, {1, 0, 1}, {1, 1, 1.5f}, {-1, 1, 1.5f}};
    for (const auto isa : ltc::batch::instruction_sets) {
        if (!ltc::batch::available(isa)) continue;
        for (const std::size_t n : {2u, 4u})
            for (const int lobes : {0, 1, 2, 3}) {  // batch::shade_polygon_light, _one_lobe, _two_lobe, _cosine_lobe
                results_soa out(count);
                if (lobes == 0)
                    ltc::batch::shade_polygon_light<Policy>(pts.view(), glm::vec3(1.0f), light.data(), n,
                                                            ltc::sidedness::two_sided, out.view(), count, isa);
                else if (lobes == 3)
                    ltc::batch::shade_polygon_light_cosine_lobe<Policy>(pts.view(), glm::vec3(1.0f), light.data(), n,
                                                                        ltc::sidedness::two_sided, out.view(), count, isa);
                else if (lobes == 1)
                    ltc::batch::shade_polygon_light_one_lobe<Policy>(pts.view(), glm::vec3(1.0f), light.data(), n,
                                                                     ltc::sidedness::two_sided, out.view(), count, isa);
                else
                    ltc::batch::shade_polygon_light_two_lobe<Policy>(pts.view(), glm::vec3(1.0f), light.data(), n,
                                                                     ltc::sidedness::two_sided, out.view(), count, isa);
                for (std::size_t i = 0; i < count; ++i) {
                    const glm::vec3 P = pts.vec(0, i), N = pts.vec(3, i), V = pts.vec(6, i);
                    const glm::vec3 F0 = pts.vec(10, i), albedo = pts.vec(13, i), radiance(1.0f);
                    const float r = pts.a[9][i];
                    const auto side = ltc::sidedness::two_sided;
                    const auto want =
                        lobes == 0 ? ltc::shade_polygon_light<Policy>(P, N, V, r, F0, albedo, radiance, light.data(), n, side)
                        : lobes == 3 ? ltc::shade_polygon_light_cosine_lobe<Policy>(P, N, V, r, F0, albedo, radiance,
                                                                                   light.data(), n, side)
                        : lobes == 1
                            ? ltc::shade_polygon_light_one_lobe<Policy>(P, N, V, r, F0, albedo, radiance, light.data(), n,
                                                                        side)
                            : ltc::shade_polygon_light_two_lobe<Policy>(P, N, V, r, F0, albedo, radiance, light.data(), n,
                                                                        side);
                    const auto got = out.at(i);
                    CAPTURE(static_cast<int>(isa), n, lobes, i, got.specular.x, want.specular.x, got.diffuse.x,
                            want.diffuse.x);
                    for (int c = 0; c < 3; ++c) REQUIRE(std::isfinite(got.specular[c]));
                    if (n < 3 || i % 8 == 1 || i % 8 == 3) {  // nothing to shade: zeros, as the scalar function
                        CHECK(got.specular == glm::vec3(0.0f));
                        CHECK(got.diffuse == glm::vec3(0.0f));
                        CHECK(want.specular == glm::vec3(0.0f));
                    } else if (i % 8 == 2 || i % 8 == 4) {  // handed back to the scalar function
                        CHECK(got.specular == want.specular);
                        CHECK(got.diffuse == want.diffuse);
                    }
                }
            }
    }
}

namespace {

// Many quad lights over one point, with the one-lobe GGX table (lobes = 1: shade_quad_lights_one_lobe) or the
// two-lobe table (lobes = 2: shade_quad_lights_two_lobe), against the scalar shading light by
// light. With two lobes the frame and the fetch are the scalar ones, so the specular tolerance
// is the sum of the two lobes' (each lobe's I_ltc within its own), the diffuse one lobe 1's.
// lobes = 3: the table of an LTC and the cosine (shade_quad_lights_cosine_lobe), the cosine's
// tolerance that of the LTC of M^-1 = I (its integral is E).
void check_quad_lights(int lobes) {
    const std::size_t count = 517;
    ltc_test::rng g(21);
    std::vector<float> v[15];
    std::vector<std::vector<glm::vec3>> quads;
    for (std::size_t j = 0; j < count; ++j) {
        quads.push_back(ltc_test::random_polygon(g, 4, true, j % 2 == 0));
        for (int k = 0; k < 4; ++k) {
            const glm::vec3 p = quads.back()[static_cast<std::size_t>(k)];
            v[k].push_back(p.x), v[4 + k].push_back(p.y), v[8 + k].push_back(p.z);
        }
        for (int c = 0; c < 3; ++c) v[12 + c].push_back(float(g.uniform(0.5, 4)));
    }
    ltc::batch::quad_lights<float> lights;
    for (int k = 0; k < 4; ++k) lights.x[k] = v[k].data(), lights.y[k] = v[4 + k].data(), lights.z[k] = v[8 + k].data();
    for (int c = 0; c < 3; ++c) lights.radiance[c] = v[12 + c].data();
    const glm::vec3 P(0.1f, -0.2f, 0.05f), N(0.2f, 0.1f, 1.0f), V(0.7f, -0.3f, 0.5f), F0(0.9f, 0.6f, 0.3f), albedo(0.5f);
    for (const float roughness : {0.1f, 0.6f})
        for (const auto side : {ltc::sidedness::one_sided, ltc::sidedness::two_sided})
            for (const auto isa : ltc::batch::instruction_sets) {
                if (!ltc::batch::available(isa)) continue;
                results_soa out(count);
                if (lobes == 3)
                    ltc::batch::shade_quad_lights_cosine_lobe<Policy>(P, N, V, roughness, F0, albedo, lights, side,
                                                                      out.view(), count, isa);
                else if (lobes == 1)
                    ltc::batch::shade_quad_lights_one_lobe<Policy>(P, N, V, roughness, F0, albedo, lights, side, out.view(),
                                                                   count, isa);
                else
                    ltc::batch::shade_quad_lights_two_lobe<Policy>(P, N, V, roughness, F0, albedo, lights, side, out.view(),
                                                                   count, isa);
                const ltc::shading_frame<float> frame = ltc::make_shading_frame(N, V);
                const auto lobe = ltc::ggx::fetch(frame.cos_theta_v, roughness);
                const auto two = lobes == 3 ? ltc::ggx_cosine_lobe::fetch(frame.cos_theta_v, roughness)
                                            : ltc::ggx_two_lobe::fetch(frame.cos_theta_v, roughness);
                auto cosine = two[0];
                cosine.m_inv = glm::mat3(1.0f);
                std::size_t bad = 0;
                for (std::size_t j = 0; j < count; ++j) {
                    const glm::vec3 radiance(v[12][j], v[13][j], v[14][j]);
                    const auto want =
                        lobes == 3 ? ltc::shade_polygon_light_cosine_lobe<Policy>(P, N, V, roughness, F0, albedo, radiance,
                                                                                 quads[j].data(), 4, side)
                        : lobes == 1 ? ltc::shade_polygon_light_one_lobe<Policy>(P, N, V, roughness, F0, albedo, radiance,
                                                                               quads[j].data(), 4, side)
                                   : ltc::shade_polygon_light_two_lobe<Policy>(P, N, V, roughness, F0, albedo, radiance,
                                                                               quads[j].data(), 4, side);
                    auto tol = tolerance(frame, lobes == 1 ? lobe : lobes == 3 ? two[1] : two[0], P, F0, albedo, radiance,
                                         quads[j], want);
                    if (lobes == 3) tol.specular += tolerance(frame, cosine, P, F0, albedo, radiance, quads[j], want).specular;
                    if (lobes == 2) tol.specular += tolerance(frame, two[1], P, F0, albedo, radiance, quads[j], want).specular;
                    bad += violations(out.at(j), want, tol);
                }
                CAPTURE(static_cast<int>(isa), roughness, side == ltc::sidedness::two_sided);
                CHECK(bad == 0);
                // N = 0: nothing to shade, zeros as from shade_polygon_light.
                results_soa none(count);
                if (lobes == 3)
                    ltc::batch::shade_quad_lights_cosine_lobe<Policy>(P, glm::vec3(0.0f), V, roughness, F0, albedo, lights,
                                                                      side, none.view(), count, isa);
                else if (lobes == 1)
                    ltc::batch::shade_quad_lights_one_lobe<Policy>(P, glm::vec3(0.0f), V, roughness, F0, albedo, lights, side,
                                                                   none.view(), count, isa);
                else
                    ltc::batch::shade_quad_lights_two_lobe<Policy>(P, glm::vec3(0.0f), V, roughness, F0, albedo, lights, side,
                                                                   none.view(), count, isa);
                for (std::size_t j = 0; j < count; ++j) bad += none.at(j).specular != glm::vec3(0.0f) ||
                                                               none.at(j).diffuse != glm::vec3(0.0f);
                CHECK(bad == 0);
            }
}

}  // namespace

TEST_CASE("one-lobe batch shading of many quad lights matches shade_polygon_light_one_lobe light by light", "[batch][shading]") {
    check_quad_lights(1);
}

TEST_CASE("two-lobe batch shading of many quad lights matches shade_polygon_light_two_lobe", "[batch][shading][two_lobe]") {
    check_quad_lights(2);
}

TEST_CASE("quad-light batches: coordinates near FLT_MAX give finite results", "[batch][shading][bad_input]") {
    // The fuzzer's input (tests/fuzz/, now fuzz_shading.cpp): the differences p - P near FLT_MAX
    // made the local frame's dot products overflow (NaN) until the batch divided them by their
    // largest coordinate, as ltc::integrate_polygon_light does.
    const float big = 3.40282347e+38f;
    const glm::vec3 P(-6.6722e+36f, -big, -big), N(-big), V(-big), F0(0.04f), albedo(0.5f);
    const glm::vec3 quad[4] = {{-7.60631128e+37f, -7.60631128e+37f, -big},
                               {-big, -big, -big},
                               {-3.40277256e+38f, -6.67220288e+36f, -1.76813407e+38f},
                               {-big, -3.24331611e+38f, -big}};
    constexpr std::size_t count = 17;
    std::vector<float> v[15];
    for (std::size_t j = 0; j < count; ++j) {
        for (int k = 0; k < 4; ++k) v[k].push_back(quad[k].x), v[4 + k].push_back(quad[k].y), v[8 + k].push_back(quad[k].z);
        for (int c = 0; c < 3; ++c) v[12 + c].push_back(1.0f);
    }
    ltc::batch::quad_lights<float> lights;
    for (int k = 0; k < 4; ++k) lights.x[k] = v[k].data(), lights.y[k] = v[4 + k].data(), lights.z[k] = v[8 + k].data();
    for (int c = 0; c < 3; ++c) lights.radiance[c] = v[12 + c].data();
    for (const auto isa : ltc::batch::instruction_sets) {
        if (!ltc::batch::available(isa)) continue;
        for (int lobes = 0; lobes <= 3; ++lobes) {  // shade_quad_lights, _one_lobe, _two_lobe, _cosine_lobe
            results_soa out(count);
            if (lobes == 0)
                ltc::batch::shade_quad_lights<Policy>(P, N, V, 0.0f, F0, albedo, lights, ltc::sidedness::two_sided, out.view(),
                                                      count, isa);
            else if (lobes == 1)
                ltc::batch::shade_quad_lights_one_lobe<Policy>(P, N, V, 0.0f, F0, albedo, lights, ltc::sidedness::two_sided,
                                                               out.view(), count, isa);
            else if (lobes == 2)
                ltc::batch::shade_quad_lights_two_lobe<Policy>(P, N, V, 0.0f, F0, albedo, lights, ltc::sidedness::two_sided,
                                                               out.view(), count, isa);
            else
                ltc::batch::shade_quad_lights_cosine_lobe<Policy>(P, N, V, 0.0f, F0, albedo, lights,
                                                                  ltc::sidedness::two_sided, out.view(), count, isa);
            CAPTURE(static_cast<int>(isa), lobes);
            for (const auto& c : out.c)
                for (const float x : c) CHECK(std::isfinite(x));
        }
    }
}

TEST_CASE("LTC-and-cosine batch shading of many quad lights matches shade_polygon_light_cosine_lobe",
          "[batch][shading][cosine_lobe]") {
    check_quad_lights(3);
}

TEST_CASE("the default shading is the table of an LTC and the cosine, bit for bit", "[batch][shading][cosine_lobe]") {
    // ltc::shade_polygon_light, batch::shade_polygon_light and batch::shade_quad_lights are the
    // _cosine_lobe functions (the default model, an LTC and the cosine); the _one_lobe ones keep
    // the paper's single LTC.
    const std::size_t count = 67;
    const points_soa pts(count, 23);
    ltc_test::rng g(29);
    const glm::vec3 radiance(2.0f, 1.0f, 0.5f);
    std::vector<float> v[15];
    for (std::size_t j = 0; j < count; ++j) {
        const auto q = ltc_test::random_polygon(g, 4, true, j % 2 == 0);
        for (int k = 0; k < 4; ++k) v[k].push_back(q[k].x), v[4 + k].push_back(q[k].y), v[8 + k].push_back(q[k].z);
        for (int c = 0; c < 3; ++c) v[12 + c].push_back(float(g.uniform(0.5, 4)));
    }
    ltc::batch::quad_lights<float> lights;
    for (int k = 0; k < 4; ++k) lights.x[k] = v[k].data(), lights.y[k] = v[4 + k].data(), lights.z[k] = v[8 + k].data();
    for (int c = 0; c < 3; ++c) lights.radiance[c] = v[12 + c].data();
    const auto same = [](const results_soa& x, const results_soa& y) {
        for (int k = 0; k < 6; ++k)
            if (x.c[k] != y.c[k]) return false;
        return true;
    };
    for (const auto side : {ltc::sidedness::one_sided, ltc::sidedness::two_sided})
        for (const auto isa : ltc::batch::instruction_sets) {
            if (!ltc::batch::available(isa)) continue;
            const auto light = ltc_test::random_polygon(g, 5, true, false);
            results_soa a(count), b(count), c(count), d(count);
            ltc::batch::shade_polygon_light(pts.view(), radiance, light.data(), 5, side, a.view(), count, isa);
            ltc::batch::shade_polygon_light_cosine_lobe(pts.view(), radiance, light.data(), 5, side, b.view(), count, isa);
            CAPTURE(static_cast<int>(isa));
            CHECK(same(a, b));
            const glm::vec3 P(0.1f, -0.2f, 0.05f), N(0.2f, 0.1f, 1.0f), V(0.7f, -0.3f, 0.5f), F0(0.9f, 0.6f, 0.04f);
            ltc::batch::shade_quad_lights(P, N, V, 0.35f, F0, glm::vec3(0.5f), lights, side, c.view(), count, isa);
            ltc::batch::shade_quad_lights_cosine_lobe(P, N, V, 0.35f, F0, glm::vec3(0.5f), lights, side, d.view(), count,
                                                      isa);
            CHECK(same(c, d));
        }
    // The scalar function, float and double, every horizon-clipping strategy.
    const auto scalar = [&](auto zero) {
        using T = decltype(zero);
        using vec3 = glm::vec<3, T>;
        std::vector<vec3> light;
        for (const auto& p : ltc_test::random_polygon(g, 5, true, false)) light.push_back(vec3(p));
        std::size_t shaded = 0, differs = 0;
        for (const auto clip : {ltc::horizon_clipping::ltc_space, ltc::horizon_clipping::shading_first,
                                ltc::horizon_clipping::sphere_analytic, ltc::horizon_clipping::sphere_table})
            for (const auto side : {ltc::sidedness::one_sided, ltc::sidedness::two_sided})
                for (std::size_t i = 0; i < count; ++i) {
                    const vec3 P(pts.vec(0, i)), N(pts.vec(3, i)), V(pts.vec(6, i)), F0(pts.vec(10, i)),
                        albedo(pts.vec(13, i)), L(radiance);
                    const T r = T(pts.a[9][i]);
                    const auto x = ltc::shade_polygon_light(P, N, V, r, F0, albedo, L, light.data(), 5, side, clip);
                    const auto y =
                        ltc::shade_polygon_light_cosine_lobe(P, N, V, r, F0, albedo, L, light.data(), 5, side, clip);
                    const auto z = ltc::shade_polygon_light_one_lobe(P, N, V, r, F0, albedo, L, light.data(), 5, side, clip);
                    CAPTURE(sizeof(T), static_cast<int>(clip), i);
                    CHECK(x.specular == y.specular);
                    CHECK(x.diffuse == y.diffuse);
                    shaded += x.specular != vec3(T(0));
                    differs += x.specular != z.specular;
                }
        // Not the one-lobe table: nearly every lit point differs (about 97% measured).
        CAPTURE(sizeof(T), shaded, differs);
        CHECK(differs > shaded / 2);
    };
    scalar(0.0f);
    scalar(0.0);
}

}  // namespace ltc_test_batch_shading
