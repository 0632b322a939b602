// common/error_summary.hpp -- the mean, 95th percentile and max of a sample of relative errors:
// the columns of the error reports' tables (ggx_error_report, shape_error_report).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace ltc_examples {

struct stats {
    double mean = 0, p95 = 0, max = 0;
    std::size_t count = 0;
};

inline stats summarize(std::vector<double> e) {
    stats s;
    s.count = e.size();
    if (e.empty()) return s;
    std::sort(e.begin(), e.end());
    double sum = 0;
    for (double x : e) sum += x;
    s.mean = sum / double(e.size());
    // 95th percentile: the smallest value with at least 95% of the sample at or below it.
    const std::size_t k = std::size_t(std::ceil(0.95 * double(e.size())));
    s.p95 = e[std::min(e.size() - 1, k > 0 ? k - 1 : 0)];
    s.max = e.back();
    return s;
}

}  // namespace ltc_examples
