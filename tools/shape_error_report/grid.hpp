// shape_error_report/grid.hpp -- the documented grid (main.cpp's file comment): view angles,
// roughnesses, sizes and placements of the sphere, disk and tube lights, each light's geometry in
// the local frame (N = +z, the shading point at the origin), and slots for the results.
#pragma once

#include <ltc/reference/ground_truth.hpp>  // estimate

#include <glm/glm.hpp>

#include <cmath>
#include <vector>

namespace shape_error_report {

using glm::dvec3;
constexpr double pi = 3.141592653589793;
constexpr double deg = pi / 180.0;

enum shape_id { sphere, disk, tube, shape_count };
const char* const shape_names[shape_count] = {"sphere", "disk", "tube"};

const double thetas[] = {0, 30, 60, 80};
const double roughnesses[] = {0.1, 0.25, 0.5, 1.0};
/// Angular radius (sphere, disk across its tilt axis) or half-length (tube), degrees; index 3 is
/// "close", whose angle follows from the distance (main.cpp).
const double size_angles[] = {2, 10, 30};
const char* const size_names[] = {"2 deg", "10 deg", "30 deg", "close"};
constexpr int size_count = 4;
const char* const placement_names[shape_count][4] = {{"mirror", "side", "straddling", ""},
                                                     {"mirror", "side", "straddling", ""},
                                                     {"mirror-across", "mirror-along", "side", "straddling"}};
constexpr int placement_counts[shape_count] = {3, 3, 4};

constexpr double disk_tilt = 45 * deg;     // between the disk's normal and the direction to it
constexpr double tube_radius = 0.01;       // the thin tube, axis at distance 1 from the point
constexpr double close_sphere = 1.2;       // distance to the centre, in radii
constexpr double close_disk = 0.05;        // distance to the disk's plane, in radii
constexpr double close_tube = 3.0;         // distance to the axis, in radii
constexpr int polygon_sizes[] = {8, 16, 32, 64};

struct config {
    int shape = 0, theta = 0, rough = 0, size = 0, placement = 0;  // indices into the arrays above
    bool inside = false;                       // a sphere containing the point (sanity lines)
    bool straddles = false;                    // partly below the horizon
    dvec3 centre{0}, normal{0};                // sphere, disk; the tube's axis runs p0-p1
    dvec3 p0{0}, p1{0};
    double radius = 0;
    // Results (evaluate.hpp): Monte Carlo truth of the real GGX, and per tube the thin line's
    // (in 1/length: times 2 radius to compare), the cylinder's Lambertian form factor, and the
    // real GGX over the tube's ribbon quad (ltc/shading/tube_light.hpp, two-sided).
    ltc::ground_truth::estimate gt, line, tube_cosine, ribbon_gt;
    double albedo = 0;                     // the table's magnitude
    double ltc = 0, ltc_2017 = 0;          // magnitude * I (shade_*_light, F0 = 1); the 2017 disk
    double polygon[4] = {0, 0, 0, 0};      // disk: magnitude * integrate_disk_polygon, n as above
    double diffuse = 0, diffuse_exact = 0; // E of shade_*_light; its exact value (main.cpp)
    double ribbon = 0, ribbon_diffuse = 0; // tube: shade_tube_light's magnitude * I and E
};

inline dvec3 direction(double azimuth_deg, double elevation_deg) {
    const double a = azimuth_deg * deg, e = elevation_deg * deg;
    return {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

/// The tangents at direction c: `across` horizontal, `up` in the vertical plane of c, towards +z
/// (at the zenith: across = y, up = -x).
inline void tangents(const dvec3& c, dvec3& across, dvec3& up) {
    const dvec3 h = glm::cross(dvec3(0, 0, 1), c);
    across = glm::length(h) > 1e-9 ? glm::normalize(h) : dvec3(0, 1, 0);
    up = glm::cross(c, across);
}

/// The light's angle (degrees): size_angles, or for "close" the one its distance gives.
inline double size_angle(int shape, int size) {
    if (size < 3) return size_angles[size];
    if (shape == sphere) return std::asin(1 / close_sphere) / deg;
    if (shape == disk) return std::atan(1 / close_disk) / deg;
    return 30;  // the close tube: the 30 deg tube, three radii from its axis
}

/// Where the light's centre lies (unit vector); straddling: azimuth 135, elevation half the
/// light's angle, so that about a quarter of it is below the horizon.
inline dvec3 placement_direction(int shape, int placement, double theta, double angle) {
    const dvec3 mirror(-std::sin(theta * deg), 0, std::cos(theta * deg));
    if (shape == tube) placement = placement <= 1 ? 0 : placement - 1;
    switch (placement) {
        case 0: return mirror;
        case 1: return direction(90, 30);
        default: return direction(135, angle / 2);
    }
}

inline config make_config(int shape, int t, int r, int s, int p) {
    config c;
    c.shape = shape, c.theta = t, c.rough = r, c.size = s, c.placement = p;
    const double angle = size_angle(shape, s);
    const dvec3 dir = placement_direction(shape, p, thetas[t], angle);
    dvec3 across, up;
    tangents(dir, across, up);
    if (shape == sphere) {
        // Centre at distance 1: radius sin(angle); close: 1 / 1.2.
        c.centre = dir;
        c.radius = s < 3 ? std::sin(angle * deg) : 1 / close_sphere;
        c.straddles = c.centre.z < c.radius;
    } else if (shape == disk) {
        // Centre at distance 1, normal tilted 45 deg from the point (the disk is seen foreshortened,
        // an ellipse) towards `up` (mirror) or `across` (side, straddling: the close disk's plane then
        // crosses the horizon): radius tan(angle); close: 20 times its plane's distance.
        c.centre = dir;
        c.normal = -(std::cos(disk_tilt) * dir + std::sin(disk_tilt) * (p == 0 ? up : across));
        c.radius = s < 3 ? std::tan(angle * deg) : std::cos(disk_tilt) / close_disk;
        const double rim_drop = c.radius * std::sqrt(glm::max(0.0, 1 - c.normal.z * c.normal.z));
        c.straddles = c.centre.z < rim_drop;
    } else {
        // Axis at distance 1, perpendicular to dir: across (horizontal) or along `up` (mirror-along,
        // straddling); half-length tan(angle); radius 0.01, close: 1/3.
        const dvec3 axis = (p == 1 || p == 3) ? up : across;
        const double half = std::tan(angle * deg);
        c.p0 = dir - half * axis;
        c.p1 = dir + half * axis;
        c.radius = s < 3 ? tube_radius : 1 / close_tube;
        const double drop = c.radius * std::sqrt(glm::max(0.0, 1 - axis.z * axis.z));
        c.straddles = glm::min(c.p0.z, c.p1.z) < drop;
    }
    return c;
}

/// Every configuration: sphere, disk, tube grids, then 16 spheres containing the point.
inline std::vector<config> make_grid() {
    std::vector<config> grid;
    for (int shape = 0; shape < shape_count; ++shape)
        for (int t = 0; t < 4; ++t)
            for (int r = 0; r < 4; ++r)
                for (int s = 0; s < size_count; ++s)
                    for (int p = 0; p < placement_counts[shape]; ++p) grid.push_back(make_config(shape, t, r, s, p));
    for (int t = 0; t < 4; ++t)
        for (int r = 0; r < 4; ++r) {
            config c = make_config(sphere, t, r, 0, 0);
            c.inside = true;
            c.straddles = true;
            c.centre = dvec3(0.3, -0.2, 0.5);
            c.radius = 2;
            grid.push_back(c);
        }
    return grid;
}

}  // namespace shape_error_report
