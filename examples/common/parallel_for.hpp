// examples/common/parallel_for.hpp -- f(i) for i in [0, n) on worker threads (indices handed out
// in order), shared by the error reports (ggx_error_report, textured_error_report).
#pragma once

#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace ltc_examples {

template <typename F>
void parallel_for(std::size_t n, unsigned threads, F&& f) {
    std::atomic<std::size_t> next{0};
    std::vector<std::thread> pool;
    for (unsigned k = 0; k < threads; ++k)
        pool.emplace_back([&] {
            for (std::size_t i; (i = next.fetch_add(1)) < n;) f(i);
        });
    for (auto& t : pool) t.join();
}

}  // namespace ltc_examples
