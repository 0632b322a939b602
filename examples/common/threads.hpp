// common/threads.hpp -- timing and threads: seconds since a time point, and rows of an image
// shaded on worker threads with optional progress on stderr (common/progress.hpp).
#pragma once

#include "common/progress.hpp"

#include <atomic>
#include <chrono>
#include <cstddef>
#include <thread>
#include <vector>

namespace ltc_examples {

using clock_type = std::chrono::steady_clock;

inline double seconds_since(clock_type::time_point t0) {
    return std::chrono::duration<double>(clock_type::now() - t0).count();
}

/// Runs row(y) for y in [0, height) on `threads` workers (rows handed out in order). With a
/// label, the calling thread shows the progress on stderr (common/progress.hpp) until all are
/// done; it counts row_cost[y] pixels per finished row (rows of sky cost nothing), else rows.
template <typename Row>
void for_each_row(int height, unsigned threads, Row&& row, const char* label = nullptr,
                  const std::vector<long long>* row_cost = nullptr) {
    const auto cost = [&](int y) {
        return row_cost ? static_cast<std::size_t>((*row_cost)[static_cast<std::size_t>(y)]) : std::size_t(1);
    };
    std::atomic<int> next{0};
    std::atomic<std::size_t> done{0};
    std::size_t total = 0;
    for (int y = 0; y < height; ++y) total += cost(y);
    std::vector<std::thread> pool;
    for (unsigned k = 0; k < threads; ++k)
        pool.emplace_back([&] {
            for (int y; (y = next.fetch_add(1)) < height;) {
                row(y);
                done.fetch_add(cost(y));
            }
        });
    if (label != nullptr) {
        progress shown(label, row_cost ? "pixels" : "rows");
        watch(shown, done, total);
    }
    for (auto& t : pool) t.join();
}

}  // namespace ltc_examples
