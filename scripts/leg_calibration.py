#!/usr/bin/env python3
"""leg_calibration.py: the fishing-line lengths of the leg's eight PAMs (models/leg_pam.xml,
issue 27) for a start posture: each muscle starts DEFORMATION_MM past its plant's free length
at its start pressure, so every line is taut and pre-tensioned a little (the arm's rule:
models/arm_2pam_plant_calibration.toml stretches its antagonist 1 mm). The tendon lengths
come from the model's sites by planar kinematics (hip flexion, knee flexion and ankle plantar
flexion positive, as the MJCF's axes say), the free lengths from each plant's tensile test
(scripts/fit-estimators.sh writes them: renders/tensile/leg_<m>.csv, the rows at zero
deformation). Prints the [muscles.<m>] line_mm values the leg scenarios carry.

    python3 scripts/leg_calibration.py [--hip 20] [--knee 40] [--ankle -20] [--pressure 0.4]
"""
import argparse
import csv
import math
import os
import xml.etree.ElementTree as ET

MUSCLES = ["IL", "GM", "RF", "VAS", "BFS", "GAS", "SOL", "TA"]
DEFORMATION_MM = 2.0
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def bodies_and_sites(path):
    """body -> (parent, pos, hinge axis sign or None), site -> (body, pos)"""
    tree = ET.parse(path)
    bodies, sites = {}, {}

    def walk(elem, parent):
        for body in elem.findall("body"):
            name = body.get("name")
            pos = [float(v) for v in body.get("pos", "0 0 0").split()]
            joint = body.find("joint")
            axis = None
            if joint is not None and joint.get("type") == "hinge":
                axis = (joint.get("name"), [float(v) for v in joint.get("axis").split()][1])
            bodies[name] = (parent, pos, axis)
            for site in body.findall("site"):
                sites[site.get("name")] = (name, [float(v) for v in site.get("pos").split()])
            walk(body, name)

    walk(tree.getroot().find("worldbody"), None)
    tendons = {}
    for spatial in tree.getroot().find("tendon").findall("spatial"):
        tendons[spatial.get("name")] = [s.get("site") for s in spatial.findall("site")]
    return bodies, sites, tendons


def frame(bodies, name, angles):
    """world position (x, z) and rotation about +y of body `name`"""
    parent, pos, axis = bodies[name]
    if parent is None:
        x, z, phi = 0.0, 0.0, 0.0
    else:
        x, z, phi = frame(bodies, parent, angles)
    px, pz = pos[0], pos[2]
    x += px * math.cos(phi) + pz * math.sin(phi)
    z += -px * math.sin(phi) + pz * math.cos(phi)
    if axis is not None:
        phi += axis[1] * math.radians(angles[axis[0]])   # about +y (or -y for a -y axis)
    return x, z, phi


def site_position(bodies, sites, name, angles):
    body, pos = sites[name]
    x, z, phi = frame(bodies, body, angles)
    return (x + pos[0] * math.cos(phi) + pos[2] * math.sin(phi),
            z - pos[0] * math.sin(phi) + pos[2] * math.cos(phi))


def free_length_mm(muscle, pressure_mpa):
    path = os.path.join(ROOT, "renders", "tensile", f"leg_{muscle}.csv")
    with open(path) as f:
        rows = [r for r in csv.DictReader(f) if r["direction"] == "loading"
                and abs(float(r["deformation_mm"])) < 0.05]
    row = min(rows, key=lambda r: abs(float(r["pressure_MPa"]) - pressure_mpa))
    if abs(float(row["pressure_MPa"]) - pressure_mpa) > 0.01:
        raise SystemExit(f"{path}: no tensile row at {pressure_mpa} MPa")
    return float(row["length_mm"]) - float(row["deformation_mm"])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--hip", type=float, default=20.0)
    parser.add_argument("--knee", type=float, default=40.0)
    parser.add_argument("--ankle", type=float, default=-20.0)
    parser.add_argument("--pressure", type=float, default=0.4, help="start pressure [MPa]")
    args = parser.parse_args()
    bodies, sites, tendons = bodies_and_sites(os.path.join(ROOT, "models", "leg_pam.xml"))
    angles = {"hip": args.hip, "knee": args.knee, "ankle": args.ankle}
    for m in MUSCLES:
        points = [site_position(bodies, sites, s, angles) for s in tendons[f"{m}_line"]]
        tendon_mm = 1000.0 * sum(math.dist(a, b) for a, b in zip(points, points[1:]))
        muscle_mm = free_length_mm(m, args.pressure) + DEFORMATION_MM
        print(f"[muscles.{m}]  # tendon {tendon_mm:.1f} mm, muscle {muscle_mm:.1f} mm")
        print(f"line_mm = {tendon_mm - muscle_mm:.2f}")


if __name__ == "__main__":
    main()
