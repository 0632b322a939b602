// ltc/shading/surface.hpp -- what ltc::shade takes and returns: a shading point with its material
// (surface), the reflected radiance (shading_result), and the per-call options (shade_options).
//
//   ltc::surface<float> s{P, N, V, roughness, F0, albedo};
//   ltc::shading_result<float> r = ltc::shade(s, light);      // ltc/shading/shade.hpp
//   glm::vec3 colour = r.specular + r.diffuse;
//
// Named fields in a fixed order, so a brace list reads as the call of the paper's shader
// (P, N, V, roughness, F0, albedo) and the fields can be set by name when six vec3 in a row
// would invite a swap.
#pragma once

#include <ltc/config.hpp>
#include <ltc/shading/polygon_light_integrals.hpp>  // horizon_clipping

#include <glm/glm.hpp>

#include <cmath>

LTC_NAMESPACE_BEGIN

namespace detail {
template <typename T>
LTC_HOST_DEVICE inline bool finite(const glm::vec<3, T>& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
}  // namespace detail

/// A shading point and its material, in world space.
template <typename T>
struct surface {
    glm::vec<3, T> position{T(0)};  ///< P
    /// N, any length. Zero or not finite: the result is 0 (no frame to shade in).
    glm::vec<3, T> normal{T(0), T(0), T(1)};
    /// V, the direction towards the eye, any length. Zero or not finite: the result is 0. A view
    /// from below the surface (N.V < 0, interpolated normals) is shaded as grazing.
    glm::vec<3, T> view{T(0), T(0), T(1)};
    /// The tables' roughness (GGX alpha = roughness^2), clamped to [0, 1]; NaN reads as 0.
    T roughness{T(0.5)};
    glm::vec<3, T> f0{T(0.04)};     ///< specular colour at normal incidence (any 3 channels)
    glm::vec<3, T> albedo{T(0)};    ///< diffuse albedo (Lambert)
    /// Anisotropic models only (ltc::ggx::anisotropic): the direction of `roughness`, any length,
    /// projected onto N's plane; zero, not finite or parallel to N: a fixed direction of that
    /// plane (make_tangent_frame). Isotropic models ignore it.
    glm::vec<3, T> tangent{T(0)};
    /// Anisotropic models only: the roughness along N x tangent (alpha_y = roughness_bitangent^2;
    /// `roughness` is along the tangent), clamped to [0, 1], NaN read as 0. Isotropic models
    /// ignore it.
    T roughness_bitangent{T(0.5)};
};

/// Specular and diffuse radiance reflected towards V (RGB, or any 3 channels).
template <typename T>
struct shading_result {
    glm::vec<3, T> specular{T(0)};
    glm::vec<3, T> diffuse{T(0)};
};

/// Options of ltc::shade that are not part of the light or the material.
struct shade_options {
    /// Where polygonal lights (polygon_light, the tube light's ribbon) are clipped to the horizon
    /// (ltc/shading/polygon_light_integrals.hpp). The disk, sphere and line lights clip exactly
    /// and ignore it; textured quads clip in LTC space (the paper's order) and ignore it.
    horizon_clipping clip = horizon_clipping::ltc_space;
};

LTC_NAMESPACE_END
