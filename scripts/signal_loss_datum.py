#!/usr/bin/env python3
"""signal_loss_datum.py: the calibration of a gauge's lost line to an observed loss. Yoshida and
Hosoda (Sec. IV-C, Fig. 7) report that the agonist's model estimate "dropped around 2.7 second"
into the reaching task, its fishing line having lost contact and the deformation read zero from
then on. Taking the task's time base as starting with the ramps (the paper's 12 s experiment;
reaching.toml runs them from the muscle's command start_s), this runs the scenario, reads the
muscle's true length at start_s + datum (and at the datum's ends, +- its precision) and prints
its shortening from the trial's first tick: the value of
muscles.<m>.gauge.contact.lost_at_shortening_mm that makes the line leave the board then
(gauge_contact.h solves the contact's misalignment for it in closed form). It refuses a
shortening that is not steady up to the datum (an earlier, larger one would lose the line
first).

    python3 scripts/signal_loss_datum.py [--scenario scenarios/reaching.toml]
        [--muscle agonist] [--datum-s 2.7] [--precision-s 0.05] [--pamsim PATH]
"""

import argparse
import csv
import os
import subprocess
import sys
import tempfile
import tomllib

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def trajectory(pamsim, scenario):
    with tempfile.TemporaryDirectory() as out:
        run = subprocess.run(
            [pamsim, "run", scenario, "--no-plot", "--out", out], capture_output=True, text=True
        )
        if run.returncode != 0:
            sys.exit(run.stderr.strip())
        with open(os.path.join(out, "trajectory.csv")) as f:
            return list(csv.DictReader(f))


def shortening_at(rows, column, t):
    """The shortening [mm] from the first row at time t, linear between rows."""
    times = [float(r["time_s"]) for r in rows]
    if not times[0] < t <= times[-1]:
        sys.exit(f"--datum-s: trial time {t:.3f} s lies outside the trial's ({times[-1]:.3f} s)")
    k = next(i for i, ti in enumerate(times) if ti >= t)
    l0 = float(rows[0][column])
    a, b = float(rows[k - 1][column]), float(rows[k][column])
    u = (t - times[k - 1]) / (times[k] - times[k - 1])
    return l0 - (a + u * (b - a))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--scenario", default=os.path.join(ROOT, "scenarios", "reaching.toml"))
    ap.add_argument("--muscle", default="agonist")
    ap.add_argument("--datum-s", type=float, default=2.7, help="the paper's 'around 2.7 second'")
    ap.add_argument("--precision-s", type=float, default=0.05, help="the datum's last digit")
    ap.add_argument("--pamsim", default=os.path.join(ROOT, "build", "src", "sim", "pamsim"))
    a = ap.parse_args()
    with open(a.scenario, "rb") as f:
        muscle = tomllib.load(f)["muscles"][a.muscle]
    start = float(muscle["command"]["start_s"])
    column = f"length_{muscle.get('label', a.muscle)}_mm"
    rows = trajectory(a.pamsim, a.scenario)
    t_datum = start + a.datum_s
    # steady: no earlier shortening as large as the datum's
    s_datum = shortening_at(rows, column, t_datum)
    earlier = max(
        float(rows[0][column]) - float(r[column]) for r in rows if float(r["time_s"]) < t_datum
    )
    if earlier > s_datum:
        sys.exit(
            f"{a.scenario}: the {a.muscle} shortens {earlier:.3f} mm before the datum, more "
            f"than the datum's {s_datum:.3f} mm"
        )
    datum = f"{a.datum_s:.2f} +- {a.precision_s:.2f} s"
    print(f"the ramps start at {start:.2f} s; the datum {datum} into them")
    for dt in (-a.precision_s, 0.0, a.precision_s):
        t = t_datum + dt
        s = shortening_at(rows, column, t)
        print(f"trial time {t:.2f} s: the {a.muscle} shortened {s:.3f} mm from the start")


if __name__ == "__main__":
    main()
