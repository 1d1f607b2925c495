#!/usr/bin/env python3
"""fit_and_drop.py: pamsim from Python, as in a notebook: fit a spring law to a virtual
tensile test of a physical plant, check its inversion, run a drop with and without the
reflex and plot the angle with matplotlib.

    PYTHONPATH=build/python python3 examples/fit_and_drop.py [OUT.png]

(after `make build`; with an installed pamsim, plain `python3` finds it). Writes OUT.png
(default renders/python_example/drop.png) and prints what it found.
"""

import os
import sys

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import pamsim  # noqa: E402

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "renders/python_example/drop.png")

# 1. the lab's fit: a tensile test of PAM A's plant (AVBDL with friction), Eq. (3) fitted
data = pamsim.tensile_test(
    os.path.join(root, "models/pams/plant_pam_a.toml"),
    pressures_MPa=[0.4, 0.5, 0.6, 0.7, 0.8],
    noise_force_N=0.2,
    seed=1,
)
fit = pamsim.fit(
    "eq3", data["pressure_MPa"], data["deformation_mm"], data["force_N"], data["length_mm"]
)
law = fit["model"]
print(f"fit: {law}  rmse {fit['rmse_N']:.3f} N, R^2 {fit['r2']:.5f} over {fit['points']} points")

# 2. length from (p, f): invert the fitted law over the measured points, vectorised
d_est = law.deformation_mm(data["pressure_MPa"], data["force_N"])
err = d_est - data["deformation_mm"]
print(f"deformation from (p, f): RMS error {np.sqrt(np.mean(err**2)):.3f} mm")

# 3. the drop-mass experiment with and without the reflex
drop = os.path.join(root, "scenarios/drop_mass.toml")
reflex = pamsim.run(drop)
passive = pamsim.run(os.path.join(root, "scenarios/drop_mass_passive.toml"))
for name, r in (("reflex", reflex), ("passive", passive)):
    m = r.summary["metrics"]
    print(f"{name}: peak drop {m['peak_drop_deg']:.2f} deg")

fig, ax = plt.subplots(figsize=(7, 4))
for name, r in (("stretch reflex", reflex), ("passive", passive)):
    t = pamsim.trajectory(r)
    ax.plot(t["time_s"], t["angle_deg"], label=name)
ax.set_xlabel("time [s]")
ax.set_ylabel("joint angle [deg]")
ax.set_title("0.2 kg mass dropped into the basket (drop_mass.toml)")
ax.legend()
os.makedirs(os.path.dirname(out), exist_ok=True)
fig.savefig(out, dpi=100)
print(out)
