#!/usr/bin/env python3
"""table1_plants.py: every shipped plant rebuilt with the diameters of Yoshida and Hosoda's
Table I: the sleeve's diameter, the bladder a rubber tube of Table I's diameter inside it
(`bladder.diameter_mm`, the Gent-Gent law for natural rubber: src/pam_actuator/avbdl.h),
end regions 3.2 R0 long (the plant file's default for a tube: the DMSP-20's 32 mm at R0 =
10 mm, scaled with the radius),
the friction rule of the shipped files on the new radius, the braid angle kept (25 deg, an
assumption). Each is tested as the lab tests (`pamsim tensile`, 2.5 mm steps to 7.5 mm and
back, the protocol's pressures) and fitted with Eq. (2)-(3) (`pamsim fit`); the table gives
the free lengths, the fitted slope m of Eq. (2) and the pull at 5 mm past the free length
beside Table IV's, for walls of 0.5 and 1.0 mm (the shipped PAM A-D files assume 1.0 mm: a
4 or 6 mm latex tube; Table I gives no wall). The changes are `pamsim tensile --set`s on the
shipped plant files; the tests' data go to a temp folder.
Prints Markdown; writes it to OUT/table1_plants.md too.

    python3 scripts/table1_plants.py [--pamsim build/src/sim/pamsim] [--out renders/findings]
"""

import argparse
import csv
import os
import subprocess
import sys
import tempfile
import tomllib


def publish(text, out, name):
    """Prints the Markdown and writes it to OUT/NAME whole (temp file, then rename)."""
    os.makedirs(out, exist_ok=True)
    tmp = os.path.join(out, f".{name}.tmp")
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, os.path.join(out, name))
    print(text)


def options(doc):
    """--pamsim, --out (made absolute), then cd to the repository root, where the model
    paths are relative."""
    ap = argparse.ArgumentParser(description=doc.splitlines()[0])
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    ap.add_argument("--pamsim", default=os.path.join(root, "build/src/sim/pamsim"))
    ap.add_argument("--out", default=os.path.join(root, "renders/findings"))
    args = ap.parse_args()
    os.chdir(root)
    return os.path.abspath(args.pamsim), os.path.abspath(args.out)


# name, shipped plant file, Table I: sleeve and bladder diameter [mm], the tensile test's
# pressures [MPa] (Yoshida and Hosoda, Sec. II-B, for A-D; the arm's:
# scripts/fit-estimators.sh), and Table IV's Eq. (2)-(3) where it has one (m, h, a0..a3)
PLANTS = [
    (
        "agonist",
        "plant_agonist.toml",
        16.0,
        4.0,
        [0.2, 0.3, 0.4, 0.5, 0.6, 0.7],
        (-60.1, 170.1, 0.911, 0.256, 7.00, -0.201),
    ),
    (
        "antagonist",
        "plant_antagonist.toml",
        16.1,
        4.0,
        [0.2, 0.3, 0.4, 0.5, 0.6, 0.7],
        (-70.3, 178.5, 22.4, -0.129, 1.24, 0.871),
    ),
    ("PAM-A", "plant_pam_a.toml", 19.9, 6.0, [0.4, 0.5, 0.6, 0.7, 0.8], None),
    ("PAM-B", "plant_pam_b.toml", 13.4, 4.0, [0.4, 0.5, 0.6, 0.7, 0.8], None),
    ("PAM-C", "plant_pam_c.toml", 13.4, 4.0, [0.4, 0.5, 0.6, 0.7, 0.8], None),
    ("PAM-D (silicone)", "plant_pam_d.toml", 19.0, 6.0, [0.2, 0.3, 0.4, 0.5, 0.6], None),
]
WALLS_MM = [0.5, 1.0]
SHOWN_MPA = [0.2, 0.4, 0.6]  # where the free lengths and pulls are shown (A-C: 0.4-0.8)


