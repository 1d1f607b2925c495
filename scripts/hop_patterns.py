#!/usr/bin/env python3
"""hop_patterns.py: the grid of feedforward pressure patterns from which
scenarios/hopping.toml's was chosen. Each pattern repeats a crouch phase (the
extensors GM, VAS, SOL at LOW, the mono-articular flexors IL, BFS, TA at FLEX) and a push-off
(extensors at 0.7 MPa, flexors at 0) for 5 s; the biarticular RF and GAS follow the
extensors or hold 0.4 MPa. Runs hopping.toml without reflexes (reflex.enabled=false) with
each pattern set by --set, and prints the patterns that hop at least five times (the trunk
above 0 mm: the foot in the air), most regular first: hops, the spread of the hops' heights
after the first (max - min over max), the lowest of them [mm], the pattern.

    python3 scripts/hop_patterns.py [--pamsim build/src/sim/pamsim]
"""

import argparse
import csv
import itertools
import os
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DURATION_S = 5.0


def steps(times, values):
    return f'{{ kind = "steps", times_s = {times}, MPa = {values} }}'


def overrides(low, crouch_s, push_s, flex, biarticular):
    times, ext, flx = [], [], []
    t = 0.0
    while t < DURATION_S - 1e-9:
        times += [round(t, 3), round(t + crouch_s, 3)]
        ext += [low, 0.7]
        flx += [flex, 0.0]
        t += crouch_s + push_s
    sets = ["reflex.enabled=false"]
    for m in ("GM", "VAS", "SOL") + (("RF", "GAS") if biarticular else ()):
        sets.append(f"muscles.{m}.command={steps(times, ext)}")
    for m in ("IL", "BFS", "TA"):
        sets.append(f"muscles.{m}.command={steps(times, flx)}")
    if not biarticular:
        sets += [f'muscles.{m}.command={{ kind = "constant", MPa = 0.4 }}' for m in ("RF", "GAS")]
    return sets


def apexes(pamsim, sets):
    with tempfile.TemporaryDirectory() as tmp:
        cmd = [
            pamsim,
            "run",
            os.path.join(ROOT, "scenarios", "hopping.toml"),
            "--out",
            os.path.join(tmp, "run"),
            "--quiet",
        ]
        for s in sets:
            cmd += ["--set", s]
        if subprocess.run(
            cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL
        ).returncode not in (0, 4):
            return []
        with open(os.path.join(tmp, "run", "trajectory.csv")) as f:
            z = [float(r["position_mm"]) for r in csv.DictReader(f)]
    return [z[i] for i in range(1, len(z) - 1) if z[i] > 0 and z[i] > z[i - 1] and z[i] >= z[i + 1]]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pamsim", default=os.path.join(ROOT, "build", "src", "sim", "pamsim"))
    pamsim = os.path.abspath(parser.parse_args().pamsim)
    found = []
    for low, crouch, push, flex, biart in itertools.product(
        [0.25, 0.35], [0.25, 0.35, 0.45], [0.1, 0.15, 0.2, 0.3], [0.3, 0.5], [False, True]
    ):
        hops = apexes(pamsim, overrides(low, crouch, push, flex, biart))
        if len(hops) >= 5:
            later = hops[1:]
            spread = (max(later) - min(later)) / max(later)
            found.append((spread, len(hops), min(later), (low, crouch, push, flex, biart)))
    found.sort()
    print(
        "| hops | spread after the first | lowest [mm] | pattern: extensors low [MPa], crouch [s], "
        "push [s], flexors [MPa], biarticular with extensors |"
    )
    print("| --- | --- | --- | --- |")
    for spread, n, lowest, pattern in found:
        print(f"| {n} | {100 * spread:.1f} % | {lowest:.1f} | {pattern} |")
    print(f"{len(found)} of 96 patterns hop at least five times")


if __name__ == "__main__":
    main()
