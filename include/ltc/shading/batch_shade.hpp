// ltc/shading/batch_shade.hpp -- ltc::shade (ltc/shading/shade.hpp) in batches, shaped as a
// renderer's loops: one light over many shading points (a pass over a G-buffer, a light baker's
// texels), and many polygon lights over one point (docs/batches.md).
//
//   ltc::batch::surfaces<float> pts{count, {px, py, pz}, {nx, ny, nz}, {vx, vy, vz},
//                                   roughness, ltc::batch::uniform(F0), ltc::batch::uniform(albedo)};
//   ltc::batch::shading_results<float> out;   // specular[3], diffuse[3]: one array each, count items
//   ltc::batch::shade(pts, quad, out);                          // ltc::ggx::ltc_and_cosine
//   ltc::batch::shade(ltc::surface<float>{P, N, V, roughness, F0, albedo}, lights, out);
//
// Item i is ltc::shade's for point i, or light i's own contribution: specular = sum over the
// model's lobes of L (F0 magnitude + (1 - F0) fresnel) I_lobe, diffuse = L albedo E (I_lobe: eq. 3
// through M^-1; E: eq. 11), to rounding in SIMD lanes, the same bits elsewhere (shade). Bad input
// as ltc::shade: a point not finite, or of zero normal or view, gets 0; polygon_lights' invalid
// emission normals throw ltc::invalid_light.
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/edge_policy.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/shading/batch.hpp>
#include <ltc/shading/batch_lobe_set.hpp>
#include <ltc/shading/batch_soa.hpp>
#include <ltc/shading/detail/batch_simd.hpp>
#include <ltc/shading/ggx_models.hpp>
#include <ltc/shading/lights/polygon_light.hpp>
#include <ltc/shading/lobes.hpp>
#include <ltc/shading/shade.hpp>
#include <ltc/shading/shading_frame.hpp>
#include <ltc/shading/surface.hpp>
#include <ltc/tables/ltc_table.hpp>

#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

LTC_NAMESPACE_BEGIN
namespace batch {

/// The LTC tables a model's lobes are fetched from in SIMD lanes: specialize with
/// `static std::array<ltc_table, lobe_set<C>::tables> of(const Model&)`, C the model's
/// coefficients: the tables of Model::coefficients<T>'s lobe set, in the order and layout
/// ltc::batch::lobe_set names (ltc/shading/batch_lobe_set.hpp); the scalar path uses the model's
/// fetch. Not specialized: no SIMD kernel for the model (ltc::shade point by point). A model with
/// state (a table loaded at run time, as one_lobe_table) is passed to shade as its first argument.
template <typename Model>
struct model_tables {};

template <>
struct model_tables<ggx::one_lobe> {
    static std::array<ltc_table, 1> of(const ggx::one_lobe&) { return {ggx::table}; }
};

template <>
struct model_tables<ggx::ltc_and_cosine> {
    static std::array<ltc_table, 2> of(const ggx::ltc_and_cosine&) {
        return {ggx_cosine_lobe::lobe_table(0), ggx_cosine_lobe::lobe_table(1)};
    }
};

template <>
struct model_tables<ggx::two_lobes> {
    static std::array<ltc_table, 2> of(const ggx::two_lobes&) {
        return {ggx_two_lobe::lobe_table(0), ggx_two_lobe::lobe_table(1)};
    }
};

/// The model of one LTC per node of any ltc_table (ltc/tables/ltc_table.hpp), a view of it:
/// batch::shade(one_lobe_table(table), points, light, out) shades point i as ltc::shade_lobes
/// with lobes::one{table.fetch(cos theta_v, roughness)}.
struct one_lobe_table {
    const ltc_table* table;

    explicit one_lobe_table(const ltc_table& t) : table(&t) {}

