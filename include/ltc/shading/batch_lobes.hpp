// ltc/shading/batch_lobes.hpp -- the machinery of the GGX batch shading (ltc/shading/batch_shading.hpp,
// batch_cosine_lobe.hpp, batch_two_lobe.hpp): one polygonal light over many shading points with the
// lobes of one or two LTC tables (and the cosine's, integrated as the form factor), many quad lights
// over one point; and shade_polygon_light_with_table, the batch shading with any one-lobe table.
//
// Item i gets what the scalar shading gives for it with horizon_clipping::ltc_space, up to
// rounding (tests/test_batch_shading.cpp derives the tolerance): the frame, the table fetch, the
// form factor E and the LTC integrals of eq. (3). One point per SIMD lane
// (ltc/shading/detail/batch_simd_shading.inc), with the instruction sets of ltc/shading/batch.hpp
// (ltc::batch::isa, run-time dispatch); points the kernel hands back and the last count % width
// go through the scalar function. Policy: as in ltc/shading/batch.hpp (edge_policy::automatic by
// default; policies without a SIMD kernel shade every point with the scalar function).
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/edge_policy.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/shading/detail/batch_simd.hpp>
#include <ltc/shading/batch.hpp>
#include <ltc/shading/batch_soa.hpp>
#include <ltc/shading/polygon_light_radiance.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

