// ltc/shading/detail/texture_filter.hpp -- the one-dimensional pieces of the prefilter of textured
// lights (paper section 5.3; the filter (*) and its levels are described in
// ltc/shading/light_texture.hpp): the sample grid of one axis of a level, the normalized
// Gaussian taps of (*) along an axis, a loop split over threads, and the lerp that keeps a
// constant texture constant.
#pragma once

#include <ltc/config.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <thread>
#include <vector>

LTC_NAMESPACE_BEGIN

namespace detail {

/// One axis of a level: output sample i (0 <= i < count) sits at ((i - margin_cells) + 0.5) / cells.
struct texture_axis {
    int texels = 1;        ///< n, texels of the image along this axis
    int cells = 1;         ///< n_k, cells across [0, 1]
    int margin_cells = 0;  ///< extra cells on each side
    int count() const { return cells + 2 * margin_cells; }
    double position(int i) const { return (double(i - margin_cells) + 0.5) / double(cells); }
};

/// Normalized 1D weights of (*) at the uv coordinate p for an axis of n texels and the level's
/// sigma: taps [first, first + weights.size()) of the texels, summing to 1 (in double).
inline void gaussian_taps(double p, int n, double sigma, int& first, std::vector<double>& weights) {
    const double d = std::max(0.0, std::max(-p, p - 1.0));
    const double s = std::sqrt(sigma * sigma + d * d);
    // Nearest texel centre (always kept): (t + 0.5) / n closest to p.
    int nearest = static_cast<int>(std::floor(p * n));
    nearest = std::min(std::max(nearest, 0), n - 1);
    weights.clear();
    const double cn = (nearest + 0.5) / n;
    if (!(s * n > 1e-6)) {  // sigma (in texels) ~ 0: the limit of (*) is the nearest texel
        first = nearest;
        weights.push_back(1.0);
        return;
    }
    const double radius = 7.0 * s;
    int lo = static_cast<int>(std::ceil((p - radius) * n - 0.5));
    int hi = static_cast<int>(std::floor((p + radius) * n - 0.5));
    lo = std::min(std::max(lo, 0), nearest);
    hi = std::max(std::min(hi, n - 1), nearest);
    first = lo;
    // exp(-((p - c)^2 - (p - cn)^2) / (2 s^2)): relative to the nearest texel, so the largest
    // weight is 1 and nothing underflows.
    const double dn2 = (p - cn) * (p - cn);
    const double inv = 1.0 / (2.0 * s * s);
    double sum = 0;
    for (int t = lo; t <= hi; ++t) {
        const double c = (t + 0.5) / n;
        const double w = std::exp(-((p - c) * (p - c) - dn2) * inv);
        weights.push_back(w);
        sum += w;
    }
    for (double& w : weights) w /= sum;
}

/// Runs body(i) for i in [0, n) on up to hardware_concurrency threads (contiguous blocks).
template <typename Body>
inline void parallel_for(int n, const Body& body) {
    // Once per program: the call reads /sys on Linux, which every filter pass would pay again.
    static const unsigned hw = std::thread::hardware_concurrency();
    int threads = static_cast<int>(hw == 0 ? 1 : hw);
    threads = std::min(threads, std::max(1, n / 16));
    if (threads <= 1) {
        for (int i = 0; i < n; ++i) body(i);
        return;
    }
    std::vector<std::thread> pool;
    pool.reserve(static_cast<std::size_t>(threads));
    for (int t = 0; t < threads; ++t) {
        const int begin = static_cast<int>(static_cast<long long>(n) * t / threads);
        const int end = static_cast<int>(static_cast<long long>(n) * (t + 1) / threads);
        pool.emplace_back([&body, begin, end] {
            for (int i = begin; i < end; ++i) body(i);
        });
    }
    for (auto& th : pool) th.join();
}

/// a + t (b - a): returns a exactly when a == b (so constants stay constant).
inline glm::vec3 lerp_exact(const glm::vec3& a, const glm::vec3& b, float t) { return a + t * (b - a); }

}  // namespace detail

LTC_NAMESPACE_END
