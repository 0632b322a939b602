// render/shapes.hpp -- the lights of --shapes: a one-sided disk (facing the floor and the camera),
// a sphere and a tube (an open cylinder, glowing all around) above the floor, in front of the
// polygonal lights; and one pixel of their two renders:
//   LTC        ltc::shade<ltc::ggx::one_lobe> with an ltc::disk_light (one-sided), an
//              ltc::sphere_light and an ltc::tube_light, each built once (float; the one-lobe GGX
//              table, Schlick's Fresnel through its magnitude and fresnel terms; specular and
//              diffuse);
//   reference  Monte Carlo of the real GGX (double) by ltc/reference/shape_ground_truth.hpp, as
//              shade_reference.hpp does for the polygons: the specular radiance with Schlick's
//              Fresnel is radiance * (F0 A + (1 - F0) B), A = int rho cos and B = int rho cos
//              (1 - V.H)^5 over the shape (models ltc::brdf::ggx<double> and ggx_schlick_weight,
//              alpha = roughness^2, the table's convention). The diffuse term is a third Monte
//              Carlo integral, D = int cos / pi over the shape (lambert_model below; only where
//              albedo > 0): for the tube the LTC's diffuse is not exact (the ribbon's ends, see
//              ltc/shading/lights/tube_light.hpp), so a closed form would not measure it. BRDF
//              and light sampling, balance heuristic; each pixel, shape and integral has its own
//              seed.
// The shapes are not drawn as emitters and cast no shadows: the camera's floor pixels are those
// of the default render, lit by the three shapes only.
#pragma once

#include "camera.hpp"
#include "common/colour.hpp"
#include "math.hpp"
#include "scene.hpp"
#include "shade_reference.hpp"

#include <ltc/brdf/ggx.hpp>
#include <ltc/reference/shape_ground_truth.hpp>
#include <ltc/shading/ggx_models.hpp>
#include <ltc/shading/lights/disk_light.hpp>
#include <ltc/shading/lights/sphere_light.hpp>
#include <ltc/shading/lights/tube_light.hpp>
#include <ltc/shading/shade.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace render {

/// The three shape lights (world space, z up): their geometry (which the reference integrates) and
/// the library's lights built from it once (which the LTC render shades).
struct shape_lights {
    static constexpr int count = 3;
    const char* names[count] = {"disk", "sphere", "tube"};
    // Disk: one-sided, emitting towards +disk_normal (down towards the floor and the camera).
    vec3 disk_centre{-2.0f, 3.0f, 0.9f};
    vec3 disk_normal = glm::normalize(vec3(0.0f, -1.0f, -0.7f));
    float disk_radius = 0.45f;
    vec3 disk_radiance = vec3(1.00f, 0.80f, 0.55f) * 20.0f;
    // Sphere: glows all around.
    vec3 sphere_centre{0.0f, 3.0f, 0.6f};
    float sphere_radius = 0.3f;
    vec3 sphere_radiance = vec3(0.95f, 0.95f, 1.00f) * 30.0f;
    // Tube: an open cylinder around p0-p1, slightly tilted.
    vec3 tube_p0{1.3f, 3.0f, 0.5f}, tube_p1{2.9f, 3.4f, 0.7f};
    float tube_radius = 0.06f;
    vec3 tube_radiance = vec3(0.55f, 0.75f, 1.00f) * 40.0f;
    // The same three as the library's lights (after the members above, which they are built from).
    ltc::disk_light<float> disk =
        ltc::disk_light<float>::one_sided(disk_centre, disk_normal, disk_radius, disk_radiance);
    ltc::sphere_light<float> sphere{sphere_centre, sphere_radius, sphere_radiance};
    ltc::tube_light<float> tube{tube_p0, tube_p1, tube_radius, tube_radiance};
};

