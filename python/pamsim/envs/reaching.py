"""pamsim/Reaching-v0: the arm of the reaching task (scenarios/reaching.toml) driven to a target
angle profile by the agent as its controller.

The arm of Yoshida and Hosoda's reaching validation (its two PAMs on the shoulder, the
ITV1000-class regulator, the sensors as hardware) starts at rest at its calibrated posture.
Each episode the target moves from that start angle to a final angle drawn in
``FINAL_DEG`` (the span the paper's 0.2-0.6 MPa ramps sweep, -66 to -15 deg) along a ramp
of ``RAMP_S`` seconds from ``RAMP_START_S``, then holds; the agent tracks it.

Action and observation: the valve commands [MPa] of both muscles (agonist, antagonist) and
their measured channels, as ``pam_trial_env.PamTrialEnv`` says, then the target angle [deg]
at the observation's tick (the task's command, not a measurement).

Reward: minus |angle - target| [deg] times the control period [s] each step (the tracking
error's integral, deg s). An episode lasts ``duration_s`` (4 s).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .data import data_dir
from .pam_trial_env import PamTrialEnv, joint_state

__all__ = ["ReachingEnv"]

FINAL_DEG = (-60.0, -20.0)
RAMP_START_S = 0.5
RAMP_S = 2.0


class ReachingEnv(PamTrialEnv):
    task_observation_size = 1

    def __init__(
        self,
        scenario: str | None = None,
        observation: str = "measured",
        fiber: bool = False,
        randomize: bool = True,
        noise_scale: float = 1.0,
        duration_s: float = 4.0,
        final_deg: float = -30.0,
        p_max_MPa: float | None = None,
        render_mode: str | None = None,
        overrides: dict[str, Any] | None = None,
    ) -> None:
        if not duration_s > RAMP_START_S + RAMP_S:
            raise ValueError(
                f"duration_s must exceed the ramp's end {RAMP_START_S + RAMP_S} s, got {duration_s}"
            )
        self.randomize = randomize
        self.final_deg = final_deg
        self.start_position = 0.0
        super().__init__(
            scenario or str(data_dir() / "scenarios" / "reaching.toml"),
            {},
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
            self.final_deg = float(rng.uniform(*FINAL_DEG))
        return {}, {"final_deg": self.final_deg}

    def target_deg(self, time_s: float) -> float:
        """The target angle [deg] at `time_s`: the start, a ramp, then the final angle."""
        u = min(max((time_s - RAMP_START_S) / RAMP_S, 0.0), 1.0)
        return self.start_position + u * (self.final_deg - self.start_position)

    def task_observation(self, time_s: float) -> list[float]:
        return [self.target_deg(time_s)]

    def step_reward(self, observation: dict[str, Any], period_s: float) -> float:
        angle = joint_state(observation)[0]
        return -abs(angle - self.target_deg(observation["time_s"])) * period_s
