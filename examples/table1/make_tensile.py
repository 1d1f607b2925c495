#!/usr/bin/env python3
"""make_tensile.py: Table IV's two spring laws (Yoshida and Hosoda [1], Eq. (2)-(3)) as the
tensile tests the lab fitted them to, for identifying the arm's muscles as Table I builds them
(docs/physics.md, "The muscles as Table I builds them").

The paper publishes the fits, not the rows. This writes the rows the fits give at the
protocol scripts/fit-estimators.sh runs on the plants (the arm's 0.2-0.7 MPa in 0.1 MPa
steps; 2.5 mm steps from the natural length l_n(p) = h + m p to 15 mm and back): force
(a3 p d + a2 p + a1 d + a0) d at length l_n(p) + d, without noise or hysteresis (a fit has
neither). It also writes each law refitted from its own rows (`pamsim fit`), which is Table
IV's law without a [geometry] table: identify_table1.toml's base scenario needs an estimator, and
one that names no braid angle lets the identification move the plant's (its strain
gauge's q is Table IV's).

    python3 examples/table1/make_tensile.py [PAMSIM]   (default build/src/sim/pamsim; 0.1 s)

writes examples/table1/recordings/tensile_{agonist,antagonist}.csv and
examples/table1/recordings/table4_{agonist,antagonist}_refit.toml.
"""

import os
import re
import subprocess
import sys
import tempfile
import tomllib

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
PRESSURES_MPA = [0.2, 0.3, 0.4, 0.5, 0.6, 0.7]
DEFORMATIONS_MM = [2.5 * k for k in range(7)]  # 0 .. 15 mm


def table4_law(muscle):
    """(m, h, a0, a1, a2, a3) of models/pams/table4_<muscle>.toml's [spring] table."""
    with open(os.path.join(ROOT, "models", "pams", f"table4_{muscle}.toml"), "rb") as f:
        spring = tomllib.load(f)["spring"]
    return {k: float(spring[k]) for k in ("m", "h", "a0", "a1", "a2", "a3")}


def rows(law):
    """pamsim tensile's CSV rows: loading up to 15 mm, then unloading back to 0."""
    out = []
    for p in PRESSURES_MPA:
        natural = law["h"] + law["m"] * p  # Eq. (2)
        back = DEFORMATIONS_MM[-2::-1]
        for direction, steps in (("loading", DEFORMATIONS_MM), ("unloading", back)):
            for d in steps:
                # Eq. (3)
                f = (law["a3"] * p * d + law["a2"] * p + law["a1"] * d + law["a0"]) * d
                out.append(f"{p:g},{d:g},{f:.6g},{natural + d:.6g},{direction}")
    return out


def write_atomically(path, text):
    with open(path + ".tmp", "w") as f:
        f.write(text)
    os.replace(path + ".tmp", path)


def main():
    default = os.path.join(ROOT, "build", "src", "sim", "pamsim")
    pamsim = sys.argv[1] if len(sys.argv) > 1 else default
    if not os.access(pamsim, os.X_OK):
        sys.exit(f"make_tensile.py: {pamsim}: no pamsim there (build it, or give its path)")
    folder = os.path.join(HERE, "recordings")
    os.makedirs(folder, exist_ok=True)
    for muscle in ("agonist", "antagonist"):
        csv_path = os.path.join(folder, f"tensile_{muscle}.csv")
        write_atomically(
            csv_path,
            "pressure_MPa,deformation_mm,force_N,length_mm,direction\n"
            + "\n".join(rows(table4_law(muscle)))
            + "\n",
        )
        with tempfile.TemporaryDirectory() as tmp:
            fitted = os.path.join(tmp, "refit.toml")
            # from the repository's root: the provenance names the files as the repository does
            done = subprocess.run(
                [
                    os.path.abspath(pamsim),
                    "fit",
                    "--model",
                    "eq3",
                    os.path.relpath(csv_path, ROOT),
                    "--sensors-from",
                    f"models/pams/table4_{muscle}.toml",
                    "-o",
                    fitted,
                ],
                stdout=subprocess.DEVNULL,
                cwd=ROOT,
            )
            if done.returncode != 0:  # pamsim fit has said why, in one line
                sys.exit(f"make_tensile.py: pamsim fit exited {done.returncode}")
            with open(fitted) as f:  # the gauge's q stays; the geometry (its braid) goes
                text = re.sub(r"\n\[geometry\][^\[]*", "\n", f.read())
        write_atomically(os.path.join(folder, f"table4_{muscle}_refit.toml"), text)
        print(f"wrote {csv_path}")


if __name__ == "__main__":
    main()
