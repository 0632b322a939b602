#!/usr/bin/env python3
"""The README's speed tables and plot, from Google Benchmark JSON.

Runs bench_batch and bench_shading in each of their builds (benchmarks/CMakeLists.txt: the build
type's flags, -O2, and both with -march=x86-64-v3), every row the median of 5 repetitions with
the benchmarks interleaved at random, writes each run's JSON to --out, prints the tables as
Markdown (throughput and ratio to the reference port of the same executable: both sides are
compiled with the same flags), and draws docs/images/speed.png (needs matplotlib: Debian
python3-matplotlib).

    python3 benchmarks/speed_tables.py --build build --out build/speed
    python3 benchmarks/speed_tables.py --json build/speed      # tables and plot from earlier runs
"""
import argparse
import json
import os
import subprocess
import sys

BUILDS = [("", "-O3"), ("_o2", "-O2"), ("_avx2", "-O3 -march=x86-64-v3"), ("_o2_avx2", "-O2 -march=x86-64-v3")]

# (benchmark name in the JSON, column title)
BATCH_ROWS = [
    ("BM_reference_shader", "reference port"),
    ("BM_library_scalar<ltc::edge_policy::exact>", "scalar, exact"),
    ("BM_library_scalar<minimax_rational>", "scalar, default (minimax_rational)"),
    ("BM_batch_quads<minimax_rational, isa::baseline>", "batch, baseline (SSE2)"),
    ("BM_batch_quads<minimax_rational, isa::avx2>", "batch, AVX2"),
    ("BM_batch_quads<minimax_rational, isa::avx512>", "batch, AVX-512"),
    ("BM_batch_quads<minimax_rational, isa::automatic>", "batch, automatic"),
]
SHADING_ROWS = [
    ("BM_reference_shading", "reference shading port"),
    ("BM_library_scalar<ltc::edge_policy::exact>", "shade_polygon_light_one_lobe, exact"),
    ("BM_library_scalar<ltc::edge_policy::minimax_rational>", "shade_polygon_light_one_lobe, default edge terms"),
    ("BM_shade<ltc::ggx::one_lobe>", "shade<ggx::one_lobe>"),
    ("BM_shade<ltc::ggx::ltc_and_cosine>", "shade<ggx::ltc_and_cosine>"),
    ("BM_shade<ltc::ggx::two_lobes>", "shade<ggx::two_lobes>"),
    ("BM_shade<ltc::ggx::anisotropic>", "shade<ggx::anisotropic>"),
    ("BM_batch_shading<isa::baseline>", "batch, baseline (SSE2)"),
    ("BM_batch_shading<isa::avx2>", "batch, AVX2"),
    ("BM_batch_shading<isa::avx512>", "batch, AVX-512"),
    ("BM_batch_shading<isa::automatic>", "batch, automatic"),
]


def run(build, out):
    os.makedirs(out, exist_ok=True)
    for program in ("bench_batch", "bench_shading"):
        for suffix, _ in BUILDS:
            exe = os.path.join(build, "benchmarks", program + suffix)
            if not os.path.exists(exe):
                print(f"skipped {exe} (not built)", file=sys.stderr)
                continue
            path = os.path.join(out, program + suffix + ".json")
            subprocess.run([exe, "--benchmark_min_time=0.2", "--benchmark_repetitions=5",
                            "--benchmark_enable_random_interleaving=true",
                            "--benchmark_report_aggregates_only=true",
                            f"--benchmark_out={path}", "--benchmark_out_format=json"],
                           check=True, stdout=subprocess.DEVNULL)


def medians(path):
    """name -> (items per second, max_abs_err or None), medians of the repetitions."""
    with open(path) as f:
        data = json.load(f)
    rows = {}
    for b in data["benchmarks"]:
        if b.get("aggregate_name") != "median":
            continue
        rows[b["run_name"]] = (b.get("items_per_second", 0.0), b.get("max_abs_err"))
    return rows, data["context"]


def table(json_dir, program, rows):
    header = "| build | " + " | ".join(title for _, title in rows) + " |"
    lines = [header, "|" + "---|" * (len(rows) + 1)]
    ratios = {}
    errors = {}
    for suffix, flags in BUILDS:
        path = os.path.join(json_dir, program + suffix + ".json")
        if not os.path.exists(path):
            continue
        m, _ = medians(path)
        ref = m[rows[0][0]][0]
        cells = []
        for name, title in rows:
            ips, err = m.get(name, (0.0, None))
            cells.append(f"{ips / 1e6:.1f} M/s ({ips / ref:.2f}x)")
            ratios.setdefault(title, []).append(ips / ref)
            if err is not None:
                errors.setdefault(title, []).append(err)
        lines.append(f"| {flags} | " + " | ".join(cells) + " |")
    err_line = "max abs error: " + ", ".join(
        f"{title} {max(v):.1e}" for title, v in errors.items())
    return "\n".join(lines), ratios, err_line


def plot(json_dir, image):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.6))
    for ax, (program, rows, what) in zip(axes, [("bench_batch", BATCH_ROWS, "quad integral, 4096 items"),
                                               ("bench_shading", SHADING_ROWS, "GGX shading of a quad light, 4096 points")]):
        _, ratios, _ = table(json_dir, program, rows)
        builds = [flags for suffix, flags in BUILDS
                  if os.path.exists(os.path.join(json_dir, program + suffix + ".json"))]
        width = 0.8 / len(rows)
        for k, (_, title) in enumerate(rows):
            values = ratios.get(title, [])
            ax.bar([i + k * width for i in range(len(values))], values, width, label=title)
        ax.set_xticks([i + 0.4 - width / 2 for i in range(len(builds))])
        ax.set_xticklabels([b.replace(" -march", "\n-march") for b in builds], fontsize=8)
        ax.axhline(1.0, color="black", linewidth=0.6)
        ax.set_ylabel("throughput / reference port")
        ax.set_title(what, fontsize=10)
        ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=2, frameon=False)
    fig.tight_layout()
    fig.savefig(image, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default="build", help="the CMake build directory")
    parser.add_argument("--out", default=None, help="run the benchmarks, writing their JSON here")
    parser.add_argument("--json", default=None, help="use the JSON of an earlier run instead")
    parser.add_argument("--image", default=os.path.join("docs", "images", "speed.png"))
    args = parser.parse_args()
    json_dir = args.json
    if json_dir is None:
        json_dir = args.out or os.path.join(args.build, "speed")
        run(args.build, json_dir)
    _, context = medians(os.path.join(json_dir, "bench_batch.json"))
    print(f"CPU: {context.get('num_cpus')} x {context.get('mhz_per_cpu')} MHz, {context.get('date')}\n")
    for program, rows in (("bench_batch", BATCH_ROWS), ("bench_shading", SHADING_ROWS)):
        text, _, errors = table(json_dir, program, rows)
        print(f"{program}:\n\n{text}\n\n{errors}\n")
    try:
        plot(json_dir, args.image)
        print(f"wrote {args.image}")
    except ImportError:
        print("matplotlib not found (Debian: python3-matplotlib): no plot", file=sys.stderr)


if __name__ == "__main__":
    main()
