// examples/common/parallel_for.hpp -- f(i) for i in [0, n) on worker threads (indices handed out
// in order), shared by the error reports (ggx_error_report, textured_error_report,
// shape_error_report); with a label, their progress on stderr (common/progress.hpp).
#pragma once

#include "common/progress.hpp"

#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace ltc_examples {

/// With a label, the calling thread shows how many of the n items (`unit`) are done.
template <typename F>
void parallel_for(std::size_t n, unsigned threads, F&& f, const char* label = nullptr, const char* unit = "") {
    std::atomic<std::size_t> next{0}, done{0};
    std::vector<std::thread> pool;
    for (unsigned k = 0; k < threads; ++k)
        pool.emplace_back([&] {
            for (std::size_t i; (i = next.fetch_add(1)) < n;) {
                f(i);
                done.fetch_add(1);
            }
        });
    if (label != nullptr) {
        progress shown(label, unit);
        watch(shown, done, n);
    }
    for (auto& t : pool) t.join();
}

}  // namespace ltc_examples
