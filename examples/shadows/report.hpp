// shadows/report.hpp -- the sweep's results: error_vs_time.csv, the printed tables (the errors over
// all the floor, over its dielectric tiles and over its gold tiles), the equal-time comparison, and
// the noise and bias of (a), (a+) and (d).
// Equal time: at the time of (a), (a+) or (d) with K samples, the errors of (a), (b), (c) and (e)
// at that same time, interpolated linearly in (log time, log error) between their measured spp
// (beyond their range, extrapolated along the nearest segment's slope, marked ~); over all the
// floor by the wall clock and by the CPU time (measure.hpp: the steadier one where other work
// shares the cores), over each material by the CPU time. The time is always the whole image's.
#pragma once

#include "measure.hpp"
#include "shade_ratio.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace shadows {

struct sweep_row {
    method which;
    int spp;
    double seconds, cpu_seconds, rays_per_pixel;
    region_errors error;
};

inline bool write_csv(const std::filesystem::path& path, const std::vector<sweep_row>& rows) {
    const std::string name = path.string();
    std::FILE* f = std::fopen(name.c_str(), "w");
    if (f == nullptr) {
        std::fprintf(stderr, "error: cannot write %s\n", name.c_str());
        return false;
    }
    std::fprintf(f, "method,spp,seconds,mean_relative_error,relative_rmse,rays_per_pixel,cpu_seconds,mean_signed_error");
    for (const char* g : {"dielectric", "gold"})
        std::fprintf(f, ",%s_mean_relative_error,%s_relative_rmse,%s_mean_signed_error", g, g, g);
    std::fprintf(f, "\n");
    for (const sweep_row& r : rows) {
        const error_measure& e = r.error[region::floor];
        std::fprintf(f, "%s,%d,%.6g,%.6g,%.6g,%.4g,%.6g,%.6g", method_name(r.which), r.spp, r.seconds, e.mean_rel,
                     e.rel_rmse, r.rays_per_pixel, r.cpu_seconds, e.mean_signed);
        for (region g : {region::dielectric, region::gold})
            std::fprintf(f, ",%.6g,%.6g,%.6g", r.error[g].mean_rel, r.error[g].rel_rmse, r.error[g].mean_signed);
        std::fprintf(f, "\n");
    }
    const bool ok = std::fclose(f) == 0;
    if (ok) std::printf("wrote %s\n", name.c_str());
    return ok;
}

inline void print_table(const std::vector<sweep_row>& rows, region g) {
    if (rows.empty()) return;
    std::printf("\nerrors over %s (%zu pixels); times and rays: the whole image's\n", region_name(g),
                rows[0].error[g].pixels);
    std::printf("%-23s %5s %9s %9s %8s %10s %10s %12s\n", "method", "spp", "seconds", "CPU s", "rays/px", "mean |e|",
                "rel RMSE", "mean signed");
    for (const sweep_row& r : rows) {
        const std::string name = std::string(method_label(r.which)) + " " + method_name(r.which);
        const error_measure& e = r.error[g];
        std::printf("%-23s %5d %9.4f %9.4f %8.1f %9.2f%% %9.2f%% %+11.2f%%\n", name.c_str(), r.spp, r.seconds,
                    r.cpu_seconds, r.rays_per_pixel, 100 * e.mean_rel, 100 * e.rel_rmse, 100 * e.mean_signed);
    }
}

inline double time_of(const sweep_row& r, bool cpu) { return cpu ? r.cpu_seconds : r.seconds; }

/// An error at a time: its value, and whether it was extrapolated.
struct timed_error {
    double value = NAN;
    bool extrapolated = true;
};

/// The error of `which` over g at time t (file comment): mean |e|, or the RMSE.
inline timed_error error_at_time(const std::vector<sweep_row>& rows, method which, region g, double t, bool cpu,
                                 bool rmse) {
    std::vector<std::pair<double, double>> p;  // (log t, log e)
    for (const sweep_row& r : rows) {
        const double e = rmse ? r.error[g].rel_rmse : r.error[g].mean_rel;
        if (r.which == which && time_of(r, cpu) > 0 && e > 0) p.emplace_back(std::log(time_of(r, cpu)), std::log(e));
    }
    timed_error out;
    if (p.empty()) return out;
    std::sort(p.begin(), p.end());
    const double x = std::log(t);
    if (p.size() == 1) {  // the Monte Carlo rate
        out.value = std::exp(p[0].second - 0.5 * (x - p[0].first));
        return out;
    }
    std::size_t k = 0;  // the segment [k, k + 1]
    while (k + 2 < p.size() && x > p[k + 1].first) ++k;
    out.extrapolated = x < p.front().first || x > p.back().first;
    const double dx = p[k + 1].first - p[k].first;
    const double slope = dx > 0 ? (p[k + 1].second - p[k].second) / dx : 0.0;
    out.value = std::exp(p[k].second + slope * (x - p[k].first));
    return out;
}

/// The rows the comparison is made at: (a), (a+) and (d) with K = 1, 4, 16.
inline bool equal_time_anchor(const sweep_row& r) {
    return (r.which == method::ratio_ltc || r.which == method::ratio_ltc_adaptive ||
            r.which == method::ratio_ltc_denoised) &&
           (r.spp == 1 || r.spp == 4 || r.spp == 16);
}

/// A cell of the equal-time table: 100 e (percent) or e / x, ~ when extrapolated; "-" if skipped.
inline std::string cell(const timed_error& e, double x, bool percent, bool skip = false) {
    char s[32] = "- ";
    if (!skip) std::snprintf(s, sizeof s, percent ? "%.2f%%%s" : "%.2f%s", percent ? 100 * e.value : e.value / x,
                             e.extrapolated ? "~" : " ");
    return s;
}

