// render -- a small CPU renderer: LTC shading of polygonal lights next to its Monte Carlo reference.
//
//   render [--width W] [--height H] [--spp N] [--threads K] [--out DIR] [--exposure E]
//          [--seed S] [--texture FILE | --no-texture] [--texture-radiance R] [--help]
//
// The scene (z up): a tiled ground plane seen by a pinhole camera 2.8 units above it, lit by two
// one-sided, constant-radiance polygonal lights standing behind the floor, facing the camera and
// tilted 10 degrees towards the floor: a warm 1.2 x 3.4 rectangle leaning 20 degrees (rotated in
// its own plane; left) and a cool irregular pentagon (right); and between them a one-sided
// textured quad light (paper sections 5.2-5.4) in the same plane: by default a procedural
// stained-glass window (192 x 256 texels, generated here: a pointed arch of coloured glass
// cells and a rose, joined by dark lead lines, on a black -- non-emitting -- surround), or any
// image given by --texture (loaded with stb_image). The lights are drawn as emitters where the
// camera sees them (their radiance, the textured one with its texture, the same in both
// renders); there are no shadows (nothing in the scene can occlude a light).
//
// Floor layout: four material stripes running away from the camera, crossed by five bands of
// roughness, so that each light's reflection runs along a stripe boundary through every band:
//   stripes, left to right   dielectric | gold | dielectric | copper
//                            (the rectangle's reflection straddles the first boundary, the
//                            textured light's the middle one, the pentagon's the last one)
//   bands, near to far       roughness 0.9, 0.7, 0.5, 0.3, 0.1 (alpha = roughness^2)
//   dielectric: F0 = 0.04 and a Lambertian albedo 0.5; gold, copper: coloured F0, no diffuse;
//   thin grout lines between the tiles (a rough, dark dielectric).
// The camera sees the floor at theta_v = 50 to 76 degrees from its normal: grazing angles, where
// the fitted LTC table is least accurate (see the README's error table).
//
// Images, written into --out (default: the current directory):
//   ltc.png        per pixel and light, ltc::shade_polygon_light (specular + diffuse; default
//                  horizon clipping, one-sided): the GGX LTC table, the exact polygon integral,
//                  Schlick's Fresnel through the table's magnitude and fresnel terms (Hill
//                  2016); for the textured light ltc::shade_textured_quad_light (the same table
//                  and Fresnel, I_D I_L: the exact polygon integral times one trilinear fetch
//                  into the prefiltered ltc::light_texture, specular and diffuse). float.
//   reference.png  the same GGX BRDF integrated without approximation: for every pixel and
//                  polygonal light, two Monte Carlo integrals by ltc::ground_truth::integrate
//                  (BRDF sampling of visible normals + uniform spherical-polygon sampling, balance
//                  heuristic, one direction from each technique per iteration, --spp iterations
//                  each),
//                      A = int_P rho cos dL                 (model ltc::brdf::ggx<double>)
//                      B = int_P rho cos (1 - V.H)^5 dL      (the same, times Schlick's weight)
//                  so that the specular radiance with Schlick's Fresnel is exactly
//                  radiance * (F0 A + (1 - F0) B); the diffuse term is the closed-form
//                  clipped form factor (ltc::form_factor, exact: no approximation to measure
//                  there). For the textured light, ltc::textured_ground_truth::integrate of the
//                  real (unfiltered, bilinearly interpolated) texture, --spp iterations:
//                      S = int_Q L(w) F(V, w) rho cos dw   (lobe brdf_lobe<ggx<double>>, RGB)
//                      D = int_Q L(w) cos / pi dw          (lobe ltc_lobe, M = I: the clamped
//                                                           cosine; only where albedo > 0)
//                  radiance S + albedo D. The estimator weights each sample by a scalar lobe
//                  times the RGB radiance callback L(u, v); Schlick's Fresnel
//                  F = F0 + (1 - F0) (1 - V.H)^5 depends on the direction only, and on the quad
//                  each (u, v) is one direction w = x(u, v) / |x(u, v)|, so the callback returns
//                  L(u, v) F(V, w(u, v)): the same Fresnel as F0 A + (1 - F0) B above, in one
//                  integral, exactly. The directions come from GGX (visible normals) or cosine
//                  sampling and from area sampling of the quad proportional to half uniform,
//                  half texel luminance (texel_distribution: no samples wasted on black texels),
//                  balance heuristic. The diffuse term is sampled too: unlike the constant
//                  lights, int L cos over a texture has no closed form. double. Deterministic:
//                  every pixel, light, integral (and, for the textured light, iteration) has its
//                  own seed, so the image is the same whatever the thread count.
//   error.png      false colour of the relative error of luminance,
//                      e = |Y_ltc - Y_ref| / max(Y_ref, floor),  floor = 0.01 / exposure,
//                  on a fixed scale: 0% dark blue, 5% blue, 10% green, 15% yellow, 20% and
//                  above red. Background and emitters are black.
//   textured_error.png  (with the textured light) the same for the textured light's contribution
//                  alone, |Y_ltc,tex - Y_ref,tex| / max(Y_ref,tex, floor).
//
// Both renders are tone mapped identically: radiance * exposure, the ACES filmic curve of
// Narkowicz 2015 per channel, clamp to [0, 1], sRGB encoding. One camera ray through each
// pixel centre (no antialiasing: tile edges alias, identically in both images).
//
// Printed: the time of each render and their ratio; error statistics of the LTC render over the
// floor pixels whose reference luminance is at least the floor (mean signed and mean, median,
// 95th percentile and max absolute relative error; mean per tile), the reference's own Monte
// Carlo noise (relative standard error of Y_ref: mean, median, 95th percentile, max) and the
// share of pixels where the LTC differs from the reference by more than 3 standard errors (where
// the difference is the LTC's, not the noise's); the count of non-finite values (expected 0,
// replaced by black and left out of the statistics). With the textured light, these statistics
// come three times: for all lights (the images), for the two polygonal lights alone (the same
// numbers, seeds and images as --no-texture, which renders the scene without the textured
// light), and for the textured light's contribution alone (the floor is then Y_ref,tex >=
// 0.01 / exposure). For the textured light the standard error of Y_ref is exact: the
// luminance of every iteration's RGB value (specular + albedo x diffuse) enters the variance.
// Exit status 0, or 1 if an image could not be written or read or a value was not finite, 2
// for bad arguments. A progress bar with an ETA for the reference render goes to stderr.
//
// Dependencies: GLM, stb_image_write and stb_image (Debian: libstb-dev, <stb/stb_image_write.h>,
// <stb/stb_image.h>).
#include <ltc/fitting/brdf/ggx.hpp>
#include <ltc/reference/ground_truth.hpp>
#include <ltc/shading/light_texture.hpp>
#include <ltc/core/polygon.hpp>
#include <ltc/shading/polygon_light.hpp>
#include <ltc/shading/textured_light.hpp>
#include <ltc/reference/textured_ground_truth.hpp>

#include <glm/glm.hpp>

// stb_image_write and stb_image (one translation unit holds their implementations). GCC 12 and Clang 14 give no
// warning for it under -Wall -Wextra -Wpedantic; older or newer releases of the header have
// tripped these, so they are silenced for the header only.
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#endif
#if defined(_MSC_VER)
#pragma warning(push, 0)
#endif
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
#if defined(_MSC_VER)
#pragma warning(pop)
#endif
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

using glm::dvec3;
using glm::vec3;
constexpr double pi = 3.141592653589793;
constexpr double deg = pi / 180.0;

// ------------------------------------------------------------------------------------------------
// Options

struct options {
    int width = 256;
    int height = 160;
    int spp = 2048;  // MIS iterations per pixel, light and integral
    unsigned threads = 0;  // 0: all hardware threads
    std::string out = ".";
    double exposure = 1.0;
    std::uint64_t seed = 1;
    bool textured = true;      // the textured light (--no-texture: the two polygonal lights only)
    std::string texture;       // image file of the textured light; empty: the stained glass
    double texture_radiance = 8.0;  // radiance of a white texel
};

