"""drop_mass_eval.py: what the examples that learn on pamsim/DropMass-v0 share: the training
and held-out seeds, the observation scaled to order one, a policy's and a reflex's episode on
the same draws, and the held-out table (return, peak drop, mass kept, mistrips).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

import pamsim
from pamsim.envs.drop_mass import DropMassEnv

TRAIN_SEEDS = list(range(6))
HELD_OUT_SEEDS = list(range(1000, 1020))
CENTER = np.array([0.4, 15.0, 145.0, 0.0])  # MPa, N, mm, mm/s: a muscle's measured channels
SCALE = np.array([0.1, 10.0, 5.0, 100.0])


def scaled(obs: np.ndarray) -> np.ndarray:
    """The measured channels of each muscle about CENTER in units of SCALE."""
    return ((obs.reshape(-1, 4) - CENTER) / SCALE).reshape(-1)


def policy_episode(
    env: DropMassEnv, seed: int, act: Callable[[np.ndarray], np.ndarray]
) -> tuple[float, dict]:
    """One episode of a policy (observation -> valve commands): its return and summary."""
    obs, _ = env.reset(seed=seed)
    total = 0.0
    while True:
        obs, reward, terminated, truncated, info = env.step(act(obs))
        total += reward
        if terminated or truncated:
            return total, info["summary"]


def reflex_episode(env: DropMassEnv, seed: int, scenario: str) -> tuple[float, dict]:
    """A scenario's own controller (a stretch reflex) on the same draws as env's reset."""
    _, info = env.reset(seed=seed)
    overrides = {
        "sim.duration_s": env.duration_s,
        "drop.time_s": info["drop_time_s"],
        "drop.mass_kg": info["mass_kg"],
        "drop.height_m": info["height_m"],
    }
    result = pamsim.run(scenario, overrides, seed=info["sensor_seed"])
    log = pamsim.trajectory(result)
    angle, time_s = log["angle_deg"], log["time_s"]
    dt = time_s[1] - time_s[0]
    # the environment's return on the log: the deviation's integral from the second tick on
    # (the log's ticks; the environment also counts the state after the last one)
    total = -float(np.sum(np.abs(angle[2:] - angle[0]))) * dt
    if result.summary.get("mass_retained", 1) == 0:
        total -= env.mass_lost_penalty
    return total, result.summary


def evaluate(env: DropMassEnv, run, seeds: list[int], reflex: bool) -> dict[str, float]:
    """Means over `seeds`; the mistrips per trial for a reflex (NaN for a policy, whose
    trial's summary counts the scenario's own reflex, which does not act)."""
    returns, drops, kept, mistrips = [], [], [], []
    for seed in seeds:
        ret, summary = run(env, seed)
        returns.append(ret)
        drops.append(summary["peak_drop_deg"])
        kept.append(summary.get("mass_retained", 1))
        mistrips.append(summary.get("mistrips", 0) if reflex else math.nan)
    return {
        "return": float(np.mean(returns)),
        "peak_drop_deg": float(np.mean(drops)),
        "peak_drop_sd": float(np.std(drops, ddof=1)),
        "mass_kept": float(np.mean(kept)),
        "mistrips": float(np.mean(mistrips)),
    }


def print_table(env: DropMassEnv, rows: dict, seeds: list[int]) -> None:
    """The held-out comparison; `rows` maps a name to (episode function, is a reflex)."""
    print(f"\nheld-out seeds {seeds[0]}-{seeds[-1]} ({len(seeds)} drops):")
    print(
        f"{'controller':34s} {'return [deg s]':>15s} {'peak drop [deg]':>18s} "
        f"{'mass kept':>10s} {'mistrips':>9s}"
    )
    for name, (run, reflex) in rows.items():
        r = evaluate(env, run, seeds, reflex)
        drop = f"{r['peak_drop_deg']:.2f} +- {r['peak_drop_sd']:.2f}"
        mistrips = "-" if math.isnan(r["mistrips"]) else f"{r['mistrips']:.2f}"
        print(f"{name:34s} {r['return']:15.3f} {drop:>18s} {r['mass_kept']:10.2f} {mistrips:>9s}")
