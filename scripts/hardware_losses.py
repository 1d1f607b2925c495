#!/usr/bin/env python3
"""hardware_losses.py: reruns README's "Findings" on the hardware's losses (issue 25, items 2
and 3): the falling-mass experiment over 20 seeds with the braid friction as Maxwell-slip
elements, the shoulder on a ball bearing's losses instead of the MJCF's damping, the
bladders' rubber relaxing, the fishing lines extensible (nylon, braided polyethylene), and the
arm's muscles as Table I builds them (models/pams/table1, with and without the bearing). Each row is `pamsim run --trials 20`
with `--set` overrides; the Maxwell-slip rows use the shipped plant files with their
[friction] made "maxwell_slip" (travels 0.1 and 0.5 mm, an example: no source sizes them),
written to a temp folder. Prints Markdown; writes it to OUT too.

    python3 scripts/hardware_losses.py [--pamsim build/src/sim/pamsim] [--out renders/findings]
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from findings import cell, options, publish, run  # noqa: E402  (shared with findings.py)

SCENARIOS = [("model reflex (1/800)", "drop_mass.toml"),
             ("fiber reflex (1/300)", "drop_mass_fiber.toml"),
             ("passive", "drop_mass_passive.toml")]
# a ball bearing: SKF's M = 0.5 mu P d, mu = 0.0015, the lines' 30-60 N, an 8 mm bore
BEARING = ["joints.shoulder.damping_N_m_s_per_rad=0", "joints.shoulder.frictionloss_N_m=0.0003"]


# the arm's muscles as seeds/000 Table I builds them (a 4 mm tube in the sleeve), wall and
# braid angle identified from Table IV (examples/table1), their own fits and calibration
TABLE1 = [f'{key}="../models/pams/table1/{kind}_{m}.toml"' for m in ("agonist", "antagonist")
          for key, kind in ((f"muscles.{m}.plant", "plant"), (f"model.{m}_params", "fitted"))]
TABLE1 += ['model.calibration="../models/arm_2pam_table1_calibration.toml"']


def line(diameter_mm, modulus_mpa):
    return [f"muscles.{m}.line_{k}" for m in ("agonist", "antagonist")
            for k in (f"diameter_mm={diameter_mm}", f"modulus_MPa={modulus_mpa}")]


# the bladder rubber's relaxation: a loss tangent of 0.05 held over 0.16-160 Hz by one Prony
# term per decade, g = (2 tan(delta) / pi) ln 10 (src/pam_actuator/bladder_relaxation.h); the
# loss tangent is an unfilled natural rubber's order of magnitude, not a measured value
RELAXATION_WEIGHT = 2 * 0.05 / 3.141592653589793 * 2.302585092994046
RELAXING = [f"muscles.{m}.plant.bladder.{k}" for m in ("agonist", "antagonist")
            for k in ("relaxation_weights=[" + ",".join([f"{RELAXATION_WEIGHT:.4f}"] * 4) + "]",
                      "relaxation_times_s=[0.001,0.01,0.1,1.0]")]


def slip_plants(folder):
    """The shipped plants with Maxwell-slip braid friction; the --set keys that use them."""
    sets = []
    for muscle in ("agonist", "antagonist"):
        with open(os.path.join("models", "pams", f"plant_{muscle}.toml")) as f:
            text = f.read()
        text = text.replace("velocity_scale_mm_s = 1.0", 'model = "maxwell_slip"\n'
                            "breakaway_mm = [0.1, 0.5]\nweights = [0.5, 0.5]")
        path = os.path.join(folder, f"plant_{muscle}.toml")
        with open(path, "w") as f:
            f.write(text)
        sets.append(f'muscles.{muscle}.plant="{path}"')
    return sets


def rows(folder):
    slip = slip_plants(folder)
    return [("shipped (tanh friction, 0.1 N m s/rad, inextensible lines)", []),
            ("Maxwell-slip braid friction", slip),
            ("ball bearing instead of 0.1 N m s/rad", BEARING),
            ("ball bearing and Maxwell-slip", BEARING + slip),
            ("relaxing bladders (tan delta 0.05, 0.16-160 Hz)", RELAXING),
            ("ball bearing, Maxwell-slip and relaxing bladders", BEARING + slip + RELAXING),
            ("0.5 mm nylon lines (2.5 GPa)", line(0.5, 2500)),
            ("0.5 mm braided PE lines (50 GPa)", line(0.5, 50000)),
            ("Table I's muscles (a 4 mm tube in the sleeve, identified from Table IV)", TABLE1),
            ("Table I's muscles on a ball bearing", TABLE1 + BEARING),
            ("Table I's muscles on a ball bearing, 0.5 mm braided PE lines", TABLE1 + BEARING +
             line(0.5, 50000))]


def main():
    pamsim, out, threads = options(__doc__)

    lines = ["| hardware | " + " | ".join(s[0] for s in SCENARIOS) + " | passive rest |",
             "| --- | " + " | ".join("---" for _ in SCENARIOS) + " | --- |"]
    with tempfile.TemporaryDirectory() as folder:
        for label, overrides in rows(folder):
            metrics = [run(pamsim, threads, scenario, overrides) for _, scenario in SCENARIOS]
            rest = metrics[-1]["final_angle_deg"]["mean"]
            lines.append(f"| {label} | " + " | ".join(cell(m) for m in metrics) +
                         f" | {rest:.2f} deg |")
            print(lines[-1], file=sys.stderr)
    publish("\n".join(lines) + "\n", out, "hardware_losses.md")


if __name__ == "__main__":
    main()
