"""The Gymnasium environments (pamsim.envs), where gymnasium is installed (the pip install
test installs it; Debian has no package): the environment checker, the observation against
the trial log at the same tick, determinism and the reset's randomization, and bad actions."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

gymnasium = pytest.importorskip("gymnasium")

import pamsim  # noqa: E402  (registers the environments)
from pamsim.envs.drop_mass import MEASURED  # noqa: E402


def make(**kwargs):
    return gymnasium.make("pamsim/DropMass-v0", **kwargs)


def test_the_observed_quantities_are_measured_rows_of_the_channel_table():
    """What the environments observe is what a controller on the robot sees: each name a
    per-muscle row of trajectory.csv's channel table marked measured, none of the plant's
    truths."""
    rows = {r["quantity"]: r for r in pamsim.channels()}
    for name in MEASURED + ("fiber_rate_mm_s",):
        assert name in rows, name
        assert rows[name]["measured"] and rows[name]["per_muscle"], name


def test_every_registered_environment_passes_the_checker():
    from gymnasium.utils.env_checker import check_env

    for env_id, kwargs in (
        ("pamsim/DropMass-v0", {}),
        ("pamsim/DropMass-Noisy-v0", {}),
        ("pamsim/Reaching-v0", {}),
        ("pamsim/Reaching-Noisy-v0", {}),
        ("pamsim/Landing-v0", {"duration_s": 0.3}),
        ("pamsim/Hopping-v0", {"duration_s": 0.3}),
        ("pamsim/DropMass-FastValve-v0", {}),
        ("pamsim/Reaching-FastValve-v0", {}),
        ("pamsim/DropMass-SlowValve-v0", {}),
        ("pamsim/Reaching-SlowValve-v0", {}),
    ):
        env = gymnasium.make(env_id, **kwargs)
        check_env(env.unwrapped, skip_render_check=True)
        env.close()


def episode(env, seed, action):
    obs, info = env.reset(seed=seed)
    observations, rewards = [obs], []
    while True:
        obs, reward, terminated, truncated, step_info = env.step(action)
        observations.append(obs)
        rewards.append(reward)
        if terminated or truncated:
            return np.array(observations), np.array(rewards), info, step_info


def test_the_observation_is_the_logs_measured_columns_at_the_same_tick():
    env = make(duration_s=0.7)
    observations, _, _, _ = episode(env, 3, np.array([0.4, 0.4], dtype=np.float32))
    result = env.unwrapped.last_result
    log = pamsim.trajectory(result)
    labels = env.unwrapped.muscles  # the log's muscle labels ("ago", "anta")
    for k, obs in enumerate(observations[:-1]):  # the last step ends the trial
        expected = [_column(log, c, m)[k] for m in labels for c in MEASURED]
        np.testing.assert_array_equal(obs, np.array(expected), err_msg=f"tick {k}")


def _column(log, measured, label):
    # "p_meas_MPa" -> "p_meas_ago_MPa": the muscle's label before the unit
    stem, unit = {
        "p_meas_MPa": ("p_meas", "MPa"),
        "force_meas_N": ("force_meas", "N"),
        "length_est_mm": ("length_est", "mm"),
        "velocity_est_mm_s": ("velocity_est", "mm_s"),
    }[measured]
    return log[f"{stem}_{label}_{unit}"]


def test_the_same_seed_gives_the_same_episode_and_seeds_differ():
    action = np.array([0.45, 0.35], dtype=np.float32)
    a = episode(make(duration_s=0.7), 11, action)
    b = episode(make(duration_s=0.7), 11, action)
    assert a[0].tobytes() == b[0].tobytes() and a[1].tobytes() == b[1].tobytes()
    infos = [make(duration_s=0.7).reset(seed=s)[1] for s in (1, 2, 3)]
    assert len({(i["drop_time_s"], i["mass_kg"], i["height_m"]) for i in infos}) == 3
    for i in infos:
        assert 0.3 <= i["drop_time_s"] <= 0.6 and 0.15 <= i["mass_kg"] <= 0.25
        assert 0.10 <= i["height_m"] <= 0.18


def test_a_nan_action_raises_and_leaves_the_episode_where_it_was():
    env = make(duration_s=0.7)
    obs, _ = env.reset(seed=1)
    before = env.unwrapped._trial.observe()["time_s"]
    with pytest.raises(ValueError, match="NaN"):
        env.step(np.array([np.nan, 0.4], dtype=np.float32))
    assert env.unwrapped._trial.observe()["time_s"] == before


def test_an_action_outside_the_space_is_clipped_with_one_warning_per_episode():
    env = make(duration_s=0.7)
    env.reset(seed=1)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        for _ in range(3):
            env.step(np.array([2.0, -1.0], dtype=np.float32))
    assert len([w for w in caught if "clipped" in str(w.message)]) == 1
    assert env.unwrapped._trial.observe()["command_MPa"][0] <= 0.8


def test_the_action_space_tops_at_the_scenarios_valve_range_unless_given():
    env = make(duration_s=0.7)
    top = pamsim.Trial(env.unwrapped.scenario).command_max_MPa
    assert 0.0 < top <= 1.0
    assert np.all(env.action_space.high == np.float32(top))
    assert np.all(make(duration_s=0.7, p_max_MPa=0.5).action_space.high == np.float32(0.5))


def vector_episode(vec, steps):
    """`steps` batched steps of a fixed action from reset(seed=5): every output's bytes."""
    out = [vec.reset(seed=5)[0].tobytes()]
    action = np.tile(np.array([0.45, 0.35], dtype=np.float32), (vec.num_envs, 1))
    for _ in range(steps):
        obs, reward, terminated, truncated, _ = vec.step(action)
        out += [obs.tobytes(), reward.tobytes(), terminated.tobytes(), truncated.tobytes()]
    vec.close()
    return out


