#!/usr/bin/env python3
"""python_overhead.py: what calling pamsim from Python costs against the same C++ loop,
measured in one run (the issue-18 figures):
  law     SpringModel.force_N over 10^6 points (numpy arrays) / the plain C++ loop over them
  step    one Trial.step() from Python (the reflex controller, drop_mass.toml) / one
          SteppedTrial::step in a C++ loop
Run: PYTHONPATH=build/python python3 bench/python_overhead.py (best of 5 each).
"""

import os
import time

import numpy as np

import pamsim
from pamsim import _pamsim

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
law = pamsim.SpringModel.from_file(os.path.join(root, "models/pams/table4_agonist.toml"))
rng = np.random.default_rng(1)
p = rng.uniform(0.1, 0.8, 1_000_000)
d = rng.uniform(0.0, 25.0, 1_000_000)


def best(fn, n=5):
    times = []
    for _ in range(n):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


py_law = best(lambda: law.force_N(p, d))
cxx_law = min(_pamsim._cxx_force_loop_s(law, p, d) for _ in range(5))
print(
    f"law over 1e6 points: python {py_law * 1e3:.2f} ms, C++ loop {cxx_law * 1e3:.2f} ms, "
    f"ratio {py_law / cxx_law:.2f}"
)

drop = os.path.join(root, "scenarios/drop_mass.toml")
periods = 1500


def python_steps():
    trial = pamsim.Trial(drop)
    t0 = time.perf_counter()
    n = 0
    while n < periods and trial.step():
        n += 1
    return (time.perf_counter() - t0) / n


py_step = min(python_steps() for _ in range(5))
cxx_step = min(_pamsim._cxx_step_s(drop, None, periods) for _ in range(5))
print(
    f"Trial.step: python {py_step * 1e6:.1f} us, C++ loop {cxx_step * 1e6:.1f} us per control "
    f"period, ratio {py_step / cxx_step:.2f}"
)
