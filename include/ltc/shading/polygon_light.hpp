// ltc/shading/polygon_light.hpp -- shading a point with a constant-radiance polygonal light (paper section 5.1;
// Hill and Heitz 2016 for the Fresnel term and the clipless variant).
//
//   #include <ltc/shading/polygon_light.hpp>
//   ltc::polygon_light_result<float> r = ltc::shade_polygon_light(
//       P, N, V, roughness, F0, albedo, radiance, vertices, n, ltc::sidedness::one_sided);
//   glm::vec3 colour = r.specular + r.diffuse;
//
// Inputs, all in world space: the shading point P, the normal N, the direction V towards the eye
// (N and V are normalized here), the roughness (alpha = roughness^2, the convention of the GGX
// table), the specular colour F0, the diffuse albedo, the light's radiance and its n >= 3
// vertices (a simple planar polygon, any n). Outputs:
//
//   diffuse  = albedo * radiance * E(P)                        Lambert: albedo/pi int_P cos dw
//   specular = radiance * (F0 magnitude + (1 - F0) fresnel) * I_ltc(P)
//
// with E the clipped form factor (paper eq. 11, with the chosen edge policy; in the sphere modes
// the clipless approximation) and I_ltc the integral of the LTC
// distribution over the polygon (eq. 3), its coefficients (M^-1, magnitude, fresnel) taken from
// the GGX table at (cos theta_v, roughness). magnitude I_ltc approximates int_P rho cos (the
// fit's error, measured by examples/ggx_error_report.cpp against ltc/reference/ground_truth.hpp).
//
// Frame. The LTC table is fitted in the local frame N = +z, V = (sin theta_v, 0, cos theta_v),
// so the polygon is rotated into (T1, T2, N) with T1 = normalize(V - N (V.N)), T2 = N x T1 (a
// right-handed rotation: orientations are preserved). V - N (V.N) is computed as N x (V x N)
// with a cancellation-free V x N, so T1 is accurate and orthogonal to N even when V is within
// an ulp of N. When V is exactly parallel to N the projection is the zero vector; then any T1
// orthogonal to N is right, because at normal incidence the isotropic lobe is symmetric about
// N, and T1 comes from the branch-free orthonormal basis of Duff et al. 2017 ("Building an
// orthonormal basis, revisited", JCGT 6(1)). cos theta_v = clamp(N.V, 0, 1): a view from below
// the surface (interpolated normals) is shaded as grazing.
//
// Sign convention. A polygon's integrals are signed (polygon.hpp): positive when its vertices
// turn clockwise as seen from the shading point, i.e. when its right-hand normal
// (p1 - p0) x (p2 - p0) points away from P. A one-sided light emits from that front face only
// (max(0, signed)): a light whose vertices appear counter-clockwise from P contributes 0. A
// two-sided light takes |signed|. The same facing test applies to diffuse and specular.
//
// Horizon clipping (horizon_clipping):
//   ltc_space (default)  the paper's order: rotate, apply M^-1, clip to z >= 0 in the LTC's
//                        own space. Exact integral of the LTC distribution D over the polygon.
//                        D is not zero below the shading horizon (M does not map the upper
//                        hemisphere into itself), so the part of a light below the surface
//                        still receives some of the lobe: "leaks" from below.
//   shading_first        clip the polygon to the shading horizon once, in the (T1, T2, N)
//                        frame, before M^-1; the clipped polygon feeds both the diffuse
//                        integral (no second clip needed) and the specular one, which then
//                        applies M^-1 and clips again in LTC space (D_o is a clamped cosine:
//                        without that clip the integral is not D's). Exact integral of D over
//                        the part of the polygon above the surface; nothing leaks from below.
//   sphere_analytic,     Hill's clipless approximation (ltc/shading/clipless.hpp) for both terms: no
//   sphere_table         polygon clipping at all; the analytic or tabulated sphere form factor.
// Which is better where, measured by examples/ggx_error_report.cpp (shipped 64 x 64 GGX table
// against the Monte Carlo ground truth, 720 configurations, 195 of them with a significant
// light straddling the horizon):
//   - lights entirely above the horizon: ltc_space and shading_first are identical (the first
//     clip does nothing); so are all lights at normal incidence (M^-1 then maps the upper
//     hemisphere onto itself).
//   - lights straddling the horizon: the fit underestimates them on average (mean signed
//     error -4.4% with ltc_space); removing the leak lowers the integral further (-5.3%), yet
//     shading_first has the smaller mean absolute error (7.35% against 7.59%): at theta_v = 30
//     deg it is clearly better (mean |error| 1.7% against 2.7%, bias -0.5% against +1.0%), at
//     60 and 80 deg the two are within 0.1%, and configuration by configuration it is the
//     closer one in 85 of 195. The leak itself is small: a light entirely below the horizon
//     (elevation -10 deg) receives at most 7e-4 of the directional albedo from ltc_space.
//   So: ltc_space is the default (the paper's order, the exact integral of the fitted
//   distribution, and the cheapest); shading_first is the better choice where lights often
//   cross the horizon at moderate view angles, where the diffuse term is computed anyway (one
//   clip for both), or where no light from below the surface is acceptable. Skipping the second
//   clip of shading_first (one clip only, integrating the unclamped cosine over M^-1 P) would
//   change results by up to 0.8% of the ground truth in the same grid: it is kept.
//   - sphere_analytic / sphere_table: exact for compact lights well above the horizon, but the
//     sphere stands in for M^-1 P, which a sharp lobe stretches into a large, elongated polygon:
//     on the straddling configurations the sphere differs from exact clipping by 6.2% on average
//     (95th percentile 22%, max 110%; worst at roughness 0.25), and its mean error against the
//     ground truth is 10.7% against 9.4% for ltc_space (relative errors over the 555
//     configurations whose ground truth is at least 1e-3 of the albedo). The table adds at
//     most 2.3e-3 |F|.
// (Figures for the table shipped when this was written; the example prints the current ones.)
//
// Cost and memory: no allocation for any n. ltc_space streams the vertices through the
// library's clipped integrals (vertices transformed on the fly). shading_first streams them
// through two Sutherland-Hodgman stages in sequence, each holding only its first and previous
// vertex (a clip stage needs nothing else: every emitted vertex is consumed at once by the
// next stage, and the closing edges are processed last), so it also runs in O(1) memory.
//
// Degenerate input gives finite results: n < 3, a vertex at the shading point (the light is
// seen edge-on) and N = 0 give 0; a light entirely below the horizon gives 0 diffuse, and 0
// specular except for ltc_space's leak (above).
#pragma once

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/shading/clipless.hpp>
#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/core/polygon.hpp>
#include <ltc/shading/table.hpp>
#include <ltc/core/transformed.hpp>

