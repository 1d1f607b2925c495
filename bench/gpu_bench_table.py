#!/usr/bin/env python3
"""gpu_bench_table.py: pamsim_bench's render results (--benchmark_out JSON files, one per GL
backend) as one Markdown table, with EGL's rate over OSMesa's for each benchmark both ran.
Used by bench/gpu_bench.sh.
Usage: gpu_bench_table.py RESULTS.json..."""

import json
import sys


def rows(path):
    """(benchmark name without its run suffixes, its counters, its label) of each result."""
    try:
        with open(path) as f:
            runs = json.load(f).get("benchmarks", [])
    except (OSError, ValueError) as e:  # a run that failed part way: its log says why
        print(f"- {path}: no results ({e})")
        runs = []
    for r in runs:
        name = r["name"].split("/min_time")[0].split("/real_time")[0].split("/manual_time")[0]
        yield name, r, r.get("label", "")


def rate(r):
    for key in ("frames_per_s", "pamsim_frames_per_s"):
        if key in r:
            return float(r[key])
    return None


def main(paths):
    table = {}  # name -> {backend: result}
    backends = []
    for path in paths:
        backend = path.rsplit("/", 1)[-1].removesuffix(".json").split("-")[-1]
        backends.append(backend)
        for name, r, _ in rows(path):
            table.setdefault(name, {})[backend] = r
    print(
        "| benchmark | "
        + " | ".join(f"{b} [frames/s]" for b in backends)
        + " | egl / osmesa | pamsim / bare MuJoCo (egl) |"
    )
    print("| --- |" + " --- |" * (len(backends) + 2))
    for name, by in table.items():
        cells = [f"{rate(by[b]):.1f}" if b in by and rate(by[b]) else "" for b in backends]
        egl, osm = by.get("egl"), by.get("osmesa")
        ratio = f"{rate(egl) / rate(osm):.2f}" if egl and osm and rate(osm) else ""
        mujoco = (
            f"{float(egl['pamsim_over_mujoco']):.2f}" if egl and "pamsim_over_mujoco" in egl else ""
        )
        print(f"| {name} | " + " | ".join(cells) + f" | {ratio} | {mujoco} |")
    labels = {lab for p in paths for _, _, lab in rows(p) if lab}
    print()
    for lab in sorted(labels):
        print(f"- GL: {lab}")


if __name__ == "__main__":
    main(sys.argv[1:])
