"""The part every pamsim environment shares: a step-wise trial of a scenario whose valve
commands the agent sets each control period, observed as the robot's controller would be.

Action: the valve commands [MPa], one per muscle in model order, in [0, p_max]
(valve.command_max_MPa unless ``p_max_MPa`` is given). A command outside is clipped, with one
warning per episode; a NaN raises ValueError and leaves the episode where it was. The
scenario's own controller still reads the sensors (its estimates are the observation's) but
its commands are replaced.

Observation (float64), per muscle in model order: measured pressure [MPa], gauge force [N],
estimated length [mm], estimated stretch velocity [mm/s], as the trial log's columns
p_meas_<m>_MPa, force_meas_<m>_N, length_est_<m>_mm, velocity_est_<m>_mm_s have them at the
same tick; with ``fiber=True`` also the fiber sensor's rate [mm/s]; then what the task adds
(a target, ``task_observation``); with ``observation="privileged"`` last the true angle [deg]
and angular velocity [deg/s] (a slide joint: its position [mm] and velocity [mm/s]).

A subclass gives the reset's draws (``draw``: scenario overrides and their info), the reward
of a step (``step_reward``) and of the episode's end (``end_reward``). An episode lasts
``duration_s`` (None: the scenario's own), then is truncated; a trial that diverges
terminates it. The reset runs the first control tick with the scenario's own commands, so
that the first observation is a real reading.

``overrides``: scenario keys set in every trial ({"valve.dead_time_ms": 2.0}), as the
registered variants set them.

Rendering: ``render_mode="rgb_array"`` makes ``render()`` return the state as a 640 x 480
RGB frame (``render_width``, ``render_height``), the scene of ``pamsim render`` without its
overlays, drawn offscreen.
"""

from __future__ import annotations

import warnings
from typing import Any

import gymnasium
import numpy as np
import numpy.typing as npt
from gymnasium import spaces

from .._pamsim import Trial

Obs = npt.NDArray[np.float64]
Act = npt.NDArray[np.float32]

# what the policy observes per muscle: rows of trajectory.csv's channel table marked measured
# (pamsim.channels(); a test holds this list to it), by their names without the muscle
MEASURED = ("p_meas_MPa", "force_meas_N", "length_est_mm", "velocity_est_mm_s")


def joint_state(observation: dict[str, Any]) -> tuple[float, float]:
    """The measured joint's true position and velocity: a hinge's [deg, deg/s], a slide's
    [mm, mm/s]."""
    if "angle_deg" in observation:
        return observation["angle_deg"], observation["angular_velocity_deg_s"]
    return observation["position_mm"], observation["velocity_mm_s"]