void print_help(const char* argv0) {
    std::printf(
        "usage: %s [--width W] [--height H] [--spp N] [--threads K] [--out DIR] [--exposure E]\n"
        "          [--seed S] [--texture FILE | --no-texture] [--texture-radiance R] [--help]\n"
        "\n"
        "Renders a tiled floor (GGX dielectric, gold and copper; roughness 0.1 .. 0.9) lit by a\n"
        "rotated rectangular light, a pentagonal light and, between them, a textured quad light (a\n"
        "procedural stained-glass window, or FILE), twice: with LTC (ltc::shade_polygon_light;\n"
        "ltc::shade_textured_quad_light, the prefiltered-texture fetch I_D I_L) and with a Monte\n"
        "Carlo reference of the same GGX BRDF with Schlick's Fresnel (ltc::ground_truth::integrate,\n"
        "BRDF and light sampling with MIS, the diffuse term in closed form; for the textured light\n"
        "ltc::textured_ground_truth::integrate of the unfiltered texture, specular and diffuse), and\n"
        "writes into DIR:\n"
        "  ltc.png             the LTC render\n"
        "  reference.png       the Monte Carlo reference\n"
        "  error.png           relative error of luminance, |Y_ltc - Y_ref| / max(Y_ref, 0.01 / E), on\n"
        "                      a fixed scale: 0%% dark blue, 5%% blue, 10%% green, 15%% yellow, 20%% and\n"
        "                      above red; background and emitters black\n"
        "  textured_error.png  the same for the textured light's contribution alone (not written\n"
        "                      with --no-texture)\n"
        "It prints the render times, error statistics over the floor pixels with Y_ref >= 0.01 / E\n"
        "(mean, median, 95th percentile, max; per tile) and the reference's own Monte Carlo noise:\n"
        "for all lights, for the two polygonal lights alone (the numbers of --no-texture) and for\n"
        "the textured light's contribution alone.\n"
        "\n"
        "  --width W        image width in pixels (default 256)\n"
        "  --height H       image height in pixels (default 160)\n"
        "  --spp N          Monte Carlo iterations per pixel, light and integral (default 2048; each\n"
        "                   draws one BRDF and one light direction; two integrals per polygonal\n"
        "                   light, for Schlick's Fresnel; one specular integral for the textured\n"
        "                   light, Fresnel included, and one diffuse integral where albedo > 0);\n"
        "                   0 renders the LTC image only\n"
        "  --threads K      worker threads (default: all hardware threads); the images do not\n"
        "                   depend on it\n"
        "  --out DIR        output directory, created if needed (default: the current directory)\n"
        "  --exposure E     linear exposure before the tone curve (default 1)\n"
        "  --seed S         base seed of the reference (default 1)\n"
        "  --texture FILE   the textured light's picture: a PNG (or any image stb_image reads: JPEG,\n"
        "                   BMP, TGA, ...), 8-bit sRGB converted to linear, times its alpha (transparent\n"
        "                   texels emit nothing); images over 1024 texels on a side are box-filtered\n"
        "                   down by an integer factor. The quad keeps the image's aspect ratio, within\n"
        "                   2.6 x 3.2 units. Default: a procedural stained-glass window, 192 x 256\n"
        "  --no-texture     leave the textured light out: the scene, images and statistics of the two\n"
        "                   polygonal lights alone\n"
        "  --texture-radiance R  radiance of a white texel (default 8; the polygonal lights have\n"
        "                   radiance 6 times their colour)\n"
        "  --help           this text\n"
        "\n"
        "Floor: stripes dielectric | gold | dielectric | copper (left to right), crossed by bands of\n"
        "roughness 0.9, 0.7, 0.5, 0.3, 0.1 (near to far). Tone mapping, the same for both renders:\n"
        "exposure, the ACES filmic curve (Narkowicz 2015), clamp, sRGB. The default run takes about\n"
        "35 s on 2 cores (about 25 s with --no-texture).\n",
        argv0);
}

bool parse_number(const char* s, double& v) {
    char* end = nullptr;
    v = std::strtod(s, &end);
    return end != s && *end == '\0' && std::isfinite(v);
}

/// Returns 0 to go on, 1 after --help, 2 on an error.
int parse_args(int argc, char** argv, options& o) {
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--help" || a == "-h") {
            print_help(argv[0]);
            return 1;
        }
        if (a == "--no-texture") {
            o.textured = false;
            continue;
        }
        if (i + 1 >= argc) {
            std::fprintf(stderr, "%s: unknown option or missing value: %s (see --help)\n", argv[0], a.c_str());
            return 2;
        }
        const char* value = argv[++i];
        double v = 0;
        const bool number = parse_number(value, v);
        const bool integer = number && v == std::floor(v);
        const auto bad = [&] {
            std::fprintf(stderr, "%s: bad value for %s: %s\n", argv[0], a.c_str(), value);
            return 2;
        };
        if (a == "--width" || a == "--height") {
            if (!integer || v < 1 || v > 16384) return bad();
            (a == "--width" ? o.width : o.height) = static_cast<int>(v);
        } else if (a == "--spp") {
            if (!integer || v < 0 || v > 1e8) return bad();
            o.spp = static_cast<int>(v);
        } else if (a == "--threads") {
            if (!integer || v < 1 || v > 1024) return bad();
            o.threads = static_cast<unsigned>(v);
        } else if (a == "--exposure") {
            if (!number || !(v > 0)) return bad();
            o.exposure = v;
        } else if (a == "--seed") {
            if (!integer || v < 0 || v > 9e15) return bad();
            o.seed = static_cast<std::uint64_t>(v);
        } else if (a == "--out") {
            o.out = value;
        } else if (a == "--texture") {
            o.texture = value;
            o.textured = true;
        } else if (a == "--texture-radiance") {
            if (!number || !(v >= 0) || v > 1e6) return bad();
            o.texture_radiance = v;
        } else {
            std::fprintf(stderr, "%s: unknown option: %s (see --help)\n", argv[0], a.c_str());
            return 2;
        }
    }
    return 0;
}

// ------------------------------------------------------------------------------------------------
// Scene

struct material {
    float roughness;
    vec3 f0;
    vec3 albedo;
};

struct light {
    const char* name;
    std::vector<vec3> vertices;  // front face: clockwise as seen from the lit side
    vec3 radiance;
    vec3 centre, front;  // front: unit normal of the emitting side
    vec3 axis_u, axis_v;  // orthonormal axes of the light's plane (hit test)
    std::vector<glm::vec2> outline;  // the vertices in (axis_u, axis_v) coordinates
};

/// A planar light: outline points (in its plane, around the centre) placed on the plane through
/// `centre` with unit normal `front` (the emitting side), "up" in the plane towards `up`.
light make_light(const char* name, const std::vector<glm::vec2>& outline, vec3 centre, vec3 front, vec3 up,
                 vec3 radiance) {
    light l;
    l.name = name;
    l.radiance = radiance;
    l.centre = centre;
    l.front = glm::normalize(front);
    l.axis_v = glm::normalize(up - glm::dot(up, l.front) * l.front);
    l.axis_u = glm::cross(l.axis_v, l.front);
    l.outline = outline;
    for (const auto& p : outline) l.vertices.push_back(centre + p.x * l.axis_u + p.y * l.axis_v);
    // One-sided convention of the library (polygon.hpp): the right-hand normal
    // (p1 - p0) x (p2 - p0) points away from the lit points, i.e. against `front`.
    const vec3 n = glm::cross(l.vertices[1] - l.vertices[0], l.vertices[2] - l.vertices[0]);
    if (glm::dot(n, l.front) > 0) {
        std::reverse(l.vertices.begin(), l.vertices.end());
        std::reverse(l.outline.begin(), l.outline.end());
    }
    return l;
}

