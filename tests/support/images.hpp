// Random linear-RGB test images (deterministic: ltc_test::rng), shared by the texture tests.
#pragma once

#include "support/rng.hpp"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ltc_test {

/// w x h texels, channels uniform in [0, 4), [0, 1) and [0, blue_max), drawn in that order.
inline std::vector<glm::vec3> random_image(int w, int h, std::uint64_t seed, double blue_max) {
    rng r(seed);
    std::vector<glm::vec3> img(std::size_t(w) * std::size_t(h));
    for (auto& c : img) {
        const float x = float(r.uniform(0, 4));
        const float y = float(r.uniform(0, 1));
        const float z = float(r.uniform(0, blue_max));
        c = glm::vec3(x, y, z);
    }
    return img;
}

}  // namespace ltc_test