#include <ltc/shading/ggx_fetch.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <type_traits>

namespace ltc {

/// Where the polygon is clipped to the horizon (file comment).
enum class horizon_clipping { ltc_space, shading_first, sphere_analytic, sphere_table };

/// Specular and diffuse radiance reflected towards V (RGB, or any 3 channels).
template <typename T>
struct polygon_light_result {
    glm::vec<3, T> specular{T(0)};
    glm::vec<3, T> diffuse{T(0)};
};

/// The two integrals behind a result, signed like every polygon integral of the library:
/// form_factor = E (clipped cosine integral / pi), ltc = I_ltc (integral of the LTC over P).
template <typename T>
struct polygon_light_integrals {
    T form_factor{0};
    T ltc{0};
};

/// The local shading frame (T1, T2, N) and cos theta_v of a shading point (file comment).
template <typename T>
struct shading_frame {
    glm::vec<3, T> t1{T(1), T(0), T(0)};
    glm::vec<3, T> t2{T(0), T(1), T(0)};
    glm::vec<3, T> n{T(0), T(0), T(1)};
    T cos_theta_v{1};
    bool valid{true};  ///< false when N is the zero vector

    /// Coordinates of the world-space vector d in the frame: (d.T1, d.T2, d.N).
    LTC_HOST_DEVICE glm::vec<3, T> to_local(const glm::vec<3, T>& d) const {
        return glm::vec<3, T>(glm::dot(d, t1), glm::dot(d, t2), glm::dot(d, n));
    }
};

/// Duff et al. 2017, listing 3: a unit vector orthogonal to the unit vector n, branch-free
/// (copysign), continuous except across n.z = 0's sign change.
template <typename T>
LTC_HOST_DEVICE inline glm::vec<3, T> orthonormal_tangent(const glm::vec<3, T>& n) {
    const T sign = std::copysign(T(1), n.z);
    const T a = T(-1) / (sign + n.z);
    return glm::vec<3, T>(T(1) + sign * n.x * n.x * a, sign * n.x * n.y * a, -sign * n.x);
}

/// The frame of ltc's tables at a shading point: N = +z, V in the half-plane x > 0 of y = 0.
template <typename T>
LTC_HOST_DEVICE inline shading_frame<T> make_shading_frame(const glm::vec<3, T>& N, const glm::vec<3, T>& V) {
    shading_frame<T> f;
    const glm::vec<3, T> n = detail::safe_normalize(N);
    if (n == glm::vec<3, T>(T(0))) {
        f.valid = false;
        return f;
    }
    const glm::vec<3, T> v = detail::safe_normalize(V);
    const T nv = glm::dot(n, v);
    // V - N (V.N) as N x (V x N), with V x N from the cancellation-free cross product of
    // polygon.hpp: accurate relative to its own length even for V within an ulp of +-N, and
    // orthogonal to N to rounding (the plain difference is neither, there).
    glm::vec<3, T> t1 = detail::safe_normalize(glm::cross(n, detail::stable_cross(v, n, nv)));
    if (t1 == glm::vec<3, T>(T(0))) t1 = orthonormal_tangent(n);  // V = +-N exactly (or V = 0)
    f.n = n;
    f.t1 = t1;
    f.t2 = glm::cross(n, t1);
    f.cos_theta_v = glm::clamp(nv, T(0), T(1));
    return f;
}

namespace detail {

/// p / (its largest |coordinate|): the integrals only see directions, and this keeps M^-1 p
/// finite for huge coordinates.
template <typename T>
LTC_HOST_DEVICE inline glm::vec<3, T> rescaled(const glm::vec<3, T>& p) {
    const T s = glm::max(glm::max(std::abs(p.x), std::abs(p.y)), std::abs(p.z));
    return s > T(0) ? p / s : glm::vec<3, T>(T(0));
}

/// Streaming sum of edge_integral_z over a closed polygon given vertex by vertex (unit vectors).
template <typename T, typename Policy = edge_policy::exact>
struct edge_sum {
    glm::vec<3, T> first{T(0)}, prev{T(0)};
    bool started = false;
    T sum{0};
    LTC_HOST_DEVICE void push(const glm::vec<3, T>& q) {
        if (started)
            sum += edge_integral_z<Policy>(prev, q);
        else
            first = q, started = true;
        prev = q;
    }
    LTC_HOST_DEVICE void close() {
        if (started) sum += edge_integral_z<Policy>(prev, first);
    }
};

/// Streaming Sutherland-Hodgman clip of a closed polygon of unit vectors to z >= 0: processes
/// the edges (v0 v1), ..., (v_n-1 v0) as vertices arrive and pushes the clipped polygon's unit
/// vertices to `next` (a cyclic rotation of clip_to_horizon's output, which changes no
/// integral). Crossing points have z exactly 0 (polygon.hpp's division-free construction).
template <typename T, typename Next>
struct clip_stage {
    Next& next;
    glm::vec<3, T> first{T(0)}, prev{T(0)};
    bool started = false;
    LTC_HOST_DEVICE void edge(const glm::vec<3, T>& p, const glm::vec<3, T>& q) {
        const bool p_in = p.z >= T(0), q_in = q.z >= T(0);
        if (p_in != q_in)
            next.push(safe_normalize(p_in ? horizon_crossing_direction(p, q) : horizon_crossing_direction(q, p)));
        if (q_in) next.push(q);
    }
    LTC_HOST_DEVICE void push(const glm::vec<3, T>& q) {
        if (started)
            edge(prev, q);
        else
            first = q, started = true;
        prev = q;
    }
    LTC_HOST_DEVICE void close() {
        if (started) edge(prev, first);
        next.close();
    }
};

/// Applies M^-1 to each unit vertex and forwards the unit result.
template <typename T, typename Next>
struct transform_stage {
    const glm::mat<3, 3, T>& m_inv;
    Next& next;
    LTC_HOST_DEVICE void push(const glm::vec<3, T>& q) { next.push(safe_normalize(m_inv * q)); }
    LTC_HOST_DEVICE void close() { next.close(); }
};

/// Forwards each vertex to two consumers.
template <typename T, typename A, typename B>
struct tee_stage {
    A& a;
    B& b;
    LTC_HOST_DEVICE void push(const glm::vec<3, T>& q) {
        a.push(q);
        b.push(q);
    }
    LTC_HOST_DEVICE void close() {
        a.close();
        b.close();
    }
};

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

}  // namespace detail

/// The signed integrals (form factor E and LTC integral I_ltc) of the world-space polygon
/// vertices[0..n) seen from P in `frame`, for the LTC whose inverse matrix in the local frame
/// is m_inv (any scale, any sign of determinant). Policy evaluates the edge terms (edge_policy;
/// exact by default, minimax_rational for speed at float accuracy).
template <typename Policy = edge_policy::exact, typename T>
LTC_HOST_DEVICE inline polygon_light_integrals<T> integrate_polygon_light(
    const shading_frame<T>& frame, const glm::mat<3, 3, T>& m_inv, const glm::vec<3, T>& P,
    const glm::vec<3, T>* vertices, std::size_t n, horizon_clipping clip = horizon_clipping::ltc_space) {
    using vec3 = glm::vec<3, T>;
    polygon_light_integrals<T> r;
    if (!frame.valid || n < 3) return r;
    // Local coordinates of vertex i: as given (the clipless orientation test needs the planar
    // polygon), and divided by their largest coordinate (the integrals only need directions).
    const auto local_raw = [&](std::size_t i) { return frame.to_local(vec3(vertices[i]) - P); };
    const auto local_at = [&](std::size_t i) { return frame.to_local(detail::rescaled(vec3(vertices[i]) - P)); };
    switch (clip) {
        case horizon_clipping::shading_first:
            return detail::integrals_shading_first<T, Policy>(m_inv, local_at, n, true);
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
            r.form_factor = clipless::detail::integrate_signed<T, Policy>(glm::mat<3, 3, T>(T(1)), T(1), local_raw, n, how, table);
            r.ltc = clipless::detail::integrate_signed<T, Policy>(m_inv, glm::determinant(m_inv), local_raw, n, how, table);
            return r;
        }
        case horizon_clipping::ltc_space:
        default: {
            // The edge terms take unit vertices (M^-1 of any scale may leave M^-1 p far from it),
            // normalized once: before the general path, after the quad path's clip.
            const auto local_dirs = detail::make_directions(local_at);
            const auto ltc_dirs = detail::make_directions([&](std::size_t i) { return m_inv * local_at(i); });
            r.form_factor = clamped_cosine<T, Policy>::signed_integral(local_dirs, n);
            const T s = clamped_cosine<T, Policy>::signed_integral(ltc_dirs, n);
            r.ltc = glm::determinant(m_inv) < T(0) ? -s : s;
            return r;
        }
    }
}

