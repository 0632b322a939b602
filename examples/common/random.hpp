// common/random.hpp -- seeds for the renderers' Monte Carlo (render, shadows): independent seeds
// per run, pixel and iteration from one base seed, each fed to ltc::ground_truth::splitmix64.
#pragma once

#include <cstdint>

namespace ltc_examples {

/// SplitMix64's finalizer of a combination of a and b.
inline std::uint64_t mix_seed(std::uint64_t a, std::uint64_t b) {
    std::uint64_t z = a * 0x9E3779B97F4A7C15ull + b + 0x632BE59BD9B4E019ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

}  // namespace ltc_examples
