"""pamsim/DropMass-v0: the falling-mass experiment with the agent as the arm's controller.

A vertical arm driven by an antagonistic pair of PAMs holds a basket; a mass falls into it
(Yoshida and Hosoda's stretch-reflex experiment, scenarios/drop_mass.toml). Each step is one
control period (10 ms at the scenario's 100 Hz): the action sets both valve commands, the
observation is what the robot's controller has on hardware, never the true state unless
``observation="privileged"``.

Action: the valve commands [MPa], one per muscle (agonist, antagonist), in [0, p_max]
(valve.command_max_MPa). A command outside is clipped, with one warning per episode; a NaN
raises ValueError and leaves the episode where it was. The scenario's own controller still
reads the sensors (its estimates are the observation's) but its commands are replaced.

Observation (float64), per muscle in model order: measured pressure [MPa], gauge force [N],
estimated length [mm], estimated stretch velocity [mm/s], as the trial log's columns
p_meas_<m>_MPa, force_meas_<m>_N, length_est_<m>_mm, velocity_est_<m>_mm_s have them at the
same tick; with ``fiber=True`` also the fiber sensor's rate [mm/s] (fiber_rate_<m>_mm_s);
with ``observation="privileged"`` also the true angle [deg] and angular velocity [deg/s] (on
a scenario whose measured joint is a slide: its position [mm] and velocity [mm/s]).

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
import warnings
from pathlib import Path
from typing import Any

import gymnasium
import numpy as np
import numpy.typing as npt
from gymnasium import spaces

from .._pamsim import Trial

Obs = npt.NDArray[np.float64]
Act = npt.NDArray[np.float32]

DROP_TIME_S = (0.3, 0.6)
MASS_KG = (0.15, 0.25)
HEIGHT_M = (0.10, 0.18)
MEASURED = ("p_meas_MPa", "force_meas_N", "length_est_mm", "velocity_est_mm_s")


def data_dir() -> Path:
    """The folder holding models/ and scenarios/ (installed with the package)."""
    return Path(__file__).resolve().parent.parent / "data"


def _joint_state(observation: dict[str, Any]) -> tuple[float, float]:
    """The measured joint's true position and velocity: a hinge's [deg, deg/s], a slide's
    [mm, mm/s]."""
    if "angle_deg" in observation:
        return observation["angle_deg"], observation["angular_velocity_deg_s"]
    return observation["position_mm"], observation["velocity_mm_s"]


class DropMassEnv(gymnasium.Env[Obs, Act]):
    metadata: dict[str, Any] = {"render_modes": []}

    def __init__(self, scenario: str | None = None, observation: str = "measured",
                 fiber: bool = False, randomize: bool = True, noise_scale: float = 1.0,
                 duration_s: float = 1.5, mass_lost_penalty: float = 10.0,
                 p_max_MPa: float | None = None, render_mode: str | None = None) -> None:
        if observation not in ("measured", "privileged"):
            raise ValueError(f'observation must be "measured" or "privileged", got {observation!r}')
        if render_mode is not None:
            raise ValueError("DropMassEnv renders nothing yet (render_mode must be None)")
        self.scenario = scenario or str(data_dir() / "scenarios" / "drop_mass.toml")
        self.privileged = observation == "privileged"
        self.fiber = fiber
        self.randomize = randomize
        self.duration_s = duration_s
        self.mass_lost_penalty = mass_lost_penalty
        self.noise_scale = noise_scale
        self._trial: Trial | None = None
        self._start_position = 0.0
        self._warned = False
        self._time_s = 0.0
        self.last_result: Any = None
        if randomize and not duration_s > DROP_TIME_S[1]:
            raise ValueError(f"duration_s must exceed the latest drop time {DROP_TIME_S[1]} s, "
                             f"got {duration_s}")
        probe = Trial(self.scenario, self._draws_as_overrides(
            [DROP_TIME_S[1], MASS_KG[1], HEIGHT_M[1]] if randomize else [math.nan] * 3))
        self.muscles: list[str] = list(probe.muscles)
        # the actions' top: the scenario's valve range unless given
        self.p_max_MPa: float = probe.command_max_MPa if p_max_MPa is None else p_max_MPa
        n = len(self.muscles)
        self.action_space = spaces.Box(0.0, self.p_max_MPa, shape=(n,), dtype=np.float32)
        size = n * (len(MEASURED) + (1 if fiber else 0)) + (2 if self.privileged else 0)
        self.observation_space = spaces.Box(-np.inf, np.inf, shape=(size,), dtype=np.float64)

    def _overrides(self, drop_time_s: float, mass_kg: float, height_m: float) -> dict[str, Any]:
        return {"sim.duration_s": self.duration_s, "drop.time_s": drop_time_s,
                "drop.mass_kg": mass_kg, "drop.height_m": height_m,
                "sensors.noise_scale": self.noise_scale}

    def _draws_as_overrides(self, draws: list[float]) -> dict[str, Any]:
        """The scenario keys of a reset's draws (NaN: the scenario's own value)."""
        return {k: v for k, v in self._overrides(*draws).items()
                if not (isinstance(v, float) and math.isnan(v))}

    def _observe(self) -> Obs:
        assert self._trial is not None
        o = self._trial.observe()
        m = o["measured"]
        names = MEASURED + (("fiber_rate_mm_s",) if self.fiber else ())
        values = [m[name][i] for i in range(len(self.muscles)) for name in names]
        if self.privileged:
            values += list(_joint_state(o))
        return np.array(values, dtype=np.float64)

    def reset(self, *, seed: int | None = None,
              options: dict[str, Any] | None = None) -> tuple[Obs, dict[str, Any]]:
        super().reset(seed=seed)
        rng = self.np_random
        if self.randomize:
            draws = [float(rng.uniform(*r)) for r in (DROP_TIME_S, MASS_KG, HEIGHT_M)]
        else:
            draws = [math.nan] * 3
        overrides = self._draws_as_overrides(draws)
        sensor_seed = int(rng.integers(1, 2**31))
        self._trial = Trial(self.scenario, overrides, seed=sensor_seed)
        self._start_position = _joint_state(self._trial.observe())[0]
        self._trial.step()   # the first tick with the scenario's own commands
        self._time_s = self._trial.observe()["time_s"]
        self._warned = False
        info = {"drop_time_s": draws[0], "mass_kg": draws[1], "height_m": draws[2],
                "sensor_seed": sensor_seed}
        return self._observe(), info

    def _checked(self, action: Act) -> npt.NDArray[np.float64]:
        a = np.asarray(action, dtype=np.float64).reshape(-1)
        if a.shape != self.action_space.shape:
            raise ValueError(f"action must have shape {self.action_space.shape}, got {a.shape}")
        if np.isnan(a).any():
            raise ValueError(f"action holds NaN (valve commands [MPa]): {a.tolist()}")
        clipped = np.clip(a, 0.0, self.p_max_MPa)
        if not np.array_equal(clipped, a) and not self._warned:
            warnings.warn(f"action {a.tolist()} MPa clipped to [0, {self.p_max_MPa}] "
                          "(once per episode)", stacklevel=3)
            self._warned = True
        return clipped

    def step(self, action: Act) -> tuple[Obs, float, bool, bool, dict[str, Any]]:
        if self._trial is None:
            raise RuntimeError("call reset() before step()")
        commands = self._checked(action)
        running = self._trial.step(pressure_commands_MPa=commands)
        o = self._trial.observe()
        period_s = o["time_s"] - self._time_s   # the control period just run
        self._time_s = o["time_s"]
        reward = -abs(_joint_state(o)[0] - self._start_position) * period_s
        obs = self._observe()
        if running and not self._trial.done:
            return obs, reward, False, False, {}
        result = self._trial.finish()
        self.last_result = result
        summary = result.summary
        if summary.get("mass_retained", 1) == 0:
            reward -= self.mass_lost_penalty
        diverged = summary["status"] != "ok"
        return obs, reward, diverged, not diverged, {"summary": summary}