/// Radiance of one floor pixel from shape k (0 disk, 1 sphere, 2 tube): LTC (float).
inline vec3 shade_ltc_shape(const scene& s, const shape_lights& L, const pixel_hit& hit, int k) {
    if (hit.kind != pixel_hit::floor) return vec3(0.0f);
    const material& m = s.materials[static_cast<std::size_t>(hit.material)];
    const ltc::surface<float> point{hit.p, vec3(0, 0, 1), hit.v, m.roughness, m.f0, m.albedo};
    const ltc::shading_result<float> r = k == 0   ? ltc::shade<ltc::ggx::one_lobe>(point, L.disk)
                                         : k == 1 ? ltc::shade<ltc::ggx::one_lobe>(point, L.sphere)
                                                  : ltc::shade<ltc::ggx::one_lobe>(point, L.tube);
    return r.specular + r.diffuse;
}

/// The Lambertian lobe cos / pi as a model of ltc/brdf/model.hpp (cosine sampling).
struct lambert_model {
    static double eval(const dvec3&, const dvec3& L, double) { return L.z > 0 ? L.z / pi : 0.0; }
    static double pdf(const dvec3&, const dvec3& L, double) { return L.z > 0 ? L.z / pi : 0.0; }
    static dvec3 sample(const dvec3&, const glm::dvec2& u, double) {
        const double r = std::sqrt(u.x), phi = 2.0 * pi * u.y;
        return dvec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u.x)));
    }
};

/// One pixel's reference for shape k: its radiance and the variance of its luminance.
struct shape_reference_pixel {
    dvec3 radiance{0.0};
    double variance = 0.0;
};

/// Radiance of one floor pixel from shape k: the Monte Carlo reference (double; file comment).
inline shape_reference_pixel shade_reference_shape(const scene& s, const shape_lights& L, const pixel_hit& hit, int k,
                                                   std::uint64_t pixel_seed, int spp) {
    shape_reference_pixel out;
    if (hit.kind != pixel_hit::floor || spp <= 0) return out;
    const material& m = s.materials[static_cast<std::size_t>(hit.material)];
    const dvec3 P(hit.p), N(0, 0, 1), F0(m.f0), albedo(m.albedo);
    const ltc::shading_frame<double> frame = ltc::make_shading_frame(N, dvec3(hit.v));
    const dvec3 V = frame.to_local(glm::normalize(dvec3(hit.v)));
    const double alpha = double(m.roughness) * double(m.roughness);  // the table's convention
    namespace gt = ltc::ground_truth;
    const auto integrate = [&](const auto& model, std::uint64_t seed) {
        gt::options o;
        o.samples = static_cast<std::uint64_t>(spp);
        o.seed = seed;
        if (k == 0)
            return gt::integrate_disk(model, V, alpha, frame.to_local(dvec3(L.disk_centre) - P),
                                      frame.to_local(dvec3(L.disk_normal)), double(L.disk_radius), false, o);
        if (k == 1)
            return gt::integrate_sphere(model, V, alpha, frame.to_local(dvec3(L.sphere_centre) - P),
                                        double(L.sphere_radius), o);
        return gt::integrate_tube(model, V, alpha, frame.to_local(dvec3(L.tube_p0) - P),
                                  frame.to_local(dvec3(L.tube_p1) - P), double(L.tube_radius), o);
    };
    const dvec3 Le(k == 0 ? L.disk_radiance : k == 1 ? L.sphere_radiance : L.tube_radiance);
    const gt::estimate A = integrate(ltc::brdf::ggx<double>{}, mix_seed(pixel_seed, 0));
    const gt::estimate B = integrate(ggx_schlick_weight{}, mix_seed(pixel_seed, 1));
    out.radiance = Le * (F0 * A.mean + (dvec3(1.0) - F0) * B.mean);
    const double a = luminance(Le * F0), b = luminance(Le * (dvec3(1.0) - F0));
    out.variance = a * a * A.standard_error * A.standard_error + b * b * B.standard_error * B.standard_error;
    if (albedo.r > 0 || albedo.g > 0 || albedo.b > 0) {
        const gt::estimate D = integrate(lambert_model{}, mix_seed(pixel_seed, 2));
        out.radiance += albedo * Le * D.mean;
        const double c = luminance(albedo * Le) * D.standard_error;
        out.variance += c * c;
    }
    return out;
}

}  // namespace render
