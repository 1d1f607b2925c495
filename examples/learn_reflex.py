#!/usr/bin/env python3
"""learn_reflex.py: a linear policy learned from zero with CMA-ES on pamsim/DropMass-v0,
compared on held-out seeds with the passive arm, the stretch reflex of Table II and, given a
tuning's result, the tuned reflex.

The policy sets both valve commands each control period from what the arm's controller
measures (pressure, gauge force, estimated length and velocity of each muscle, scaled to
order one): commands = clip(0.4 + 0.1 (W z + b), 0, 0.8) MPa, 18 numbers, all zero at the
start (which is the passive arm holding its 0.4 MPa pretension). CMA-ES (the `cma` package)
maximises the mean return (minus the integral of the angle's deviation from its start, deg s,
and 10 per lost mass) over
the training seeds; the table then compares, on seeds it never saw, the peak drop, the mass
kept, the mistrips (a reflex firing before the mass lands; a policy has no trigger) and the
return of the passive arm, the scenario's own Table II reflex (scenarios/drop_mass.toml, run
by pamsim.run with the same drop, mass, height and sensor noise), the tuned reflex (the
scenario `pamsim tune scenarios/tune_reflex.toml` writes as best.toml, run the same way)
and the learned policy.

    .venv/bin/pip install gymnasium cma
    pamsim tune scenarios/tune_reflex.toml          # optional: the tuned reflex's row
    .venv/bin/python examples/learn_reflex.py [--generations 25] [--out learn_reflex.csv] \
        [--tuned renders/tune_reflex/best.toml]

It writes the learning curve (generation, best and mean training return) as CSV.
"""

from __future__ import annotations

import argparse
import csv
import math
import time

import cma
import numpy as np
from drop_mass_eval import (
    HELD_OUT_SEEDS,
    TRAIN_SEEDS,
    policy_episode,
    print_table,
    reflex_episode,
    scaled,
)

from pamsim.envs.drop_mass import DropMassEnv


def policy_commands(params: np.ndarray, obs: np.ndarray) -> np.ndarray:
    w, b = params[:16].reshape(2, 8), params[16:]
    return np.clip(0.4 + 0.1 * (w @ scaled(obs) + b), 0.0, 0.8).astype(np.float32)


def episode(env: DropMassEnv, seed: int, params: np.ndarray) -> tuple[float, dict]:
    return policy_episode(env, seed, lambda obs: policy_commands(params, obs))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--generations", type=int, default=25)
    parser.add_argument("--out", default="learn_reflex.csv", help="the learning curve (CSV)")
    parser.add_argument("--tuned", help="a tuned reflex's scenario (pamsim tune's best.toml)")
    args = parser.parse_args()
    env = DropMassEnv()
    es = cma.CMAEvolutionStrategy(np.zeros(18), 0.5, {"seed": 1, "popsize": 8, "verbose": -9})
    start = time.perf_counter()
    with open(args.out, "w", newline="") as f:
        curve = csv.writer(f)
        curve.writerow(["generation", "best_return", "mean_return", "elapsed_s"])
        for generation in range(args.generations):
            candidates = es.ask()
            returns = [
                np.mean([episode(env, s, np.asarray(c))[0] for s in TRAIN_SEEDS])
                for c in candidates
            ]
            es.tell(candidates, [-r for r in returns])
            elapsed = time.perf_counter() - start
            curve.writerow([generation, max(returns), np.mean(returns), round(elapsed, 1)])
            print(
                f"generation {generation:3d}: best return {max(returns):8.3f} deg s, "
                f"mean {np.mean(returns):8.3f} ({elapsed:.0f} s)",
                flush=True,
            )
    learned = np.asarray(es.result.xbest)
    rows = {
        "passive arm (0.4 / 0.4 MPa)": (lambda e, s: episode(e, s, np.zeros(18)), False),
        "stretch reflex, Table II": (lambda e, s: reflex_episode(e, s, e.scenario), True),
    }
    if args.tuned:
        rows["tuned stretch reflex"] = (lambda e, s: reflex_episode(e, s, args.tuned), True)
    rows["learned linear policy"] = (lambda e, s: episode(e, s, learned), False)
    print_table(env, rows, HELD_OUT_SEEDS)
    if not math.isfinite(es.result.fbest):
        raise SystemExit("the search found no finite return")


if __name__ == "__main__":
    main()
