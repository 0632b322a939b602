// The GLSL port (include/ltc/glsl/ltc_shade.glsl) run as a compute shader (tests/glsl/
// shade_port.comp) on a Vulkan device, against the C++ ltc::shade with ltc::ggx::ltc_and_cosine
// and polygon lights: the random points of the batch tests (tests/support/batch_points.hpp), bad
// input, polygons of 3 to 8 vertices under each facing rule in both vertex orders. Skipped, saying
// so, where no Vulkan device exists (lavapipe, Debian's mesa-vulkan-drivers, is a CPU one).
//
// Tolerance. Stage by stage, each the batch kernels' bound (tests/support/shading_tolerance.hpp)
// with every operation's error k = 9 times float's unit roundoff u: Vulkan's precision table lets
// a division err by 2.5 ulp and inversesqrt by 2, and sqrt inherits from 1 / inversesqrt (4.5 ulp
// = 9 u, the loosest operation the port uses); + - * are correctly rounded, and `precise` forbids
// contraction. The frame against make_shading_frame; the lobes against the C++ fetch at the
// shader's cos theta_v (plus the shift of the node weights that the square root's error makes:
// su = 31 sqrt(1 - c) differs by (k + 3) u su, times the largest step between neighbouring nodes;
// the LTC's matrix channels divided by its magnitude: their relative errors add, plus 2 k u);
// each light's shading at the shader's frame and lobes against ltc::shade_lobes at the same.
// Bad input: exactly the C++'s zeros. Every output finite.
#include "support/batch_points.hpp"
#include "support/clip_comparison.hpp"
#include "support/rng.hpp"
#include "support/shading_tolerance.hpp"
#include "support/vulkan_compute.hpp"

#include <ltc/shading/ggx_cosine_lobe_fetch.hpp>
#include <ltc/shading/ggx_models.hpp>
#include <ltc/shading/lights/polygon_light.hpp>
#include <ltc/shading/shade.hpp>
#include <ltc/tables/ggx_cosine_lobe.hpp>

#include <catch2/catch.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

