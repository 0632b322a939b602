#!/usr/bin/env python3
"""docs/results/summary.md and the README's results:summary block, from the generated results.

Reads docs/results/ggx_error.md (ggx_error_report's table 1) and the benchmarks' JSON
(bench_batch, bench_shading: medians of the repetitions), and writes the accuracy and speed lines.
Run by tools/results.sh; never edit the outputs by hand (CTest's docs_check compares them).
"""
import argparse
import json
import os
import re

BEGIN, END = "<!-- results:summary:begin -->", "<!-- results:summary:end -->"


def medians(path):
    with open(path) as f:
        data = json.load(f)
    return {b["run_name"]: b.get("items_per_second", 0.0)
            for b in data["benchmarks"] if b.get("aggregate_name") == "median"}


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--results", required=True)
    p.add_argument("--json", required=True)
    p.add_argument("--readme", required=True)
    p.add_argument("--stamp", required=True)
    a = p.parse_args()

    text = open(os.path.join(a.results, "ggx_error.md")).read()
    m = re.search(r"^\s*exact\s*\|\s*([0-9.]+%)\s+([0-9.]+%)", text, re.M)
    mean, p95 = m.group(1), m.group(2)
    count = re.search(r"all ([0-9]+) significant configurations", text).group(1)
    quads = medians(os.path.join(a.json, "bench_batch.json"))
    shading = medians(os.path.join(a.json, "bench_shading.json"))
    ref_q = quads["BM_reference_shader"]
    ref_s = shading["BM_reference_shading"]
    best_q = max(v for k, v in quads.items() if k.startswith("BM_batch_quads"))
    best_s = max(v for k, v in shading.items() if k.startswith("BM_batch_shading"))
    lines = [
        f"- **Accuracy**: GGX shading of polygonal lights with the paper's one-lobe table, against a Monte "
        f"Carlo ground truth over {count} configurations: mean relative error {mean}, 95th percentile {p95} "
        f"([results/ggx_error.md](docs/results/ggx_error.md), which also compares the horizon clippings and "
        f"the three models of `ltc::shade`).",
        f"- **Speed**: the clamped-cosine integral of a quad in batches at {best_q / ref_q:.1f}x a port of the "
        f"paper's shader compiled alongside, GGX shading of a quad light in batches at {best_s / ref_s:.1f}x "
        f"its shading ([results/speed.md](docs/results/speed.md)).",
    ]
    with open(os.path.join(a.results, "summary.md"), "w") as f:
        f.write("# Summary\n\n" + a.stamp + "\n\n" + "\n".join(l.replace("](docs/results/", "](") for l in lines) + "\n")
    readme = open(a.readme).read()
    i, j = readme.index(BEGIN) + len(BEGIN), readme.index(END)
    readme = readme[:i] + "\n" + "\n".join(lines) + "\n" + readme[j:]
    with open(a.readme, "w") as f:
        f.write(readme)


if __name__ == "__main__":
    main()
