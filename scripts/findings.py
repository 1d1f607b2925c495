#!/usr/bin/env python3
"""findings.py: reruns the lines behind README's "Findings" that are single runs: the
passive arm, the length estimate's error, and the ideal plant's reflexes, each over 20 seeds
(`pamsim run --trials 20` with `--set` overrides, so any line can be rerun by hand). Prints
Markdown; writes it to OUT too. The tables are sweep files with case axes:
scenarios/sweep_findings_regulator.toml (the regulator bracket x the two reflexes) and
scenarios/sweep_findings_gates.toml (each gate off, on two regulators), tabled by
`pamsim report DB --table peak_drop_deg,mass_retained,retriggers_after_impact,mistrips`.

    python3 scripts/findings.py [--pamsim build/src/sim/pamsim] [--out renders/findings]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

TRIALS = 20

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
    ]
    publish("\n".join(parts) + "\n", out, "findings.md")


if __name__ == "__main__":
    main()