def test_threaded_and_sync_vector_envs_give_the_same_episode_bytes():
    from pamsim.envs import ThreadedVectorEnv
    from pamsim.envs.drop_mass import DropMassEnv

    def fns():
        return [lambda: DropMassEnv(duration_s=0.7) for _ in range(3)]

    sync = gymnasium.vector.SyncVectorEnv(fns())
    threaded = ThreadedVectorEnv(fns(), threads=2)
    steps = 150  # past the 70-step episodes: the autoresets are compared too
    a, b = vector_episode(sync, steps), vector_episode(threaded, steps)
    assert a == b
    made = gymnasium.make_vec(
        "pamsim/DropMass-v0", num_envs=2, vectorization_mode="vector_entry_point", duration_s=0.7
    )
    assert isinstance(made, ThreadedVectorEnv) and made.num_envs == 2
    made.close()


def test_gymnasiums_sync_and_async_vector_envs_run_it_alike():
    kwargs = {"num_envs": 2, "duration_s": 0.7}
    sync = gymnasium.make_vec("pamsim/DropMass-v0", vectorization_mode="sync", **kwargs)
    asynchronous = gymnasium.make_vec("pamsim/DropMass-v0", vectorization_mode="async", **kwargs)
    assert vector_episode(sync, 20) == vector_episode(asynchronous, 20)


def test_a_slide_joints_scenario_observes_and_rewards_in_mm():
    from pamsim.envs.data import data_dir

    scenario = str(data_dir() / "scenarios" / "pulley_sine_5kg.toml")
    env = make(scenario=scenario, observation="privileged", randomize=False, duration_s=0.3)
    obs, _ = env.reset(seed=1)
    assert obs.shape == env.observation_space.shape
    o = env.unwrapped._trial.observe()
    assert "position_mm" in o and "angle_deg" not in o
    assert obs[-2] == o["position_mm"] and obs[-1] == o["velocity_mm_s"]
    _, reward, _, _, _ = env.step(env.action_space.high)
    moved = env.unwrapped._trial.observe()["position_mm"] - env.unwrapped.start_position
    assert reward == pytest.approx(-abs(moved) * 0.01, rel=1e-9)  # 100 Hz control
    env.close()


def test_reaching_observes_its_target_ramp_and_rewards_the_tracking_error():
    from pamsim.envs.reaching import RAMP_S, RAMP_START_S

    env = gymnasium.make("pamsim/Reaching-v0", observation="privileged", duration_s=2.6)
    obs, info = env.reset(seed=4)
    assert -60.0 <= info["final_deg"] <= -20.0
    start = env.unwrapped.start_position
    hold = np.array([0.4, 0.4], dtype=np.float32)  # the calibrated posture's commands
    total, n = 0.0, 0
    while True:
        obs, reward, terminated, truncated, _ = env.step(hold)
        t = env.unwrapped.trial.observe()["time_s"] if not (terminated or truncated) else None
        if t is not None:
            u = min(max((t - RAMP_START_S) / RAMP_S, 0.0), 1.0)
            # the target (before the privileged angle and velocity): a ramp from the start
            assert obs[-3] == pytest.approx(start + u * (info["final_deg"] - start), abs=1e-9)
            # the reward: the tracking error over the control period
            assert reward == pytest.approx(-abs(obs[-2] - obs[-3]) * 0.01, rel=1e-9)
        total += reward
        n += 1
        if terminated or truncated:
            break
    assert truncated and n == 259  # 2.6 s at 100 Hz, the reset's tick aside
    assert total < 0.0
    infos = [gymnasium.make("pamsim/Reaching-v0").reset(seed=s)[1]["final_deg"] for s in (1, 2)]
    assert infos[0] != infos[1]
    env.close()


