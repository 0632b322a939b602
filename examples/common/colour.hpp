// common/colour.hpp -- colour arithmetic: Rec. 709 luminance, sRGB decoding and encoding, the tone
// curve (exposure, ACES filmic curve of Narkowicz 2015, sRGB, 8 bits) and the false-colour scale of
// the error images.
#pragma once

#include "math.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace ltc_examples {

constexpr double lum_r = 0.2126, lum_g = 0.7152, lum_b = 0.0722;  // Rec. 709 luminance
inline double luminance(const dvec3& c) { return lum_r * c.r + lum_g * c.g + lum_b * c.b; }

inline double srgb_decode(double x) { return x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4); }

inline double aces(double x) {  // Narkowicz 2015, "ACES Filmic Tone Mapping Curve"
    return glm::clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

inline double srgb_encode(double x) {
    return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

inline std::uint8_t to_byte(double x) {
    return static_cast<std::uint8_t>(std::lround(glm::clamp(x, 0.0, 1.0) * 255.0));
}

inline void tone_map(const dvec3& radiance, double exposure, std::uint8_t* rgb) {
    for (int c = 0; c < 3; ++c) rgb[c] = to_byte(srgb_encode(aces(radiance[c] * exposure)));
}

/// The fixed false-colour scale of error.png: e in [0, 0.2] through five sRGB colours.
inline void error_colour(double e, std::uint8_t* rgb) {
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

}  // namespace ltc_examples