LTC_NAMESPACE_BEGIN
namespace batch {

namespace detail {

template <typename T>
inline glm::vec<3, T> item(const T* const (&c)[3], std::size_t i) {
    return glm::vec<3, T>(c[0][i], c[1][i], c[2][i]);
}

template <typename T>
inline void write(const shading_results<T>& out, std::size_t i, const polygon_light_result<T>& r) {
    for (int c = 0; c < 3; ++c) out.specular[c][i] = r.specular[c], out.diffuse[c][i] = r.diffuse[c];
}

}  // namespace detail

namespace detail {

/// The batch shading of one polygonal light with the sum of the LTCs of Lobes tables: the SIMD
/// kernel (ltc/shading/detail/batch_simd_shading.inc) for the full vectors of points, then
/// scalar(frame, i) for the tail and for the points it hands back. With Cosine, tables[0] is the
/// cosine lobe's (ltc/shading/ggx_cosine_lobe_fetch.hpp), integrated as the form factor.
template <typename Policy, int Lobes, bool Cosine = false, typename T, typename Scalar>
void shade_polygon_light_lobes(const ltc_table* const (&tables)[Lobes], const shading_points<T>& points,
                               const glm::vec<3, T>& radiance, const glm::vec<3, T>* vertices, std::size_t n,
                               sidedness side, const shading_results<T>& out, std::size_t count, isa which,
                               Scalar&& scalar) {
    using EdgePolicy = edge_policy::resolve_t<Policy, T>;
    // The light's vertices by axis: on the stack for up to 16 vertices.
    constexpr std::size_t stack = 16;
    T buffer[3][stack];
    std::vector<T> heap(n > stack ? 3 * n : 0);
    T* axis[3] = {buffer[0], buffer[1], buffer[2]};
    if (n > stack) axis[0] = heap.data(), axis[1] = heap.data() + n, axis[2] = heap.data() + 2 * n;
    for (std::size_t k = 0; k < n; ++k)
        for (int c = 0; c < 3; ++c) axis[c][k] = vertices[k][c];
    const shading_light<T> light{axis[0], axis[1], axis[2], n, {radiance.x, radiance.y, radiance.z},
                                 side == sidedness::two_sided};
    std::size_t vectorized = 0;
    if constexpr (simd_policy<EdgePolicy, T>) {
#if LTC_SIMD
        if (n >= 3) switch (resolve(which)) {
                case isa::baseline:
                    vectorized = run_shade_baseline<EdgePolicy, Lobes, Cosine>(tables, light, points, out, count);
                    break;
#if LTC_SIMD_AVX2
                case isa::avx2:
                    vectorized = run_shade_avx2<EdgePolicy, Lobes, Cosine>(tables, light, points, out, count);
                    break;
#endif
#if LTC_SIMD_AVX512
                case isa::avx512:
                    vectorized = run_shade_avx512<EdgePolicy, Lobes, Cosine>(tables, light, points, out, count);
                    break;
#endif
                default: break;
            }
#endif
    }
    (void)which;
    for (std::size_t i = 0; i < count; ++i) {
        if (i < vectorized && !std::isnan(out.specular[0][i])) continue;
        const glm::vec<3, T> N(points.nx[i], points.ny[i], points.nz[i]), V(points.vx[i], points.vy[i], points.vz[i]);
        write(out, i, scalar(make_shading_frame(N, V), i));
    }
}

}  // namespace detail

/// The one-lobe batch shading with any LTC table (ltc/tables/ltc_table.hpp) in place of the GGX table:
/// item i gets ltc::shade_polygon_light(frame, table.fetch(frame.cos_theta_v, roughness), ...)
/// up to rounding (the same kernel).
template <typename Policy = edge_policy::automatic, typename T>
void shade_polygon_light_with_table(const ltc_table& table, const shading_points<T>& points,
                                    const glm::vec<3, T>& radiance, const glm::vec<3, T>* vertices, std::size_t n,
                                    sidedness side, const shading_results<T>& out, std::size_t count,
                                    isa which = isa::automatic) {
    const ltc_table* const tables[1] = {&table};
    // The scalar path: what ltc::shade_polygon_light_one_lobe does, with `table`.
    const auto scalar = [&](const shading_frame<T>& frame, std::size_t i) {
        const glm::vec<3, T> P(points.px[i], points.py[i], points.pz[i]);
        return ltc::shade_polygon_light<Policy>(frame, table.fetch(frame.cos_theta_v, points.roughness[i]), P,
                                                detail::item(points.f0, i), detail::item(points.albedo, i), radiance,
                                                vertices, n, side);
    };
    detail::shade_polygon_light_lobes<Policy, 1>(tables, points, radiance, vertices, n, side, out, count, which, scalar);
}

/// count quad lights: vertex k of light i is (x[k][i], y[k][i], z[k][i]) in world space, its
/// radiance (radiance[0][i], radiance[1][i], radiance[2][i]).
template <typename T>
struct quad_lights {
    const T* x[4] = {};
    const T* y[4] = {};
    const T* z[4] = {};
    const T* radiance[3] = {};
};

namespace detail {

/// shade_quad_lights with `count_lobes` (1 or 2) lobes' coefficients, each with its share in its
/// magnitude and Fresnel term (ltc/shading/ggx_two_lobe_fetch.hpp): one more I_ltc per lobe; and,
/// where `cosine` is given, a cosine lobe (ltc/shading/ggx_cosine_lobe_fetch.hpp) integrated as E.
template <typename Policy, typename T>
void shade_quad_lights_lobes(const glm::vec<3, T>& P, const shading_frame<T>& frame, const ltc_coefficients<T>* lobes,
                             int count_lobes, const glm::vec<3, T>& F0, const glm::vec<3, T>& albedo,
                             const quad_lights<T>& lights, sidedness side, const shading_results<T>& out,
                             std::size_t count, isa which, const ltc_coefficients<T>* cosine = nullptr) {
    using vec3 = glm::vec<3, T>;
    if (!frame.valid) {  // N = 0: nothing to shade, as in ltc::shade_polygon_light
        for (std::size_t i = 0; i < count; ++i) write(out, i, polygon_light_result<T>{});
        return;
    }
    vec3 brdf[2];
    for (int l = 0; l < count_lobes; ++l) brdf[l] = F0 * lobes[l].magnitude + (vec3(T(1)) - F0) * lobes[l].fresnel;
    const vec3 brdf_cosine = cosine ? F0 * cosine->magnitude + (vec3(T(1)) - F0) * cosine->fresnel : vec3(T(0));
    // The lights in the local frame (frame.to_local(p - P)) block by block, then E (M = I) and
    // each lobe's I_ltc (M = its M^-1) through the quad kernel.
    constexpr std::size_t block = 256;
    T x[4][block], y[4][block], z[4][block], E[block], I[2][block];
    for (std::size_t base = 0; base < count; base += block) {
        const std::size_t b = count - base < block ? count - base : block;
        quad_soa<T> soa;
        for (std::size_t k = 0; k < 4; ++k) {
            for (std::size_t j = 0; j < b; ++j) {
                const vec3 d = vec3(lights.x[k][base + j], lights.y[k][base + j], lights.z[k][base + j]) - P;
                x[k][j] = glm::dot(d, frame.t1), y[k][j] = glm::dot(d, frame.t2), z[k][j] = glm::dot(d, frame.n);
            }
            soa.x[k] = x[k], soa.y[k] = y[k], soa.z[k] = z[k];
        }
        soa.m_inv = matrices<T>::same_for_all(glm::mat<3, 3, T>(T(1)));
        integrate_quads<Policy>(soa, E, b, side, which);
        for (int l = 0; l < count_lobes; ++l) {
            soa.m_inv = matrices<T>::same_for_all(lobes[l].m_inv);
            integrate_quads<Policy>(soa, I[l], b, side, which);
        }
        for (std::size_t j = 0; j < b; ++j) {
            const vec3 radiance = item(lights.radiance, base + j);
            T e = E[j], i0 = I[0][j], i1 = count_lobes > 1 ? I[1][j] : T(0);
            const T sum = e + i0 + i1;  // each at most about 1 in size: inf or NaN only from a non-finite term
            if (!(sum - sum == T(0))) {
                // Local coordinates whose products overflow (differences near FLT_MAX: a NaN the
                // fuzzer found): the light again through ltc::integrate_polygon_light, which
                // divides each difference by its largest coordinate (only directions count).
                vec3 quad[4];
                for (std::size_t k = 0; k < 4; ++k)
                    quad[k] = vec3(lights.x[k][base + j], lights.y[k][base + j], lights.z[k][base + j]);
                const polygon_light_integrals<T> first = integrate_polygon_light<Policy>(frame, lobes[0].m_inv, P, quad, 4);
                e = apply_sidedness(first.form_factor, side), i0 = apply_sidedness(first.ltc, side);
                if (count_lobes > 1)
                    i1 = apply_sidedness(integrate_polygon_light<Policy>(frame, lobes[1].m_inv, P, quad, 4).ltc, side);
            }
            polygon_light_result<T> r;
            r.specular = radiance * brdf[0] * i0;
            if (count_lobes > 1) r.specular += radiance * brdf[1] * i1;
            if (cosine) r.specular += radiance * brdf_cosine * e;
            r.diffuse = albedo * radiance * e;
            write(out, base + j, r);
        }
    }
}

}  // namespace detail

}  // namespace batch
LTC_NAMESPACE_END