std::vector<glm::vec2> rotated(std::vector<glm::vec2> p, double angle_deg) {
    const float c = static_cast<float>(std::cos(angle_deg * deg)), s = static_cast<float>(std::sin(angle_deg * deg));
    for (auto& q : p) q = glm::vec2(c * q.x - s * q.y, s * q.x + c * q.y);
    return p;
}

// ------------------------------------------------------------------------------------------------
// The textured light's picture

/// A linear-RGB image, row-major, row 0 first (v = 0 at the top of the light).
struct image {
    int width = 0, height = 0;
    std::vector<vec3> texels;
};

double srgb_decode(double x) { return x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4); }

std::uint64_t hash64(std::uint64_t z) {  // SplitMix64 finalizer
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

double hash01(std::int64_t i, std::int64_t j, std::uint64_t salt) {  // uniform in [0, 1)
    const std::uint64_t z = hash64(static_cast<std::uint64_t>(i) * 0x632BE59BD9B4E019ull ^
                                   hash64(static_cast<std::uint64_t>(j) + salt));
    return static_cast<double>(z >> 11) * 0x1.0p-53;
}

/// The default picture: a stained-glass window, linear RGB in [0, 1]. Drawn in window units
/// (x in [-1.5, 1.5] left to right, y in [0, 4] bottom to top) on a width x height grid: a
/// pointed arch (springing at y = 2.2, apex at 3.85) framed by lead; inside, a rose (radius
/// 0.72 around (0, 2.75): an amber heart, eight ruby and cobalt petals, lead spokes and rings)
/// and below it irregular glass cells (the Voronoi cells of a jittered grid, 0.42 units, one of
/// seven glass colours each, slightly mottled) joined by lead lines 0.05 units wide. Lead and the
/// surround outside the arch are black (they emit nothing). Deterministic (hashes, no RNG state).
image stained_glass(int width, int height) {
    image img;
    img.width = width;
    img.height = height;
    img.texels.assign(static_cast<std::size_t>(width) * height, vec3(0.0f));
    static const double palette[7][3] = {
        // sRGB
        {0.82, 0.10, 0.14},  // ruby
        {0.12, 0.25, 0.85},  // cobalt
        {0.10, 0.62, 0.28},  // emerald
        {0.98, 0.70, 0.12},  // amber
        {0.52, 0.18, 0.72},  // violet
        {0.92, 0.90, 0.78},  // clear
        {0.10, 0.62, 0.68},  // teal
    };
    const double half_width = 1.5, top = 4.0;
    const double inner = 1.32;                  // half span of the opening
    const double spring = 2.2, apex = 3.85;     // springing line and apex of the arch
    const double lead = 0.025;                  // half width of the lead lines
    const double frame = 0.07;                  // width of the lead frame along the arch
    // Pointed arch: two arcs of radius R centred at x = -+c on the springing line, each through
    // its own side's jamb (x = +-inner) and the apex: (inner + c) = R, c^2 + (apex - spring)^2 = R^2.
    const double h = apex - spring;
    const double c = (h * h - inner * inner) / (2.0 * inner), R = inner + c;
    const double rose_x = 0.0, rose_y = 2.75, rose_r = 0.72;
    const double cell = 0.42;
    // Distance from (x, y) inside the opening to its outline (positive inside).
    const auto inside_distance = [&](double x, double y) {
        const double bottom = y - 0.12;
        const double side = inner - std::abs(x);
        double d = std::min(bottom, side);
        if (y > spring) d = std::min(bottom, R - std::hypot(std::abs(x) + c, y - spring));
        return d;
    };
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            const double x = ((i + 0.5) / width - 0.5) * 2.0 * half_width;
            const double y = (1.0 - (j + 0.5) / height) * top;
            const double d = inside_distance(x, y);
            if (d < frame) continue;  // surround and frame: black
            int colour = 0;
            bool is_lead = false;
            const double rx = x - rose_x, ry = y - rose_y, r = std::hypot(rx, ry);
            if (r < rose_r + lead) {
                // The rose: heart, petals between eight spokes, rings at 0.24 and rose_r.
                const double angle = std::atan2(ry, rx) + pi;  // [0, 2 pi]
                const double sector = angle / (pi / 4.0);
                const int k = static_cast<int>(sector) % 8;
                const double spoke = std::min(sector - std::floor(sector), std::ceil(sector) - sector) * (pi / 4.0) * r;
                is_lead = std::abs(r - rose_r) < lead || std::abs(r - 0.24) < lead || (r > 0.24 && spoke < lead);
                colour = r < 0.24 ? 3 : (k % 2 == 0 ? 0 : 1);
                if (r > 0.5 && r < rose_r - lead) colour = k % 2 == 0 ? 4 : 6;  // the petals' tips
            } else {
                // Voronoi cells of a jittered grid: the nearest and second-nearest seeds.
                const std::int64_t gi = static_cast<std::int64_t>(std::floor(x / cell));
                const std::int64_t gj = static_cast<std::int64_t>(std::floor(y / cell));
                double d1 = INFINITY, d2 = INFINITY;
                glm::dvec2 s1(0.0), s2(0.0);
                std::int64_t best_i = 0, best_j = 0;
                for (std::int64_t b = gj - 2; b <= gj + 2; ++b)
                    for (std::int64_t a = gi - 2; a <= gi + 2; ++a) {
                        const glm::dvec2 seed((static_cast<double>(a) + 0.15 + 0.7 * hash01(a, b, 1)) * cell,
                                              (static_cast<double>(b) + 0.15 + 0.7 * hash01(a, b, 2)) * cell);
                        const double dd = glm::length(glm::dvec2(x, y) - seed);
                        if (dd < d1) {
                            d2 = d1, s2 = s1;
                            d1 = dd, s1 = seed, best_i = a, best_j = b;
                        } else if (dd < d2) {
                            d2 = dd, s2 = seed;
                        }
                    }
                // Distance to the bisector of the two nearest seeds: (d2^2 - d1^2) / (2 |s2 - s1|).
                const double edge = (d2 * d2 - d1 * d1) / (2.0 * glm::length(s2 - s1));
                is_lead = edge < lead || std::abs(r - rose_r) < 2.0 * lead + lead;  // ring around the rose
                colour = static_cast<int>(hash01(best_i, best_j, 3) * 7.0) % 7;
            }
            if (d < frame + 2.0 * lead) is_lead = true;  // lead between frame and glass
            if (is_lead) continue;
            // Mottled glass: +-12% of smooth variation.
            const double mottle = 1.0 + 0.12 * std::sin(17.0 * x + 3.0 * std::sin(11.0 * y)) * std::sin(13.0 * y + 2.0 * x);
            vec3& t = img.texels[static_cast<std::size_t>(j) * width + i];
            for (int ch = 0; ch < 3; ++ch)
                t[ch] = static_cast<float>(glm::clamp(srgb_decode(palette[colour][ch]) * mottle, 0.0, 1.0));
        }
    return img;
}

/// Loads an image file with stb_image: 8-bit sRGB (any channel count) to linear RGB times alpha,
/// box-filtered down by an integer factor (in linear RGB) while a side exceeds 1024 texels.
/// Returns false (with a message) if it cannot be read.
bool load_image(const std::string& path, image& img) {
    int w = 0, h = 0, channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
    if (data == nullptr) {
        std::fprintf(stderr, "error: cannot read the texture %s: %s\n", path.c_str(), stbi_failure_reason());
        return false;
    }
    std::vector<vec3> full(static_cast<std::size_t>(w) * h);
    for (std::size_t i = 0; i < full.size(); ++i) {
        const unsigned char* p = data + 4 * i;
        const double alpha = p[3] / 255.0;
        for (int c = 0; c < 3; ++c) full[i][c] = static_cast<float>(srgb_decode(p[c] / 255.0) * alpha);
    }
    stbi_image_free(data);
    const int factor = (std::max(w, h) + 1023) / 1024;  // 1 up to 1024 texels
    img.width = std::max(1, w / factor);
    img.height = std::max(1, h / factor);
    img.texels.assign(static_cast<std::size_t>(img.width) * img.height, vec3(0.0f));
    for (int j = 0; j < img.height; ++j)
        for (int i = 0; i < img.width; ++i) {
            glm::dvec3 sum(0.0);
            int n = 0;
            for (int b = j * factor; b < std::min(h, (j + 1) * factor); ++b)
                for (int a = i * factor; a < std::min(w, (i + 1) * factor); ++a, ++n)
                    sum += glm::dvec3(full[static_cast<std::size_t>(b) * w + a]);
            img.texels[static_cast<std::size_t>(j) * img.width + i] = vec3(sum / static_cast<double>(std::max(n, 1)));
        }
    return true;
}

