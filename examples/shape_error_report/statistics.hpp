// shape_error_report/statistics.hpp -- mean, 95th percentile and max of a sample of errors; which
// configurations count (significant: truth >= 1e-3 of the albedo, as in ggx_error_report); and a
// column of a table: a name and the relative error of one configuration.
#pragma once

#include "grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

namespace shape_error_report {

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

/// In the statistics: a grid configuration (not a sanity line) whose truth is at least 1e-3 of the
/// directional albedo (the others are invisible next to any light that faces the lobe).
inline bool significant(const config& c) { return !c.inside && c.gt.mean >= 1e-3 * c.albedo; }

inline double relative(double value, double truth) { return std::abs(value - truth) / truth; }

/// A column of a table: its name and the error of one configuration.
struct column {
    const char* name;
    std::function<double(const config&)> error;
};

/// The errors of one column over the significant configurations of `shape` that `keep` accepts.
inline std::vector<double> errors(const std::vector<config>& grid, int shape, const column& col,
                                  const std::function<bool(const config&)>& keep) {
    std::vector<double> e;
    for (const config& c : grid)
        if (c.shape == shape && significant(c) && keep(c)) e.push_back(col.error(c));
    return e;
}

}  // namespace shape_error_report
