#!/usr/bin/env python3
"""Error against shading time of the shadows example's methods, log-log.

    python3 plot_error_vs_time.py [--cpu] [error_vs_time.csv] [error_vs_time.png]

Reads the CSV that `shadows` writes (method, spp, seconds, mean_relative_error, relative_rmse,
rays_per_pixel, cpu_seconds, and the same errors over the dielectric and the gold tiles) and draws
the mean relative error (top row) and the relative RMSE (bottom row) over all the floor, its
dielectric tiles and its gold tiles (columns; all the floor only, for a CSV without the materials'
columns) against the wall-clock seconds of shading the whole image (with --cpu: its CPU seconds,
steadier on a shared machine): one line per method, its spp marked at every point. Equal time is
a vertical line: the lowest curve there is the best method for that budget.
Needs python3 and matplotlib (Debian: python3-matplotlib, for /usr/bin/python3).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt

LABELS = {
    "ratio_ltc": "(a) LTC + ratio, LTC and light-area samples (MIS)",
    "ratio_ltc_adaptive": "(a+) (a) with an early stop after 4 agreeing samples",
    "ratio_area": "(b) LTC + ratio, light-area samples",
    "mis": "(c) Monte Carlo, MIS",
    "ratio_ltc_denoised": "(d) (a), its estimates denoised",
    "mis_denoised": "(e) (c), denoised by the same filter",
}
REGIONS = [("", "all the floor"), ("dielectric_", "the dielectric tiles"), ("gold_", "the gold tiles")]
ERRORS = [("mean_relative_error", "mean relative error |e|"), ("relative_rmse", "relative RMSE")]


def main():
    args = [a for a in sys.argv[1:] if a != "--cpu"]
    time_column = "cpu_seconds" if "--cpu" in sys.argv[1:] else "seconds"
    src = args[0] if args else "error_vs_time.csv"
    dst = args[1] if len(args) > 1 else src.rsplit(".", 1)[0] + ".png"
    runs = {}
    with open(src, newline="") as f:
        reader = csv.DictReader(f)
        regions = [r for r in REGIONS if r[0] + ERRORS[0][0] in reader.fieldnames]
        for row in reader:
            runs.setdefault(row["method"], []).append(row)

    fig, axes = plt.subplots(len(ERRORS), len(regions), figsize=(5.2 * len(regions), 8.5), squeeze=False)
    clock = "CPU" if time_column == "cpu_seconds" else "wall clock"
    for i, (column, error_name) in enumerate(ERRORS):
        for j, (prefix, region_name) in enumerate(regions):
            ax = axes[i][j]
            for method, rows in runs.items():
                rows.sort(key=lambda r: int(r["spp"]))
                t = [float(r[time_column]) for r in rows]
                e = [float(r[prefix + column]) for r in rows]
                line, = ax.plot(t, e, "o-", markersize=3.5, label=LABELS.get(method, method))
                for r, x, y in zip(rows, t, e):
                    ax.annotate(r["spp"], (x, y), textcoords="offset points", xytext=(3, 3), fontsize=6.5,
                                color=line.get_color())
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel("shading time of the whole image, %s (s)" % clock)
            ax.set_ylabel(error_name + " of luminance")
            ax.set_title("%s over %s" % (error_name, region_name), fontsize=10)
            ax.grid(True, which="both", alpha=0.3)
    axes[0][0].legend(fontsize=7.5)
    fig.tight_layout()
    fig.savefig(dst, dpi=110)
    print("wrote", dst)


if __name__ == "__main__":
    main()
