// textured_error_report/statistics.hpp -- the relative errors of a configuration and their mean,
// 95th percentile and max.
#pragma once

#include "evaluate.hpp"
#include "setup.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace textured_error_report {

struct stats {
    std::vector<double> v;
    void add(double x) { v.push_back(x); }
    double mean() const {
        double s = 0;
        for (double x : v) s += x;
        return v.empty() ? 0 : s / double(v.size());
    }
    /// Nearest rank: the sorted value at p (n - 1), rounded.
    double pct(double p) const {
        if (v.empty()) return 0;
        std::vector<double> s = v;
        std::sort(s.begin(), s.end());
        return s[std::min(s.size() - 1, std::size_t(p * double(s.size() - 1) + 0.5))];
    }
    double max() const { return v.empty() ? 0 : *std::max_element(v.begin(), v.end()); }
};

/// (sum_rgb(approx) - MC) / MC of int L D: the texture error of method m, signed.
inline double signed_texture_error(const texture_result& t, int m) { return (sum(t.approx[m]) - t.truth) / t.truth; }
inline double texture_error(const texture_result& t, int m) { return std::abs(signed_texture_error(t, m)); }

/// |sum_rgb(approx) - sum_rgb(full)| / sum_rgb(full): the error against the exact integral of the
/// texel-constant texture (the full-refinement cells), free of Monte Carlo noise.
inline double exact_error(const texture_result& t, int m) {
    return std::abs(sum(t.approx[m]) - sum(t.full)) / sum(t.full);
}

/// |magnitude sum_rgb(approx) - MC| / MC of int L rho cos: what a renderer gets (magnitude 1
/// for the diffuse lobe, where rho cos = D).
inline double shading_error(const config& c, const texture_result& t, int m) {
    const double magnitude = c.diffuse() ? 1.0 : c.coeff.magnitude;
    return std::abs(magnitude * sum(t.approx[m]) - t.shading_truth) / t.shading_truth;
}

}  // namespace textured_error_report
