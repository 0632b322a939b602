// shadows/screen_order.hpp -- where a pixel's sample points come from: independent random numbers
// per pixel, or by default screen-ordered points (ltc/core/screen_order.hpp: scrambled Sobol
// points in a shuffled Morton order of the pixels), so that neighbouring pixels' points are
// stratified together and the errors that (d)'s and (e)'s filter averages over neighbours partly
// cancel. Each pixel's point stays uniform, so that every Monte Carlo sum keeps its expectation.
#pragma once

#include "common/random.hpp"

#include <ltc/core/screen_order.hpp>

#include <glm/glm.hpp>

#include <cstdint>

namespace shadows {

/// A pixel's sample points: with `screen`, stream k's point is ltc::screen_point at (x, y) for
/// the image's seed `run` and k; without it the methods draw their own random numbers.
struct pixel_points {
    bool screen = false;
    int x = 0, y = 0;
    std::uint64_t run = 0;

    std::uint64_t seed(std::uint64_t stream) const { return ltc_examples::mix_seed(run, stream); }
    glm::vec2 at(std::uint64_t stream) const {
        return ltc::screen_point<float>(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), seed(stream));
    }
};

}  // namespace shadows
