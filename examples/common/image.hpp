// common/image.hpp -- images in and out: a linear-RGB image (render's textured light), read from a
// file with stb_image (sRGB to linear, times alpha, box-filtered down to 1024 texels a side), and
// 8-bit RGB PNGs written with stb_image_write.
#pragma once

#include "colour.hpp"
#include "math.hpp"
#include "stb.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace ltc_examples {

/// A linear-RGB image, row-major, row 0 first (v = 0 at the top of the light).
struct image {
    int width = 0, height = 0;
    std::vector<vec3> texels;
};

/// Loads an image file with stb_image: 8-bit sRGB (any channel count) to linear RGB times alpha,
/// box-filtered down by an integer factor (in linear RGB) while a side exceeds 1024 texels.
/// Returns false (with a message) if it cannot be read.
inline bool load_image(const std::string& path, image& img) {
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

inline bool write_png(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& rgb) {
    const std::string name = path.string();
    if (stbi_write_png(name.c_str(), width, height, 3, rgb.data(), width * 3) == 0) {
        std::fprintf(stderr, "error: cannot write %s\n", name.c_str());
        return false;
    }
    std::printf("wrote %s\n", name.c_str());
    return true;
}

}  // namespace ltc_examples
