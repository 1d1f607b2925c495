"""ThreadedVectorEnv: N pamsim environments stepped side by side on threads.

The work of a step is the C++ trial's control period, which runs with the GIL released, so
N environments use up to N cores from one Python process (no pickling, no processes, as
gymnasium's AsyncVectorEnv needs). It is gymnasium's SyncVectorEnv with each call's
sub-environment steps (or resets) run on a thread pool: the batching, the "next step"
autoreset and the infos are SyncVectorEnv's, so an episode is the same, byte for byte, as
under SyncVectorEnv with the same seeds (tests/test_envs.py).

    env = gymnasium.make_vec("pamsim/DropMass-v0", num_envs=8,
                             vectorization_mode="vector_entry_point")   # ThreadedVectorEnv
"""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from concurrent.futures import ThreadPoolExecutor
from copy import deepcopy
from typing import Any

import gymnasium
import numpy as np
import numpy.typing as npt
from gymnasium.vector import AutoresetMode, SyncVectorEnv
from gymnasium.vector.utils import concatenate, iterate

Step = tuple[Any, float, bool, bool, dict[str, Any]]


class ThreadedVectorEnv(SyncVectorEnv):
    def __init__(
        self,
        env_fns: Sequence[Callable[[], gymnasium.Env[Any, Any]]],
        threads: int | None = None,
        copy: bool = True,
    ) -> None:
        super().__init__(env_fns, copy=copy, autoreset_mode=AutoresetMode.NEXT_STEP)
        self.threads = threads or min(len(self.envs), os.cpu_count() or 1)
        self._pool = ThreadPoolExecutor(self.threads, thread_name_prefix="pamsim-env")

    def reset(
        self, *, seed: int | list[int | None] | None = None, options: dict[str, Any] | None = None
    ) -> tuple[Any, dict[str, Any]]:
        if options is not None and "reset_mask" in options:
            return super().reset(seed=seed, options=options)  # partial resets: in turn
        seeds: list[int | None]
        if seed is None:
            seeds = [None] * self.num_envs
        elif isinstance(seed, int):
            seeds = [seed + i for i in range(self.num_envs)]
        else:
            seeds = list(seed)
        if len(seeds) != self.num_envs:
            raise ValueError(f"seed: {len(seeds)} seeds for {self.num_envs} environments")
        results = list(
            self._pool.map(
                lambda i: self.envs[i].reset(seed=seeds[i], options=options), range(self.num_envs)
            )
        )
        infos: dict[str, Any] = {}
        for i, (obs, info) in enumerate(results):
            self._env_obs[i] = obs
            infos = self._add_info(infos, info, i)
        self._terminations[:] = False
        self._truncations[:] = False
        self._autoreset_envs[:] = False
        self._observations = concatenate(
            self.single_observation_space, self._env_obs, self._observations
        )
        return (deepcopy(self._observations) if self.copy else self._observations), infos

    def _one_step(self, i: int, action: Any) -> Step:
        if self._autoreset_envs[i]:  # the episode ended at the last step: "next step" reset
            obs, info = self.envs[i].reset()
            return obs, 0.0, False, False, info
        obs, reward, terminated, truncated, info = self.envs[i].step(action)
        return obs, float(reward), bool(terminated), bool(truncated), info

    def step(
        self, actions: Any
    ) -> tuple[
        Any, npt.NDArray[np.float64], npt.NDArray[np.bool_], npt.NDArray[np.bool_], dict[str, Any]
    ]:
        per_env = list(iterate(self.action_space, actions))
        results = list(self._pool.map(self._one_step, range(self.num_envs), per_env))
        infos: dict[str, Any] = {}
        for i, (obs, reward, terminated, truncated, info) in enumerate(results):
            self._env_obs[i] = obs
            self._rewards[i] = reward
            self._terminations[i] = terminated
            self._truncations[i] = truncated
            infos = self._add_info(infos, info, i)
        self._observations = concatenate(
            self.single_observation_space, self._env_obs, self._observations
        )
        self._autoreset_envs = np.logical_or(self._terminations, self._truncations)
        return (
            (deepcopy(self._observations) if self.copy else self._observations),
            np.copy(self._rewards),
            np.copy(self._terminations),
            np.copy(self._truncations),
            infos,
        )

    def close_extras(self, **kwargs: Any) -> None:
        self._pool.shutdown(wait=True)
        super().close_extras(**kwargs)


def _threaded(
    env_class: Callable[..., gymnasium.Env[Any, Any]],
    num_envs: int,
    threads: int | None,
    env_kwargs: dict[str, Any],
) -> ThreadedVectorEnv:
    return ThreadedVectorEnv(
        [lambda: env_class(**env_kwargs) for _ in range(num_envs)], threads=threads
    )


def make_threaded(
    num_envs: int = 1, threads: int | None = None, **env_kwargs: Any
) -> ThreadedVectorEnv:
    """gymnasium.make_vec's vector entry point: num_envs DropMassEnv on threads."""
    from .drop_mass import DropMassEnv

    return _threaded(DropMassEnv, num_envs, threads, env_kwargs)


def make_threaded_reaching(
    num_envs: int = 1, threads: int | None = None, **env_kwargs: Any
) -> ThreadedVectorEnv:
    """The same for ReachingEnv."""
    from .reaching import ReachingEnv

    return _threaded(ReachingEnv, num_envs, threads, env_kwargs)
