// ltc/fitting/options.hpp -- the fitter's settings (options) and the coordinates of the nodes of
// a fitted table (node_x, node_cos_theta, node_roughness, node_alpha).
//
// Node (t, a) of an N x N table has x = t / (N - 1), cos theta_v = max(1 - x^2, cos_min)
// and roughness r = a / (N - 1), alpha = max(r^2, alpha_min) (see ltc/tables/ltc_table.hpp).
#pragma once

#include <ltc/config.hpp>

#include <algorithm>

LTC_NAMESPACE_BEGIN
namespace fit {

/// What each node minimizes: the paper's L3 distance between the lobes (l3, the default: the
/// shipped tables), the relative error of integrals over a fixed family of polygons (integrals),
/// or their sum (combined); see ltc/fitting/integral_objective.hpp and fit_integrals.hpp.
enum class objective { l3, integrals, combined };

struct options {
    int size = 64;                 ///< N: the table has N x N nodes
    double alpha_min = 1e-4;       ///< alpha = max(roughness^2, alpha_min) (paper code: 1e-4)
    double cos_theta_min = 7.9632671073326335e-4;  ///< cos(1.57): V.z = 0 leaves rho undefined
    int moment_samples = 64;       ///< n x n samples for magnitude, fresnel, average direction
    int error_samples = 32;        ///< n x n samples per distribution for the L3 error (paper: 32)
    int rounds = 2;                ///< proposal refreshes per node (see ltc/fitting/error_metric.hpp)
    int parameters = 4;            ///< 4: (m11, m22, m13, m31); 3: m31 = 0, as the paper's code
    double tolerance = 1e-5;       ///< Nelder-Mead relative tolerance on the objective (paper: 1e-5)
    int max_evaluations = 400;     ///< per Nelder-Mead run
    double initial_step = 0.1;     ///< simplex size of the first round (log / ratio units)
    unsigned threads = 0;          ///< worker threads for fit_table (0: all cores)
    double progress_interval = 0.1;  ///< seconds between progress callbacks
    objective goal = objective::l3;  ///< the per-node objective (l3: the shipped tables)
    bool fit_magnitude = false;      ///< integrals / combined: also fit a scale of the magnitude
};

/// x = sqrt(1 - cos theta_v) of node t of n.
inline double node_x(int t, int n) { return n > 1 ? double(t) / double(n - 1) : 0.0; }
/// cos theta_v of node t of n: 1 - x^2, at least cos_theta_min.
inline double node_cos_theta(int t, int n, double cos_theta_min) {
    const double x = node_x(t, n);
    return std::max(1.0 - x * x, cos_theta_min);
}
/// Roughness of node a of n.
inline double node_roughness(int a, int n) { return n > 1 ? double(a) / double(n - 1) : 1.0; }
/// alpha of node a of n: max(roughness^2, alpha_min).
inline double node_alpha(int a, int n, double alpha_min) {
    const double r = node_roughness(a, n);
    return std::max(r * r, alpha_min);
}

}  // namespace fit
LTC_NAMESPACE_END