class PamTrialEnv(gymnasium.Env[Obs, Act]):
    metadata: dict[str, Any] = {"render_modes": ["rgb_array"], "render_fps": 100}
    task_observation_size = 0  # entries the task adds to the observation
    render_width, render_height = 640, 480  # render_mode="rgb_array"'s frame [px]

    def __init__(
        self,
        scenario: str,
        probe_overrides: dict[str, Any],
        observation: str,
        fiber: bool,
        noise_scale: float,
        duration_s: float | None,
        p_max_MPa: float | None,
        render_mode: str | None,
        overrides: dict[str, Any] | None = None,
    ) -> None:
        if observation not in ("measured", "privileged"):
            raise ValueError(f'observation must be "measured" or "privileged", got {observation!r}')
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f'render_mode must be None or "rgb_array", got {render_mode!r}')
        self.render_mode = render_mode
        self.scenario = scenario
        self.privileged = observation == "privileged"
        self.fiber = fiber
        self.noise_scale = noise_scale
        self.duration_s = duration_s
        self.overrides = dict(overrides or {})  # scenario keys of every trial (a variant's)
        self._trial: Trial | None = None
        self._warned = False
        self._time_s = 0.0
        self.last_result: Any = None
        probe = Trial(self.scenario, self.scenario_overrides(probe_overrides))
        self.muscles: list[str] = list(probe.muscles)
        probe.step()  # one control period: the frames' rate
        self.metadata = {**self.metadata, "render_fps": round(1.0 / probe.observe()["time_s"])}
        # the actions' top: the scenario's valve range unless given
        self.p_max_MPa: float = probe.command_max_MPa if p_max_MPa is None else p_max_MPa
        n = len(self.muscles)
        self.action_space = spaces.Box(0.0, self.p_max_MPa, shape=(n,), dtype=np.float32)
        size = (
            n * (len(MEASURED) + (1 if fiber else 0))
            + self.task_observation_size
            + (2 if self.privileged else 0)
        )
        self.observation_space = spaces.Box(-np.inf, np.inf, shape=(size,), dtype=np.float64)

    # what a task defines
    def draw(self, rng: np.random.Generator) -> tuple[dict[str, Any], dict[str, Any]]:
        """The reset's scenario overrides and their info, drawn from `rng`."""
        return {}, {}

    def task_observation(self, time_s: float) -> list[float]:
        """The task's entries of the observation at `time_s` (a target)."""
        return []

    def step_reward(self, observation: dict[str, Any], period_s: float) -> float:
        raise NotImplementedError

    def end_reward(self, summary: dict[str, Any]) -> float:
        return 0.0

    def scenario_overrides(self, task: dict[str, Any]) -> dict[str, Any]:
        """Every trial's overrides: the episode's length (None: the scenario's), the noise, the
        variant's and the task's."""
        length = {} if self.duration_s is None else {"sim.duration_s": self.duration_s}
        return {**length, "sensors.noise_scale": self.noise_scale, **self.overrides, **task}

    @property
    def trial(self) -> Trial:
        if self._trial is None:
            raise RuntimeError("call reset() before step()")
        return self._trial

    def _observe(self) -> Obs:
        o = self.trial.observe()
        m = o["measured"]
        names = MEASURED + (("fiber_rate_mm_s",) if self.fiber else ())
        values = [m[name][i] for i in range(len(self.muscles)) for name in names]
        values += self.task_observation(o["time_s"])
        if self.privileged:
            values += list(joint_state(o))
        return np.array(values, dtype=np.float64)

    def reset(
        self, *, seed: int | None = None, options: dict[str, Any] | None = None
    ) -> tuple[Obs, dict[str, Any]]:
        super().reset(seed=seed)
        overrides, info = self.draw(self.np_random)
        sensor_seed = int(self.np_random.integers(1, 2**31))
        self._trial = Trial(self.scenario, self.scenario_overrides(overrides), seed=sensor_seed)
        self.start_position = joint_state(self._trial.observe())[0]
        self._trial.step()  # the first tick with the scenario's own commands
        self._time_s = self._trial.observe()["time_s"]
        self._warned = False
        return self._observe(), {**info, "sensor_seed": sensor_seed}

    def render(self) -> npt.NDArray[np.uint8] | None:
        """With render_mode="rgb_array": the state now as a (height, width, 3) uint8 frame,
        drawn offscreen (OSMesa unless PAMSIM_GL_BACKEND or MUJOCO_GL says egl)."""
        if self.render_mode != "rgb_array":
            return None
        return self.trial.render(self.render_width, self.render_height)

    def _checked(self, action: Act) -> npt.NDArray[np.float64]:
        a = np.asarray(action, dtype=np.float64).reshape(-1)
        if a.shape != self.action_space.shape:
            raise ValueError(f"action must have shape {self.action_space.shape}, got {a.shape}")
        if np.isnan(a).any():
            raise ValueError(f"action holds NaN (valve commands [MPa]): {a.tolist()}")
        clipped = np.clip(a, 0.0, self.p_max_MPa)
        if not np.array_equal(clipped, a) and not self._warned:
            warnings.warn(
                f"action {a.tolist()} MPa clipped to [0, {self.p_max_MPa}] (once per episode)",
                stacklevel=3,
            )
            self._warned = True
        return clipped

    def step(self, action: Act) -> tuple[Obs, float, bool, bool, dict[str, Any]]:
        trial = self.trial
        commands = self._checked(action)
        running = trial.step(pressure_commands_MPa=commands)
        o = trial.observe()
        period_s = o["time_s"] - self._time_s  # the control period just run
        self._time_s = o["time_s"]
        reward = self.step_reward(o, period_s)
        obs = self._observe()
        if running and not trial.done:
            return obs, reward, False, False, {}
        result = trial.finish()
        self.last_result = result
        summary = result.summary
        reward += self.end_reward(summary)
        diverged = summary["status"] != "ok"
        return obs, reward, diverged, not diverged, {"summary": summary}
