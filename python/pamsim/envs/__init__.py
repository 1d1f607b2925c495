"""Gymnasium environments over pamsim's trials, registered when pamsim is imported with
gymnasium installed (``pip install gymnasium``):

    import gymnasium, pamsim
    env = gymnasium.make("pamsim/DropMass-v0")

``pamsim/DropMass-v0``: the falling-mass experiment of Yoshida and Hosoda's stretch reflex
paper with the agent as the arm's controller (``drop_mass.DropMassEnv``);
``pamsim/DropMass-Noisy-v0``: the same with twice the sensors' noise;
``pamsim/Reaching-v0``: the reaching task's arm tracking a target angle profile
(``reaching.ReachingEnv``), and ``pamsim/Reaching-Noisy-v0``; ``pamsim/Scenario-v0``: any
scenario file rewarded by its summary's metrics, and ``pamsim/Landing-v0``: the PAM leg's
landing, ``pamsim/Hopping-v0`` its hopping (``scenario.ScenarioEnv``);
``-FastValve-v0`` and ``-SlowValve-v0`` variants of DropMass and Reaching at the pressure
regulator bracket's ends (models/pams/regulator_bracket.toml: the ITV2000 class and the
ITV1000 class; the shipped scenarios run the slow end, so ``-SlowValve-v0`` equals the plain
id episode for episode and names the choice). Vectorised by
gymnasium (``make_vec(..., vectorization_mode="sync" | "async")``) or on threads in one
process (``"vector_entry_point"``: ``vector.ThreadedVectorEnv``).
"""

from __future__ import annotations

from typing import Any

from .data import regulator_bracket

__all__ = ["DropMassEnv", "ReachingEnv", "ScenarioEnv", "ThreadedVectorEnv", "register_envs"]


def __getattr__(name: str) -> Any:
    """The environments' classes, imported when first asked for (pamsim's import stays light)."""
    if name == "DropMassEnv":
        from .drop_mass import DropMassEnv

        return DropMassEnv
    if name == "ReachingEnv":
        from .reaching import ReachingEnv

        return ReachingEnv
    if name == "ScenarioEnv":
        from .scenario import ScenarioEnv

        return ScenarioEnv
    if name == "ThreadedVectorEnv":
        from .vector import ThreadedVectorEnv

        return ThreadedVectorEnv
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def register_envs() -> None:
    """Registers the environments with gymnasium (pamsim's import does it when it can)."""
    import gymnasium

    entry = "pamsim.envs.drop_mass:DropMassEnv"
    vector = "pamsim.envs.vector:make_threaded"  # make_vec(..., "vector_entry_point")
    if "pamsim/DropMass-v0" in gymnasium.registry:
        return
    gymnasium.register("pamsim/DropMass-v0", entry_point=entry, vector_entry_point=vector)
    gymnasium.register(
        "pamsim/DropMass-Noisy-v0",
        entry_point=entry,
        vector_entry_point=vector,
        kwargs={"noise_scale": 2.0},
    )
    reaching = "pamsim.envs.reaching:ReachingEnv"
    reaching_vector = "pamsim.envs.vector:make_threaded_reaching"
    gymnasium.register(
        "pamsim/Reaching-v0", entry_point=reaching, vector_entry_point=reaching_vector
    )
    gymnasium.register(
        "pamsim/Reaching-Noisy-v0",
        entry_point=reaching,
        vector_entry_point=reaching_vector,
        kwargs={"noise_scale": 2.0},
    )
    gymnasium.register("pamsim/Scenario-v0", entry_point="pamsim.envs.scenario:ScenarioEnv")
    gymnasium.register("pamsim/Landing-v0", entry_point="pamsim.envs.scenario:landing")
    gymnasium.register("pamsim/Hopping-v0", entry_point="pamsim.envs.scenario:hopping")
    # the pressure regulator bracket's ends (models/pams/regulator_bracket.toml)
    for end, name in (("fast", "FastValve"), ("slow", "SlowValve")):
        valve = {"overrides": regulator_bracket(end)}
        gymnasium.register(
            f"pamsim/DropMass-{name}-v0", entry_point=entry, vector_entry_point=vector, kwargs=valve
        )
        gymnasium.register(
            f"pamsim/Reaching-{name}-v0",
            entry_point=reaching,
            vector_entry_point=reaching_vector,
            kwargs=valve,
        )
