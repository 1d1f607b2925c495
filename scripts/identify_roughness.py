#!/usr/bin/env python3
"""identify_roughness.py: how rough the identification example's prediction is along the
regulator's dead time, at the chamber solver's tolerance of the pneumatics file and at the
example arm's. Runs examples/identify/arm.toml with the steps recording's commands at dead
times 6 ms + k x STEP_MS (k = -4..4) and prints, per tolerance, the RMS over the trial of the
angle's first differences, y(k + 1) - y(k), and second differences, y(k + 1) - 2 y(k) + y(k - 1):
for a prediction smooth at the step's scale the first are alike and the second far smaller;
where the second are as large as the first, the differences are the solver's error, not the
dead time's effect (the roughness `pamsim identify` reports, docs/identification.md).
With --landing, the same along a line of the harder family's parameters (scripts/
identify_families.py) over which the ball's landing in a passive drop moves by a physics
step, with the model's own contact and with sim.contact_soft_onset_mm = 1 (arm.toml's).

    python3 scripts/identify_roughness.py [--pamsim build/src/sim/pamsim] [--landing]
"""

import argparse
import math
import os
import sys
import tomllib

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "examples", "identify"))
import make_recordings  # noqa: E402  (the example's commands)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import identify_families  # noqa: E402  (the harder family's drop)

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


# the line along which, at the model's own contact, the harder arm's landing moves by a
# physics step (shared with tests/sim/core/contact_onset_test.cc)
with open(os.path.join(ROOT, "examples", "identify", "landing_line.toml"), "rb") as _f:
    LANDING = tomllib.load(_f)
LANDING_STEPS = LANDING["steps"]
CONTACTS = {  # name: the contact's key as --set
    "the model's own (starts at full impedance)": ["sim.contact_soft_onset_mm=0"],
    "softened over 1 mm (the example arm's)": ["sim.contact_soft_onset_mm=1"],
}


def landing_angle(pamsim, t, contact):
    """The passive drop's angle column [deg] at fraction t of the way along the line."""
    sets = [f"{p['key']}={p['from'] + t * (p['to'] - p['from'])!r}" for p in LANDING["parameter"]]
    sets += identify_families.DROP + ["sensors.noise_scale=0"]
    return [float(r["angle_deg"]) for r in make_recordings.trajectory(pamsim, sets + contact)]


def angle(pamsim, dead_time_ms, solver):
    """The trial's angle column [deg] with the steps recording's commands."""
    sets = [f"valve.dead_time_ms={dead_time_ms!r}"] + make_recordings.RECORDINGS["steps"][0]
    return [float(r["angle_deg"]) for r in make_recordings.trajectory(pamsim, sets + solver)]


def rms(values):
    return math.sqrt(sum(v * v for v in values) / len(values))


def differences(ys):
    """The RMS over the trial of the first and of the second differences along `ys`."""
    first = [
        rms([b - a for a, b in zip(ys[k], ys[k + 1], strict=False)]) for k in range(len(ys) - 1)
    ]
    second = [
        rms([a - 2 * b + c for a, b, c in zip(ys[k - 1], ys[k], ys[k + 1], strict=False)])
        for k in range(1, len(ys) - 1)
    ]
    return first, second


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--pamsim", default=os.path.join(ROOT, "build", "src", "sim", "pamsim"))
    ap.add_argument("--landing", action="store_true", help="along the harder arm's line instead")
    args = ap.parse_args()
    if args.landing:
        print(
            f"| contact | angle's first differences, RMS [deg] per 1/{LANDING_STEPS} of the line "
            "| largest over median |"
        )
        print("| --- | --- | --- |")
        for name, contact in CONTACTS.items():
            ys = [
                landing_angle(args.pamsim, k / LANDING_STEPS, contact)
                for k in range(LANDING_STEPS + 1)
            ]
            first = differences(ys)[0]
            ratio = max(first) / sorted(first)[len(first) // 2]
            print(f"| {name} | {' '.join(f'{v:.2g}' for v in first)} | {ratio:.3g} |")
        return
    print(
        f"| solver tolerance | angle's first differences, RMS [deg] per {STEP_MS} ms "
        "| second differences, RMS [deg] |"
    )
    print("| --- | --- | --- |")
    for name, solver in TOLERANCES.items():
        ys = [angle(args.pamsim, round(6.0 + k * STEP_MS, 6), solver) for k in range(-4, 5)]
        first, second = differences(ys)
        print(
            f"| {name} | {' '.join(f'{v:.2g}' for v in first)} "
            f"| {' '.join(f'{v:.2g}' for v in second)} |"
        )


if __name__ == "__main__":
    main()
