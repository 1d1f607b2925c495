#!/usr/bin/env python3
"""tension_reflex.py: reruns README's "The tension (Ib) reflex" table (issue 27, item 1): the
paper's drop (0.2 kg from 0.14 m) and the heavier drop (0.5 kg from 0.3 m) with no reflex,
the stretch (Ia) reflex alone, the tension (Ib) reflex alone and both, 20 seeds each: peak
drop, trials that keep the mass, the agonist's peak line tension (mean [min, max]) against
the 100 N working limit, and the reflexes' triggers. The heavy rows run
scenarios/drop_mass_heavy*.toml; the paper's drop runs the same files with the paper's mass
and height set back. Prints Markdown; writes it to OUT too.

    python3 scripts/tension_reflex.py [--pamsim build/src/sim/pamsim] [--out renders/findings]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from findings import TRIALS, cell, options, publish, run  # noqa: E402  (shared with findings.py)

LIMIT_N = 100.0
REFLEXES = [("no reflex", "drop_mass_heavy.toml", ["reflex.enabled=false"]),
            ("Ia (stretch)", "drop_mass_heavy.toml", []),
            ("Ib (tension)", "drop_mass_heavy_ib.toml", []),
            ("Ia + Ib", "drop_mass_heavy_ia_ib.toml", [])]
DROPS = [("paper's drop, 0.2 kg from 0.14 m", ["drop.mass_kg=0.2", "drop.height_m=0.14"]),
         ("heavier drop, 0.5 kg from 0.3 m", [])]


def tension_cell(m):
    """the agonist's peak pull, mean [min, max], and how many trials stay under the limit."""
    peak = m["peak_tension_ago_N"]
    return (f"{peak['mean']:.1f} N [{peak['min']:.1f}, {peak['max']:.1f}]"
            f" ({'under' if peak['max'] < LIMIT_N else 'over'} {LIMIT_N:.0f} N)")


def triggers_cell(m):
    return (f"Ia {m['reflex_triggers_ago']['mean']:.1f}, "
            f"Ib {m['tension_triggers_ago']['mean']:.1f}")


def main():
    pamsim, out, threads = options(__doc__)
    lines = ["| drop | reflexes | peak drop, mass kept | agonist's peak tension | "
             f"agonist's triggers per trial ({TRIALS} seeds) |",
             "| --- | --- | --- | --- | --- |"]
    for drop_label, drop_sets in DROPS:
        for label, scenario, sets in REFLEXES:
            m = run(pamsim, threads, scenario, drop_sets + sets)
            lines.append(f"| {drop_label} | {label} | {cell(m)} | {tension_cell(m)} | "
                         f"{triggers_cell(m)} |")
            print(lines[-1], file=sys.stderr)
    publish("\n".join(lines) + "\n", out, "tension_reflex.md")


if __name__ == "__main__":
    main()
