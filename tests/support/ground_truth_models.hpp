// Shared pieces of the Monte Carlo ground truth tests (test_ground_truth.cpp,
// test_ground_truth_sampling.cpp): "BRDFs" whose integrals over a polygon have closed forms, and
// test polygons (above the horizon, straddling it, non-convex, both windings).
#pragma once

#include <ltc/reference/ground_truth.hpp>
#include <ltc/ltc.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ltc_test::ground_truth_checks {

using glm::dvec2;
using glm::dvec3;
namespace gt = ltc::ground_truth;
inline constexpr double pi = 3.141592653589793;

/// The clamped cosine as a "BRDF": eval = max(0, L.z) / pi (a white Lambertian, its cosine
/// included), sampled by ltc::clamped_cosine.
struct lambert {
    double eval(const dvec3&, const dvec3& L, double) const { return L.z > 0 ? L.z / ltc::pi<double>() : 0.0; }
    double pdf(const dvec3& V, const dvec3& L, double a) const { return eval(V, L, a); }
    dvec3 sample(const dvec3&, const dvec2& u, double) const { return ltc::clamped_cosine<double>::sample(u); }
};

/// A linearly transformed cosine as the "BRDF" (stateful: called through the instance).
struct ltc_model {
    ltc::transformed<ltc::clamped_cosine<double>> d;
    double eval(const dvec3&, const dvec3& L, double) const { return d.eval(L); }
    double pdf(const dvec3&, const dvec3& L, double) const { return d.pdf(L); }
    dvec3 sample(const dvec3&, const dvec2& u, double) const { return d.sample(u); }
};

/// The constant 1 with uniform sphere sampling: the estimate is the solid angle.
struct constant_one {
    double eval(const dvec3&, const dvec3&, double) const { return 1.0; }
    double pdf(const dvec3&, const dvec3&, double) const { return 1.0 / (4 * ltc::pi<double>()); }
    dvec3 sample(const dvec3&, const dvec2& u, double) const {
        const double z = 1 - 2 * u.x, r = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * ltc::pi<double>() * u.y;
        return {r * std::cos(phi), r * std::sin(phi), z};
    }
};

struct named_polygon {
    const char* name;
    std::vector<dvec3> v;
};

/// Test polygons: above the horizon, straddling it, non-convex (an L and a star), both windings.
inline std::vector<named_polygon> polygons() {
    std::vector<named_polygon> p;
    p.push_back({"quad above", {{-1, 0, 0.5}, {1, 0, 0.5}, {1, 2, 1.5}, {-1, 2, 1.5}}});
    p.push_back({"quad straddling", {{-1, 0, -0.5}, {1, 0, -0.5}, {1, 2, 1.5}, {-1, 2, 1.5}}});
    p.push_back({"triangle straddling, reversed", {{-0.2, 1, 0.6}, {1, 0.3, 1.0}, {-1, -0.5, -0.5}}});
    p.push_back({"small triangle", {{0.3, 0.1, 2}, {0.32, 0.1, 2}, {0.3, 0.12, 2}}});
    // An L-shaped hexagon in the plane z = 1 (non-convex; the fan from vertex 0 has a negative
    // triangle), clockwise as seen from the origin.
    p.push_back({"L shape", {{-1, -1, 1}, {1, -1, 1}, {1, 0, 1}, {0, 0, 1}, {0, 1, 1}, {-1, 1, 1}}});
    // A 5-pointed star in a tilted plane, partly below the horizon.
    std::vector<dvec3> star;
    for (int i = 0; i < 10; ++i) {
        const double phi = ltc::pi<double>() * i / 5, r = i % 2 ? 0.35 : 1.0;
        const dvec2 q(r * std::cos(phi), r * std::sin(phi));
        star.push_back(dvec3(q.x, 0.8 + 0.5 * q.y, 0.3 + q.y));
    }
    p.push_back({"star", star});
    return p;
}

}  // namespace ltc_test::ground_truth_checks
