// ltc/shading/shadowed_polygon_light.hpp -- the names of the shadowed shading before
// ltc::shade_shadowed<Model> (ltc/shading/shade_shadowed.hpp, which this header includes: the
// estimator, its options, results and callbacks):
//
//   auto r = ltc::shade_polygon_light_shadowed(P, N, V, roughness, F0, albedo, radiance,
//                                              vertices, n, ltc::sidedness::one_sided, visible,
//                                              options);  // options.lobes: the analytic part
//
// is ltc::shade_shadowed<Model>(ltc::surface{P, N, V, roughness, F0, albedo}, light, visible,
// options) with the light of the old sidedness rule (one-sided: the front is the side from which
// the vertices turn clockwise, ltc/shading/lights/polygon_light.hpp) and Model by options.lobes
// (analytic_lobes). The same bits as before for finite input and a roughness in [0, 1]; the bad
// input of ltc::shade (a non-finite position, a zero view vector) now gives 0.
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/shading/ggx_models.hpp>
#include <ltc/shading/lights/polygon_light.hpp>
#include <ltc/shading/polygon_light.hpp>
#include <ltc/shading/cosine_lobe_polygon_light.hpp>
#include <ltc/shading/shade_shadowed.hpp>
#include <ltc/shading/surface.hpp>
#include <ltc/shading/two_lobe_polygon_light.hpp>

#include <glm/glm.hpp>

#include <cstddef>
#include <utility>

LTC_NAMESPACE_BEGIN

/// Deprecated: use ltc::shade_shadowed<Model> (the model decides the lobes).
/// The analytic part of shade_polygon_light_shadowed: ggx::one_lobe, ggx::two_lobes or
/// ggx::ltc_and_cosine:
///   analytic_lobes::one          ltc::ggx::one_lobe (the default here)
///   analytic_lobes::two          ltc::ggx::two_lobes
///   analytic_lobes::cosine_lobe  ltc::ggx::ltc_and_cosine (ltc::shade's default)
enum class analytic_lobes { one, two, cosine_lobe };

/// Deprecated: use ltc::shadow_sampling with ltc::shade_shadowed<Model>.
/// The sample plan and, for shade_polygon_light_shadowed, the analytic part's lobes.
template <typename T>
struct shadow_options : shadow_sampling<T> {
    analytic_lobes lobes = analytic_lobes::one;
};

/// Deprecated: use ltc::shade_shadowed<Model> (ltc/shading/shade_shadowed.hpp).
/// The shadowed shading of the polygon vertices[0..n) with the old sidedness rule, the model by
/// options.lobes (analytic_lobes; the file's first comment).
template <typename T, typename Visible>
shadowed_polygon_light_result<T> shade_polygon_light_shadowed(
    const glm::vec<3, T>& P, const glm::vec<3, T>& N, const glm::vec<3, T>& V, T roughness,
    const glm::vec<3, T>& F0, const glm::vec<3, T>& albedo, const glm::vec<3, T>& radiance,
    const glm::vec<3, T>* vertices, std::size_t n, sidedness side, Visible&& visible,
    const shadow_options<T>& options = {}) {
    const surface<T> s{P, N, V, roughness, F0, albedo};
    const polygon_light<T> light = detail::polygon_light_access<T>::with_sidedness(vertices, n, side, radiance);
    switch (options.lobes) {  // one line per model
        case analytic_lobes::two:
            return shade_shadowed<ggx::two_lobes>(s, light, std::forward<Visible>(visible), options);
        case analytic_lobes::cosine_lobe:
            return shade_shadowed<ggx::ltc_and_cosine>(s, light, std::forward<Visible>(visible), options);
        default:
            return shade_shadowed<ggx::one_lobe>(s, light, std::forward<Visible>(visible), options);
    }
}

LTC_NAMESPACE_END
