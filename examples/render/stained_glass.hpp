// render/stained_glass.hpp -- the textured light's default picture, generated: a stained-glass
// window (a pointed arch of coloured glass cells and a rose, joined by dark lead lines, on a black
// surround), deterministic (hashes, no RNG state).
#pragma once

#include "common/colour.hpp"
#include "common/image.hpp"
#include "math.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace render {

inline std::uint64_t hash64(std::uint64_t z) {  // SplitMix64 finalizer
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

inline double hash01(std::int64_t i, std::int64_t j, std::uint64_t salt) {  // uniform in [0, 1)
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
inline image stained_glass(int width, int height) {
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

}  // namespace render
