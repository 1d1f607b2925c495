"""Where the environments find pamsim's models and scenarios, and the data they read there."""

from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any


def data_dir() -> Path:
    """The folder holding models/ and scenarios/ (installed with the package)."""
    return Path(__file__).resolve().parent.parent / "data"


def regulator_bracket(end: str) -> dict[str, Any]:
    """The scenario keys of one end ("fast" or "slow") of the pressure regulator's bracket,
    as models/pams/regulator_bracket.toml gives them."""
    with open(data_dir() / "models" / "pams" / "regulator_bracket.toml", "rb") as f:
        bracket = tomllib.load(f)
    if end not in bracket:
        raise ValueError(f"the regulator bracket has no end {end!r}: {sorted(bracket)}")
    return dict(bracket[end])