/// Shading with explicit LTC coefficients (m_inv in the local frame of `frame`, magnitude,
/// fresnel; e.g. from ltc::ltc_table::fetch(frame.cos_theta_v, roughness)).
template <typename Policy = edge_policy::exact, typename T>
LTC_HOST_DEVICE inline polygon_light_result<T> shade_polygon_light(
    const shading_frame<T>& frame, const ltc_coefficients<T>& lobe, const glm::vec<3, T>& P,
    const glm::vec<3, T>& F0, const glm::vec<3, T>& albedo, const glm::vec<3, T>& radiance,
    const glm::vec<3, T>* vertices, std::size_t n, sidedness side,
    horizon_clipping clip = horizon_clipping::ltc_space) {
    const polygon_light_integrals<T> I = integrate_polygon_light<Policy>(frame, lobe.m_inv, P, vertices, n, clip);
    polygon_light_result<T> r;
    const glm::vec<3, T> brdf_scale = F0 * lobe.magnitude + (glm::vec<3, T>(T(1)) - F0) * lobe.fresnel;
    r.specular = radiance * brdf_scale * apply_sidedness(I.ltc, side);
    r.diffuse = albedo * radiance * apply_sidedness(I.form_factor, side);
    return r;
}

/// Shading with the library's GGX table: cos theta_v from N and V, the coefficients from
/// ltc::ggx::fetch(cos theta_v, roughness) (alpha = roughness^2).
template <typename Policy = edge_policy::exact, typename T>
inline polygon_light_result<T> shade_polygon_light(const glm::vec<3, T>& P, const glm::vec<3, T>& N,
                                                   const glm::vec<3, T>& V, T roughness, const glm::vec<3, T>& F0,
                                                   const glm::vec<3, T>& albedo, const glm::vec<3, T>& radiance,
                                                   const glm::vec<3, T>* vertices, std::size_t n, sidedness side,
                                                   horizon_clipping clip = horizon_clipping::ltc_space) {
    const shading_frame<T> frame = make_shading_frame(N, V);
    return shade_polygon_light<Policy>(frame, ggx::fetch<T>(frame.cos_theta_v, roughness), P, F0, albedo, radiance, vertices,
                               n, side, clip);
}

}  // namespace ltc
