// The derived tolerances of a second float shading path against the scalar ltc::shade, stage by
// stage: the frame (make_shading_frame), the table fetch (ltc_table::fetch) and the lobes'
// shading at given frame and coefficients (ltc::shade_lobes). The batch kernels' lanes
// (tests/test_batch_lanes.cpp, tests/test_batch_shade.cpp) and the GLSL port on a Vulkan device
// (tests/test_glsl_port.cpp) are checked with them.
//
// Every bound is first order in the rounding of one operation. `k` scales it: the largest error
// of one operation of the second path in units of T's unit roundoff u (1: IEEE operations as the
// C++; a GPU's division and square root are allowed more, tests/test_glsl_port.cpp). The
// derivations, for k = 1, are the ones of the files that use them (file comments there).
#pragma once

#include "support/clip_comparison.hpp"
#include "support/rounding_bound.hpp"

#include <ltc/shading/lights/polygon_light.hpp>
#include <ltc/shading/lobes.hpp>
#include <ltc/shading/shading_frame.hpp>
#include <ltc/tables/ltc_table.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace ltc_test::shading_tolerance {

template <typename T>
constexpr double unit_roundoff = std::numeric_limits<T>::epsilon() / 2;

/// x clamped to [0, 1], NaN read as 0 (ltc_table's rule for its inputs).
inline double saturate(double x) { return x > 0 ? (x < 1 ? x : 1) : 0; }

// ---- the frame (tests/test_batch_lanes.cpp's file comment) --------------------------------

inline double cross_bound(double delta_a, double a, double delta_b, double b, double u) {
    return 2 * (delta_a * b + a * delta_b) + 2 * u * a * b;
}

struct frame_bounds {
    double t1, t2, n, cos_theta_v;
};

/// The frame's tolerance for unit-ish N, V, each component: t1, t2, n and cos theta_v.
inline frame_bounds frame(const glm::vec3& N, const glm::vec3& V, double k = 1) {
    const double u = k * unit_roundoff<float>;
    const double delta = 12 * u;
    const glm::dvec3 n = glm::normalize(glm::dvec3(N)), v = glm::normalize(glm::dvec3(V));
    const glm::dvec3 d = glm::dot(n, v) >= 0 ? n - v : n + v;
    const glm::dvec3 w = glm::cross(v, d), t = glm::cross(n, w);
    const double dd = 2 * delta + u * glm::length(d);
    const double dw = std::sqrt(3.0) * cross_bound(delta, 1, dd, glm::length(d), u);
    const double dt = std::sqrt(3.0) * cross_bound(delta, 1, dw, glm::length(w), u);
    frame_bounds f;
    f.n = delta;
    f.t1 = glm::length(t) == 0 ? 8 * delta : 2 * dt / glm::length(t) + delta;
    f.t2 = 2 * (delta + f.t1) + 2 * u;
    f.cos_theta_v = 2 * std::sqrt(3.0) * delta + 6 * u;
    return f;
}

/// The fetch's tolerance for channel c of `table` at (cos theta_v, roughness), both sides given
/// the same cos theta_v: two levels of lerps, 8 u max |node|, plus, where |s - nearest| lies
/// within rounding of the snap tolerance (the table's own, eps of float), the node difference
/// times that tolerance (the two sides may snap differently).
inline double fetch(const ltc::ltc_table& table, float cos_theta_v, float roughness, int c, double k = 1) {
    const double u = k * unit_roundoff<float>;
    const double su = std::sqrt(1.0 - saturate(cos_theta_v)) * (table.width() - 1);
    const double sv = saturate(roughness) * (table.height() - 1);
    const int t0 = std::min(int(su), table.width() - 2), a0 = std::min(int(sv), table.height() - 2);
    double big = 0;
    for (int dt = 0; dt < 2; ++dt)
        for (int da = 0; da < 2; ++da) big = std::max(big, double(std::abs(table.node(t0 + dt, a0 + da, c))));
    const double eps = 0x1.0p-23, w1 = table.width() - 1;
    const double tol_u = eps * (w1 * w1 / std::max(su, 1.0) + 2 * su), tol_v = 4 * eps * sv;
    double snap = 0;
    if (std::abs(std::abs(su - std::floor(su + 0.5)) - tol_u) <= 8 * u * (1 + su)) snap += tol_u * 2 * big;
    if (std::abs(std::abs(sv - std::floor(sv + 0.5)) - tol_v) <= 8 * u * (1 + sv)) snap += tol_v * 2 * big;
    return 8 * u * big + snap;
}

// ---- the lobes' shading (tests/test_batch_shade.cpp's file comment) -------------------------

/// The light's vertices in the order it walks them.
template <typename T>
std::vector<glm::vec<3, T>> walked(const ltc::polygon_light<T>& light) {
    std::vector<glm::vec<3, T>> w;
    for (std::size_t i = 0; i < light.size(); ++i) w.push_back(light.vertex(i));
    return w;
}

