// ltc/shading/polygon_light_integrals.hpp -- the two signed integrals behind the shading of a
// polygonal light (paper section 5.1): the form factor E of the polygon (eq. 11) and the
// integral I_ltc of the LTC distribution over it (eq. 3), with one of four horizon-clipping
// strategies (horizon_clipping); ltc/shading/polygon_light.hpp turns them into radiance.
//
//   ltc::polygon_light_integrals<float> I = ltc::integrate_polygon_light(
//       ltc::make_shading_frame(N, V), m_inv, P, vertices, n, ltc::horizon_clipping::ltc_space);
//
// Conventions: world-space vertices seen from P in the shading frame, m_inv the LTC's inverse
// matrix in that frame (any scale, any sign of determinant); the results signed like every
// polygon integral of the library. Degenerate cases: an invalid frame or n < 3 gives 0. No
// allocation for any n (horizon_clipping: how each strategy streams the vertices).
#pragma once

#include <ltc/core/detail/polygon_stages.hpp>  // edge_sum, clip_stage, transform_stage, tee_stage
#include <ltc/shading/shading_frame.hpp>  // shading_frame

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/shading/clipless.hpp>
#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/core/polygon.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <type_traits>

LTC_NAMESPACE_BEGIN

/// Where the polygon is clipped to the horizon:
///   ltc_space (default)  the paper's order: rotate, apply M^-1, clip to z >= 0 in the LTC's
///                        own space. Exact integral of the LTC distribution D over the polygon.
///                        D is not zero below the shading horizon (M does not map the upper
///                        hemisphere into itself), so the part of a light below the surface
///                        still receives some of the lobe: "leaks" from below.
///   shading_first        clip the polygon to the shading horizon once, in the (T1, T2, N)
///                        frame, before M^-1; the clipped polygon feeds both the diffuse
///                        integral (no second clip needed) and the specular one, which then
///                        applies M^-1 and clips again in LTC space (D_o is a clamped cosine:
///                        without that clip the integral is not D's). Exact integral of D over
///                        the part of the polygon above the surface; nothing leaks from below.
///   sphere_analytic,     Hill's clipless approximation (ltc/shading/clipless.hpp) for both terms: no
///   sphere_table         polygon clipping at all; the analytic or tabulated sphere form factor.
/// Lights entirely above the horizon: ltc_space and shading_first are identical (the first clip
/// does nothing); so are all lights at normal incidence (M^-1 then maps the upper hemisphere onto
/// itself). ltc_space is the default (the paper's order, the exact integral of the fitted
/// distribution, and the cheapest); shading_first is the better choice where lights often cross
/// the horizon at moderate view angles, where the diffuse term is computed anyway (one clip for
/// both), or where no light from below the surface is acceptable. sphere_analytic and
/// sphere_table are exact for compact lights well above the horizon, but the sphere stands in for
/// M^-1 P, which a sharp lobe stretches into a large, elongated polygon; the table adds at most
/// 2.3e-3 |F| (ltc/shading/sphere_table.hpp). Their errors against the ground truth:
/// docs/results/ (tools/ggx_error_report); the comparison made when they were written:
/// docs/design_notes.md.
///
/// Cost and memory: no allocation for any n. ltc_space streams the vertices through the
/// library's clipped integrals (vertices transformed on the fly). shading_first streams them
/// through two Sutherland-Hodgman stages in sequence, each holding only its first and previous
/// vertex (a clip stage needs nothing else: every emitted vertex is consumed at once by the
/// next stage, and the closing edges are processed last), so it also runs in O(1) memory.
enum class horizon_clipping { ltc_space, shading_first, sphere_analytic, sphere_table };

/// The two integrals behind a result, signed like every polygon integral of the library:
/// form_factor = E (clipped cosine integral / pi), ltc = I_ltc (integral of the LTC over P).
template <typename T>
struct polygon_light_integrals {
    T form_factor{0};
    T ltc{0};
};

