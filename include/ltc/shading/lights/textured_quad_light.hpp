// ltc/shading/lights/textured_quad_light.hpp -- textured quad lights (paper sections 5.2-5.4): the
// light's radiance is a 2D colour texture, prefiltered by ltc/shading/light_texture.hpp.
//
//   ltc::light_texture<float> tex(width, height, rgb);               // once per texture
//   glm::vec3 I = ltc::integrate_textured_quad(d, quad, tex);        // ~ int_quad L(w) D(w) dw
//   auto light = ltc::textured_quad_light<float>::one_sided(quad_world, emission_normal, tex);
//   ltc::shading_result<float> r = ltc::shade(surface, light);        // ltc/shading/shade.hpp
//
// Eq. (12)-(14): int_P L D dw ~= I_D I_L, I_D = int_P D dw exact (eq. 3), I_L = int_P L D dw / I_D
// by one trilinear fetch into the prefiltered texture (sections 5.3-5.4), or by exact cells
// (textured_method). Conventions: the corners carry uv (0,0), (1,0), (1,1), (0,1), the texture
// mapped on the parallelogram spanned from corner 0 by corners 1 and 3. Degenerate cases: never
// NaN or Inf for finite input; 0 for a light below the horizon or a quad of zero area; a constant
// texture c gives c I_D exactly, the untextured result.
#pragma once

#include <ltc/config.hpp>

#include <ltc/core/clamped_cosine.hpp>
#include <ltc/shading/light_texture.hpp>
#include <ltc/shading/quick_cells.hpp>
#include <ltc/shading/textured_cells.hpp>
#include <ltc/shading/textured_fetch.hpp>
#include <ltc/core/polygon.hpp>
#include <ltc/shading/shading_frame.hpp>
#include <ltc/shading/lights/light_error.hpp>
#include <ltc/shading/lights/polygon_light.hpp>  // winding, detail::vector_area_x2
#include <ltc/shading/surface.hpp>
#include <ltc/core/transformed.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <limits>

LTC_NAMESPACE_BEGIN

/// I_D I_L (eq. 12-14) for the LTC d and the textured quad: the RGB approximation of
/// int_quad L(w) D(w) dw. Two-sided by default (like transformed::integrate); one_sided gives 0
/// when the quad's vertices turn counter-clockwise as seen from the origin. With L(w) the texture
/// seen through the quad, the integral of L D splits into
///
///   I   = int_P L(w) D(w) dw  ~=  I_D I_L                                              (12)
///   I_D = int_P D(w) dw                   exact: eq. (3), transformed::integrate        (13)
///   I_L = int_P L D dw / int_P D dw       the average colour seen through D             (14)
///
/// and I_L is approximated by one trilinear fetch into the prefiltered texture (section 5.3), at
/// the texture coordinates and filter width of fetch_parameters (ltc/shading/textured_fetch.hpp:
/// section 5.4, eq. 15, and its degenerate cases). Only I_L is approximate: with a constant
/// texture L = c, the fetch returns c exactly and I_D I_L = c I_D is the untextured result
/// (tests/test_textured.cpp checks this bit for bit). I_D is 0 for a light entirely below the
/// horizon (then the result is 0 and nothing is fetched) and finite for a degenerate quad (0 for
/// a zero-area one).
///
/// Known limits of the approximation. The Gaussian stands in for F = D / I_D projected to the
/// texture, which is neither Gaussian nor isotropic; the anisotropy of the texture mapping
/// (sigma is isotropic in uv, so non-square quads are filtered isotropically in uv, not in
/// space) and the variation of the cosine over the polygon are ignored (section 5.4), and the
/// fetch point is the foot of the perpendicular, not where the lobe's energy lands. It fails for
/// a sharp lobe whose highlight falls on a small bright detail (or next to it): fetched at the
/// foot point with a filter of the wrong width and shape, the detail is missed (the result is the
/// background) or smeared over the wrong place. The paper presents I_L as an approximation for
/// this reason; the cell methods (textured_method) integrate the texel-constant texture instead.
/// The methods' errors against Monte Carlo: tools/textured_error_report, and docs/design_notes.md
/// ("Textured polygonal lights").
template <typename T>
inline glm::vec<3, T> integrate_textured_quad(const transformed<clamped_cosine<T>>& d, const glm::vec<3, T> quad[4],
                                              const light_texture<T>& tex, sidedness side = sidedness::two_sided) {
    const T i_d = d.integrate(quad, 4, side);
    if (!(i_d > T(0))) return glm::vec<3, T>(T(0));
    const textured_fetch<T> f = fetch_parameters(d.inverse_matrix(), quad);
    return i_d * tex.lookup(f.uv, tex.lod_for_sigma(f.sigma));
}

