"""Gymnasium environments over pamsim's trials, registered when pamsim is imported with
gymnasium installed (``pip install gymnasium``):

    import gymnasium, pamsim
    env = gymnasium.make("pamsim/DropMass-v0")

``pamsim/DropMass-v0``: the falling-mass experiment of Yoshida and Hosoda's stretch reflex
paper with the agent as the arm's controller (``drop_mass.DropMassEnv``);
``pamsim/DropMass-Noisy-v0``: the same with twice the sensors' noise.
"""

from __future__ import annotations

from typing import Any

__all__ = ["DropMassEnv", "register_envs"]


def __getattr__(name: str) -> Any:
    """The environments' classes, imported when first asked for (pamsim's import stays light)."""
    if name == "DropMassEnv":
        from .drop_mass import DropMassEnv

        return DropMassEnv
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def register_envs() -> None:
    """Registers the environments with gymnasium (pamsim's import does it when it can)."""
    import gymnasium

    entry = "pamsim.envs.drop_mass:DropMassEnv"
    if "pamsim/DropMass-v0" in gymnasium.registry:
        return
    gymnasium.register("pamsim/DropMass-v0", entry_point=entry)
    gymnasium.register("pamsim/DropMass-Noisy-v0", entry_point=entry,
                       kwargs={"noise_scale": 2.0})