def table1_sets(shipped, sleeve_mm, tube_mm, wall_mm):
    """`pamsim tensile --set` changes that give the shipped plant Table I's diameters, a tube
    bladder (a rubber plant's becomes Gent-Gent natural rubber; a silicone one keeps its Yeoh
    constants) and friction areas scaled by the new pi R0^2 (the shipped files' rule:
    A0 = 0.030 / 0.024 pi R0^2)."""
    with open(os.path.join("models", "pams", shipped), "rb") as f:
        plant = tomllib.load(f)
    scale = (sleeve_mm / plant["geometry"]["diameter_mm"]) ** 2
    sets = [
        f"geometry.diameter_mm={sleeve_mm}",
        f"geometry.wall_thickness_mm={wall_mm}",
        f"bladder.diameter_mm={tube_mm}",
    ]
    if "C10_MPa" not in plant["bladder"]:  # not silicone's explicit Yeoh constants
        sets += ['bladder.material="natural_rubber"', 'bladder.law="gent_gent"']
    for direction in ("extension", "contraction"):
        for area in ("A0_mm2", "A1_mm2"):
            value = plant["friction"][direction][area] * scale
            sets.append(f"friction.{direction}.{area}={value:.3f}")
    return sets


def tensile_and_fit(pamsim, plant, sets, pressures, folder, name):
    """The free length per pressure and the pull 5 mm past it, and the fitted (m, h)."""
    data = os.path.join(folder, name + ".csv")
    fit = os.path.join(folder, name + "_fit.toml")
    changes = [arg for change in sets for arg in ("--set", change)]
    subprocess.run(
        [
            pamsim,
            "tensile",
            "--plant",
            plant,
            *changes,
            "--pressures-MPa",
            ",".join(str(p) for p in pressures),
            "--max-deformation-mm",
            "7.5",
            "-o",
            data,
            "--force",
        ],
        check=True,
        capture_output=True,
    )
    subprocess.run(
        [pamsim, "fit", "--model", "eq3", data, "-o", fit, "--force"],
        check=True,
        capture_output=True,
    )
    free, pull = {}, {}
    with open(data) as f:
        for row in csv.DictReader(f):
            p, d = float(row["pressure_MPa"]), float(row["deformation_mm"])
            if row["direction"] != "loading":
                continue
            if d == 0.0:
                free[p] = float(row["length_mm"])
            if d == 5.0:
                pull[p] = float(row["force_N"])
    with open(fit, "rb") as f:
        m = tomllib.load(f)["spring"]["m"]
    return free, pull, m


def table_iv(law, p):
    m, h, a0, a1, a2, a3 = law
    return h + m * p, (a3 * p * 5 + a2 * p + a1 * 5 + a0) * 5


def shown(values, fmt):
    return " / ".join(fmt.format(values[p]) if p in values else "-" for p in SHOWN_MPA)


def rows(pamsim, folder):
    lines = []
    for name, shipped, sleeve, tube, pressures, law in PLANTS:
        for wall in WALLS_MM:
            plant = os.path.join("models", "pams", shipped)
            sets = table1_sets(shipped, sleeve, tube, wall)
            try:
                free, pull, m = tensile_and_fit(
                    pamsim, plant, sets, pressures, folder, f"{name}_{wall}"
                )
            except subprocess.CalledProcessError as e:
                why = e.stderr.decode().strip().splitlines()[-1]
                lines.append(f"| {name} | {sleeve} / {tube} | {wall} | {why} | | | |")
                continue
            paper = ""
            if law:
                ln = {p: table_iv(law, p)[0] for p in SHOWN_MPA}
                f5 = {p: table_iv(law, p)[1] for p in SHOWN_MPA}
                paper = f"{shown(ln, '{:.1f}')}; {law[0]}; {shown(f5, '{:.0f}')}"
            lines.append(
                f"| {name} | {sleeve} / {tube} | {wall} | {shown(free, '{:.1f}')} | "
                f"{m:.1f} | {shown(pull, '{:.0f}')} |" + (f" {paper} |" if paper else " |")
            )
            print(lines[-1], file=sys.stderr)
    return lines


def main():
    pamsim, out = options(__doc__)
    lines = [
        "| muscle | Table I sleeve / tube [mm] | wall [mm] | free length at "
        "0.2 / 0.4 / 0.6 MPa [mm] | fitted m [mm/MPa] | pull 5 mm past it at 0.2 / 0.4 / 0.6 "
        "MPa [N] | "
        "Table IV: l_n; m; pull |",
        "| --- | --- | --- | --- | --- | --- | --- |",
    ]
    with tempfile.TemporaryDirectory() as folder:
        lines += rows(pamsim, folder)
    publish("\n".join(lines) + "\n", out, "table1_plants.md")


if __name__ == "__main__":
    main()
