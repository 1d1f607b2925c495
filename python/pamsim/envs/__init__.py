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
``-FastValve-v0`` variants of DropMass and Reaching with the regulator bracket's fast end
(ITV2000 class; the shipped scenarios are its slow end). Vectorised by
gymnasium (``make_vec(..., vectorization_mode="sync" | "async")``) or on threads in one
process (``"vector_entry_point"``: ``vector.ThreadedVectorEnv``).
"""

from __future__ import annotations

from typing import Any

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


# the regulator bracket's fast end, ITV2000 class (models/pams/pneumatics.toml)
FAST_VALVE = {"valve.supply_sonic_conductance_dm3_per_s_bar": 1.0,
              "valve.exhaust_sonic_conductance_dm3_per_s_bar": 1.0, "valve.dead_time_ms": 2.0,
              "valve.valve_time_constant_ms": 5.0, "valve.proportional_band_kPa": 250.0}


def register_envs() -> None:
    """Registers the environments with gymnasium (pamsim's import does it when it can)."""
    import gymnasium

    entry = "pamsim.envs.drop_mass:DropMassEnv"
    vector = "pamsim.envs.vector:make_threaded"   # make_vec(..., "vector_entry_point")
    if "pamsim/DropMass-v0" in gymnasium.registry:
        return
    gymnasium.register("pamsim/DropMass-v0", entry_point=entry, vector_entry_point=vector)
    gymnasium.register("pamsim/DropMass-Noisy-v0", entry_point=entry, vector_entry_point=vector,
                       kwargs={"noise_scale": 2.0})
    reaching = "pamsim.envs.reaching:ReachingEnv"
    reaching_vector = "pamsim.envs.vector:make_threaded_reaching"
    gymnasium.register("pamsim/Reaching-v0", entry_point=reaching,
                       vector_entry_point=reaching_vector)
    gymnasium.register("pamsim/Reaching-Noisy-v0", entry_point=reaching,
                       vector_entry_point=reaching_vector, kwargs={"noise_scale": 2.0})
    gymnasium.register("pamsim/Scenario-v0", entry_point="pamsim.envs.scenario:ScenarioEnv")
    gymnasium.register("pamsim/Landing-v0", entry_point="pamsim.envs.scenario:landing")
    gymnasium.register("pamsim/Hopping-v0", entry_point="pamsim.envs.scenario:hopping")
    # the regulator bracket's fast end (ITV2000 class; the shipped scenarios are its slow
    # end, ITV1000 class: models/pams/pneumatics.toml)
    gymnasium.register("pamsim/DropMass-FastValve-v0", entry_point=entry,
                       vector_entry_point=vector, kwargs={"overrides": FAST_VALVE})
    gymnasium.register("pamsim/Reaching-FastValve-v0", entry_point=reaching,
                       vector_entry_point=reaching_vector, kwargs={"overrides": FAST_VALVE})
