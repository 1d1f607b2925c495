#!/usr/bin/env python3
"""ppo_drop_mass.py: PPO from stable-baselines3 on pamsim/DropMass-v0, the deep-RL option
beside learn_reflex.py's CMA-ES, compared on the same held-out seeds with the passive arm and
the stretch reflex of Table II. Not run in CI: stable-baselines3 needs PyTorch (from the
registry, a download of about 3 GB with its CUDA libraries; a CPU-only torch is smaller).

The policy network sees the measured channels scaled as learn_reflex.py scales them (each
muscle's pressure, gauge force, estimated length and velocity about a nominal point) and
sets both valve commands each control period; PPO's Gaussian actions are clipped to the
valve range [0, 0.7] MPa by stable-baselines3 before the environment sees them.

    python3 -m venv .venv-rl && .venv-rl/bin/pip install . stable-baselines3
    .venv-rl/bin/python examples/ppo_drop_mass.py [--timesteps 150000] [--save ppo.zip]
"""

from __future__ import annotations

import argparse
import time

import gymnasium
import numpy as np
from drop_mass_eval import (
    HELD_OUT_SEEDS,
    TRAIN_SEEDS,
    policy_episode,
    print_table,
    reflex_episode,
    scaled,
)
from stable_baselines3 import PPO

import pamsim  # noqa: F401  (registers the environments)


class ScaledObservation(gymnasium.ObservationWrapper):
    """The measured channels about their nominal point, in units of order one."""

    def __init__(self, env: gymnasium.Env) -> None:
        super().__init__(env)
        n = env.observation_space.shape[0]
        self.observation_space = gymnasium.spaces.Box(-np.inf, np.inf, (n,), np.float32)

    def observation(self, observation: np.ndarray) -> np.ndarray:
        return scaled(observation).astype(np.float32)


class TrainingSeeds(gymnasium.Wrapper):
    """Resets cycle through the training seeds, so that PPO sees the drops CMA-ES sees."""

    def __init__(self, env: gymnasium.Env) -> None:
        super().__init__(env)
        self.episodes = 0

    def reset(self, *, seed=None, options=None):
        self.episodes += 1
        return self.env.reset(seed=TRAIN_SEEDS[self.episodes % len(TRAIN_SEEDS)], options=options)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--timesteps", type=int, default=150_000, help="PPO's training steps")
    parser.add_argument("--save", help="where to save the trained policy (.zip)")
    args = parser.parse_args()
    train = TrainingSeeds(ScaledObservation(gymnasium.make("pamsim/DropMass-v0")))
    model = PPO("MlpPolicy", train, seed=1, n_steps=1500, batch_size=150, verbose=0)
    start = time.perf_counter()
    model.learn(total_timesteps=args.timesteps)
    print(f"PPO: {args.timesteps} steps in {time.perf_counter() - start:.0f} s")
    if args.save:
        model.save(args.save)
    env = gymnasium.make("pamsim/DropMass-v0").unwrapped

    def act(obs: np.ndarray) -> np.ndarray:
        action, _ = model.predict(scaled(obs).astype(np.float32), deterministic=True)
        return np.clip(action, 0.0, env.p_max_MPa).astype(np.float32)

    rows = {
        "passive arm (0.4 / 0.4 MPa)": (
            lambda e, s: policy_episode(e, s, lambda obs: np.full(2, 0.4, np.float32)),
            False,
        ),
        "stretch reflex, Table II": (lambda e, s: reflex_episode(e, s, e.scenario), True),
        "PPO (stable-baselines3)": (lambda e, s: policy_episode(e, s, act), False),
    }
    print_table(env, rows, HELD_OUT_SEEDS)


if __name__ == "__main__":
    main()
