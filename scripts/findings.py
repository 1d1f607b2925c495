#!/usr/bin/env python3
"""findings.py: reruns the measurements behind README's "Findings" tables (issue 12): each
reflex of the falling-mass experiment over 20 seeds, on the physical plant across the
regulator bracket (Fig. 9 re-examined), with each of the reflex's gates switched off, and on
the ideal plant for comparison. Every row is one `pamsim run --trials 20` with `--set`
overrides, so any row can be rerun by hand. Prints Markdown; writes it to OUT too.

    python3 scripts/findings.py [--pamsim build/src/sim/pamsim] [--out renders/findings]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

TRIALS = 20

# (label, overrides) for the regulator bracket of models/pams/pneumatics.toml [regulator]:
# the shipped ITV1000-class loop (issue 25), the ITV2000 class, the loop before issue 25
LOOP_BEFORE = ['valve.feedback="instant"', 'valve.sense="chamber"', "valve.dead_time_ms=5",
               "valve.valve_time_constant_ms=10", "valve.proportional_band_kPa=20",
               "valve.supply_sonic_conductance_dm3_per_s_bar=1",
               "valve.exhaust_sonic_conductance_dm3_per_s_bar=1"]
REGULATOR_ROWS = [
    ("ideal source (`valve.model=\"iso6358\"`)", ['valve.model="iso6358"']),
    ("loop before issue 25: instant, on the chamber, 5 ms / 10 ms / 20 kPa, C = 1", LOOP_BEFORE),
    ("ITV2000 class: delayed, on its outlet, 2 ms / 5 ms / 250 kPa, C = 1",
     ["valve.dead_time_ms=2", "valve.valve_time_constant_ms=5", "valve.proportional_band_kPa=250",
      "valve.supply_sonic_conductance_dm3_per_s_bar=1",
      "valve.exhaust_sonic_conductance_dm3_per_s_bar=1"]),
    ("ITV1000 class with instant feedback (the pilot diaphragm's bound)",
     ['valve.feedback="instant"']),
    ("ITV1000 class: delayed, on its outlet, 10 ms / 20 ms / 380 kPa, C = 0.35 (shipped)", []),
]

GATES_OFF = ["reflex.refractory_s=0", "reflex.arm_after_s=0", "reflex.min_tension_N=0",
             "reflex.reciprocal_trigger_inhibition=false"]
GATE_ROWS = [
    ("all four on (shipped)", []),
    ("refractory time off (`reflex.refractory_s=0`)", [GATES_OFF[0]]),
    ("arming delay off (`reflex.arm_after_s=0`)", [GATES_OFF[1]]),
    ("minimum line tension off (`reflex.min_tension_N=0`)", [GATES_OFF[2]]),
    ("reciprocal trigger inhibition off", [GATES_OFF[3]]),
    ("all four off (the paper's reflex)", GATES_OFF),
]

REFLEXES = [("model reflex (1/800)", "drop_mass.toml"), ("fiber reflex (1/300)", "drop_mass_fiber.toml")]


def run(pamsim, threads, scenario, overrides):
    """One `pamsim run --trials 20`; returns its summary's metrics."""
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "run")
        cmd = [pamsim, "run", os.path.join("scenarios", scenario), "--trials", str(TRIALS),
               "--threads", str(threads), "--out", out]
        for o in overrides:
            cmd += ["--set", o]
        # exit 4: a trial diverged; its summary says so and the row still counts it
        done = subprocess.run(cmd, stdout=subprocess.DEVNULL)
        if done.returncode not in (0, 4):
            sys.exit(f"findings.py: {' '.join(cmd)} exited {done.returncode}")
        with open(os.path.join(out, "summary.json")) as f:
            return json.load(f)["metrics"]


def cell(m):
    """peak drop mean [min, max], trials that keep the mass, retriggers, mistrips."""
    drop = m["peak_drop_deg"]
    kept = round(m["mass_retained"]["mean"] * m["mass_retained"]["count"])
    text = f"{drop['mean']:.1f} deg [{drop['min']:.1f}, {drop['max']:.1f}], {kept}/{TRIALS} kept"
    retrig = m.get("retriggers_after_impact", {}).get("mean")
    if retrig is not None:
        text += f", {retrig:.1f} retriggers"
    mistrips = m.get("mistrips", {}).get("mean") or 0.0
    if mistrips:
        text += f", {mistrips:.2f} mistrips"
    return text


def table(pamsim, threads, rows, header, base_overrides=()):
    lines = [f"| {header} | " + " | ".join(r[0] for r in REFLEXES) + " |",
             "| --- | " + " | ".join("---" for _ in REFLEXES) + " |"]
    for label, overrides in rows:
        cells = [cell(run(pamsim, threads, scenario, list(base_overrides) + overrides))
                 for _, scenario in REFLEXES]
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
        print(lines[-1], file=sys.stderr)
    return "\n".join(lines)


def publish(text, out, name):
    """Prints the Markdown and writes it to OUT/NAME whole (temp file, then rename)."""
    os.makedirs(out, exist_ok=True)
    tmp = os.path.join(out, f".{name}.tmp")
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, os.path.join(out, name))
    print(text)


def options(doc):
    """--pamsim, --out, --threads (the paths made absolute), then cd to the repository root,
    where the scenario paths are relative."""
    ap = argparse.ArgumentParser(description=doc.splitlines()[0])
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    ap.add_argument("--pamsim", default=os.path.join(root, "build/src/sim/pamsim"))
    ap.add_argument("--out", default=os.path.join(root, "renders/findings"))
    ap.add_argument("--threads", type=int, default=os.cpu_count() or 1)
    args = ap.parse_args()
    os.chdir(root)
    return os.path.abspath(args.pamsim), os.path.abspath(args.out), args.threads


def main():
    pamsim, out, threads = options(__doc__)

    passive = run(pamsim, threads, "drop_mass_passive.toml", [])
    ideal = run(pamsim, threads, "drop_mass_ideal.toml", [])
    # drop_mass_fiber.toml's reflex on the ideal plant: Table II's fiber threshold and gain
    ideal_fiber = run(pamsim, threads, "drop_mass_ideal.toml",
                      ['reflex.sensor="fiber"', "reflex.v_thr_mm_s=25.0",
                       "reflex.k_MPa_s_per_mm=0.0033333333333333335"])
    est = run(pamsim, threads, "drop_mass.toml", [])["length_est_rmse_pct"]
    est_ideal = ideal["length_est_rmse_pct"]
    parts = [
        f"Passive (no reflex): {cell(passive)}.",
        f"Length estimate RMSE: {est['mean']:.2f} % of length [{est['min']:.2f}, "
        f"{est['max']:.2f}] on the physical plant, {est_ideal['mean']:.3f} % on the ideal one.",
        "",
        "Ideal plant (`drop_mass_ideal.toml`): model reflex " + cell(ideal) +
        "; fiber reflex " + cell(ideal_fiber) + ".",
        "",
        "Physical plant across the regulator bracket (feedback, sensing, dead time / valve lag / band, C):",
        "",
        table(pamsim, threads, REGULATOR_ROWS, "regulator"),
        "",
        "Physical plant, shipped regulator (ITV1000 class), each gate off:",
        "",
        table(pamsim, threads, GATE_ROWS, "gate"),
        "",
        "Physical plant, the loop before issue 25, each gate off:",
        "",
        table(pamsim, threads, GATE_ROWS, "gate", LOOP_BEFORE),
    ]
    publish("\n".join(parts) + "\n", out, "findings.md")


if __name__ == "__main__":
    main()
