#!/usr/bin/env python3
"""band_widths.py: two band runs of one protocol (`pamsim validate ... --bands N`, their
folders) side by side: per cell with a paper value, the RMSE's 5-95 % range and its width in
each, and whether the paper's value lies inside; then how many rigs each run's protocol
refused. What a new bracket did to the bands: how far it widened each cell, and whether it
refused more rigs.

    python3 scripts/band_widths.py BEFORE_DIR AFTER_DIR
"""

import argparse
import csv
import os
import sys


def rmse_rows(folder):
    with open(os.path.join(folder, "bands.csv")) as f:
        rows = csv.DictReader(f)
        return {r["cell"]: r for r in rows if r["metric"] == "rmse" and r["paper_pct"]}


def refused(folder):
    with open(os.path.join(folder, "draws.csv")) as f:
        rows = list(csv.DictReader(f))
    return sum(1 for r in rows if r["refused"]), len(rows)


def band(row):
    if row is None or not row["p5_pct"]:
        return "n/a", "n/a", "-"
    lo, hi = float(row["p5_pct"]), float(row["p95_pct"])
    return f"[{lo:.3g}, {hi:.3g}]", f"{hi - lo:.3g}", row["paper_is"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("before")
    ap.add_argument("after")
    a = ap.parse_args()
    for folder in (a.before, a.after):
        for name in ("bands.csv", "draws.csv"):
            if not os.path.isfile(os.path.join(folder, name)):
                sys.exit(f"{folder}: no {name} (the folder of a `pamsim validate ... --bands` run)")
    before, after = rmse_rows(a.before), rmse_rows(a.after)
    columns = ["cell", "paper RMSE"]
    for run in ("before", "after"):
        columns += [f"{run}: 5-95 %", "width", "paper is"]
    print("| " + " | ".join(columns) + " |")
    print("|" + " --- |" * len(columns))
    for cell, row in after.items():
        b, w = band(before.get(cell)), band(row)
        print("| " + " | ".join((cell, row["paper_pct"]) + b + w) + " |")
    for name, folder in (("before", a.before), ("after", a.after)):
        k, n = refused(folder)
        print(f"\n{name}: the protocol refused {k} of {n} rigs", end="")
    print()


if __name__ == "__main__":
    main()