/// How the textured integral int_quad L D is computed (the policy of integrate_textured_quad
/// and shade_textured_quad_light): `fetch`, the paper's I_D I_L (integrate_textured_quad);
/// `exact_cells`, the integral of the texel-constant texture over adaptive cells, each cell's I_D
/// exact and its radiance the mean of its texels (ltc/shading/textured_cells.hpp, with an error
/// bound and a budget); `quick_cells`, the real-time improvement on the fetch
/// (ltc/shading/quick_cells.hpp): 16 exact cells and up to 8 of their children in two kernel
/// calls, each leaf its mean, or the paper's fetch at the foot point clamped into it in the (at
/// most) two leaves of largest I_D that are wider than the lobe (docs/textured.md compares the
/// three; docs/design_notes.md, "Textured polygonal lights", against Monte Carlo and in cost).
/// For example, the exact integral over 64 adaptive cells:
///
///   light = ltc::textured_quad_light<float>::one_sided(quad_world, emission_normal, tex,
///                                                      ltc::textured_policy{ltc::textured_method::exact_cells, {64}});
enum class textured_method {
    fetch,        ///< I_D I_L with one prefiltered fetch (sections 5.3-5.4; the default)
    quick_cells,  ///< integrate_quick_cells: 16 to 22 cells, a fetch in the wide ones (docs/textured.md)
    exact_cells,  ///< integrate_textured_cells with textured_policy::budget
};

struct textured_policy {
    textured_method method = textured_method::fetch;
    cell_budget budget{};  ///< exact_cells only: 64 cells by default

    /// The cells of quick_cells' first kernel call (ltc/shading/quick_cells.hpp: the level two
    /// below the last, at most 4 x 4); its second call adds up to 8. quick_cells ignores budget.
    static constexpr std::size_t quick_cells_budget = 16;
};

/// The textured integral by the policy's method: integrate_textured_quad above (fetch), or the
/// cells of tex (ltc/shading/textured_cells.hpp).
template <typename T>
inline glm::vec<3, T> integrate_textured_quad(const transformed<clamped_cosine<T>>& d, const glm::vec<3, T> quad[4],
                                              const light_texture<T>& tex, sidedness side,
                                              const textured_policy& policy) {
    switch (policy.method) {
        case textured_method::quick_cells: return integrate_quick_cells(d, quad, tex, side).value;
        case textured_method::exact_cells: return integrate_textured_cells(d, quad, tex.cells(), side, policy.budget).value;
        default: return integrate_textured_quad(d, quad, tex, side);
    }
}

/// Specular and diffuse radiance reflected towards V by a textured quad light (RGB).
template <typename T>
using textured_light_result = shading_result<T>;

/// The RGB integrals of a textured light: int L cos / pi and int L D (each lobe's).
template <typename T>
struct textured_light_integrals {
    glm::vec<3, T> form_factor{T(0)};
    glm::vec<3, T> ltc{T(0)};
};

/// A textured quad light (integrate_textured_quad) as ltc::shade takes it (ltc/shading/shade.hpp):
///
///   auto light = ltc::textured_quad_light<float>::one_sided(quad, emission_normal, tex);
///   ltc::shading_result<float> r = ltc::shade<ltc::ggx::one_lobe>(surface, light);
///
/// quad[0..3] the world-space corners with uv (0,0), (1,0), (1,1), (0,1), copied into the light;
/// the texture is referred to (it must outlive the light's use) and `policy` picks the textured
/// integral (textured_method; the paper's fetch by default). The corners' order carries the
/// texture's orientation, so it is never changed: a one-sided light whose emission normal points
/// to the side from which the corners turn counter-clockwise tests which side of the quad's plane
/// P lies on (in front: the two-sided integral; behind: 0), the other one keeps the signed
/// integral's facing (ltc/shading/lights/polygon_light.hpp, "Facing"). Checked construction as
/// polygon_light's (ltc::invalid_light).
template <typename T>
class textured_quad_light {
public:
    using vec3 = glm::vec<3, T>;

