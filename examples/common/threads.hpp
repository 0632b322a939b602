// common/threads.hpp -- timing and threads: seconds since a time point, and rows of an image
// shaded on worker threads with an optional progress bar (with an ETA) on stderr.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <thread>
#include <vector>

namespace ltc_examples {

using clock_type = std::chrono::steady_clock;

inline double seconds_since(clock_type::time_point t0) {
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

}  // namespace ltc_examples
