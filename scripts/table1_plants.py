#!/usr/bin/env python3
"""table1_plants.py: every shipped plant rebuilt with seeds/000 Table I's own diameters (issue
25, item 1): the sleeve's diameter, the bladder a rubber tube of Table I's diameter inside it
(`bladder.diameter_mm`, the Gent-Gent law for natural rubber: src/pam_actuator/avbdl.h),
end regions 3.2 R0 long (the plant file's default for a tube: the DMSP-20's 32 mm at R0 =
10 mm, scaled with the radius),
the friction rule of the shipped files on the new radius, the braid angle kept (25 deg, an
assumption). Each is tested as the lab tests (`pamsim tensile`, 2.5 mm steps to 7.5 mm and
back, the protocol's pressures) and fitted with Eq. (2)-(3) (`pamsim fit`); the table gives
the free lengths, the fitted slope m of Eq. (2) and the pull at 5 mm past the free length
beside Table IV's, for walls of 0.5 and 1.0 mm (the shipped PAM A-D files assume 1.0 mm: a
4 or 6 mm latex tube; Table I gives no wall). The plant files are written to a temp folder.
Prints Markdown; writes it to OUT/table1_plants.md too.

    python3 scripts/table1_plants.py [--pamsim build/src/sim/pamsim] [--out renders/findings]
"""
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from findings import options, publish  # noqa: E402  (shared with findings.py)

# name, shipped plant file, Table I: sleeve and bladder diameter [mm], the tensile test's
# pressures [MPa] (seeds/000 Sec. II-B for A-D; the arm's: scripts/fit-estimators.sh), and
# Table IV's Eq. (2)-(3) where it has one (m, h, a0..a3)
PLANTS = [
    ("agonist", "plant_agonist.toml", 16.0, 4.0, [0.2, 0.3, 0.4, 0.5, 0.6, 0.7],
     (-60.1, 170.1, 0.911, 0.256, 7.00, -0.201)),
    ("antagonist", "plant_antagonist.toml", 16.1, 4.0, [0.2, 0.3, 0.4, 0.5, 0.6, 0.7],
     (-70.3, 178.5, 22.4, -0.129, 1.24, 0.871)),
    ("PAM-A", "plant_pam_a.toml", 19.9, 6.0, [0.4, 0.5, 0.6, 0.7, 0.8], None),
    ("PAM-B", "plant_pam_b.toml", 13.4, 4.0, [0.4, 0.5, 0.6, 0.7, 0.8], None),
    ("PAM-C", "plant_pam_c.toml", 13.4, 4.0, [0.4, 0.5, 0.6, 0.7, 0.8], None),
    ("PAM-D (silicone)", "plant_pam_d.toml", 19.0, 6.0, [0.2, 0.3, 0.4, 0.5, 0.6], None),
]
WALLS_MM = [0.5, 1.0]
SHOWN_MPA = [0.2, 0.4, 0.6]   # where the free lengths and pulls are shown (A-C: 0.4-0.8)


def table1_plant(shipped, sleeve_mm, tube_mm, wall_mm):
    """The shipped plant file's text with Table I's diameters, a tube bladder and friction
    areas scaled by the new pi R0^2 (the shipped files' rule: A0 = 0.030 / 0.024 pi R0^2)."""
    with open(os.path.join("models", "pams", shipped)) as f:
        text = f.read()
    old_mm = float(re.search(r"^diameter_mm = ([0-9.]+)", text, re.M).group(1))
    scale = (sleeve_mm / old_mm) ** 2
    text = re.sub(r"^diameter_mm = [0-9.]+", f"diameter_mm = {sleeve_mm}", text, flags=re.M)
    text = re.sub(r"^wall_thickness_mm = [0-9.]+", f"wall_thickness_mm = {wall_mm}", text,
                  flags=re.M)
    silicone = 'material = "silicone"' in text
    # a plant built with its tube already (PAMs A-C): the [bladder] table's law and tube lines
    # (and their comments' continuation lines) are written anew below
    head, rest = text.split("\n[bladder]\n", 1)
    end = rest.find("\n[")
    bladder, tail = (rest, "") if end < 0 else (rest[:end + 1], rest[end + 1:])
    bladder = re.sub(r"^(law|diameter_mm) = [^\n]*\n( +#[^\n]*\n)*", "", bladder, flags=re.M)
    text = head + "\n[bladder]\n" + bladder + tail
    text = re.sub(r"^material = .*$", ('material = "silicone"' if silicone else
                                       'material = "natural_rubber"\nlaw = "gent_gent"') +
                  f"\ndiameter_mm = {tube_mm}", text, flags=re.M)
    text = re.sub(r"(A[01]_mm2) = ([0-9.]+)",
                  lambda m: f"{m.group(1)} = {float(m.group(2)) * scale:.3f}", text)
    return text


def tensile_and_fit(pamsim, plant, pressures, folder, name):
    """The free length per pressure and the pull 5 mm past it, and the fitted (m, h)."""
    data = os.path.join(folder, name + ".csv")
    fit = os.path.join(folder, name + "_fit.toml")
    subprocess.run([pamsim, "tensile", "--plant", plant, "--pressures-MPa",
                    ",".join(str(p) for p in pressures), "--max-deformation-mm", "7.5",
                    "-o", data, "--force"], check=True, capture_output=True)
    subprocess.run([pamsim, "fit", "--model", "eq3", data, "-o", fit, "--force"], check=True,
                   capture_output=True)
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
    with open(fit) as f:
        text = f.read()
    m = float(re.search(r"^m = (\S+)", text, re.M).group(1))
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
            plant = os.path.join(folder, f"{name}_{wall}.toml")
            with open(plant, "w") as f:
                f.write(table1_plant(shipped, sleeve, tube, wall))
            try:
                free, pull, m = tensile_and_fit(pamsim, plant, pressures, folder, f"{name}_{wall}")
            except subprocess.CalledProcessError as e:
                why = e.stderr.decode().strip().splitlines()[-1]
                lines.append(f"| {name} | {sleeve} / {tube} | {wall} | {why} | | | |")
                continue
            paper = ""
            if law:
                ln = {p: table_iv(law, p)[0] for p in SHOWN_MPA}
                f5 = {p: table_iv(law, p)[1] for p in SHOWN_MPA}
                paper = f"{shown(ln, '{:.1f}')}; {law[0]}; {shown(f5, '{:.0f}')}"
            lines.append(f"| {name} | {sleeve} / {tube} | {wall} | {shown(free, '{:.1f}')} | "
                         f"{m:.1f} | {shown(pull, '{:.0f}')} |" + (f" {paper} |" if paper else " |"))
            print(lines[-1], file=sys.stderr)
    return lines


def main():
    pamsim, out, _ = options(__doc__)
    lines = ["| muscle | Table I sleeve / tube [mm] | wall [mm] | free length at "
             "0.2 / 0.4 / 0.6 MPa [mm] | fitted m [mm/MPa] | pull 5 mm past it at 0.2 / 0.4 / 0.6 "
             "MPa [N] | "
             "Table IV: l_n; m; pull |",
             "| --- | --- | --- | --- | --- | --- | --- |"]
    with tempfile.TemporaryDirectory() as folder:
        lines += rows(pamsim, folder)
    publish("\n".join(lines) + "\n", out, "table1_plants.md")


if __name__ == "__main__":
    main()
