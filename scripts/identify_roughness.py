#!/usr/bin/env python3
"""identify_roughness.py: how rough the identification example's prediction is along the
regulator's dead time, at the chamber solver's tolerance of the pneumatics file and at the
example arm's. Runs examples/identify/arm.toml with the steps recording's commands at dead
times 6 ms + k x STEP_MS (k = -4..4) and prints, per tolerance, the RMS over the trial of the
angle's first differences, y(k + 1) - y(k), and second differences, y(k + 1) - 2 y(k) + y(k - 1):
for a prediction smooth at the step's scale the first are alike and the second far smaller;
where the second are as large as the first, the differences are the solver's error, not the
dead time's effect (the roughness `pamsim identify` reports, docs/identification.md).

    python3 scripts/identify_roughness.py [--pamsim build/src/sim/pamsim]
"""

import argparse
import math
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "examples", "identify"))
import make_recordings  # noqa: E402  (the example's commands)

STEP_MS = 0.01
TOLERANCES = {  # name: the solver's keys as --set
    "the pneumatics file's (relative 1e-4, absolute 1 Pa)": [
        "pneumatics.solver.relative_tolerance=1e-4",
        "pneumatics.solver.absolute_tolerance_Pa=1",
    ],
    "the example arm's (relative 1e-8, absolute 0.001 Pa)": [
        "pneumatics.solver.relative_tolerance=1e-8",
        "pneumatics.solver.absolute_tolerance_Pa=0.001",
    ],
}


def angle(pamsim, dead_time_ms, solver):
    """The trial's angle column [deg] with the steps recording's commands."""
    sets = [f"valve.dead_time_ms={dead_time_ms!r}"] + make_recordings.RECORDINGS["steps"][0]
    return [float(r["angle_deg"]) for r in make_recordings.trajectory(pamsim, sets + solver)]


def rms(values):
    return math.sqrt(sum(v * v for v in values) / len(values))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--pamsim", default=os.path.join(ROOT, "build", "src", "sim", "pamsim"))
    args = ap.parse_args()
    print(
        f"| solver tolerance | angle's first differences, RMS [deg] per {STEP_MS} ms "
        "| second differences, RMS [deg] |"
    )
    print("| --- | --- | --- |")
    for name, solver in TOLERANCES.items():
        ys = [angle(args.pamsim, round(6.0 + k * STEP_MS, 6), solver) for k in range(-4, 5)]
        first = [
            rms([b - a for a, b in zip(ys[k], ys[k + 1], strict=False)]) for k in range(len(ys) - 1)
        ]
        second = [
            rms([a - 2 * b + c for a, b, c in zip(ys[k - 1], ys[k], ys[k + 1], strict=False)])
            for k in range(1, len(ys) - 1)
        ]
        print(
            f"| {name} | {' '.join(f'{v:.2g}' for v in first)} "
            f"| {' '.join(f'{v:.2g}' for v in second)} |"
        )


if __name__ == "__main__":
    main()
