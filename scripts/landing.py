#!/usr/bin/env python3
"""landing.py: reruns README's "The leg" table (issue 27, item 4): the PAM leg of
models/leg_pam.xml dropped from 50, 100 and 200 mm (its sole above the floor) with no reflex,
the stretch (Ia) reflex alone, the tension (Ib) reflex alone and both, 20 seeds each, behind
the shipped ITV1000-class regulator; and, at 100 mm, behind a direct valve (valve.model =
"iso6358": no regulator loop) for contrast. Each cell is the mean over the seeds: the knee's
largest flexion (its collapse), the floor's peak push on the sole, the vastus's and the
soleus's peak pulls, the touchdowns. Prints Markdown; writes it to OUT too.

    python3 scripts/landing.py [--pamsim build/src/sim/pamsim] [--out renders/findings]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from findings import TRIALS, options, publish, run  # noqa: E402  (shared with findings.py)

# the crouched sole is 6.7 mm above the floor with the trunk's slide at 0
HEIGHTS_MM = [50, 100, 200]
REFLEXES = [("none", "landing.toml", []),
            ("Ia", "landing_reflex.toml", ["reflex.ib.k_MPa_per_N=0"]),
            ("Ib", "landing_reflex.toml", ["reflex.k_MPa_s_per_mm=0"]),
            ("Ia + Ib", "landing_reflex.toml", [])]


def start(height_mm):
    return f"joints.trunk_z.start_mm={height_mm - 6.7:.1f}"


def row(label, m):
    mean = lambda k: m[k]["mean"]  # noqa: E731
    return (f"| {label} | {mean('knee_angle_max_deg'):.1f} deg | {mean('grf_max_N'):.0f} N | "
            f"{mean('peak_tension_VAS_N'):.0f} N | {mean('peak_tension_SOL_N'):.0f} N | "
            f"{mean('grf_touchdowns'):.1f} |")


def main():
    pamsim, out, threads = options(__doc__)
    lines = [f"| drop, reflexes ({TRIALS} seeds) | knee collapse (largest flexion) | peak floor "
             "push | VAS peak pull | SOL peak pull | touchdowns |",
             "| --- | --- | --- | --- | --- | --- |"]
    for height in HEIGHTS_MM:
        for label, scenario, sets in REFLEXES:
            m = run(pamsim, threads, scenario, [start(height)] + sets)
            lines.append(row(f"{height} mm, {label}", m))
            print(lines[-1], file=sys.stderr)
    for label, scenario, sets in REFLEXES:
        m = run(pamsim, threads, scenario, [start(100), 'valve.model="iso6358"'] + sets)
        lines.append(row(f"100 mm, {label}, direct valve", m))
        print(lines[-1], file=sys.stderr)
    publish("\n".join(lines) + "\n", out, "landing.md")


if __name__ == "__main__":
    main()