// ------------------------------------------------------------------------------------------------
// Scene (continued)

/// A one-sided textured quad light: a rectangle with texture coordinates (0,0) at its top left,
/// (1,0) top right, (1,1) bottom right, (0,1) bottom left as seen from the front (the image's
/// first row at the top, not mirrored). In this order the corners turn clockwise as seen from
/// the front: the library's one-sided orientation.
struct textured_light {
    const char* name = "textured quad";
    vec3 quad[4];
    vec3 centre, front, axis_u, axis_v;  // axis_u: right, axis_v: up, as seen from the front
    float half_width = 0, half_height = 0;
    image picture;  // linear radiance (the texture times the light's radiance scale)
    std::unique_ptr<ltc::light_texture<float>> prefiltered;  // the LTC render's levels
    std::unique_ptr<ltc::textured_ground_truth::texel_distribution> area_density;  // reference
    /// The radiance at uv: the unfiltered texture, bilinear (what both renders draw and what the
    /// reference integrates).
    vec3 radiance(double u, double v) const {
        return ltc::bilinear_image_lookup(picture.width, picture.height, picture.texels.data(), u, v);
    }
};

struct scene {
    // Camera.
    vec3 eye{0.0f, -6.5f, 2.8f};
    vec3 target{0.0f, 2.0f, 0.3f};
    float vfov_deg = 48.0f;
    // Floor: x in [x0, x1], y in [y0, y1], z = 0: `columns` material stripes along y, crossed
    // by `bands` of roughness (the lights' reflections run along the stripes, across the bands).
    static constexpr int columns = 4, bands = 5;
    float x0 = -4.0f, x1 = 4.0f;
    // Band edges along y, spaced to look about equally tall from the camera.
    float band_edges[bands + 1] = {-3.3f, -2.5f, -1.6f, -0.4f, 1.4f, 4.5f};
    float y0 = band_edges[0], y1 = band_edges[bands];
    float grout = 0.02f;  // half width of the grout lines
    float roughness[bands] = {0.9f, 0.7f, 0.5f, 0.3f, 0.1f};  // near to far
    const char* column_names[columns] = {"dielectric", "gold", "dielectric", "copper"};
    std::vector<material> materials;  // [band * columns + column], then the grout
    std::vector<light> lights;
    std::unique_ptr<textured_light> textured;  // null without the textured light

    scene() {
        const vec3 gold(1.000f, 0.766f, 0.336f), copper(0.955f, 0.638f, 0.538f);  // F0, linear sRGB
        for (float r : roughness)
            for (int c = 0; c < columns; ++c)
                if (c % 2 == 0)
                    materials.push_back({r, vec3(0.04f), vec3(0.5f)});
                else
                    materials.push_back({r, c == 1 ? gold : copper, vec3(0.0f)});
        materials.push_back({0.8f, vec3(0.04f), vec3(0.02f)});  // grout

        // Two tall lights standing behind the floor, facing the camera and tilted 10 degrees
        // towards the floor, each above the boundary between a dielectric and a metal stripe:
        // a 1.2 x 3.4 rectangle leaning 20 degrees, and an irregular pentagon.
        const vec3 front = glm::normalize(vec3(0.0f, -1.0f, -0.18f));
        const vec3 up(0.0f, 0.0f, 1.0f);
        const std::vector<glm::vec2> rect = {{-0.6f, -1.7f}, {0.6f, -1.7f}, {0.6f, 1.7f}, {-0.6f, 1.7f}};
        lights.push_back(make_light("rectangle", rotated(rect, 20.0), vec3(-3.0f, 5.0f, 1.9f), front, up,
                                    vec3(1.00f, 0.78f, 0.50f) * 6.0f));
        const std::vector<glm::vec2> pentagon = {
            {0.0f, 1.8f}, {0.9f, 0.5f}, {0.6f, -1.6f}, {-0.7f, -1.6f}, {-0.9f, 0.6f}};
        lights.push_back(make_light("pentagon", pentagon, vec3(3.0f, 5.0f, 1.9f), front, up,
                                    vec3(0.50f, 0.72f, 1.00f) * 6.0f));
    }

    /// Adds the textured light: the picture (linear, white = 1) times `radiance`, on a quad in
    /// the plane of the other lights (the same tilt), centred between them, with the picture's
    /// aspect ratio, as large as fits in 2.6 x 3.2 units.
    void add_textured_light(image picture, float radiance) {
        auto t = std::make_unique<textured_light>();
        for (auto& c : picture.texels) c *= radiance;
        const float aspect = static_cast<float>(picture.width) / static_cast<float>(picture.height);
        const float max_w = 2.6f, max_h = 3.2f;
        float w = max_w, h = max_w / aspect;
        if (h > max_h) h = max_h, w = max_h * aspect;
        t->half_width = 0.5f * w;
        t->half_height = 0.5f * h;
        t->centre = vec3(0.0f, 5.0f, 1.9f);
        t->front = glm::normalize(vec3(0.0f, -1.0f, -0.18f));
        const vec3 up(0.0f, 0.0f, 1.0f);
        t->axis_v = glm::normalize(up - glm::dot(up, t->front) * t->front);
        t->axis_u = glm::cross(t->axis_v, t->front);  // right, as seen from the front
        const vec3 U = t->half_width * t->axis_u, V = t->half_height * t->axis_v;
        t->quad[0] = t->centre - U + V;  // uv (0, 0): top left
        t->quad[1] = t->centre + U + V;  // (1, 0): top right
        t->quad[2] = t->centre + U - V;  // (1, 1): bottom right
        t->quad[3] = t->centre - U - V;  // (0, 1): bottom left
        t->prefiltered = std::make_unique<ltc::light_texture<float>>(picture.width, picture.height,
                                                                    picture.texels.data());
        std::vector<double> weights(picture.texels.size());
        for (std::size_t i = 0; i < weights.size(); ++i)
            weights[i] = 0.2126 * picture.texels[i].r + 0.7152 * picture.texels[i].g + 0.0722 * picture.texels[i].b;
        t->area_density = std::make_unique<ltc::textured_ground_truth::texel_distribution>(
            picture.width, picture.height, weights.data());
        t->picture = std::move(picture);
        textured = std::move(t);
    }

    /// Material index at the floor point (x, y), or -1 outside the floor.
    int material_at(float x, float y) const {
        if (!(x >= x0 && x <= x1 && y >= y0 && y <= y1)) return -1;
        const float u = (x - x0) / (x1 - x0) * columns;
        if (std::abs(u - std::round(u)) * (x1 - x0) / columns < grout) return columns * bands;
        int b = 0;
        while (b + 1 < bands && y >= band_edges[b + 1]) ++b;
        if (y - band_edges[b] < grout || band_edges[b + 1] - y < grout) return columns * bands;
        return b * columns + std::min(columns - 1, static_cast<int>(u));
    }
};

/// What the camera ray of a pixel sees.
struct pixel_hit {
    enum kind_t : std::uint8_t { background, floor, emitter_front, emitter_back, textured_front } kind = background;
    int material = -1;
    int light = -1;  // emitter_front / emitter_back: index in scene::lights; -1 for the textured light
    vec3 p{0.0f};  // floor point
    vec3 v{0.0f};  // unit direction towards the eye
    glm::vec2 uv{0.0f};  // textured_front: texture coordinates of the hit
};

