#!/usr/bin/env python3
"""regulator_loop.py: the passive drop's chamber pressure rise at impact across the regulator
bracket (models/pams/pneumatics.toml [regulator]). Each row is one
`pamsim run scenarios/drop_mass_passive.toml` with `--set` overrides, so any row can be rerun
by hand. The rise is the agonist's largest chamber pressure (trajectory.csv, logged at the
control rate) within 0.3 s after the impact less its pressure at the impact; the swing is
the largest minus the smallest pressure in that window (a loop that rings shows there).
Prints Markdown.

    python3 scripts/regulator_loop.py [--pamsim build/src/sim/pamsim]
"""

import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile
import tomllib


def loop(feedback, sense, dead_ms, lag_ms, band_kpa, conductance):
    """The --set overrides of one regulator: its loop, dead time, valve lag, band, and the
    supply and exhaust sonic conductance [dm^3/(s bar)]."""
    return [
        f'valve.feedback="{feedback}"',
        f'valve.sense="{sense}"',
        f"valve.dead_time_ms={dead_ms}",
        f"valve.valve_time_constant_ms={lag_ms}",
        f"valve.proportional_band_kPa={band_kpa}",
        f"valve.supply_sonic_conductance_dm3_per_s_bar={conductance}",
        f"valve.exhaust_sonic_conductance_dm3_per_s_bar={conductance}",
    ]


def bracket_end(end, feedback, sense):
    """One end of models/pams/regulator_bracket.toml as --set overrides, its loop as given."""
    with open("models/pams/regulator_bracket.toml", "rb") as f:
        keys = tomllib.load(f)[end]
    keys.update({"valve.feedback": feedback, "valve.sense": sense})
    return [f'{k}="{v}"' if isinstance(v, str) else f"{k}={v}" for k, v in keys.items()]


# (label, overrides); the fast / slow ends' bands are pneumatics.toml's derivation; the
# shipped regulator is the slow end with its loop delayed at the outlet
ROWS = [
    (
        "the earlier loop (instant, chamber; 5 ms / 10 ms / 20 kPa, C = 1)",
        bracket_end("earlier_loop", "instant", "chamber"),
    ),
    ("the earlier loop, dead time 1000 ms", loop("instant", "chamber", 1000, 10, 20, 1.0)),
    ("old bracket fastest (2 / 5 / 10 kPa)", loop("instant", "chamber", 2, 5, 10, 1.0)),
    ("old bracket slowest (10 / 20 / 50 kPa)", loop("instant", "chamber", 10, 20, 50, 1.0)),
    ("fast end, ITV2000 class, instant loop", bracket_end("fast", "instant", "chamber")),
    (
        "fast end, ITV2000 class, delayed loop at the outlet",
        bracket_end("fast", "delayed", "outlet"),
    ),
    ("slow end, ITV1000 class, instant loop", bracket_end("slow", "instant", "chamber")),
    ("slow end, ITV1000 class, delayed loop at the outlet (shipped)", []),
    ("delayed loop at the outlet, the old 20 kPa band", loop("delayed", "outlet", 5, 10, 20, 1.0)),
    (
        "delayed loop at the outlet, dead time 1000 ms, band 250 kPa",
        loop("delayed", "outlet", 1000, 10, 250, 1.0),
    ),
]


def rise(pamsim, overrides):
    """(rise, swing) [kPa] of the agonist's chamber pressure after the impact."""
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "run")
        cmd = [pamsim, "run", "scenarios/drop_mass_passive.toml", "--out", out]
        for o in overrides:
            cmd += ["--set", o]
        if (
            subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode
            != 0
        ):
            sys.exit(f"regulator_loop.py: {' '.join(cmd)} failed")
        with open(os.path.join(out, "summary.json")) as f:
            impact = json.load(f)["impact_time_s"]
        with open(os.path.join(out, "trajectory.csv")) as f:
            rows = [(float(r["time_s"]), float(r["p_ago_MPa"])) for r in csv.DictReader(f)]
    at = min(rows, key=lambda r: abs(r[0] - impact))[1]
    window = [p for t, p in rows if impact <= t <= impact + 0.3]
    return (max(window) - at) * 1e3, (max(window) - min(window)) * 1e3


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--pamsim", default="build/src/sim/pamsim")
    args = ap.parse_args()
    print("| regulator | rise at impact [kPa] | swing in 0.3 s [kPa] |")
    print("| --- | --- | --- |")
    for label, overrides in ROWS:
        r, s = rise(args.pamsim, overrides)
        print(f"| {label} | {r:.2f} | {s:.2f} |")


if __name__ == "__main__":
    main()