def test_a_scenario_env_rewards_its_summary_metrics_at_the_end():
    from pamsim.envs.data import data_dir

    scenario = str(data_dir() / "scenarios" / "drop_mass.toml")
    env = gymnasium.make(
        "pamsim/Scenario-v0",
        scenario=scenario,
        duration_s=1.5,
        reward={"peak_drop_deg": -1.0, "mass_retained": 2.0},
    )
    env.reset(seed=2)
    rewards = []
    while True:
        _, reward, terminated, truncated, info = env.step(np.array([0.4, 0.4], dtype=np.float32))
        rewards.append(reward)
        if terminated or truncated:
            break
    summary = info["summary"]
    assert all(r == 0.0 for r in rewards[:-1])
    assert rewards[-1] == pytest.approx(-summary["peak_drop_deg"] + 2.0 * summary["mass_retained"])
    bad = gymnasium.make(
        "pamsim/Scenario-v0", scenario=scenario, duration_s=1.2, reward={"no_such_metric": 1.0}
    )
    bad.reset(seed=1)
    with pytest.raises(ValueError, match="no_such_metric"):
        while True:
            *_, terminated, truncated, _ = bad.step(np.array([0.4, 0.4], dtype=np.float32))
            if terminated or truncated:
                break
    with pytest.raises(ValueError, match="at least one"):
        gymnasium.make("pamsim/Scenario-v0", scenario=scenario, reward={})


def test_rgb_array_frames_show_the_state_and_pass_the_checker():
    from gymnasium.utils.env_checker import check_env

    env = gymnasium.make("pamsim/DropMass-v0", render_mode="rgb_array")
    check_env(env.unwrapped)  # the render check included
    env.reset(seed=1)
    first = env.render()
    assert first.shape == (480, 640, 3) and first.dtype == np.uint8
    assert first.min() < first.max()  # a scene, not a blank frame
    assert np.array_equal(env.render(), first)  # the same state, the same frame
    for _ in range(80):  # past the drop at 0.3-0.6 s: the ball has fallen
        env.step(np.array([0.4, 0.4], dtype=np.float32))
    assert not np.array_equal(env.render(), first)
    assert env.unwrapped.metadata["render_fps"] == 100  # the control rate
    plain = gymnasium.make("pamsim/DropMass-v0")
    plain.reset(seed=1)
    assert plain.render() is None
    from pamsim.envs.drop_mass import DropMassEnv

    with pytest.raises(ValueError, match="render_mode"):
        DropMassEnv(render_mode="window")


def test_the_fast_valve_variant_fills_the_chambers_faster():
    def pressures(env_id):
        env = gymnasium.make(env_id, randomize=False, noise_scale=0.0)
        env.reset(seed=1)
        for _ in range(5):  # a step of the agonist's command, 50 ms
            env.step(np.array([0.7, 0.4], dtype=np.float32))
        return env.unwrapped.trial.observe()["pressure_MPa"][0]

    # the ITV2000 class (2 ms dead time, C = 1) against the shipped ITV1000 (10 ms, C = 0.35)
    assert pressures("pamsim/DropMass-FastValve-v0") > pressures("pamsim/DropMass-v0") + 0.01


def test_the_slow_valve_variant_is_the_shipped_regulator():
    """The bracket file's slow end and pneumatics.toml's [regulator] are one regulator: the
    same seed and actions give the same episode bytes."""
    rng = np.random.default_rng(5)
    actions = rng.uniform(0.0, 0.8, size=(90, 2)).astype(np.float32)

    def run(env_id):
        env = gymnasium.make(env_id, duration_s=0.9)  # the drop within it
        obs, _ = env.reset(seed=4)
        trace = [obs.tobytes()]
        for action in actions:
            obs, reward, terminated, truncated, _ = env.step(action)
            trace.append(obs.tobytes() + np.float64(reward).tobytes())
            if terminated or truncated:
                break
        return b"".join(trace)

    assert run("pamsim/DropMass-SlowValve-v0") == run("pamsim/DropMass-v0")
    assert run("pamsim/DropMass-FastValve-v0") != run("pamsim/DropMass-v0")


def test_the_bracket_refuses_an_end_it_does_not_have():
    from pamsim.envs.data import regulator_bracket

    with pytest.raises(ValueError, match="no end 'medium'"):
        regulator_bracket("medium")