    template <typename T>
    using coefficients = lobes::one<T>;
    template <typename T>
    coefficients<T> fetch(T cos_theta_v, T roughness) const {
        return {table->fetch(cos_theta_v, roughness)};
    }
};

template <>
struct model_tables<one_lobe_table> {
    static std::array<ltc_table, 1> of(const one_lobe_table& m) { return {*m.table}; }
};

namespace detail {

template <typename T>
inline void write(const shading_results<T>& out, std::size_t i, const shading_result<T>& r) {
    for (int c = 0; c < 3; ++c) out.specular[c][i] = r.specular[c], out.diffuse[c][i] = r.diffuse[c];
}

template <typename Model, typename = void>
struct has_tables : std::false_type {};
template <typename Model>
struct has_tables<Model, std::void_t<decltype(model_tables<Model>::of(std::declval<const Model&>()))>>
    : std::true_type {};

/// ltc::shade for one item, with the model object's fetch.
template <typename Policy, typename Model, typename T, typename Light>
inline shading_result<T> shade_item(const Model& model, const surface<T>& s, const Light& light,
                                    const shade_options& o) {
    return ltc::detail::shade_model<Policy>(model, s, light, o);
}

/// One polygon light over the full vectors of points, through the SIMD kernel of `which`:
/// returns how many points it wrote (NaN in specular red where it hands one back).
template <typename EdgePolicy, typename Lobes, typename Model, typename T>
std::size_t shade_polygon_lanes(const Model& model, const surfaces<T>& points, const polygon_light<T>& light,
                                const shading_results<T>& out, isa which) {
    static_assert(std::tuple_size<decltype(model_tables<Model>::of(model))>::value == lobe_set<Lobes>::tables,
                  "model_tables<Model>::of: one table per table of the model's lobe set (batch_lobe_set.hpp)");
    std::size_t vectorized = 0;
#if LTC_SIMD
    const auto tables = model_tables<Model>::of(model);
    const ltc_table* table_of[lobe_set<Lobes>::tables];
    for (int l = 0; l < lobe_set<Lobes>::tables; ++l) table_of[l] = &tables[static_cast<std::size_t>(l)];
    // The light's vertices by axis, in the order it walks them: on the stack for up to 16.
    const std::size_t n = light.size();
    constexpr std::size_t stack = 16;
    T buffer[3][stack];
    std::vector<T> heap(n > stack ? 3 * n : 0);
    T* axis[3] = {buffer[0], buffer[1], buffer[2]};
    if (n > stack) axis[0] = heap.data(), axis[1] = heap.data() + n, axis[2] = heap.data() + 2 * n;
    for (std::size_t k = 0; k < n; ++k)
        for (int c = 0; c < 3; ++c) axis[c][k] = light.vertex(k)[c];
    const glm::vec<3, T>& L = light.radiance();
    const shading_light<T> sl{axis[0], axis[1], axis[2], n, {L.x, L.y, L.z}, light.sides() == sidedness::two_sided};
    switch (resolve(which)) {
        case isa::baseline: vectorized = run_shade_baseline<EdgePolicy, Lobes>(table_of, sl, points, out); break;
#if LTC_SIMD_AVX2
        case isa::avx2: vectorized = run_shade_avx2<EdgePolicy, Lobes>(table_of, sl, points, out); break;
#endif
#if LTC_SIMD_AVX512
        case isa::avx512: vectorized = run_shade_avx512<EdgePolicy, Lobes>(table_of, sl, points, out); break;
#endif
        default: break;
    }
#endif
    (void)model, (void)points, (void)light, (void)out, (void)which;
    return vectorized;
}

/// One light over many points (the public shade's comment).
template <typename Policy, typename Model, typename T, typename Light>
void shade_points(const Model& model, const surfaces<T>& points, const Light& light, const shading_results<T>& out,
                  isa which, const shade_options& o) {
    using Lobes = typename Model::template coefficients<T>;
    using EdgePolicy = edge_policy::resolve_t<Policy, T>;
    std::size_t vectorized = 0;
    if constexpr (std::is_same_v<Light, polygon_light<T>> && has_tables<Model>::value &&
                  simd_policy<EdgePolicy, T>) {
        if (o.clip == horizon_clipping::ltc_space && light.size() >= 3)
            vectorized = shade_polygon_lanes<EdgePolicy, Lobes>(model, points, light, out, which);
    }
    (void)which;
    for (std::size_t i = 0; i < points.count; ++i) {
        if (i < vectorized && !std::isnan(out.specular[0][i])) continue;
        write(out, i, shade_item<Policy>(model, points.at(i), light, o));
    }
}

/// reversed[j] = lights.reversed(base + j) for j < b: the sign of each light's facing
/// dot(vector area, emission normal) from the same operations over the block (vectorizable), and
/// lights.reversed itself (its checks, its rounding) for the lights whose facing lies within the
/// rounding bound below of 0 or whose normal is not finite or zero: so the decision is the
/// factory's even where the two roundings differ (FMA contraction).
template <typename T, std::size_t N, std::size_t Block>
void reversed_block(const polygon_lights<T, N>& lights, std::size_t base, std::size_t b, T (&reversed)[Block]) {
    static_assert(N >= 3, "a vector area needs three vertices");
    constexpr T eps = std::numeric_limits<T>::epsilon();
    // ltc::detail::vector_area_x2: a = sum over i of (v[i] - v[0]) x (v[i + 1] - v[0]) (glm's
    // cross), vertex by vertex over the block; `size` sums |v[i] - v[0]|_1 |v[i + 1] - v[0]|_1.
    T a[3][Block], size[Block];
    for (std::size_t j = 0; j < b; ++j) a[0][j] = a[1][j] = a[2][j] = size[j] = T(0);
    const T* const x0 = lights.coordinates(0, 0) + base;
    const T* const y0 = lights.coordinates(1, 0) + base;
    const T* const z0 = lights.coordinates(2, 0) + base;
    for (std::size_t i = 1; i + 1 < N; ++i) {
        const T* const x1 = lights.coordinates(0, i) + base;
        const T* const y1 = lights.coordinates(1, i) + base;
        const T* const z1 = lights.coordinates(2, i) + base;
        const T* const x2 = lights.coordinates(0, i + 1) + base;
        const T* const y2 = lights.coordinates(1, i + 1) + base;
        const T* const z2 = lights.coordinates(2, i + 1) + base;
        for (std::size_t j = 0; j < b; ++j) {
            const T px = x1[j] - x0[j], py = y1[j] - y0[j], pz = z1[j] - z0[j];
            const T qx = x2[j] - x0[j], qy = y2[j] - y0[j], qz = z2[j] - z0[j];
            a[0][j] += py * qz - qy * pz, a[1][j] += pz * qx - qz * px, a[2][j] += px * qy - qx * py;
            size[j] += (std::abs(px) + std::abs(py) + std::abs(pz)) * (std::abs(qx) + std::abs(qy) + std::abs(qz));
        }
    }
    const vec3_field<T>& normals = lights.emission_normals();
    T n[3][Block];
    for (int c = 0; c < 3; ++c) {
        const T* const p = normals.component(c);
        const T value = normals.value[c];
        if (p)
            for (std::size_t j = 0; j < b; ++j) n[c][j] = p[base + j];
        else
            for (std::size_t j = 0; j < b; ++j) n[c][j] = value;
    }
    T clear[Block];
    for (std::size_t j = 0; j < b; ++j) {
        const T facing = a[0][j] * n[0][j] + a[1][j] * n[1][j] + a[2][j] * n[2][j];
        // Either rounding of facing is within 4 (N + 2) eps size |n|_1 of the exact value (the
        // differences, the products and the sums of the area, then the dot product).
        const T bound = T(4 * (N + 2)) * eps * size[j] * (std::abs(n[0][j]) + std::abs(n[1][j]) + std::abs(n[2][j]));
        reversed[j] = facing > T(0) ? T(1) : T(0);
        clear[j] = std::abs(facing) > T(2) * bound && bound < std::numeric_limits<T>::max() ? T(1) : T(0);
    }
    for (std::size_t j = 0; j < b; ++j)
        if (clear[j] == T(0)) reversed[j] = lights.reversed(base + j) ? T(1) : T(0);
}

/// Many polygon lights over one point (the public shade's comment): the frame and the fetch once, each
/// light's vertices in the order it walks them in the local frame (frame.to_local(p - P)), then
/// E (M = I) and each LTC's integral through the kernel of ltc/shading/batch.hpp, block by
/// block; the lights it hands back and the tail through ltc::shade.
template <typename Policy, typename Model, typename T, std::size_t N>
void shade_lights(const Model& model, const surface<T>& s, const polygon_lights<T, N>& lights,
                  const shading_results<T>& out, isa which, const shade_options& o) {
    using vec3 = glm::vec<3, T>;
    using Lobes = typename Model::template coefficients<T>;
    using set = lobe_set<Lobes>;
    using EdgePolicy = edge_policy::resolve_t<Policy, T>;
    const std::size_t count = lights.size();
    vec3 buffer[N];
    const auto scalar = [&](std::size_t j) { write(out, j, shade_item<Policy>(model, s, lights.light(j, buffer), o)); };
    bool simd = simd_policy<EdgePolicy, T> && o.clip == horizon_clipping::ltc_space && N >= 3 &&
                resolve(which) != isa::scalar;
    // ltc::shade's bad input: nothing to shade for any light.
    const bool unshaded = !ltc::detail::finite(s.position) || !ltc::detail::finite(s.normal) ||
                          !ltc::detail::finite(s.view) || s.view == vec3(T(0));
    const shading_point<T> p = ltc::detail::model_shading_point<Model>(s);
    if (unshaded || !p.frame.valid) simd = false;
    if (!simd) {
        for (std::size_t j = 0; j < count; ++j) scalar(j);
        return;
    }
    const Lobes c = ltc::detail::fetch_lobes(model, p, s);
    const auto ltcs = set::ltcs(c);
    vec3 brdf[set::ltc_count];
    for (int l = 0; l < set::ltc_count; ++l) brdf[l] = brdf_scale(s.f0, ltcs[static_cast<std::size_t>(l)]);
    vec3 brdf_cosine(T(0));
    if constexpr (set::cosine) brdf_cosine = brdf_scale(s.f0, set::cosine_lobe(c));
    const bool two_sided = lights.sides() == sidedness::two_sided;
    constexpr std::size_t block = N <= 64 ? 1024 / N / 16 * 16 : 16;
    T x[N][block], y[N][block], z[N][block], E[block], I[set::ltc_count][block];
    const T* xs[N];
    const T* ys[N];
    const T* zs[N];
    for (std::size_t k = 0; k < N; ++k) xs[k] = x[k], ys[k] = y[k], zs[k] = z[k];
    // The walking order of every light, or of each (its factory's decision and checks).
    const bool same_order = lights.same_order_for_all();
    const bool all_reversed = same_order && count > 0 && lights.reversed(0);
    T reversed[block];
    for (std::size_t base = 0; base < count; base += block) {
        const std::size_t b = count - base < block ? count - base : block;
        if (!same_order) reversed_block(lights, base, b, reversed);
        // Vertex k of each light's walk (where reversed: its vertex N - 1 - k), then
        // frame.to_local(p - P), axis by axis over the block.
        for (std::size_t k = 0; k < N; ++k) {
            const std::size_t r = N - 1 - k;
            for (int c = 0; c < 3; ++c) {
                T* const to = c == 0 ? x[k] : c == 1 ? y[k] : z[k];
                const T* const forward = lights.coordinates(c, k) + base;
                const T* const backward = lights.coordinates(c, r) + base;
                if (same_order) {
                    const T* const from = all_reversed ? backward : forward;
                    for (std::size_t j = 0; j < b; ++j) to[j] = from[j];
                } else {
                    for (std::size_t j = 0; j < b; ++j) {  // both loaded: a select, the loop vectorizes
                        const T f = forward[j], g = backward[j];
                        to[j] = reversed[j] != T(0) ? g : f;
                    }
                }
            }
            T* const lx = x[k];
            T* const ly = y[k];
            T* const lz = z[k];
            for (std::size_t j = 0; j < b; ++j) {
                const vec3 d = vec3(lx[j], ly[j], lz[j]) - s.position;
                lx[j] = glm::dot(d, p.frame.t1), ly[j] = glm::dot(d, p.frame.t2), lz[j] = glm::dot(d, p.frame.n);
            }
        }
        const std::size_t vectorized = integrate_vectorized<EdgePolicy, N>(
            matrices<T>::same_for_all(glm::mat<3, 3, T>(T(1))), N, xs, ys, zs, E, b, two_sided, which);
        for (int l = 0; l < set::ltc_count; ++l)
            integrate_vectorized<EdgePolicy, N>(matrices<T>::same_for_all(ltcs[static_cast<std::size_t>(l)].m_inv), N,
                                                xs, ys, zs, I[l], b, two_sided, which);
        for (std::size_t j = 0; j < b; ++j) {
            bool handed_back = j >= vectorized || std::isnan(E[j]);
            for (int l = 0; l < set::ltc_count; ++l) handed_back = handed_back || std::isnan(I[l][j]);
            if (handed_back) {
                scalar(base + j);
                continue;
            }
            // ltc::shade_lobes's terms in its order (light.emitted: radiance * scale * integral).
            const vec3 L = lights.radiances().at(base + j);
            shading_result<T> r;
            r.specular = L * brdf[0] * I[0][j];
            r.diffuse = L * s.albedo * E[j];
            for (int l = 1; l < set::ltc_count; ++l) r.specular += L * brdf[l] * I[l][j];
            if constexpr (set::cosine) r.specular += L * brdf_cosine * E[j];
            write(out, base + j, r);
        }
    }
}

}  // namespace detail

/// One light over count points: out item i = ltc::shade<Model, Policy>(points.at(i), light,
/// options) up to rounding, e.g. ltc::batch::shade<ltc::ggx::two_lobes>(pts, quad, out, isa::avx2).
/// A model with state: the overload taking it first.
///
/// Which items run in SIMD lanes (ltc/shading/batch.hpp: the instruction sets, isa, run-time
/// dispatch), and how close they are:
///   - polygon lights (ltc::polygon_light: one-sided by emission normal in either vertex order or
///     by winding, or two-sided) with the models of ltc/shading/ggx_models.hpp, one_lobe_table, or
///     a user's model with a model_tables specialization: one point per lane (ltc/shading/detail/
///     batch_simd_shading.inc). Such an item differs from ltc::shade's by rounding only, within the
///     tolerance tests/test_batch_shading.cpp derives (the integrals' clip tolerance of
///     tests/test_batch.cpp plus the local vertices' rounding amplified by M^-1's conditioning; the
///     lanes' frame and fetch within tests/test_batch_lanes.cpp's bounds), float and double
///     (tests/test_batch_shade.cpp).
///   - the items the kernel hands back (tiny or huge coordinates, V within rounding of N, an edge
///     through the point: ltc/shading/detail/lanes.inc), the last count % width, isa::scalar,
///     edge policies without a SIMD kernel (edge_policy::exact, the default in double:
///     ltc/shading/batch.hpp), clippings other than horizon_clipping::ltc_space, and a light of
///     fewer than 3 vertices go through ltc::shade itself: the same bits (where the compiler
///     contracts no a * b + c into an FMA on its own: the CMake option LTC_FP_CONTRACT_OFF).
///   - every other light (disk_light, sphere_light, line_light, tube_light, textured_quad_light,
///     a user's) and models without tables: ltc::shade point by point, no SIMD (the same bits).
///
/// Both shapes give item i as
///
///   specular = sum over the model's lobes  L (F0 magnitude + (1 - F0) fresnel) I_lobe
///   diffuse  = L albedo E
///
/// with I_lobe the lobe's integral over the light (eq. 3 through its M^-1; the cosine lobe's is
/// E) and E the clamped cosine's (eq. 11), the light's facing applied (ltc/shading/lobes.hpp).
///
/// Bad input, as ltc::shade: a point whose position, normal or view is not finite, or whose normal
/// or view is zero, gets 0 (specular and diffuse), in the SIMD lanes too; the roughness is clamped
/// to [0, 1], NaN read as 0.
template <typename Model = ggx::ltc_and_cosine, typename Policy = edge_policy::automatic, typename T, typename Light>
void shade(const surfaces<T>& points, const Light& light, const shading_results<T>& out, isa which = isa::automatic,
           const shade_options& options = {}) {
    detail::shade_points<Policy>(Model{}, points, light, out, which, options);
}

/// The same with a model object (its fetch and model_tables read it).
template <typename Model, typename Policy = edge_policy::automatic, typename T, typename Light>
void shade(const Model& model, const surfaces<T>& points, const Light& light, const shading_results<T>& out,
           isa which = isa::automatic, const shade_options& options = {}) {
    detail::shade_points<Policy>(model, points, light, out, which, options);
}

/// count = lights.size() polygon lights over one point: out item i =
/// ltc::shade<Model, Policy>(point, lights.light(i, buffer), options), light i's own contribution
/// (sum them for the point's radiance), e.g. with
/// `auto lights = ltc::batch::polygon_lights<float>::one_sided(count, x, y, z, normals, radiances)`.
/// In SIMD lanes (the first overload's comment: which lights, models and policies, how close): the
/// frame and the fetch once, each light's vertices in the order its factory walks them, and the
/// lights' integrals through the kernel of ltc/shading/batch.hpp, one light per lane. Bad input:
/// the first overload's; polygon_lights checks each light as its ltc::polygon_light factory does:
/// shade throws ltc::invalid_light for an emission normal that is zero, not finite or in the
/// light's plane (out is then partly written).
template <typename Model = ggx::ltc_and_cosine, typename Policy = edge_policy::automatic, typename T, std::size_t N>
void shade(const surface<T>& point, const polygon_lights<T, N>& lights, const shading_results<T>& out,
           isa which = isa::automatic, const shade_options& options = {}) {
    detail::shade_lights<Policy>(Model{}, point, lights, out, which, options);
}

/// The same with a model object.
template <typename Model, typename Policy = edge_policy::automatic, typename T, std::size_t N>
void shade(const Model& model, const surface<T>& point, const polygon_lights<T, N>& lights,
           const shading_results<T>& out, isa which = isa::automatic, const shade_options& options = {}) {
    detail::shade_lights<Policy>(model, point, lights, out, which, options);
}

}  // namespace batch
LTC_NAMESPACE_END