namespace ltc_test_glsl_port {  // the file's own names, apart from the other files of a unity batch

namespace {

namespace tolerance = ltc_test::shading_tolerance;
using tolerance::saturate;
using Policy = ltc::edge_policy::minimax_rational;  // the port's edge term (float's automatic)
constexpr double k_gpu = 9;                         // file comment
constexpr double u = 0x1.0p-24;
constexpr int point_floats = 20, light_result_floats = 12, light_floats = 44, max_vertices = 8;

std::uint32_t bits(float x) {
    std::uint32_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}
float value(std::uint32_t b) {
    float x;
    std::memcpy(&x, &b, sizeof x);
    return x;
}

enum class facing { emission_normal, clockwise_front, counter_clockwise_front, two_sided };  // the shader's kinds

struct light_case {
    std::vector<glm::vec3> vertices;
    facing f;
    glm::vec3 normal, radiance;
    // The light over `v`, these vertices or their widening to double.
    template <typename T>
    ltc::polygon_light<T> light_over(const std::vector<glm::vec<3, T>>& v) const {
        using vec3 = glm::vec<3, T>;
        switch (f) {
            case facing::emission_normal: return ltc::polygon_light<T>::one_sided(v.data(), v.size(), vec3(normal), vec3(radiance));
            case facing::clockwise_front:
                return ltc::polygon_light<T>::one_sided(v.data(), v.size(), ltc::winding::clockwise_front, vec3(radiance));
            case facing::counter_clockwise_front:
                return ltc::polygon_light<T>::one_sided(v.data(), v.size(), ltc::winding::counter_clockwise_front,
                                                        vec3(radiance));
            case facing::two_sided:
            default: return ltc::polygon_light<T>::two_sided(v.data(), v.size(), vec3(radiance));
        }
    }
    ltc::polygon_light<float> light() const { return light_over(vertices); }
};

// The lobes' coefficients the shader wrote for a point, as the C++ types.
ltc::lobes::ltc_and_cosine<float> lobes_at(const float* o) {
    ltc::lobes::ltc_and_cosine<float> c;
    c.ltc.m_inv = glm::mat3(0.0f);
    c.ltc.m_inv[0][0] = o[11], c.ltc.m_inv[0][2] = o[12], c.ltc.m_inv[2][0] = o[13], c.ltc.m_inv[2][2] = o[14];
    c.ltc.m_inv[1][1] = 1.0f;
    c.ltc.magnitude = o[15], c.ltc.fresnel = o[16];
    c.cosine.magnitude = o[17], c.cosine.fresnel = o[18];
    return c;
}

// The fetch's tolerance for channel c of a lobe table at the shader's (cos theta_v, roughness):
// the shared-weights bound of tolerance::fetch with k, plus the weights' shift (file comment).
double fetch_bound(const ltc::ltc_table& t, float cos_theta_v, float roughness, int c) {
    const double su = std::sqrt(1.0 - saturate(cos_theta_v)) * (t.width() - 1);
    const double sv = saturate(roughness) * (t.height() - 1);
    const int t0 = std::min(int(su), t.width() - 2), a0 = std::min(int(sv), t.height() - 2);
    double step = 0;
    for (int dt = -1; dt < 2; ++dt)  // the neighbouring intervals too: the shift may cross a node
        for (int da = 0; da < 2; ++da) {
            const int a = t0 + dt;
            if (a < 0 || a + 1 >= t.width()) continue;
            step = std::max(step, double(std::abs(t.node(a + 1, a0 + da, c) - t.node(a, a0 + da, c))));
        }
    return tolerance::fetch(t, cos_theta_v, roughness, c, k_gpu) + (k_gpu + 3) * u * su * step;
}

bool is_zero(const ltc::shading_result<float>& r) {
    return r.specular == glm::vec3(0.0f) && r.diffuse == glm::vec3(0.0f);
}
bool same_bits(const ltc::shading_result<float>& a, const ltc::shading_result<float>& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

bool finite(const float* v, int n) {
    for (int i = 0; i < n; ++i)
        if (!std::isfinite(v[i])) return false;
    return true;
}

}  // namespace

TEST_CASE("GLSL port: ltc_shade on a Vulkan device against ltc::shade", "[glsl][shading]") {
    std::string why;
    const auto vk = ltc_test::vulkan::open(why);
    if (!vk) {
        WARN("skipped: no Vulkan device: " << why);
        return;
    }
    INFO("Vulkan device: " << vk->device_name());

    // The points: the batch tests' random ones, then bad input (the C++ shades each to 0).
    const std::size_t random_count = 1031;
    const ltc_test::points_of<float> pts(random_count, 23);
    std::vector<ltc::surface<float>> surfaces;
    for (std::size_t i = 0; i < random_count; ++i)
        surfaces.push_back({pts.vec(0, i), pts.vec(3, i), pts.vec(6, i), pts.a[9][i], pts.vec(10, i), pts.vec(13, i)});
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    const glm::vec3 P(0.1f, -0.2f, 0.05f), N(0.2f, 0.1f, 1.0f), V(0.7f, -0.3f, 0.5f), F0(0.9f, 0.6f, 0.3f), A(0.5f);
    const std::size_t bad_first = surfaces.size();
    for (const auto& bad : {ltc::surface<float>{P, glm::vec3(0.0f), V, 0.5f, F0, A},
                            ltc::surface<float>{P, N, glm::vec3(0.0f), 0.5f, F0, A},
                            ltc::surface<float>{P, glm::vec3(nan, 0, 1), V, 0.5f, F0, A},
                            ltc::surface<float>{P, N, glm::vec3(inf, 0, 1), 0.5f, F0, A},
                            ltc::surface<float>{glm::vec3(0, -inf, 0), N, V, 0.5f, F0, A}})
        surfaces.push_back(bad);
    // Roughness outside [0, 1] or NaN (clamped, NaN as 0), V below the surface, V along -N.
    for (const float r : {nan, -1.0f, 2.0f, 0.0f, 1.0f}) surfaces.push_back({P, N, V, r, F0, A});
    surfaces.push_back({P, N, -V, 0.3f, F0, A});
    surfaces.push_back({P, N, -N, 0.3f, F0, A});
    surfaces.push_back({P, N, N * 3.0f, 0.3f, F0, A});

    // The lights: polygons of 3 to 8 vertices, each facing rule, both orders; a zero-area one.
    ltc_test::rng g(29);
    std::vector<light_case> cases;
    const std::size_t sizes[] = {3, 4, 5, 7, 8, 4};
    int combination = 0;
    for (const facing f : {facing::emission_normal, facing::clockwise_front, facing::counter_clockwise_front,
                           facing::two_sided})
        for (const std::size_t n : sizes) {
            const auto v = ltc_test::random_polygon(g, n, combination % 3 != 0, combination % 2 == 0);
            const glm::vec3 normal(g.direction()), radiance(3.0f, 2.0f, 1.0f);
            cases.push_back({v, f, normal, radiance});
            cases.push_back({std::vector<glm::vec3>(v.rbegin(), v.rend()), f, normal, radiance});
            ++combination;
        }
    cases.push_back({{glm::vec3(0, 0, 1), glm::vec3(1, 0, 1), glm::vec3(2, 0, 1)}, facing::two_sided, glm::vec3(0, 0, 1),
                     glm::vec3(1.0f)});
    const int light_count = static_cast<int>(cases.size());

    // The buffers (the shader's layouts).
    const ltc::ltc_table cosine_table = ltc::ggx_cosine_lobe::lobe_table(0), lobe_table = ltc::ggx_cosine_lobe::lobe_table(1);
    std::vector<std::vector<std::uint32_t>> buffers(4);
    for (std::size_t i = 0; i < std::size(ltc::tables::ggx_cosine_lobe_data); ++i)
        buffers[0].push_back(bits(ltc::tables::ggx_cosine_lobe_data[i]));
    for (const auto& s : surfaces) {
        const float p[16] = {s.position.x, s.position.y, s.position.z, s.normal.x, s.normal.y, s.normal.z,
                             s.view.x,     s.view.y,     s.view.z,     s.roughness, s.f0.x,    s.f0.y,
                             s.f0.z,       s.albedo.x,   s.albedo.y,   s.albedo.z};
        for (const float x : p) buffers[1].push_back(bits(x));
    }
    for (const auto& c : cases) {
        float l[light_floats] = {float(c.vertices.size()), float(static_cast<int>(c.f)), 0, 0,
                                 c.radiance.x, c.radiance.y, c.radiance.z, 0, c.normal.x, c.normal.y, c.normal.z, 0};
        for (std::size_t i = 0; i < c.vertices.size(); ++i)
            for (int k = 0; k < 3; ++k) l[12 + 4 * i + k] = c.vertices[i][k];
        for (const float x : l) buffers[2].push_back(bits(x));
    }
    const std::size_t stride = point_floats + light_result_floats * std::size_t(light_count);
    buffers[3].assign(surfaces.size() * stride, bits(nan));
    const std::vector<std::uint32_t> counts = {std::uint32_t(surfaces.size()), std::uint32_t(light_count)};
    vk->run(ltc_test::vulkan::read_spirv(LTC_SPIRV_SHADE_PORT), buffers, std::uint32_t((surfaces.size() + 63) / 64), counts);
    std::vector<float> out(buffers[3].size());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = value(buffers[3][i]);

    std::size_t checked = 0, frames = 0, nonzero = 0, not_finite = 0, bad_frames = 0, bad_lobes = 0, bad_results = 0,
                not_staged = 0, bad_zero = 0;
    // The largest |GLSL - C++| of a stage over its tolerance; of ltc_shade against ltc::shade,
    // absolute and relative (where the C++ value exceeds 1e-3).
    double worst_ratio = 0, worst_abs = 0, worst_relative = 0;
    std::pair<std::size_t, std::size_t> worst_at{0, 0};  // (point, light)
    std::size_t identical = 0;                            // ltc_shade's bits are ltc::shade's
    double port_vs_double = 0, cpp_vs_double = 0;         // largest relative errors against double
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        const ltc::surface<float>& s = surfaces[i];
        const float* o = &out[i * stride];
        CAPTURE(i);
        for (int l = 0; l < light_count; ++l) not_finite += !finite(o + point_floats + light_result_floats * l + 6, 6);
        const ltc::shading_frame<float> f = ltc::make_shading_frame(s.normal, s.view);
        if (i >= bad_first && i < bad_first + 5) {
            // Bad input: the C++ gives 0 for every light, and so must the port.
            for (int l = 0; l < light_count; ++l) {
                const float* r = o + point_floats + light_result_floats * l;
                CHECK(is_zero(ltc::shade(s, cases[std::size_t(l)].light())));
                for (int k = 6; k < 12; ++k) bad_zero += r[k] != 0.0f;
            }
            continue;
        }
        not_finite += !finite(o, int(stride));  // the stages too, for good input
        // The frame.
        ltc::shading_frame<float> gf;
        gf.t1 = glm::vec3(o[0], o[1], o[2]), gf.t2 = glm::vec3(o[3], o[4], o[5]), gf.n = glm::vec3(o[6], o[7], o[8]);
        gf.cos_theta_v = o[9];
        gf.valid = o[10] != 0.0f;
        REQUIRE(gf.valid == f.valid);
        const tolerance::frame_bounds fb = tolerance::frame(s.normal, s.view, k_gpu);
        const glm::vec3 got[3] = {gf.t1, gf.t2, gf.n}, want[3] = {f.t1, f.t2, f.n};
        const double bound[3] = {fb.t1, fb.t2, fb.n};
        for (int a = 0; a < 3; ++a)
            for (int c = 0; c < 3; ++c) bad_frames += !(std::abs(double(got[a][c]) - want[a][c]) <= bound[a]);
        bad_frames += !(std::abs(double(gf.cos_theta_v) - f.cos_theta_v) <= fb.cos_theta_v);
        ++frames;
        // The lobes, against the C++ fetch at the shader's cos theta_v.
        const ltc::lobes::ltc_and_cosine<float> gc = lobes_at(o);
        const auto cc = ltc::ggx::ltc_and_cosine::fetch<float>(gf.cos_theta_v, s.roughness);
        const double mag_tol = fetch_bound(lobe_table, gf.cos_theta_v, s.roughness, ltc::channel::magnitude);
        const float g_m[4] = {gc.ltc.m_inv[0][0], gc.ltc.m_inv[0][2], gc.ltc.m_inv[2][0], gc.ltc.m_inv[2][2]};
        const float c_m[4] = {cc.ltc.m_inv[0][0], cc.ltc.m_inv[0][2], cc.ltc.m_inv[2][0], cc.ltc.m_inv[2][2]};
        for (int c = 0; c < 4; ++c) {
            const double premultiplied = fetch_bound(lobe_table, gf.cos_theta_v, s.roughness, c);
            const double t = cc.ltc.magnitude > 0
                                 ? (premultiplied + std::abs(c_m[c]) * mag_tol) / cc.ltc.magnitude +
                                       2 * k_gpu * u * std::abs(c_m[c])
                                 : 0.0;
            bad_lobes += !(std::abs(double(g_m[c]) - c_m[c]) <= t);
        }
        bad_lobes += !(std::abs(double(gc.ltc.magnitude) - cc.ltc.magnitude) <= mag_tol);
        bad_lobes += !(std::abs(double(gc.ltc.fresnel) - cc.ltc.fresnel) <=
                       fetch_bound(lobe_table, gf.cos_theta_v, s.roughness, ltc::channel::fresnel));
        bad_lobes += !(std::abs(double(gc.cosine.magnitude) - cc.cosine.magnitude) <=
                       fetch_bound(cosine_table, gf.cos_theta_v, s.roughness, ltc::channel::magnitude));
        bad_lobes += !(std::abs(double(gc.cosine.fresnel) - cc.cosine.fresnel) <=
                       fetch_bound(cosine_table, gf.cos_theta_v, s.roughness, ltc::channel::fresnel));
        // Each light at the shader's frame and lobes.
        const ltc::shading_point<float> point{gf, s.position, s.f0, s.albedo};
        for (int l = 0; l < light_count; ++l) {
            const float* r = o + point_floats + light_result_floats * l;
            const auto light = cases[std::size_t(l)].light();
            ltc::shading_result<float> staged, whole;
            staged.specular = glm::vec3(r[0], r[1], r[2]), staged.diffuse = glm::vec3(r[3], r[4], r[5]);
            whole.specular = glm::vec3(r[6], r[7], r[8]), whole.diffuse = glm::vec3(r[9], r[10], r[11]);
            not_staged += !same_bits(staged, whole);  // ltc_shade is its stages
            const auto want = ltc::shade_lobes<Policy>(point, gc, light, ltc::shade_options{});
            const auto tol = tolerance::lobes<Policy>(point, gc, light, k_gpu);
            const std::size_t v = tolerance::violations(staged, want, tol);
            CAPTURE(l, staged.specular.x, want.specular.x, tol.specular.x, staged.diffuse.x, want.diffuse.x,
                    tol.diffuse.x);
            CHECK(v == 0);
            bad_results += v;
            ++checked;
            for (int c = 0; c < 3; ++c) {
                if (tol.specular[c] > 0)
                    worst_ratio = std::max(worst_ratio, std::abs(double(staged.specular[c]) - want.specular[c]) / tol.specular[c]);
                if (tol.diffuse[c] > 0)
                    worst_ratio = std::max(worst_ratio, std::abs(double(staged.diffuse[c]) - want.diffuse[c]) / tol.diffuse[c]);
            }
            // The whole chain against ltc::shade, and both against ltc::shade in double (the figures
            // of docs/results/glsl_port.md).
            const auto cpp = ltc::shade(s, light);
            identical += same_bits(whole, cpp);
            const std::vector<glm::dvec3> wide(cases[std::size_t(l)].vertices.begin(), cases[std::size_t(l)].vertices.end());
            const auto exact = ltc::shade(ltc::surface<double>{glm::dvec3(s.position), glm::dvec3(s.normal),
                                                               glm::dvec3(s.view), double(s.roughness), glm::dvec3(s.f0),
                                                               glm::dvec3(s.albedo)},
                                          cases[std::size_t(l)].light_over(wide));
            for (int c = 0; c < 3; ++c)
                for (const auto& e : {glm::dvec3(whole.specular[c], cpp.specular[c], exact.specular[c]),
                                      glm::dvec3(whole.diffuse[c], cpp.diffuse[c], exact.diffuse[c])})
                    if (std::abs(e[2]) > 1e-3) {
                        port_vs_double = std::max(port_vs_double, std::abs(e[0] - e[2]) / std::abs(e[2]));
                        cpp_vs_double = std::max(cpp_vs_double, std::abs(e[1] - e[2]) / std::abs(e[2]));
                    }
            for (int c = 0; c < 3; ++c)
                for (const auto& p : {glm::dvec2(whole.specular[c], cpp.specular[c]), glm::dvec2(whole.diffuse[c], cpp.diffuse[c])}) {
                    nonzero += p[1] != 0;
                    worst_abs = std::max(worst_abs, std::abs(p[0] - p[1]));
                    if (std::abs(p[1]) > 1e-3 && std::abs(p[0] - p[1]) / std::abs(p[1]) > worst_relative) {
                        worst_relative = std::abs(p[0] - p[1]) / std::abs(p[1]);
                        worst_at = {i, std::size_t(l)};
                    }
                }
        }
    }
    WARN("GLSL port on " << vk->device_name() << ": " << checked << " (point, light) pairs and " << frames
                         << " frames checked; shading at the shader's frame and lobes within " << worst_ratio
                         << " of the tolerance; ltc_shade against ltc::shade: " << identical
                         << " pairs bit for bit, largest difference " << worst_abs << " absolute, " << worst_relative
                         << " relative (values above 1e-3; point " << worst_at.first << ", light " << worst_at.second
                         << "); largest relative error against ltc::shade in double (values above 1e-3): the port "
                         << port_vs_double << ", ltc::shade in float " << cpp_vs_double);
    CHECK(not_finite == 0);
    CHECK(bad_zero == 0);
    CHECK(bad_frames == 0);
    CHECK(bad_lobes == 0);
    CHECK(bad_results == 0);
    CHECK(not_staged == 0);
    CHECK(nonzero > checked);  // the lights are seen: most pairs shade to something
}

}  // namespace ltc_test_glsl_port
