// ggx_error_report/statistics.hpp -- relative errors |LTC - GT| / GT over the significant
// configurations (GT >= 1e-3 of the albedo), filtered by any predicate, and their mean, 95th
// percentile and max.
#pragma once

#include "grid.hpp"
#include "ltc_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

namespace ggx_error_report {

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
    std::size_t k = std::size_t(std::ceil(0.95 * double(e.size())));
    s.p95 = e[std::min(e.size() - 1, k > 0 ? k - 1 : 0)];
    s.max = e.back();
    return s;
}

inline bool significant(const config& c, double albedo) { return c.gt.mean >= 1e-3 * albedo; }

inline std::vector<double> rel_errors(const std::vector<config>& grid, const evaluation& ev, int m,
                                      const std::function<bool(const config&)>& keep) {
    std::vector<double> e;
    for (std::size_t i = 0; i < grid.size(); ++i)
        if (keep(grid[i]) && significant(grid[i], ev.albedo[i]))
            e.push_back(std::abs(ev.value[m][i] - grid[i].gt.mean) / grid[i].gt.mean);
    return e;
}

}  // namespace ggx_error_report
