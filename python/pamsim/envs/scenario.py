"""pamsim/Scenario-v0: any scenario file with the agent as its controller, rewarded by the
trial's own metrics; pamsim/Landing-v0 and Hopping-v0: the PAM leg's landing and hopping.

Action and observation: the valve commands [MPa] of every muscle in model order and their
measured channels, as ``pam_trial_env.PamTrialEnv`` says (no task entries).

Reward: 0 each step; when the episode ends, the sum of ``reward[metric] * summary[metric]``
over the weights given, the metrics those of the scenario's ``summary.json`` (``pamsim run``
writes them; a metric the trial does not report is a ValueError naming those it does). An
episode lasts the scenario's ``sim.duration_s`` unless ``duration_s`` is given. Each reset
draws the sensors' noise seed only.

Landing-v0 is Scenario-v0 on the leg's landing with the reward ``trunk_z_min_mm`` x 0.001:
the trunk's lowest height [m] as the leg catches the fall, so that a leg that holds the body
up earns more than one that folds. Hopping-v0 is the leg's hopping (scenarios/hopping.toml)
rewarded by the trunk's highest point, ``trunk_z_max_mm`` x 0.001 [m].
"""

from __future__ import annotations

from typing import Any

from .data import data_dir
from .pam_trial_env import PamTrialEnv

__all__ = ["ScenarioEnv", "hopping", "landing"]


class ScenarioEnv(PamTrialEnv):
    def __init__(
        self,
        scenario: str,
        reward: dict[str, float],
        observation: str = "measured",
        fiber: bool = False,
        noise_scale: float = 1.0,
        duration_s: float | None = None,
        p_max_MPa: float | None = None,
        render_mode: str | None = None,
        overrides: dict[str, Any] | None = None,
    ) -> None:
        if not reward:
            raise ValueError(
                'reward must weigh at least one summary metric, e.g. {"peak_drop_deg": -1.0}'
            )
        self.reward_weights = dict(reward)
        super().__init__(
            scenario,
            {},
            observation,
            fiber,
            noise_scale,
            duration_s,
            p_max_MPa,
            render_mode,
            overrides,
        )

    def step_reward(self, observation: dict[str, Any], period_s: float) -> float:
        return 0.0

    def end_reward(self, summary: dict[str, Any]) -> float:
        missing = [m for m in self.reward_weights if m not in summary]
        if missing:
            numbers = sorted(k for k, v in summary.items() if isinstance(v, (int, float)))
            raise ValueError(f"reward: the trial reports no metric {missing}; it reports {numbers}")
        return sum(w * float(summary[m]) for m, w in self.reward_weights.items())


def hopping(**kwargs: Any) -> ScenarioEnv:
    """pamsim/Hopping-v0's entry point: ScenarioEnv on the leg's hopping, rewarded by the
    trunk's highest point [m] (trunk_z_max_mm x 0.001): hop high."""
    kwargs.setdefault("scenario", str(data_dir() / "scenarios" / "hopping.toml"))
    kwargs.setdefault("reward", {"trunk_z_max_mm": 0.001})
    return ScenarioEnv(**kwargs)


def landing(**kwargs: Any) -> ScenarioEnv:
    """pamsim/Landing-v0's entry point: ScenarioEnv on the leg's landing."""
    kwargs.setdefault("scenario", str(data_dir() / "scenarios" / "landing.toml"))
    kwargs.setdefault("reward", {"trunk_z_min_mm": 0.001})
    return ScenarioEnv(**kwargs)
