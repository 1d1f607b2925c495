"""pamsim/DropMass-v0: the falling-mass experiment with the agent as the arm's controller.

A vertical arm driven by an antagonistic pair of PAMs holds a basket; a mass falls into it
(Yoshida and Hosoda's stretch-reflex experiment, scenarios/drop_mass.toml). Each step is one
control period (10 ms at the scenario's 100 Hz): the action sets both valve commands, the
observation is what the robot's controller has on hardware, never the true state unless
``observation="privileged"``.

Action and observation: the valve commands [MPa] of both muscles (agonist, antagonist) and
their measured channels, as ``pam_trial_env.PamTrialEnv`` says (no task entries).

Reward: minus the arm's deviation from its starting angle, |angle - start| [deg], times the
control period [s] each step (the integral of the deviation, deg s: the posture held against
the drop, so that lifting the arm out of the way earns nothing); when the episode ends with
the mass lost from the basket (summary mass_retained = 0), a further -``mass_lost_penalty``
(default 10).

Each reset draws the drop time in [0.3, 0.6] s, the mass in [0.15, 0.25] kg and the drop
height in [0.10, 0.18] m (around the paper's 0.2 kg from 14 cm), and the sensors' noise seed,
from the environment's generator; ``randomize=False`` keeps the scenario's values. An episode
lasts ``duration_s`` (1.5 s), then is truncated; a trial that diverges terminates it. The
reset runs the first control tick with the scenario's own commands, so that the first
observation is a real reading.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .data import data_dir
from .pam_trial_env import MEASURED, PamTrialEnv, joint_state

__all__ = ["DropMassEnv", "MEASURED"]

DROP_TIME_S = (0.3, 0.6)
MASS_KG = (0.15, 0.25)
HEIGHT_M = (0.10, 0.18)


def _drop_overrides(draws: list[float]) -> dict[str, Any]:
    """The scenario keys of a reset's draws (NaN: the scenario's own value)."""
    keys = ("drop.time_s", "drop.mass_kg", "drop.height_m")
    return {k: v for k, v in zip(keys, draws, strict=True) if not math.isnan(v)}


class DropMassEnv(PamTrialEnv):
    def __init__(
        self,
        scenario: str | None = None,
        observation: str = "measured",
        fiber: bool = False,
        randomize: bool = True,
        noise_scale: float = 1.0,
        duration_s: float = 1.5,
        mass_lost_penalty: float = 10.0,
        p_max_MPa: float | None = None,
        render_mode: str | None = None,
        overrides: dict[str, Any] | None = None,
    ) -> None:
        if randomize and not duration_s > DROP_TIME_S[1]:
            raise ValueError(
                f"duration_s must exceed the latest drop time {DROP_TIME_S[1]} s, got {duration_s}"
            )
        self.randomize = randomize
        self.mass_lost_penalty = mass_lost_penalty
        self.start_position = 0.0
        latest = [DROP_TIME_S[1], MASS_KG[1], HEIGHT_M[1]] if randomize else [math.nan] * 3
        super().__init__(
            scenario or str(data_dir() / "scenarios" / "drop_mass.toml"),
            _drop_overrides(latest),
            observation,
            fiber,
            noise_scale,
            duration_s,
            p_max_MPa,
            render_mode,
            overrides,
        )

    def draw(self, rng: np.random.Generator) -> tuple[dict[str, Any], dict[str, Any]]:
        if self.randomize:
            draws = [float(rng.uniform(*r)) for r in (DROP_TIME_S, MASS_KG, HEIGHT_M)]
        else:
            draws = [math.nan] * 3
        info = {"drop_time_s": draws[0], "mass_kg": draws[1], "height_m": draws[2]}
        return _drop_overrides(draws), info

    def step_reward(self, observation: dict[str, Any], period_s: float) -> float:
        return -abs(joint_state(observation)[0] - self.start_position) * period_s

    def end_reward(self, summary: dict[str, Any]) -> float:
        return -self.mass_lost_penalty if summary.get("mass_retained", 1) == 0 else 0.0
