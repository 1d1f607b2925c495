#!/usr/bin/env python3
"""env_throughput.py: the Gymnasium environment's cost, measured in one run:
  env step    one DropMassEnv.step (observation, reward, action checks) / one control period
              of SteppedTrial::step in a C++ loop (pamsim._cxx_step_s) on the same scenario
  threaded    ThreadedVectorEnv steps per second (environment steps, all envs) for 1, 4 and
              16 environments (or the counts given), and the speed-up over one
Run in an environment with gymnasium (best of 3 each):
  .venv/bin/python bench/env_throughput.py [N...]   (or PYTHONPATH=build/python)
"""

import sys
import time

import gymnasium
import numpy as np

import pamsim
from pamsim import _pamsim
from pamsim.envs.data import data_dir
from pamsim.envs.drop_mass import DropMassEnv
from pamsim.envs.vector import ThreadedVectorEnv

STEPS = 300
ACTION = np.array([0.45, 0.35], dtype=np.float32)


def env_step_s() -> float:
    env = DropMassEnv(duration_s=3.0)
    env.reset(seed=1)
    t0 = time.perf_counter()
    for _ in range(STEPS):
        env.step(ACTION)
    return (time.perf_counter() - t0) / STEPS


def vector_steps_per_s(n: int) -> float:
    vec = ThreadedVectorEnv([lambda: DropMassEnv(duration_s=3.0) for _ in range(n)])
    vec.reset(seed=1)
    actions = np.tile(ACTION, (n, 1))
    t0 = time.perf_counter()
    for _ in range(STEPS // 3):
        vec.step(actions)
    rate = n * (STEPS // 3) / (time.perf_counter() - t0)
    vec.close()
    return rate


def env_counts(args) -> list:
    """The environment counts asked for (default 1, 4, 16), or exit with one line."""
    try:
        counts = [int(a) for a in args] or [1, 4, 16]
    except ValueError:
        counts = []
    if not counts or min(counts) < 1:
        sys.exit(
            f"env_throughput.py: the environment counts must be whole numbers >= 1, got "
            f"{' '.join(args)}"
        )
    return counts


counts = env_counts(sys.argv[1:])
scenario = str(data_dir() / "scenarios" / "drop_mass.toml")
py = min(env_step_s() for _ in range(3))
cxx = min(_pamsim._cxx_step_s(scenario, {"sim.duration_s": 3.0}, STEPS) for _ in range(3))
print(f"pamsim {pamsim.__version__}, gymnasium {gymnasium.__version__}")
print(f"env step {py * 1e6:.0f} us, C++ control period {cxx * 1e6:.0f} us, ratio {py / cxx:.2f}")
one = max(vector_steps_per_s(1) for _ in range(3))
for n in counts:
    rate = one if n == 1 else max(vector_steps_per_s(n) for _ in range(3))
    print(f"ThreadedVectorEnv {n:2d} envs: {rate:7.0f} env steps/s, speed-up {rate / one:.2f}")