    static textured_quad_light one_sided(const vec3 quad[4], const vec3& emission_normal, const light_texture<T>& tex,
                                         const textured_policy& policy = {}) {
        if (!detail::finite(emission_normal) || emission_normal == vec3(T(0)))
            throw invalid_light("textured_quad_light::one_sided: the emission normal is zero or not finite");
        const T facing = glm::dot(detail::vector_area_x2(quad, 4), emission_normal);
        if (!(facing != T(0)) && detail::vector_area_x2(quad, 4) != vec3(T(0)))
            throw invalid_light("textured_quad_light::one_sided: the emission normal lies in the quad's plane");
        return textured_quad_light(quad, tex, policy, facing > T(0) ? front::counter_clockwise : front::clockwise);
    }
    static textured_quad_light one_sided(const vec3 quad[4], winding w, const light_texture<T>& tex,
                                         const textured_policy& policy = {}) {
        return textured_quad_light(quad, tex, policy,
                                   w == winding::counter_clockwise_front ? front::counter_clockwise : front::clockwise);
    }
    static textured_quad_light two_sided(const vec3 quad[4], const light_texture<T>& tex,
                                         const textured_policy& policy = {}) {
        return textured_quad_light(quad, tex, policy, front::both);
    }

    const vec3* corners() const { return quad_; }
    const light_texture<T>& texture() const { return *tex_; }
    const textured_policy& policy() const { return policy_; }

    // The light interface of ltc::shade (ltc/shading/lights/polygon_light.hpp), RGB integrals.
    template <typename Policy>
    textured_light_integrals<T> integrals(const shading_frame<T>& frame, const vec3& P, const glm::mat<3, 3, T>& m_inv,
                                          const shade_options& o) const {
        textured_light_integrals<T> I;
        vec3 local[4];
        sidedness side;
        if (!prepare(frame, P, local, side)) return I;
        I.ltc = integrate_textured_quad(transformed<clamped_cosine<T>>::from_inverse(m_inv), local, *tex_, side, policy_);
        I.form_factor = form_factor(local, side, o);
        return I;
    }
    template <typename Policy>
    vec3 ltc_integral(const shading_frame<T>& frame, const vec3& P, const glm::mat<3, 3, T>& m_inv,
                      const shade_options&) const {
        vec3 local[4];
        sidedness side;
        if (!prepare(frame, P, local, side)) return vec3(T(0));
        return integrate_textured_quad(transformed<clamped_cosine<T>>::from_inverse(m_inv), local, *tex_, side, policy_);
    }
    vec3 emitted(const vec3& scale, const vec3& integral) const { return scale * integral; }

private:
    enum class front { clockwise, counter_clockwise, both };

    textured_quad_light(const vec3 quad[4], const light_texture<T>& tex, const textured_policy& policy, front f)
        : tex_(&tex), policy_(policy), front_(f) {
        for (int i = 0; i < 4; ++i) quad_[i] = quad[i];
    }

    // The local corners and the sidedness to integrate with; false when nothing is seen.
    bool prepare(const shading_frame<T>& frame, const vec3& P, vec3 (&local)[4], sidedness& side) const {
        if (!frame.valid) return false;
        for (int i = 0; i < 4; ++i) local[i] = frame.to_local(quad_[i] - P);
        side = front_ == front::clockwise ? sidedness::one_sided : sidedness::two_sided;
        if (front_ == front::counter_clockwise)
            return glm::dot(detail::vector_area_x2(quad_, 4), P - quad_[0]) > T(0);
        return true;
    }
    vec3 form_factor(const vec3 (&local)[4], sidedness side, const shade_options&) const {
        return integrate_textured_quad(transformed<clamped_cosine<T>>::from_inverse(glm::mat<3, 3, T>(T(1))), local, *tex_,
                                       side, policy_);
    }

    vec3 quad_[4];
    const light_texture<T>* tex_;
    textured_policy policy_;
    front front_;
};

LTC_NAMESPACE_END