/// One lobe at a point shaded in `frame`, the light's vertices `walk` in its walking order,
/// `value` the lobe's own shading: each integral within clip_tolerance plus the local vertices'
/// rounding amplified by M^-1's conditioning, times the lobe's factor, plus 4 u of the value.
template <typename Policy, typename T>
ltc::shading_result<double> lobe(const ltc::shading_frame<T>& frame, const ltc::ltc_coefficients<T>& lobe,
                                 const glm::vec<3, T>& P, const glm::vec<3, T>& F0, const glm::vec<3, T>& albedo,
                                 const glm::vec<3, T>& radiance, const std::vector<glm::vec<3, T>>& walk,
                                 const ltc::shading_result<T>& value, double k = 1) {
    const double u = k * unit_roundoff<T>;
    std::vector<glm::vec<3, T>> local;
    for (const auto& p : walk) local.push_back(frame.to_local(p - P));
    // Each local component within 4 u |p - P| of the exact one on either side, the local
    // directions within 8 sqrt(3) u of each other, moved by M^-1 by its conditioning at the vertex.
    using namespace ltc_test::polygon_integration;
    poly_t q_e, q_i;
    std::vector<double> d_e, d_i;
    const glm::dmat3 m(lobe.m_inv), abs_m = glm::dmat3(glm::abs(m[0]), glm::abs(m[1]), glm::abs(m[2]));
    for (const auto& l : local) {
        const glm::dvec3 ld(l), ql = m * ld;
        q_e.push_back(ld), q_i.push_back(ql);
        d_e.push_back(8 * std::sqrt(3.0));
        d_i.push_back(8 * std::sqrt(3.0) * glm::length(abs_m * glm::abs(ld)) / glm::length(ql));
    }
    const double tol_e = k * ltc_test::clip_tolerance<Policy>(glm::mat<3, 3, T>(T(1)), local) +
                         u * rounding_parts(form::cosine, q_e, d_e, 0).region / (2 * ltc_test::kPi);
    const double tol_i = k * ltc_test::clip_tolerance<Policy>(lobe.m_inv, local) +
                         u * rounding_parts(form::cosine, q_i, d_i, 0).region / (2 * ltc_test::kPi);
    ltc::shading_result<double> t;
    for (int c = 0; c < 3; ++c) {
        const double brdf = std::abs(double(F0[c]) * lobe.magnitude + (1 - double(F0[c])) * lobe.fresnel);
        t.specular[c] = double(radiance[c]) * brdf * tol_i + 4 * u * std::abs(value.specular[c]);
        t.diffuse[c] = double(albedo[c]) * double(radiance[c]) * tol_e + 4 * u * std::abs(value.diffuse[c]);
    }
    return t;
}

/// The lobes of a lobe set, each as one LTC (the cosine's with M^-1 = I, its integral E), in the
/// order ltc::shade_lobes adds them.
template <typename T>
std::vector<ltc::ltc_coefficients<T>> lobe_list(const ltc::lobes::one<T>& c) {
    return {c.ltc};
}
template <typename T>
std::vector<ltc::ltc_coefficients<T>> lobe_list(const ltc::lobes::two<T>& c) {
    return {c.first, c.second};
}
template <typename T>
std::vector<ltc::ltc_coefficients<T>> lobe_list(const ltc::lobes::ltc_and_cosine<T>& c) {
    ltc::ltc_coefficients<T> cosine = c.cosine;
    cosine.m_inv = glm::mat<3, 3, T>(T(1));
    return {cosine, c.ltc};
}

/// A lobe set's shading at `point` with `light`: the lobes' tolerances add, plus 2 u of the sum
/// per added lobe (the diffuse term is the first lobe's).
template <typename Policy, typename T, typename Lobes>
ltc::shading_result<double> lobes(const ltc::shading_point<T>& point, const Lobes& c, const ltc::polygon_light<T>& light,
                                  double k = 1) {
    const double u = k * unit_roundoff<T>;
    const auto walk = walked(light);
    ltc::shading_result<double> tol, sum;
    int l = 0;
    for (const auto& one_lobe : lobe_list(c)) {
        const auto one = ltc::shade_lobes<Policy>(point, ltc::lobes::one<T>{one_lobe}, light, ltc::shade_options{});
        const auto t = lobe<Policy>(point.frame, one_lobe, point.position, point.f0, point.albedo, light.radiance(),
                                    walk, one, k);
        if (l++ == 0) {
            tol = t, sum.specular = glm::dvec3(one.specular);
        } else {
            sum.specular += glm::dvec3(one.specular);
            tol.specular += t.specular + 2 * u * glm::abs(sum.specular);
        }
    }
    return tol;
}

/// How many of the six components of got differ from want by more than tol.
template <typename T>
std::size_t violations(const ltc::shading_result<T>& got, const ltc::shading_result<T>& want,
                       const ltc::shading_result<double>& tol) {
    std::size_t v = 0;
    for (int c = 0; c < 3; ++c) {
        v += !(std::abs(double(got.specular[c]) - want.specular[c]) <= tol.specular[c]);
        v += !(std::abs(double(got.diffuse[c]) - want.diffuse[c]) <= tol.diffuse[c]);
    }
    return v;
}

}  // namespace ltc_test::shading_tolerance
