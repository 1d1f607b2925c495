"""pamsim: simulation testbed for robot arms driven by pneumatic artificial muscles.

The compiled module (_pamsim) does the work; this package adds pandas conveniences.
Units are the papers' (MPa, mm, N) and are named in every argument and key.

    import pamsim
    law = pamsim.SpringModel.from_file("models/pams/table4_agonist.toml")
    law.force_N(pressure_MPa=[0.4, 0.5], deformation_mm=10.0)       # numpy, vectorised
    result = pamsim.run("scenarios/drop_mass.toml", {"reflex.v_thr_mm_s": 60.0})
    result.summary["peak_drop_deg"]; pamsim.frame(result)   # summary.json's object; a DataFrame

Errors in input raise pamsim.InputError, a ValueError with pamsim's one-line message.
With gymnasium installed, importing pamsim registers its environments (pamsim.envs):
gymnasium.make("pamsim/DropMass-v0").
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from ._pamsim import (  # noqa: F401
    InputError,
    Result,
    SpringModel,
    Trial,
    __version__,
    channels,
    fit,
    fit_csv,
    read_sweep,
    read_tensile_csv,
    read_tune,
    run,
    tensile_test,
)

if TYPE_CHECKING:  # numpy is imported when a value needs it; pandas only by frame()
    import numpy as np
    import numpy.typing as npt
    import pandas


def trajectory(result: Result) -> dict[str, npt.NDArray[np.float64]]:
    """A Result's log as {column: numpy array}."""
    values = result.values
    return {name: values[:, k] for k, name in enumerate(result.columns)}


def frame(result_or_columns: Result | dict[str, Any]) -> pandas.DataFrame:
    """A pandas DataFrame of a Result's log, or of the {column: values} that read_sweep,
    read_tensile_csv and tensile_test return (pandas must be installed)."""
    import pandas

    if isinstance(result_or_columns, Result):
        return pandas.DataFrame(result_or_columns.values, columns=result_or_columns.columns)
    return pandas.DataFrame(result_or_columns)


def _register_envs() -> None:
    """Registers pamsim.envs with gymnasium when it is installed (its import is optional)."""
    import importlib.util

    if importlib.util.find_spec("gymnasium") is None:
        return
    from .envs import register_envs

    register_envs()


_register_envs()
