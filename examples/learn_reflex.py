#!/usr/bin/env python3
"""learn_reflex.py: a linear policy learned from zero with CMA-ES on pamsim/DropMass-v0,
compared on held-out seeds with the passive arm and the stretch reflex of Table II.

The policy sets both valve commands each control period from what the arm's controller
measures (pressure, gauge force, estimated length and velocity of each muscle, scaled to
order one): commands = clip(0.4 + 0.1 (W z + b), 0, 0.8) MPa, 18 numbers, all zero at the
start (which is the passive arm holding its 0.4 MPa pretension). CMA-ES (the `cma` package)
maximises the mean return (minus the integral of the angle's deviation from its start, deg s,
and 10 per lost mass) over
the training seeds; the table then compares, on seeds it never saw, the peak drop, the mass
kept and the return of the passive arm, the scenario's own Table II reflex
(scenarios/drop_mass.toml, run by pamsim.run with the same drop, mass, height and sensor
noise) and the learned policy.

    .venv/bin/pip install gymnasium cma
    .venv/bin/python examples/learn_reflex.py [--generations 25] [--out learn_reflex.csv]

It writes the learning curve (generation, best and mean training return) as CSV.
"""

from __future__ import annotations

import argparse
import csv
import math
import time

import cma
import numpy as np

import pamsim
from pamsim.envs.drop_mass import DropMassEnv

TRAIN_SEEDS = list(range(6))
HELD_OUT_SEEDS = list(range(1000, 1020))
CENTER = np.array([0.4, 15.0, 145.0, 0.0])   # MPa, N, mm, mm/s: a muscle's measured channels
SCALE = np.array([0.1, 10.0, 5.0, 100.0])


def policy_commands(params: np.ndarray, obs: np.ndarray) -> np.ndarray:
    z = ((obs.reshape(-1, 4) - CENTER) / SCALE).reshape(-1)
    w, b = params[:16].reshape(2, 8), params[16:]
    return np.clip(0.4 + 0.1 * (w @ z + b), 0.0, 0.8).astype(np.float32)


def episode(env: DropMassEnv, seed: int, params: np.ndarray) -> tuple[float, dict]:
    obs, _ = env.reset(seed=seed)
    total = 0.0
    while True:
        obs, reward, terminated, truncated, info = env.step(policy_commands(params, obs))
        total += reward
        if terminated or truncated:
            return total, info["summary"]


def reflex_episode(env: DropMassEnv, seed: int) -> tuple[float, dict]:
    """The scenario's own controller (Table II's reflex) on the same draws as env's reset."""
    _, info = env.reset(seed=seed)
    overrides = {"sim.duration_s": env.duration_s, "drop.time_s": info["drop_time_s"],
                 "drop.mass_kg": info["mass_kg"], "drop.height_m": info["height_m"]}
    result = pamsim.run(env.scenario, overrides, seed=info["sensor_seed"])
    log = pamsim.trajectory(result)
    angle, time_s = log["angle_deg"], log["time_s"]
    dt = time_s[1] - time_s[0]
    # the environment's return on the log: the deviation's integral from the second tick on
    # (the log's ticks; the environment also counts the state after the last one)
    total = -float(np.sum(np.abs(angle[2:] - angle[0]))) * dt
    if result.summary.get("mass_retained", 1) == 0:
        total -= env.mass_lost_penalty
    return total, result.summary


def evaluate(env: DropMassEnv, run, seeds: list[int]) -> dict[str, float]:
    returns, drops, kept = [], [], []
    for seed in seeds:
        ret, summary = run(env, seed)
        returns.append(ret)
        drops.append(summary["peak_drop_deg"])
        kept.append(summary.get("mass_retained", 1))
    return {"return": float(np.mean(returns)), "peak_drop_deg": float(np.mean(drops)),
            "peak_drop_sd": float(np.std(drops, ddof=1)), "mass_kept": float(np.mean(kept))}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--generations", type=int, default=25)
    parser.add_argument("--out", default="learn_reflex.csv", help="the learning curve (CSV)")
    args = parser.parse_args()
    env = DropMassEnv()
    es = cma.CMAEvolutionStrategy(np.zeros(18), 0.5, {"seed": 1, "popsize": 8, "verbose": -9})
    start = time.perf_counter()
    with open(args.out, "w", newline="") as f:
        curve = csv.writer(f)
        curve.writerow(["generation", "best_return", "mean_return", "elapsed_s"])
        for generation in range(args.generations):
            candidates = es.ask()
            returns = [np.mean([episode(env, s, np.asarray(c))[0] for s in TRAIN_SEEDS])
                       for c in candidates]
            es.tell(candidates, [-r for r in returns])
            elapsed = time.perf_counter() - start
            curve.writerow([generation, max(returns), np.mean(returns), round(elapsed, 1)])
            print(f"generation {generation:3d}: best return {max(returns):8.3f} deg s, "
                  f"mean {np.mean(returns):8.3f} ({elapsed:.0f} s)", flush=True)
    learned = np.asarray(es.result.xbest)
    rows = {"passive arm (0.4 / 0.4 MPa)": lambda e, s: episode(e, s, np.zeros(18)),
            "stretch reflex, Table II": reflex_episode,
            "learned linear policy": lambda e, s: episode(e, s, learned)}
    print(f"\nheld-out seeds {HELD_OUT_SEEDS[0]}-{HELD_OUT_SEEDS[-1]} "
          f"({len(HELD_OUT_SEEDS)} drops):")
    print(f"{'controller':30s} {'return [deg s]':>15s} {'peak drop [deg]':>18s} {'mass kept':>10s}")
    for name, run in rows.items():
        r = evaluate(env, run, HELD_OUT_SEEDS)
        drop = f"{r['peak_drop_deg']:.2f} +- {r['peak_drop_sd']:.2f}"
        print(f"{name:30s} {r['return']:15.3f} {drop:>18s} {r['mass_kept']:10.2f}")
    if not math.isfinite(es.result.fbest):
        raise SystemExit("the search found no finite return")


if __name__ == "__main__":
    main()