namespace detail {

/// p / (its largest |coordinate|): the integrals only see directions, and this keeps M^-1 p
/// finite for huge coordinates.
template <typename T>
LTC_HOST_DEVICE inline glm::vec<3, T> rescaled(const glm::vec<3, T>& p) {
    const T s = glm::max(glm::max(std::abs(p.x), std::abs(p.y)), std::abs(p.z));
    return s > T(0) ? p / s : glm::vec<3, T>(T(0));
}

/// Calls f with local_at, or, for polygons of at most 8 vertices (quads: the common light), with
/// an accessor of a buffer holding local_at(i) for each i: the edge sums read vertices more than
/// once (the quad path per clip test and edge, and each integral again), and local_at rescales
/// and rotates (3 divisions and a matrix product) each time. The same values either way.
template <typename T, typename LocalAt, typename F>
LTC_HOST_DEVICE inline void with_local_vertices(const LocalAt& local_at, std::size_t n, F&& f) {
    constexpr std::size_t buffered = 8;
    if (n > buffered) return f(local_at);
    glm::vec<3, T> local[buffered];
    for (std::size_t i = 0; i < n; ++i) local[i] = local_at(i);
    // i % buffered == i (i < n <= buffered): the mask only tells the compiler so.
    f([&](std::size_t i) { return local[i % buffered]; });
}

/// shading_first: one clip in the local frame shared by both integrals, then M^-1 and the LTC
/// space clip for the specular one. `clip_in_ltc_space = false` skips the second clip (the
/// integral of the *unclamped* cosine over M^-1 of the clipped polygon: not D's integral, kept
/// for measurements only).
template <typename T, typename Policy = edge_policy::exact, typename LocalAt>
LTC_HOST_DEVICE inline polygon_light_integrals<T> integrals_shading_first(const glm::mat<3, 3, T>& m_inv,
                                                                         const LocalAt& local_at, std::size_t n,
                                                                         bool clip_in_ltc_space = true) {
    polygon_light_integrals<T> r;
    if (n < 3) return r;
    edge_sum<T, Policy> diffuse, specular;
    clip_stage<T, edge_sum<T, Policy>> ltc_clip{specular};
    bool ok = true;
    const auto run = [&](auto& spec_in) {
        transform_stage<T, std::remove_reference_t<decltype(spec_in)>> to_ltc{m_inv, spec_in};
        tee_stage<T, edge_sum<T, Policy>, decltype(to_ltc)> both{diffuse, to_ltc};
        clip_stage<T, decltype(both)> local_clip{both};
        for (std::size_t i = 0; i < n; ++i) {
            const glm::vec<3, T> u = safe_normalize(local_at(i));
            ok = ok && !(u == glm::vec<3, T>(T(0)));
            local_clip.push(u);
        }
        local_clip.close();
    };
    if (clip_in_ltc_space)
        run(ltc_clip);
    else
        run(specular);
    if (!ok) return r;  // a vertex at the shading point: edge-on
    const T det = glm::determinant(m_inv);
    r.form_factor = diffuse.sum / (T(2) * pi<T>());
    r.ltc = (det < T(0) ? -specular.sum : specular.sum) / (T(2) * pi<T>());
    return r;
}

/// integrate_polygon_light over the world-space vertices vertex_at(0..n) (polygon_light reads a
/// caller's vertices in either order through it).
template <typename Policy, typename T, typename VertexAt>
LTC_HOST_DEVICE LTC_INLINE polygon_light_integrals<T> integrate_polygon_light_at(
    const shading_frame<T>& frame, const glm::mat<3, 3, T>& m_inv, const glm::vec<3, T>& P,
    const VertexAt& vertex_at, std::size_t n, horizon_clipping clip) {
    using vec3 = glm::vec<3, T>;
    using EdgePolicy = edge_policy::resolve_t<Policy, T>;
    polygon_light_integrals<T> r;
    if (!frame.valid || n < 3) return r;
    // Local coordinates of vertex i: as given (the clipless orientation test needs the planar
    // polygon), and divided by their largest coordinate (the integrals only need directions).
    const auto local_raw = [&](std::size_t i) { return frame.to_local(vec3(vertex_at(i)) - P); };
    const auto local_at = [&](std::size_t i) { return frame.to_local(detail::rescaled(vec3(vertex_at(i)) - P)); };
    switch (clip) {
        case horizon_clipping::shading_first:
            return detail::integrals_shading_first<T, EdgePolicy>(m_inv, local_at, n, true);
        case horizon_clipping::sphere_analytic:
        case horizon_clipping::sphere_table: {
            const clipless::method how =
                clip == horizon_clipping::sphere_table ? clipless::method::table : clipless::method::analytic;
#if defined(__CUDA_ARCH__)
            const clipless::sphere_table* table = nullptr;  // device code: analytic only
#else
            const clipless::sphere_table* table =
                how == clipless::method::table ? &clipless::sphere_table::instance() : nullptr;
#endif
            r.form_factor = clipless::detail::integrate_signed<T, EdgePolicy>(glm::mat<3, 3, T>(T(1)), T(1), local_raw, n, how, table);
            r.ltc = clipless::detail::integrate_signed<T, EdgePolicy>(m_inv, glm::determinant(m_inv), local_raw, n, how, table);
            return r;
        }
        case horizon_clipping::ltc_space:
        default: {
            // The edge terms take unit vertices (M^-1 of any scale may leave M^-1 p far from it),
            // normalized once: before the general path, after the quad path's clip.
            detail::with_local_vertices<T>(local_at, n, [&](const auto& at) {
                const auto local_dirs = detail::make_directions(at);
                const auto ltc_dirs = detail::make_directions([&](std::size_t i) { return m_inv * at(i); });
                r.form_factor = clamped_cosine<T, EdgePolicy>::signed_integral(local_dirs, n);
                const T s = clamped_cosine<T, EdgePolicy>::signed_integral(ltc_dirs, n);
                r.ltc = glm::determinant(m_inv) < T(0) ? -s : s;
            });
            return r;
        }
    }
}

/// integrate_polygon_light_ltc over vertex_at(0..n).
template <typename Policy, typename T, typename VertexAt>
LTC_HOST_DEVICE inline T integrate_polygon_light_ltc_at(const shading_frame<T>& frame, const glm::mat<3, 3, T>& m_inv,
                                                        const glm::vec<3, T>& P, const VertexAt& vertex_at,
                                                        std::size_t n, horizon_clipping clip) {
    if (clip != horizon_clipping::ltc_space)
        return integrate_polygon_light_at<Policy>(frame, m_inv, P, vertex_at, n, clip).ltc;
    using vec3 = glm::vec<3, T>;
    using EdgePolicy = edge_policy::resolve_t<Policy, T>;
    if (!frame.valid || n < 3) return T(0);
    const auto local_at = [&](std::size_t i) { return frame.to_local(detail::rescaled(vec3(vertex_at(i)) - P)); };
    T s = T(0);
    detail::with_local_vertices<T>(local_at, n, [&](const auto& at) {
        s = clamped_cosine<T, EdgePolicy>::signed_integral(detail::make_directions([&](std::size_t i) { return m_inv * at(i); }), n);
    });
    return glm::determinant(m_inv) < T(0) ? -s : s;
}

}  // namespace detail

