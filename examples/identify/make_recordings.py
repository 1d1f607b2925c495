#!/usr/bin/env python3
"""make_recordings.py: the identification example's "lab recordings", made by pamsim itself
from an arm whose parameters differ from the model's (the truth identify.toml must recover):
the antagonist's bladder wall 2.7 mm (model: 3.0), the agonist's 2.2 mm (model: 2.0), the
shoulder's damping 0.16 N m s/rad (model: 0.1), the regulator's dead time 6.3 ms (model: 10; off the
regulator's 1 ms sample grid, as a real one is: on it the response has a kink).
Each recording is one `pamsim run` of
arm.toml with its commands, under another noise seed than the model's (a lab's noise is not
the model's), cut down the way a lab's logger would give it: some channels only, its own
sampling rate, 5 significant digits, and one with a gap; and a static tensile test of the
true agonist (`pamsim tensile` on its plant file with the wall changed, 0.2-0.6 MPa, with the
noise scripts/fit-estimators.sh gives the lab's sensors).

    python3 examples/identify/make_recordings.py [PAMSIM [FOLDER]]   (about 2 s; default
        build/src/sim/pamsim and examples/identify/recordings)

writes FOLDER/{steps,sine,ramps,tensile_agonist}.csv. A test makes them into another folder
and compares them with the committed ones, so that these are what this build makes.
"""

import csv
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
TRUTH = [
    "muscles.antagonist.plant.geometry.wall_thickness_mm=2.7",
    "muscles.agonist.plant.geometry.wall_thickness_mm=2.2",
    "joints.shoulder.damping_N_m_s_per_rad=0.16",
    "valve.dead_time_ms=6.3",
    "seed=7",
]
# name: (commands as --set, channels, sampling rate [Hz], gap [s] or None)
RECORDINGS = {
    "steps": (
        ['muscles.agonist.command={kind="steps", times_s=[0.0, 1.5, 3.5], MPa=[0.3, 0.5, 0.35]}'],
        ["angle_deg", "p_meas_ago_MPa", "p_meas_anta_MPa", "force_meas_ago_N", "force_meas_anta_N"],
        50.0,
        (2.0, 2.4),
    ),
    "sine": (
        [
            'muscles.antagonist.command={kind="sine", offset_MPa=0.4, amplitude_MPa=0.15, '
            "period_s=3.0}"
        ],
        ["angle_deg", "force_meas_anta_N"],
        40.0,
        None,
    ),
    "ramps": (
        [
            'muscles.agonist.command={kind="ramp", from_MPa=0.25, to_MPa=0.55, start_s=0.5, '
            "duration_s=5.0}",
            'muscles.antagonist.command={kind="ramp", from_MPa=0.55, to_MPa=0.25, start_s=0.5, '
            "duration_s=5.0}",
        ],
        ["angle_deg"],
        25.0,
        None,
    ),
}


def trajectory(pamsim, sets):
    """The rows of trajectory.csv of arm.toml run with `sets` (each a --set); pamsim's own
    line, and the exit, if it refuses them."""
    with tempfile.TemporaryDirectory() as tmp:
        args = [pamsim, "run", os.path.join(HERE, "arm.toml"), "--out", tmp, "--no-plot"]
        for s in sets:
            args += ["--set", s]
        try:
            done = subprocess.run(
                args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True
            )
        except OSError as e:
            sys.exit(f"cannot run {pamsim}: {e.strerror}")
        if done.returncode != 0:
            sys.exit(done.stderr.strip() or f"{pamsim} exited {done.returncode}")
        with open(os.path.join(tmp, "trajectory.csv")) as f:
            return list(csv.DictReader(f))


def record(
    pamsim, name, sets, channels, rate_hz, gap, out_dir, truth=TRUTH, offsets=None, delays=None
):
    """One recording: arm.toml run with `truth` and `sets`, `channels` kept at `rate_hz` (without
    the samples in `gap`), each channel shifted by its entry in `offsets` (an instrument's
    zero error, in the column's unit) and read late by its entry in `delays` [s] (an unmodelled
    delay); scripts/identify_coverage.py draws them."""
    offsets, delays = offsets or {}, delays or {}
    rows = trajectory(pamsim, truth + sets)
    step = round(100.0 / rate_hz)  # the log is at 100 Hz
    out = os.path.join(out_dir, name + ".csv")
    with open(out + ".tmp", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["time_s"] + channels)
        for i in range(0, len(rows), step):
            t = float(rows[i]["time_s"])
            if gap and gap[0] <= t < gap[1]:
                continue
            seen = {c: rows[max(0, i - round(100.0 * delays.get(c, 0.0)))][c] for c in channels}
            w.writerow(
                [f"{t:.3f}"] + [f"{float(seen[c]) + offsets.get(c, 0.0):.5g}" for c in channels]
            )
    os.replace(out + ".tmp", out)
    return out


def tensile(pamsim, out_dir):
    """The true agonist's tensile test: its plant file with the true wall."""
    with open(os.path.join(HERE, "..", "..", "models", "pams", "plant_agonist.toml")) as f:
        text = f.read()
    assert "wall_thickness_mm = 2.0" in text
    text = text.replace("wall_thickness_mm = 2.0", "wall_thickness_mm = 2.2")
    out = os.path.join(out_dir, "tensile_agonist.csv")
    with tempfile.TemporaryDirectory() as tmp:
        plant = os.path.join(tmp, "plant_agonist_true.toml")
        with open(plant, "w") as f:
            f.write(text)
        subprocess.run(
            [
                pamsim,
                "tensile",
                "--plant",
                plant,
                "-o",
                out,
                "--force",
                "--seed",
                "7",
                "--pressures-MPa",
                "0.2,0.3,0.4,0.5,0.6",
                "--max-deformation-mm",
                "15",
                "--noise-pressure-MPa",
                "0.001",
                "--noise-force-N",
                "0.5",
                "--noise-length-mm",
                "0.01",
            ],
            check=True,
            stdout=subprocess.DEVNULL,
        )
    return out


def main():
    pamsim = (
        sys.argv[1]
        if len(sys.argv) > 1
        else os.path.join(HERE, "..", "..", "build", "src", "sim", "pamsim")
    )
    out_dir = sys.argv[2] if len(sys.argv) > 2 else os.path.join(HERE, "recordings")
    os.makedirs(out_dir, exist_ok=True)
    for name, (sets, channels, rate, gap) in RECORDINGS.items():
        print(record(pamsim, name, sets, channels, rate, gap, out_dir))
    print(tensile(pamsim, out_dir))


if __name__ == "__main__":
    main()