inline void print_equal_time(const std::vector<sweep_row>& rows, bool cpu, region g) {
    if (std::none_of(rows.begin(), rows.end(), equal_time_anchor)) return;
    std::printf("\nequal %s time, errors over %s: those of the others at the shading time of x = (a), (a+)\n"
                "or (d) with K samples (interpolated log-log in time; ~ extrapolated); ratios > 1: x is better\n",
                cpu ? "CPU" : "wall-clock", region_name(g));
    std::printf("%-4s %4s %9s | %9s %10s %10s %10s %10s | %7s %7s %7s %7s | %9s %9s %9s %9s\n", "x", "K", "seconds",
                "x |e|", "(a) |e| ", "(b) |e| ", "(c) |e| ", "(e) |e| ", "(a)/x ", "(b)/x ", "(c)/x ", "(e)/x ",
                "RMSE a/x ", "RMSE b/x ", "RMSE c/x ", "RMSE e/x ");
    constexpr int columns = 4;
    const method others[columns] = {method::ratio_ltc, method::ratio_area, method::mis, method::mis_denoised};
    for (const sweep_row& x : rows) {
        if (!equal_time_anchor(x)) continue;
        const double t = time_of(x, cpu), e = x.error[g].mean_rel, r = x.error[g].rel_rmse;
        std::string means, ratios, rmses;
        for (int k = 0; k < columns; ++k) {
            const bool self = x.which == others[k];  // (a) against itself: left out
            const timed_error mean = error_at_time(rows, others[k], g, t, cpu, false);
            const timed_error rmse = error_at_time(rows, others[k], g, t, cpu, true);
            char c[3][48];
            std::snprintf(c[0], sizeof c[0], " %10s", cell(mean, e, true, self).c_str());
            std::snprintf(c[1], sizeof c[1], " %7s", cell(mean, e, false, self).c_str());
            std::snprintf(c[2], sizeof c[2], " %9s", cell(rmse, r, false, self).c_str());
            means += c[0], ratios += c[1], rmses += c[2];
        }
        std::printf("%-4s %4d %9.4f | %8.2f%%%s |%s |%s\n", method_label(x.which), x.spp, t, 100 * e, means.c_str(),
                    ratios.c_str(), rmses.c_str());
    }
}

/// One method at one K rendered twice with independent seeds (the first is the sweep's).
struct seed_pair {
    method which;
    int spp;
    std::vector<dvec3> first, second;
};

/// The noise and bias of each pair over the floor: the RMS of the per-pixel standard deviation
/// (measure.hpp's relative_noise), and the bias sqrt(RMSE^2 - noise^2 - reference noise^2) (the
/// LTC fit's and the ratio estimator's; for (a+) also the early stop's, for (d) the filter's, and
/// with --ltc-correction on (d)'s without the LTC fit's); for (a+) and (d), the shift from (a) at
/// the same K, with the same random numbers (measure.hpp's relative_shift: the early stop's or the
/// filter's bias, and the change of the ratio estimator's own bias with the samples it averages;
/// with --ltc-correction on also the LTC's correction).
inline void print_noise_bias(const std::vector<seed_pair>& pairs, const std::vector<pixel_hit>& hits,
                             const std::vector<dvec3>& ref, double floor, double reference_rms_noise) {
    if (pairs.empty()) return;
    std::printf("\nnoise and bias against the reference, over the floor, from two seeds: noise (RMS of the\n"
                "per-pixel standard deviation), RMS bias (sqrt(RMSE^2 - noise^2 - reference RMS noise^2)),\n"
                "mean signed error; for (a+) and (d), the shift from (a) at the same K and seeds (sqrt of the\n"
                "mean product of the two seeds' differences, and the mean signed difference)\n");
    std::printf("%-4s %4s %10s %10s %10s %10s %10s %12s | %10s %12s\n", "x", "K", "|e| seed1", "|e| seed2", "RMSE",
                "noise", "RMS bias", "mean signed", "shift RMS", "shift signed");
    for (const seed_pair& p : pairs) {
        const error_measure ea = measure_error(hits, p.first, ref, floor)[region::floor];
        const error_measure eb = measure_error(hits, p.second, ref, floor)[region::floor];
        const double noise = relative_noise(hits, p.first, p.second, ref, floor);
        const double mse = 0.5 * (ea.rel_rmse * ea.rel_rmse + eb.rel_rmse * eb.rel_rmse);
        const double bias2 = mse - noise * noise - reference_rms_noise * reference_rms_noise;
        std::printf("%-4s %4d %9.2f%% %9.2f%% %9.2f%% %9.2f%% %9.2f%% %+11.2f%% |", method_label(p.which), p.spp,
                    100 * ea.mean_rel, 100 * eb.mean_rel, 100 * std::sqrt(mse), 100 * noise,
                    100 * std::sqrt(std::max(0.0, bias2)), 50 * (ea.mean_signed + eb.mean_signed));
        const auto a = std::find_if(pairs.begin(), pairs.end(), [&](const seed_pair& q) {
            return q.which == method::ratio_ltc && q.spp == p.spp;
        });
        if (p.which == method::ratio_ltc || a == pairs.end()) {
            std::printf(" %10s %12s\n", "-", "-");
            continue;
        }
        const shift_measure s = relative_shift(hits, p.first, p.second, a->first, a->second, ref, floor);
        std::printf(" %9.2f%% %+11.2f%%\n", 100 * s.rms, 100 * s.mean_signed);
    }
}

}  // namespace shadows