/// The signed integrals (form factor E and LTC integral I_ltc) of the world-space polygon
/// vertices[0..n) seen from P in `frame`, for the LTC whose inverse matrix in the local frame
/// is m_inv (any scale, any sign of determinant). Policy evaluates the edge terms (edge_policy;
/// by default `automatic`: minimax_rational in float, exact in double).
template <typename Policy = edge_policy::automatic, typename T>
LTC_HOST_DEVICE inline polygon_light_integrals<T> integrate_polygon_light(
    const shading_frame<T>& frame, const glm::mat<3, 3, T>& m_inv, const glm::vec<3, T>& P,
    const glm::vec<3, T>* vertices, std::size_t n, horizon_clipping clip = horizon_clipping::ltc_space) {
    return detail::integrate_polygon_light_at<Policy>(frame, m_inv, P, [&](std::size_t i) { return vertices[i]; }, n,
                                                      clip);
}

/// I_ltc alone: integrate_polygon_light(...).ltc, the same bits, for a second lobe whose form
/// factor a first call already gave (ltc/shading/two_lobe_polygon_light.hpp). ltc_space skips the
/// form factor's edge sum; the other strategies share one clip between the two integrals and
/// compute both.
template <typename Policy = edge_policy::automatic, typename T>
LTC_HOST_DEVICE inline T integrate_polygon_light_ltc(const shading_frame<T>& frame, const glm::mat<3, 3, T>& m_inv,
                                                     const glm::vec<3, T>& P, const glm::vec<3, T>* vertices, std::size_t n,
                                                     horizon_clipping clip = horizon_clipping::ltc_space) {
    return detail::integrate_polygon_light_ltc_at<Policy>(frame, m_inv, P, [&](std::size_t i) { return vertices[i]; },
                                                          n, clip);
}

LTC_NAMESPACE_END