bool inside_polygon(const std::vector<glm::vec2>& poly, glm::vec2 q) {  // even-odd rule
    bool in = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const glm::vec2 a = poly[i], b = poly[j];
        if ((a.y > q.y) != (b.y > q.y) && q.x < (b.x - a.x) * (q.y - a.y) / (b.y - a.y) + a.x) in = !in;
    }
    return in;
}

std::vector<pixel_hit> trace_camera(const scene& s, int width, int height) {
    std::vector<pixel_hit> hits(static_cast<std::size_t>(width) * height);
    const vec3 forward = glm::normalize(s.target - s.eye);
    const vec3 right = glm::normalize(glm::cross(forward, vec3(0, 0, 1)));
    const vec3 up = glm::cross(right, forward);
    const float h = std::tan(0.5f * s.vfov_deg * static_cast<float>(deg));
    const float w = h * static_cast<float>(width) / static_cast<float>(height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float sx = (2.0f * (static_cast<float>(x) + 0.5f) / static_cast<float>(width) - 1.0f) * w;
            const float sy = (1.0f - 2.0f * (static_cast<float>(y) + 0.5f) / static_cast<float>(height)) * h;
            const vec3 d = glm::normalize(forward + sx * right + sy * up);
            pixel_hit& hit = hits[static_cast<std::size_t>(y) * width + x];
            float t_best = INFINITY;
            if (d.z < 0) {
                const float t = -s.eye.z / d.z;
                const vec3 p = s.eye + t * d;
                const int m = s.material_at(p.x, p.y);
                if (m >= 0) {
                    t_best = t;
                    hit.kind = pixel_hit::floor;
                    hit.material = m;
                    hit.p = vec3(p.x, p.y, 0.0f);
                    hit.v = -d;
                }
            }
            for (std::size_t k = 0; k < s.lights.size(); ++k) {
                const light& l = s.lights[k];
                const float dn = glm::dot(d, l.front);
                if (dn == 0) continue;
                const float t = glm::dot(l.centre - s.eye, l.front) / dn;
                if (!(t > 0 && t < t_best)) continue;
                const vec3 q = s.eye + t * d - l.centre;
                if (!inside_polygon(l.outline, glm::vec2(glm::dot(q, l.axis_u), glm::dot(q, l.axis_v)))) continue;
                t_best = t;
                hit.kind = dn < 0 ? pixel_hit::emitter_front : pixel_hit::emitter_back;
                hit.light = static_cast<int>(k);
                hit.material = -1;
            }
            if (const textured_light* l = s.textured.get()) {
                const float dn = glm::dot(d, l->front);
                const float t = dn != 0 ? glm::dot(l->centre - s.eye, l->front) / dn : -1.0f;
                if (t > 0 && t < t_best) {
                    // uv from the top-left corner along the (orthogonal) edges.
                    const vec3 q = s.eye + t * d - l->quad[0];
                    const float u = glm::dot(q, l->axis_u) / (2.0f * l->half_width);
                    const float v = -glm::dot(q, l->axis_v) / (2.0f * l->half_height);
                    if (u >= 0 && u <= 1 && v >= 0 && v <= 1) {
                        hit.kind = dn < 0 ? pixel_hit::textured_front : pixel_hit::emitter_back;
                        hit.light = -1;
                        hit.material = -1;
                        hit.uv = glm::vec2(u, v);
                    }
                }
            }
        }
    return hits;
}

// ------------------------------------------------------------------------------------------------
// Shading

/// The GGX model of ltc/fitting/brdf/ggx.hpp weighted by Schlick's (1 - V.H)^5: the integrand of the
/// LTC table's "fresnel" channel. Same sampling and density as GGX (the weight is in [0, 1]).
struct ggx_schlick_weight {
    using model = ltc::brdf::ggx<double>;
    static double eval(const dvec3& V, const dvec3& L, double alpha) {
        const double f = model::eval(V, L, alpha);
        if (!(f > 0)) return 0.0;
        const dvec3 H = glm::normalize(V + L);
        const double c = 1.0 - glm::clamp(glm::dot(V, H), 0.0, 1.0);
        const double c2 = c * c;
        return f * c2 * c2 * c;
    }
    static double pdf(const dvec3& V, const dvec3& L, double alpha) { return model::pdf(V, L, alpha); }
    static dvec3 sample(const dvec3& V, const glm::dvec2& u, double alpha) { return model::sample(V, u, alpha); }
};

/// Radiance of one pixel from the polygonal lights (and their emitters): LTC (float, the
/// renderer's path).
vec3 shade_ltc(const scene& s, const pixel_hit& hit) {
    if (hit.kind == pixel_hit::emitter_front) return s.lights[static_cast<std::size_t>(hit.light)].radiance;
    if (hit.kind != pixel_hit::floor) return vec3(0.0f);
    const material& m = s.materials[static_cast<std::size_t>(hit.material)];
    vec3 sum(0.0f);
    for (const light& l : s.lights) {
        const ltc::polygon_light_result<float> r =
            ltc::shade_polygon_light(hit.p, vec3(0, 0, 1), hit.v, m.roughness, m.f0, m.albedo, l.radiance,
                                     l.vertices.data(), l.vertices.size(), ltc::sidedness::one_sided);
        sum += r.specular + r.diffuse;
    }
    return sum;
}

/// Radiance of one pixel from the textured light (and its emitter): LTC, I_D I_L (float).
vec3 shade_ltc_textured(const scene& s, const pixel_hit& hit) {
    const textured_light* t = s.textured.get();
    if (t == nullptr) return vec3(0.0f);
    if (hit.kind == pixel_hit::textured_front) return t->radiance(hit.uv.x, hit.uv.y);
    if (hit.kind != pixel_hit::floor) return vec3(0.0f);
    const material& m = s.materials[static_cast<std::size_t>(hit.material)];
    const ltc::textured_light_result<float> r = ltc::shade_textured_quad_light(
        hit.p, vec3(0, 0, 1), hit.v, m.roughness, m.f0, m.albedo, t->quad, *t->prefiltered, ltc::sidedness::one_sided);
    return r.specular + r.diffuse;
}

std::uint64_t mix_seed(std::uint64_t a, std::uint64_t b) {  // SplitMix64 finalizer of a combination
    std::uint64_t z = a * 0x9E3779B97F4A7C15ull + b + 0x632BE59BD9B4E019ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/// Reference luminance (times the exposure) below which a pixel is left out of the statistics
/// and the relative error is taken against this floor instead: about 12/255 on screen.
constexpr double dark_floor = 0.01;

constexpr double lum_r = 0.2126, lum_g = 0.7152, lum_b = 0.0722;  // Rec. 709 luminance
double luminance(const dvec3& c) { return lum_r * c.r + lum_g * c.g + lum_b * c.b; }

struct reference_pixel {
    dvec3 radiance{0.0};  // the polygonal lights (and their emitters)
    double luminance_variance = 0.0;  // of the Monte Carlo estimate of the luminance
    dvec3 textured{0.0};  // the textured light (and its emitter)
    double textured_variance = 0.0;  // of the estimate of its luminance
};

/// The textured light's contribution to the reference (file comment): S + albedo D, both Monte
/// Carlo integrals of the unfiltered texture, and the variance of the luminance of that sum.
/// Each iteration is one call of the estimator with its own seed (so the luminance of every
/// iteration's RGB value is known and its variance exact).
void shade_reference_textured(const textured_light& t, const dvec3& P, const ltc::shading_frame<double>& frame,
                              const dvec3& V, double alpha, const dvec3& F0, const dvec3& albedo,
                              std::uint64_t seed_specular, std::uint64_t seed_diffuse, int spp,
                              reference_pixel& out) {
    dvec3 q[4];
    for (int i = 0; i < 4; ++i) q[i] = frame.to_local(dvec3(t.quad[i]) - P);
    // One-sided: lit only where its front face is seen (the estimator is two-sided).
    const dvec3 rh_normal = glm::cross(q[1] - q[0], q[2] - q[0]);
    if (!(glm::dot(q[0], rh_normal) > 0) || spp <= 0) return;
    const dvec3 e1 = q[1] - q[0], e3 = q[3] - q[0];
    // L(u, v) times Schlick's Fresnel of the direction towards (u, v) on the quad.
    const auto specular_radiance = [&](double u, double v) {
        const dvec3 w = glm::normalize(q[0] + u * e1 + v * e3);
        const dvec3 h = V + w;
        const double hl = glm::length(h);
        const double c = hl > 0 ? 1.0 - glm::clamp(glm::dot(V, h) / hl, 0.0, 1.0) : 1.0;
        const double c2 = c * c;
        return dvec3(t.radiance(u, v)) * (F0 + (dvec3(1.0) - F0) * (c2 * c2 * c));
    };
    const auto diffuse_radiance = [&](double u, double v) { return dvec3(t.radiance(u, v)); };
    const ltc::textured_ground_truth::brdf_lobe<ltc::brdf::ggx<double>> ggx_lobe{V, alpha};
    const ltc::textured_ground_truth::ltc_lobe cosine_lobe{};  // M = I: max(0, z) / pi
    const bool diffuse = albedo.r > 0 || albedo.g > 0 || albedo.b > 0;
    ltc::textured_ground_truth::options opt;
    opt.samples = 1;
    dvec3 sum(0.0);
    double y_mean = 0, y_m2 = 0;  // Welford on the luminance of each iteration's value
    for (int i = 0; i < spp; ++i) {
        opt.seed = mix_seed(seed_specular, static_cast<std::uint64_t>(i));
        dvec3 value = ltc::textured_ground_truth::integrate(ggx_lobe, q, specular_radiance, opt, t.area_density.get()).mean;
        if (diffuse) {
            opt.seed = mix_seed(seed_diffuse, static_cast<std::uint64_t>(i));
            value += albedo *
                     ltc::textured_ground_truth::integrate(cosine_lobe, q, diffuse_radiance, opt, t.area_density.get()).mean;
        }
        sum += value;
        const double y = luminance(value), delta = y - y_mean;
        y_mean += delta / (i + 1);
        y_m2 += delta * (y - y_mean);
    }
    out.textured += sum / static_cast<double>(spp);
    if (spp > 1) out.textured_variance += y_m2 / (static_cast<double>(spp - 1) * spp);
}

/// Radiance of one pixel: the Monte Carlo reference (double).
reference_pixel shade_reference(const scene& s, const pixel_hit& hit, std::uint64_t pixel_seed, int spp) {
    reference_pixel out;
    if (hit.kind == pixel_hit::emitter_front) {
        out.radiance = dvec3(s.lights[static_cast<std::size_t>(hit.light)].radiance);
        return out;
    }
    if (hit.kind == pixel_hit::textured_front) {
        out.textured = dvec3(s.textured->radiance(hit.uv.x, hit.uv.y));
        return out;
    }
    if (hit.kind != pixel_hit::floor) return out;
    const material& m = s.materials[static_cast<std::size_t>(hit.material)];
    const dvec3 P(hit.p), N(0, 0, 1), F0(m.f0), albedo(m.albedo);
    const ltc::shading_frame<double> frame = ltc::make_shading_frame(N, dvec3(hit.v));
    const dvec3 V = frame.to_local(glm::normalize(dvec3(hit.v)));
    // alpha = roughness^2, the table's convention (the model clamps it to [alpha_min, alpha_max]
    // as the fit did).
    const double alpha = double(m.roughness) * double(m.roughness);
    std::vector<dvec3> local;
    for (std::size_t k = 0; k < s.lights.size(); ++k) {
        const light& l = s.lights[k];
        const std::size_t n = l.vertices.size();
        local.resize(n);
        for (std::size_t i = 0; i < n; ++i) local[i] = frame.to_local(dvec3(l.vertices[i]) - P);
        // One-sided light: lit only where its front face is seen (polygon.hpp's orientation);
        // the ground truth integrates over the set of directions, whatever the winding.
        const dvec3 rh_normal = glm::cross(local[1] - local[0], local[2] - local[0]);
        if (!(glm::dot(local[0], rh_normal) > 0)) continue;
        const dvec3 Le(l.radiance);
        // Diffuse: closed form (the LTC render computes the same exact integral).
        const double E = ltc::form_factor(local.data(), n, ltc::sidedness::one_sided);
        out.radiance += albedo * Le * E;
        // Specular: F0 A + (1 - F0) B, each a Monte Carlo integral with its own seed.
        ltc::ground_truth::options opt;
        opt.samples = static_cast<std::uint64_t>(spp);
        opt.seed = mix_seed(pixel_seed, 2 * k);
        const ltc::ground_truth::estimate A =
            ltc::ground_truth::integrate(ltc::brdf::ggx<double>{}, V, alpha, local.data(), n, opt);
        opt.seed = mix_seed(pixel_seed, 2 * k + 1);
        const ltc::ground_truth::estimate B =
            ltc::ground_truth::integrate(ggx_schlick_weight{}, V, alpha, local.data(), n, opt);
        out.radiance += Le * (F0 * A.mean + (dvec3(1.0) - F0) * B.mean);
        // Luminance = a A + b B + const; independent estimates: variances add.
        const double a = luminance(Le * F0), b = luminance(Le * (dvec3(1.0) - F0));
        const double sa = a * A.standard_error, sb = b * B.standard_error;
        out.luminance_variance += sa * sa + sb * sb;
    }
    if (s.textured) {
        const std::uint64_t k = 2 * s.lights.size();  // after the polygonal lights' seeds
        shade_reference_textured(*s.textured, P, frame, V, alpha, F0, albedo, mix_seed(pixel_seed, k),
                                 mix_seed(pixel_seed, k + 1), spp, out);
    }
    return out;
}

// ------------------------------------------------------------------------------------------------
// Images

double aces(double x) {  // Narkowicz 2015, "ACES Filmic Tone Mapping Curve"
    return glm::clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

double srgb_encode(double x) {
    return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

std::uint8_t to_byte(double x) {
    return static_cast<std::uint8_t>(std::lround(glm::clamp(x, 0.0, 1.0) * 255.0));
}

void tone_map(const dvec3& radiance, double exposure, std::uint8_t* rgb) {
    for (int c = 0; c < 3; ++c) rgb[c] = to_byte(srgb_encode(aces(radiance[c] * exposure)));
}

/// The fixed false-colour scale of error.png: e in [0, 0.2] through five sRGB colours.
void error_colour(double e, std::uint8_t* rgb) {
    static const double stops[5][3] = {
        {0.05, 0.03, 0.25},  //  0%  dark blue
        {0.10, 0.35, 0.90},  //  5%  blue
        {0.15, 0.80, 0.40},  // 10%  green
        {0.98, 0.85, 0.10},  // 15%  yellow
        {0.90, 0.10, 0.10},  // 20%+ red
    };
    const double t = glm::clamp(e / 0.2, 0.0, 1.0) * 4.0;
    const int i = std::min(3, static_cast<int>(t));
    const double f = t - i;
    for (int c = 0; c < 3; ++c) rgb[c] = to_byte(stops[i][c] * (1 - f) + stops[i + 1][c] * f);
}

bool write_png(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& rgb) {
    const std::string name = path.string();
    if (stbi_write_png(name.c_str(), width, height, 3, rgb.data(), width * 3) == 0) {
        std::fprintf(stderr, "error: cannot write %s\n", name.c_str());
        return false;
    }
    std::printf("wrote %s\n", name.c_str());
    return true;
}

// ------------------------------------------------------------------------------------------------
// Threads and progress

using clock_type = std::chrono::steady_clock;

double seconds_since(clock_type::time_point t0) {
    return std::chrono::duration<double>(clock_type::now() - t0).count();
}

/// Runs row(y) for y in [0, height) on `threads` workers (rows handed out in order). With a
/// label, the calling thread draws a progress bar with an ETA on stderr until all are done; the
/// progress counts row_cost[y] per finished row (rows of sky cost nothing).
template <typename Row>
void for_each_row(int height, unsigned threads, Row&& row, const char* label = nullptr,
                  const std::vector<long long>* row_cost = nullptr) {
    std::atomic<int> next{0}, rows_done{0};
    std::atomic<long long> done{0};
    long long total = 0;
    for (int y = 0; y < height; ++y) total += row_cost ? (*row_cost)[static_cast<std::size_t>(y)] : 1;
    std::vector<std::thread> pool;
    for (unsigned k = 0; k < threads; ++k)
        pool.emplace_back([&] {
            for (int y; (y = next.fetch_add(1)) < height;) {
                row(y);
                done.fetch_add(row_cost ? (*row_cost)[static_cast<std::size_t>(y)] : 1);
                rows_done.fetch_add(1);
            }
        });
    if (label != nullptr) {
        const auto t0 = clock_type::now();
        const auto draw = [&](bool finished) {
            constexpr int bar = 32;
            const double elapsed = seconds_since(t0);
            const double f = finished ? 1.0 : total > 0 ? static_cast<double>(done.load()) / total : 0.0;
            const int filled = static_cast<int>(f * bar);
            char eta[32] = "ETA     ?  ";
            if (finished)
                std::snprintf(eta, sizeof eta, "done       ");
            else if (f > 0)
                std::snprintf(eta, sizeof eta, "ETA %5.1f s", elapsed * (1 - f) / f);
            std::fprintf(stderr, "\r%s [%.*s%.*s] %3d%%  %6.1f s  %s", label, filled,
                         "################################", bar - filled, "................................",
                         static_cast<int>(100 * f), elapsed, eta);
            std::fflush(stderr);
        };
        while (rows_done.load() < height) {
            draw(false);
            std::this_thread::sleep_for(std::chrono::milliseconds(250));
        }
        draw(true);
        std::fprintf(stderr, "\n");
    }
    for (auto& t : pool) t.join();
}

double percentile(std::vector<double> v, double p) {  // nearest rank
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t k = static_cast<std::size_t>(std::ceil(p * static_cast<double>(v.size())));
    return v[std::min(v.size() - 1, k > 0 ? k - 1 : 0)];
}

double mean_of(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}

bool finite3(const dvec3& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); }

/// Error statistics of an LTC image against its reference over the floor pixels.
struct error_stats {
    std::vector<double> rel, signed_rel, noise;
    std::size_t significant = 0, dark = 0;
    std::vector<std::vector<double>> tile_rel, tile_signed;
};

/// Relative error of luminance over the floor pixels with Y_ref >= floor; fills the false-colour
/// error image (count x 3 bytes; every floor pixel, against max(Y_ref, floor); the rest black).
error_stats measure_error(const std::vector<pixel_hit>& hits, const std::vector<dvec3>& ltc_img,
                          const std::vector<dvec3>& ref_img, const std::vector<double>& ref_variance, double floor,
                          std::vector<std::uint8_t>& rgb) {
    error_stats st;
    const std::size_t tiles = static_cast<std::size_t>(scene::columns) * scene::bands;
    st.tile_rel.resize(tiles);
    st.tile_signed.resize(tiles);
    for (std::size_t i = 0; i < hits.size(); ++i) {
        std::uint8_t* px = &rgb[3 * i];
        if (hits[i].kind != pixel_hit::floor) {
            px[0] = px[1] = px[2] = 0;
            continue;
        }
        const double y_ltc = luminance(ltc_img[i]), y_ref = luminance(ref_img[i]);
        const double e = std::abs(y_ltc - y_ref) / std::max(y_ref, floor);
        error_colour(e, px);
        if (!(y_ref >= floor)) {
            ++st.dark;
            continue;
        }
        const double se = std::sqrt(ref_variance[i]);
        st.rel.push_back(e);
        st.signed_rel.push_back((y_ltc - y_ref) / y_ref);
        st.noise.push_back(se / y_ref);
        st.significant += std::abs(y_ltc - y_ref) > 3 * se;
        const std::size_t m = static_cast<std::size_t>(hits[i].material);
        if (m < tiles) {
            st.tile_rel[m].push_back(e);
            st.tile_signed[m].push_back(st.signed_rel.back());
        }
    }
    return st;
}

void print_error(const scene& s, const error_stats& st, double floor, const char* y_ref = "Y_ref") {
    std::printf("relative error of the LTC render, |Y_ltc - Y_ref| / Y_ref of luminance, over the %zu floor pixels\n"
                "with %s >= %.3g (%zu darker floor pixels left out):\n",
                st.rel.size(), y_ref, floor, st.dark);
    std::printf("  mean %.2f%%  median %.2f%%  p95 %.2f%%  max %.2f%%  (mean signed %+.2f%%)\n", 100 * mean_of(st.rel),
                100 * percentile(st.rel, 0.5), 100 * percentile(st.rel, 0.95), 100 * percentile(st.rel, 1.0),
                100 * mean_of(st.signed_rel));
    std::printf("reference noise, relative standard error of Y_ref over the same pixels:\n");
    std::printf("  mean %.2f%%  median %.2f%%  p95 %.2f%%  max %.2f%%\n", 100 * mean_of(st.noise),
                100 * percentile(st.noise, 0.5), 100 * percentile(st.noise, 0.95), 100 * percentile(st.noise, 1.0));
    std::printf("pixels where |Y_ltc - Y_ref| > 3 standard errors (the LTC's error, not noise): %.1f%%\n",
                st.rel.empty() ? 0.0 : 100.0 * static_cast<double>(st.significant) / static_cast<double>(st.rel.size()));
    std::printf("\nper tile, mean |relative error| (mean signed); bands far to near, stripes left to right:\n");
    std::printf("  roughness");
    for (const char* name : s.column_names) std::printf(" %18s", name);
    std::printf("\n");
    for (int b = scene::bands - 1; b >= 0; --b) {
        std::printf("  %9.2f", static_cast<double>(s.roughness[b]));
        for (int c = 0; c < scene::columns; ++c) {
            const std::size_t m = static_cast<std::size_t>(b * scene::columns + c);
            if (st.tile_rel[m].empty()) {
                std::printf(" %18s", "-");
                continue;
            }
            char cell[40];
            std::snprintf(cell, sizeof cell, "%.1f%% (%+.1f%%)", 100 * mean_of(st.tile_rel[m]),
                          100 * mean_of(st.tile_signed[m]));
            std::printf(" %18s", cell);
        }
        std::printf("\n");
    }
}

}  // namespace

int main(int argc, char** argv) {
    options opt;
    if (const int r = parse_args(argc, argv, opt); r != 0) return r == 1 ? 0 : 2;
    if (opt.threads == 0) opt.threads = std::max(1u, std::thread::hardware_concurrency());
    const int W = opt.width, H = opt.height;
    const std::size_t count = static_cast<std::size_t>(W) * H;

    std::error_code ec;
    const std::filesystem::path out_dir(opt.out);
    std::filesystem::create_directories(out_dir, ec);
    if (!std::filesystem::is_directory(out_dir, ec)) {
        std::fprintf(stderr, "error: cannot create the output directory %s\n", opt.out.c_str());
        return 1;
    }

    scene s;
    double prefilter_seconds = 0;
    if (opt.textured) {
        image picture;
        if (opt.texture.empty())
            picture = stained_glass(192, 256);
        else if (!load_image(opt.texture, picture))
            return 1;
        const auto t0 = clock_type::now();
        try {
            s.add_textured_light(std::move(picture), static_cast<float>(opt.texture_radiance));
        } catch (const std::exception& e) {
            std::fprintf(stderr, "error: cannot prefilter the texture: %s\n", e.what());
            return 1;
        }
        prefilter_seconds = seconds_since(t0);
    }
    const textured_light* tex = s.textured.get();
    const std::vector<pixel_hit> hits = trace_camera(s, W, H);
    std::size_t floor_pixels = 0;
    for (const auto& h : hits) floor_pixels += h.kind == pixel_hit::floor;
    std::printf("%d x %d pixels (%zu on the floor), %zu lights (", W, H, floor_pixels, s.lights.size() + (tex ? 1 : 0));
    for (std::size_t k = 0; k < s.lights.size(); ++k)
        std::printf("%s%s, %zu vertices", k ? "; " : "", s.lights[k].name, s.lights[k].vertices.size());
    if (tex)
        std::printf("; %s, %d x %d texels", tex->name, tex->picture.width, tex->picture.height);
    std::printf("), %u thread%s\n", opt.threads, opt.threads == 1 ? "" : "s");
    if (tex)
        std::printf("textured light: %s, %.2f x %.2f units, white = radiance %g; prefiltered in %.3f s "
                    "(%d levels)\n",
                    opt.texture.empty() ? "procedural stained glass" : opt.texture.c_str(), 2.0 * tex->half_width,
                    2.0 * tex->half_height, opt.texture_radiance, prefilter_seconds, tex->prefiltered->level_count());

    // LTC render: each part timed as the best of 5 runs (it takes milliseconds).
    std::vector<dvec3> ltc_poly(count), ltc_tex(count, dvec3(0.0)), ltc_img(count);
    double ltc_seconds = INFINITY, ltc_tex_seconds = tex ? INFINITY : 0.0;
    for (int run = 0; run < 5; ++run) {
        const auto t0 = clock_type::now();
        for_each_row(H, opt.threads, [&](int y) {
            for (int x = 0; x < W; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * W + x;
                ltc_poly[i] = dvec3(shade_ltc(s, hits[i]));
            }
        });
        ltc_seconds = std::min(ltc_seconds, seconds_since(t0));
    }
    for (int run = 0; tex && run < 5; ++run) {
        const auto t0 = clock_type::now();
        for_each_row(H, opt.threads, [&](int y) {
            for (int x = 0; x < W; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * W + x;
                ltc_tex[i] = dvec3(shade_ltc_textured(s, hits[i]));
            }
        });
        ltc_tex_seconds = std::min(ltc_tex_seconds, seconds_since(t0));
    }
    if (!tex) {
        std::printf("LTC render:       %9.4f s  (best of 5; %.0f ns of one thread per floor pixel and light)\n",
                    ltc_seconds,
                    ltc_seconds * 1e9 * opt.threads / (static_cast<double>(floor_pixels) * s.lights.size()));
    } else {
        std::printf("LTC render:       %9.4f s  (best of 5 of each part: polygonal lights %.4f s, %.0f ns of one "
                    "thread per floor pixel and light;\n"
                    "                                textured light %.4f s, %.0f ns per floor pixel)\n",
                    ltc_seconds + ltc_tex_seconds, ltc_seconds,
                    ltc_seconds * 1e9 * opt.threads / (static_cast<double>(floor_pixels) * s.lights.size()),
                    ltc_tex_seconds, ltc_tex_seconds * 1e9 * opt.threads / static_cast<double>(floor_pixels));
    }

    std::size_t ltc_nonfinite = 0, ref_nonfinite = 0;
    for (std::size_t i = 0; i < count; ++i) {
        if (!finite3(ltc_poly[i])) ++ltc_nonfinite, ltc_poly[i] = dvec3(0.0);
        if (!finite3(ltc_tex[i])) ++ltc_nonfinite, ltc_tex[i] = dvec3(0.0);
        ltc_img[i] = ltc_poly[i] + ltc_tex[i];
    }

    std::vector<std::uint8_t> rgb(count * 3);
    for (std::size_t i = 0; i < count; ++i) tone_map(ltc_img[i], opt.exposure, &rgb[3 * i]);
    bool ok = write_png(out_dir / "ltc.png", W, H, rgb);

    if (opt.spp == 0) {
        std::printf("non-finite values: LTC %zu\n", ltc_nonfinite);
        return ok && ltc_nonfinite == 0 ? 0 : 1;
    }

    // Reference render.
    std::fflush(stdout);  // the progress bar goes to stderr
    std::vector<reference_pixel> ref(count);
    const auto t0 = clock_type::now();
    std::vector<long long> row_cost(static_cast<std::size_t>(H), 0);  // floor pixels per row
    for (std::size_t i = 0; i < count; ++i)
        row_cost[i / static_cast<std::size_t>(W)] += hits[i].kind == pixel_hit::floor;
    for_each_row(
        H, opt.threads,
        [&](int y) {
            for (int x = 0; x < W; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * W + x;
                ref[i] = shade_reference(s, hits[i], mix_seed(opt.seed, i), opt.spp);
            }
        },
        "reference", &row_cost);
    const double ref_seconds = seconds_since(t0);
    if (!tex)
        std::printf("reference render: %9.4f s  (%d iterations x 2 directions x 2 integrals per pixel and light, "
                    "%u threads)\n",
                    ref_seconds, opt.spp, opt.threads);
    else
        std::printf("reference render: %9.4f s  (%d iterations x 2 directions x 2 integrals per pixel and polygonal "
                    "light,\n"
                    "                                x 1 or 2 integrals (specular; diffuse where albedo > 0) for the "
                    "textured light, %u threads)\n",
                    ref_seconds, opt.spp, opt.threads);
    std::printf("reference / LTC:  %9.0f x\n", ref_seconds / (ltc_seconds + ltc_tex_seconds));

    std::vector<dvec3> ref_poly(count), ref_tex(count), ref_img(count);
    std::vector<double> var_poly(count), var_tex(count), var_all(count);
    for (std::size_t i = 0; i < count; ++i) {
        reference_pixel& p = ref[i];
        if (!finite3(p.radiance) || !std::isfinite(p.luminance_variance))
            ++ref_nonfinite, p.radiance = dvec3(0.0), p.luminance_variance = 0;
        if (!finite3(p.textured) || !std::isfinite(p.textured_variance))
            ++ref_nonfinite, p.textured = dvec3(0.0), p.textured_variance = 0;
        ref_poly[i] = p.radiance;
        ref_tex[i] = p.textured;
        ref_img[i] = p.radiance + p.textured;
        var_poly[i] = p.luminance_variance;
        var_tex[i] = p.textured_variance;
        var_all[i] = p.luminance_variance + p.textured_variance;  // independent seeds
    }
    for (std::size_t i = 0; i < count; ++i) tone_map(ref_img[i], opt.exposure, &rgb[3 * i]);
    ok = write_png(out_dir / "reference.png", W, H, rgb) && ok;

    // Error images and statistics.
    const double floor = dark_floor / opt.exposure;
    const error_stats all = measure_error(hits, ltc_img, ref_img, var_all, floor, rgb);
    ok = write_png(out_dir / "error.png", W, H, rgb) && ok;
    if (!tex) {
        std::printf("\n");
        print_error(s, all, floor);
    } else {
        const error_stats tex_stats = measure_error(hits, ltc_tex, ref_tex, var_tex, floor, rgb);
        ok = write_png(out_dir / "textured_error.png", W, H, rgb) && ok;
        const error_stats poly_stats = measure_error(hits, ltc_poly, ref_poly, var_poly, floor, rgb);
        std::printf("\n=== all lights (ltc.png, reference.png, error.png) ===\n");
        print_error(s, all, floor);
        std::printf("\n=== the polygonal lights alone (rectangle + pentagon: the statistics of --no-texture) ===\n");
        print_error(s, poly_stats, floor);
        std::printf("\n=== the textured light alone (its contribution to the floor: textured_error.png) ===\n");
        print_error(s, tex_stats, floor, "Y_ref,tex");
    }
    std::printf("non-finite values: LTC %zu, reference %zu\n", ltc_nonfinite, ref_nonfinite);
    return ok && ltc_nonfinite == 0 && ref_nonfinite == 0 ? 0 : 1;
}
